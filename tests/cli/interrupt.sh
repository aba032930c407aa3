#!/usr/bin/env bash
# Usage: interrupt.sh SIGNAL CODE PATTERN COMMAND... : starts COMMAND, sends SIGNAL (INT or TERM)
# after INTERRUPT_DELAY seconds (default 1: the run has begun by then), and requires exit CODE (130
# or 143: the run stopped where its outputs are whole, not killed) and, unless PATTERN is empty, a
# line of its output matching the extended regex.
set -u
signal=$1 want=$2 pattern=$3
shift 3
out=$(mktemp) && trap 'rm -f "$out"' EXIT
# Job control: a background job then keeps SIGINT (a shell ignores it in background jobs otherwise).
set -m
"$@" >"$out" 2>&1 &
pid=$!
sleep "${INTERRUPT_DELAY:-1}"
kill -"$signal" "$pid" || { echo "the command ended before the signal: $*"; cat "$out"; exit 1; }
wait "$pid"
got=$?
if [ "$got" != "$want" ]; then
    printf 'expected exit %s after SIG%s, got %s from: %s\n' "$want" "$signal" "$got" "$*"
    cat "$out"
    exit 1
fi
if [ -n "$pattern" ] && ! grep -Eq -- "$pattern" "$out"; then
    printf 'output of %s does not match /%s/:\n' "$*" "$pattern"
    cat "$out"
    exit 1
fi
exit 0
