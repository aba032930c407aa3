#!/usr/bin/env bash
# Example: files other tools read (docs/interop.md). Writes into examples/interop/out/ (or $OUT):
#  1. blocks.xml: the planner's block problem (6x3x2 -> 3x3x4, --scale 2) as one VisibleSim world,
#     the start as slidingCubes modules and the target as its targetList, then planned from it;
#  2. counterexample.xml: state 2 of the counterexample of a broken planner design (an ITF trace),
#     each module coloured by its state as in the SVG traces;
#  3. hex.xml: a hex_delete configuration as VisibleSim hexanodes;
#  4. chair.binvox: a chair as a .binvox voxel file, and a plan from it and from the bundled
#     examples/interop/arch.binvox.
# Needs a build (bash scripts/build).
set -eu
cd "$(dirname "$0")/../.."
holon=${HOLON:-./build/cli/holon}
out=${OUT:-examples/interop/out}
mkdir -p "$out"
"$holon" export --shape box:6x3x2 --target box:3x3x4 --scale 2 --margin 1 --visiblesim "$out/blocks.xml"
"$holon" plan --from "$out/blocks.xml" --to "$out/blocks.xml#target" --quiet | tail -1
status=0  # the broken design violates safety: exit 1, and the trace is written
"$holon" check tests/checker/broken/planner_no_guard.holon --region square:4x3 --from examples/check/planner_start.txt \
    --input target=examples/check/planner_target.txt --trace-out "$out/counterexample.itf.json" >/dev/null || status=$?
[ "$status" = 1 ]
"$holon" export --config "$out/counterexample.itf.json#2" --visiblesim "$out/counterexample.xml"
"$holon" export --config examples/hex/checker/surface_holes.txt --rules hex_delete --region hex:r5 --visiblesim "$out/hex.xml"
"$holon" export --shape chair:3 --binvox "$out/chair.binvox"
"$holon" plan --from "$out/chair.binvox" --to box:3x3x4 --quiet | tail -1
"$holon" plan --from examples/interop/arch.binvox --to box:4x3x1 --scale 2 --quiet | tail -1
