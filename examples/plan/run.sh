#!/usr/bin/env bash
# Example: run seed 000's U/P/F planner compiled from the library rule files.
#  1. the paper's block experiment at 2304 metamodules (6x3x2 -> 3x3x4, --scale 4) with
#     intermediate and with general1 under the random, gradient and optimal allocators, monitored;
#     snapshots and completion curves in examples/plan/out/<system>/.
#  2. a 2D plan from ASCII art (examples/plan/l_shape.txt) to a disc.
#  3. the Fig. 7 / Fig. 8 reproduction up to 2304 metamodules: out/fig7.svg, out/fig8.svg, and
#     every general system with every allocator: out/systems.csv.
# Needs a build (bash scripts/build).
set -u
cd "$(dirname "$0")/../.."
holon=./build/cli/holon
out=examples/plan/out
mkdir -p "$out"
"$holon" plan --rules planner_intermediate --from box:6x3x2 --to box:3x3x4 --scale 4 --check --out "$out/intermediate"
echo
for a in random gradient optimal; do
    "$holon" plan --rules planner_general1 --from box:6x3x2 --to box:3x3x4 --scale 4 --allocator $a --check --out "$out/general1_$a"
    echo
done
"$holon" plan --from examples/plan/l_shape.txt --to disc:6 --scale 2 --out "$out/l_to_disc"
echo
./build/bench/plan_figures "$out" --max-k 4 --max-k-gradient 4 --max-k-optimal 4
