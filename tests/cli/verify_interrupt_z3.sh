#!/usr/bin/env bash
# Usage: verify_interrupt_z3.sh HOLON: sends SIGINT to a verify whose obligations Z3 checks in this
# process, and requires exit 130 within a few seconds. Z3's own SIGINT catcher took the signal for
# one cancelled obligation, and the job went on to exit 3, or to 0 when it came between checks.
# The report so far is printed: the obligation cut short and those after it say "interrupted".
set -u
holon=$1
set -m  # job control: a background job keeps SIGINT
out=$(mktemp)
trap 'rm -f "$out"' EXIT
"$holon" verify planner_intermediate --region square:5x5 >"$out" 2>&1 &
pid=$!
sleep 1.5
kill -0 "$pid" 2>/dev/null || { echo "verify ended before the signal"; exit 1; }
kill -INT "$pid"
start=$(date +%s)
wait "$pid"
got=$?
[ "$got" = 130 ] || { echo "expected exit 130 after SIGINT, got $got"; exit 1; }
[ $(($(date +%s) - start)) -le 5 ] || { echo "verify took more than 5 s to stop"; exit 1; }
grep -Eq "progress +unknown .*interrupted by SIGINT" "$out" || { echo "no report of the interrupted obligations:"; cat "$out"; exit 1; }
exit 0
