#!/usr/bin/env bash
# Example: seed 000's general_2 metamodules realised on hex-lattice disks (Fig. 4a). The U/P/F
# planner runs planner_general2 on the square metamodule lattice; every template it fires replays
# the design's fixed motion sequence (15x15 disks per slot: a ring of 54, the skeleton, and payload
# inside it; a door opens in the wall between the two slots). Every move is then replayed and
# checked on its own (a roll about an occupied neighbour with the other side empty, onto an empty
# cell, all disks connected after it), and every slot must end in its state's layout.
# Writes examples/plan/out/disks_<plan>/: disk_moves.jsonl (one move per line), disks.svg (start
# and end side by side) and creation.svg (the creation sequence, as Fig. 4a). Needs a build
# (bash scripts/build). About 5 s.
set -u
cd "$(dirname "$0")/../.."
holon=${HOLON:-./build/cli/holon}
[ -x "$holon" ] || bash scripts/build >/dev/null
out=examples/plan/out
mkdir -p "$out"
for plan in "box:3x2 box:2x3" "box:4x4 T:4" "box:6x3 box:3x6" "box:8x8 disc:5"; do
  read -r from to <<<"$plan"
  "$holon" plan --rules planner_general2 --from "$from" --to "$to" --allocator gradient --hex-disks "$out/disks_${from#box:}_${to/:/}" | sed -n '1p;3p;5,$p'
  echo
done
