#!/usr/bin/env bash
# Usage: walkthrough.sh HOLON OUTDIR : run examples/design/run.sh, every command of
# docs/walkthrough.md, and hold it to the walkthrough: each step's exit code (run.sh compares them),
# the verdict each step's paragraph tells, and the two pictures the page shows (byte for byte, so a
# changed trace or path redraws them). Fails naming what moved.
set -u
holon=$1 out=$2
root=$(cd "$(dirname "$0")/../.." && pwd)
mkdir -p "$out"
log=$out/walkthrough.log
if ! HOLON=$holon OUT=$out bash "$root/examples/design/run.sh" >"$log" 2>&1; then
    cat "$log"; echo "FAIL: a step's exit code changed (above)"; exit 1
fi
failed=0
# The verdicts, in the order of the steps.
for line in \
    "slide                 3 cells  8" \
    "drawings     2 rules on square2d in $out/rules/" \
    "violated after 1 step: 'connected' is false" \
    "-- 1: slide at (1,0)" \
    "  A: 420 configurations, 1680 transitions; only in A: 368 configurations, 1512 transitions" \
    "  B: 52 configurations, 168 transitions; only in B: 0 configurations, 0 transitions" \
    "holds in all 52 states" \
    "components: 1; one component: every configuration reaches every other" \
    "560 states, 840 edges, 277 components" \
    "not inductive: 'connected' is false" \
    "inductive: every step from a state where it holds keeps it" \
    "  a shortest path: 8 steps" \
    '"length": 8,'; do
    grep -qF -- "$line" "$log" || { echo "FAIL: no line '$line' in the walkthrough's output"; failed=1; }
done
for svg in counterexample.svg path.svg; do
    cmp -s "$out/$svg" "$root/examples/design/$svg" ||
        { echo "FAIL: $out/$svg differs from examples/design/$svg (the page shows the latter)"; failed=1; }
done
[ $failed -eq 0 ] || { cat "$log"; exit 1; }
echo "walkthrough: every step as documented"
