#!/usr/bin/env bash
# Example: Z3 proofs of seed 000's planner lemmas (§IV-C), and proofs over the reachable states.
#  1. the U/P/F planner over intermediate: Safety, Termination and Progress for every
#     configuration of square:3x3 and every target shape.
#  2. the planner over general2: Progress is refuted for all configurations (the stuck state is made
#     of partials no run produces) but proved, with --reach, for every state reachable from
#     general_start.json; Spacer's inductive invariant is printed, and its three certificate checks
#     are written to out/ and re-checked here by the z3 and cvc5 command-line solvers.
# Needs a build (bash scripts/build); about 10 s.
set -u
cd "$(dirname "$0")/../.."
holon=./build/cli/holon
out=examples/verify/out
rm -rf "$out" && mkdir -p "$out"
"$holon" verify rules/library/planner_intermediate.holon --region square:3x3
echo
"$holon" verify rules/library/planner_general2.holon --region square:3x2 --property progress --reach \
    --from examples/verify/general_start.json --input target=examples/verify/general_target.txt --smt-out "$out"
echo
echo "certificate checks, re-checked by two other solvers:"
for f in "$out"/*_reach.*.smt2; do
    echo "  $(basename "$f"): z3 $(z3 "$f"), cvc5 $(cvc5 "$f")"
done
