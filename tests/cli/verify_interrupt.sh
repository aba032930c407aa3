#!/usr/bin/env bash
# Usage: verify_interrupt.sh HOLON SOURCE_DIR SIGNAL CODE: starts a verify whose Spacer proof runs
# in forked solver processes, sends SIGNAL (INT, TERM or KILL) to verify once they run, and
# requires exit CODE (130, 143; 137 for KILL) and every solver process gone within a second.
set -u
holon=$1 src=$2 signal=$3 want=$4
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
fail() { printf '%s\n' "$*"; cat "$out/stdout" "$out/stderr" 2>/dev/null; exit 1; }
set -m  # job control: a background job keeps SIGINT
"$holon" verify "$src/rules/library/planner_general3.holon" --region square:3x2 --property progress --reach --timeout 600 \
    --from "$src/examples/verify/general_start.json" --input target="$src/examples/verify/general_target.txt" >"$out/stdout" 2>"$out/stderr" &
pid=$!
children=
for _ in $(seq 600); do
    children=$(pgrep -P "$pid")
    [ -n "$children" ] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
done
[ -n "$children" ] || fail "no solver process started"
sleep 0.5
kill -"$signal" "$pid" || fail "verify ended before the signal"
wait "$pid"
got=$?
[ "$got" = "$want" ] || fail "expected exit $want after SIG$signal, got $got"
# The kernel ends a solver when verify dies (its parent-death signal); on a loaded machine that can
# take longer than a second to show, so wait up to five before calling one a survivor.
alive() { kill -0 "$1" 2>/dev/null && ! grep -q zombie "/proc/$1/status" 2>/dev/null && [ "$(ps -o stat= -p "$1" | cut -c1)" != Z ]; }
for c in $children; do
    for _ in $(seq 50); do alive "$c" || break; sleep 0.1; done
    alive "$c" && fail "solver process $c outlived verify by five seconds"
done
exit 0
