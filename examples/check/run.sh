#!/usr/bin/env bash
# Example: explore reconfiguration graphs and show what the checker finds.
#  1. pixel and intermediate are holonomic; the hex pivot of seed 000 Fig. 1a is not (Fig. 2):
#     the witness pair and its shortest path are drawn to examples/check/out/pivot.svg.
#  2. the U/P/F planner keeps its spanning tree, terminates and progresses on a small instance;
#     the variant without the deletion guard breaks the tree: out/no_guard.svg and out/no_guard.itf.json.
# Needs a build (bash scripts/build).
set -u
cd "$(dirname "$0")/../.."
holon=./build/cli/holon
out=examples/check/out
mkdir -p "$out"
for s in pixel intermediate general2; do
    "$holon" check rules/library/$s.holon --region square:3x3 --all --property holonomy | sed -n '1,2p;5p'
done
"$holon" check rules/library/hex_pivot.holon --region hex:r2 --all --property holonomy --svg "$out/pivot.svg" | sed -n '1,5p'
echo
"$holon" check rules/library/planner_intermediate.holon --region square:4x3 \
    --from examples/check/planner_start.txt --input target=examples/check/planner_target.txt
echo
"$holon" check tests/checker/broken/planner_no_guard.holon --region square:4x3 \
    --from examples/check/planner_start.txt --input target=examples/check/planner_target.txt \
    --svg "$out/no_guard.svg" --trace-out "$out/no_guard.itf.json"
echo "(pictures in $out/)"
