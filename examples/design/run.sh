#!/usr/bin/env bash
# The walkthrough of docs/walkthrough.md: the tromino, a metamodule designed from scratch in seven
# steps. Every step's command runs with the files of this folder, and its exit code is compared
# with the one the walkthrough expects: the script exits 1 naming the step whose verdict changed
# (tests/cli/walkthrough.sh runs it in the suite). Pictures and traces go to $OUT (default
# examples/design/out/). Needs a build (bash scripts/build).
set -u
cd "$(dirname "$0")/../.."
holon=${HOLON:-./build/cli/holon}
out=${OUT:-examples/design/out}
d=examples/design
mkdir -p "$out"
failed=0
# step N EXIT COMMAND...: run a step's command and hold its exit code to EXIT.
step() {
    local n=$1 want=$2; shift 2
    echo "== step $n: holon ${*}"
    "$holon" "$@" 2>&1
    local got=$?
    echo "(exit code $got)"
    if [ "$got" -ne "$want" ]; then
        echo "walkthrough: step $n exited $got, expected $want" >&2
        failed=1
    fi
    echo
}
# 1-2. The generators of the first version, and what holon reads in them.
step 2 0 rules $d/tromino_v1.holon
step 2 0 rules $d/tromino_v1.holon --json
step 2 0 rules $d/tromino_v1.holon --svg "$out/rules"
# 3. The checker finds the flaw: the invariant 'together' fails after one step.
step 3 1 check $d/tromino_v1.holon --region square:4x4 --from $d/start.txt \
    --svg "$out/counterexample.svg" --trace-out "$out/counterexample.itf.json"
# 5. The fix, what it changed, and the check again; whether the design is complete.
step 5 1 diff $d/tromino_v1.holon $d/tromino.holon --region square:4x4 --from $d/start.txt
step 5 0 check $d/tromino.holon --region square:4x4 --from $d/start.txt --components
step 5 0 check $d/tromino.holon --region square:4x4 --from "$out/counterexample.itf.json#0"
step 5 1 check $d/tromino.holon --region square:4x4 --all --components
# 6. The invariant proved for every configuration of the region (and refuted for the first version).
step 6 1 verify $d/tromino_v1.holon --region square:4x4
step 6 0 verify $d/tromino.holon --region square:4x4
# 7. How to get from the start to the target.
step 7 0 path $d/tromino.holon --region square:4x4 --from $d/start.txt --to $d/target.txt --svg "$out/path.svg"
step 7 0 path $d/tromino.holon --region square:4x4 --from $d/start.txt --to $d/target.txt --json
echo "(pictures and the trace in $out/)"
exit $failed
