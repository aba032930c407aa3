#!/usr/bin/env bash
# Example: seed 000's general_2 metamodules realised on hex-lattice disks (Fig. 4a). The U/P/F
# planner runs planner_general2 on the square metamodule lattice and every template it fires becomes
# single-disk pivot moves (13x13 disks per metamodule slot); every move is then replayed and checked
# on its own (a roll about an occupied neighbour with the other side empty, onto an empty cell, all
# disks connected after it). Writes examples/plan/out/disks_<plan>/disk_moves.jsonl (one move per
# line) and disks.svg (start and end side by side). Needs a build (bash scripts/build). About 30 s.
set -u
cd "$(dirname "$0")/../.."
holon=${HOLON:-./build/cli/holon}
[ -x "$holon" ] || bash scripts/build >/dev/null
out=examples/plan/out
mkdir -p "$out"
"$holon" plan --rules planner_general2 --from box:3x2 --to box:2x3 --hex-disks "$out/disks_3x2"
echo
"$holon" plan --rules planner_general2 --from box:4x4 --to T:4 --hex-disks "$out/disks_T4"
