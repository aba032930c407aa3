#!/usr/bin/env bash
# Re-checks every exported obligation with the z3 and cvc5 command-line solvers, independently of
# holon's C++ pipeline, against the verdict the manifest expects; checks the files' hashes. Both
# manifests: DIR (bounded regions) and DIR/every-size (every region of a lattice).
# Usage: proofs/recheck.sh [DIR]
set -uo pipefail
cd "$(dirname "$0")/.."
dir=${1:-proofs/smt}
fail=0 passed=0
# The bounded obligations, then those for every region (holon verify --every-size).
for sub in "$dir" "$dir/every-size"; do
    while IFS=$'\t' read -r file expected hash; do
        path="$sub/$file"
        if [ "$(sha256sum "$path" | cut -d' ' -f1)" != "$hash" ]; then echo "HASH MISMATCH $file"; fail=$((fail + 1)); continue; fi
        z=$(timeout 300 z3 -T:240 "$path" 2>&1 | head -n 1)
        # cvc5's own decision heuristic: with its default (justification) the Boolean window and
        # safety queries took up to 240 s each (planner_general1's Safety on cubic3d: 90-207 s per
        # conjunct, the bounded square_3x3 safety parts 24-240 s); with it, all of them 100 s in all.
        c=$(timeout 300 cvc5 --decision=internal --tlimit=240000 "$path" 2>&1 | head -n 1)
        if [ "$z" = "$expected" ] && [ "$c" = "$expected" ]; then
            passed=$((passed + 1))
            echo "ok    $file: z3 $z, cvc5 $c"
        else
            fail=$((fail + 1))
            echo "FAIL  $file: expected $expected, z3 said '$z', cvc5 said '$c'"
        fi
    done < <(python3 -c 'import json,sys
for e in json.load(open(sys.argv[1])): print("%s\t%s\t%s" % (e["file"], e["expected"], e["sha256"]))' "$sub/manifest.json")
done
echo "proofs: $passed passed, $fail failed"
[ "$fail" -eq 0 ]
