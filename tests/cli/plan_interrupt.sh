#!/usr/bin/env bash
# Usage: plan_interrupt.sh HOLON WORKDIR SIGNAL CODE: starts a long plan with --out and --plan-out,
# sends SIGNAL (INT or TERM) once the run has begun, and requires exit CODE (130 or 143), a summary
# marked interrupted, whole files (the CSV's and the plan's last lines complete) and no temporaries.
set -u
holon=$1 dir=$2 signal=$3 want=$4
rm -rf "$dir" && mkdir -p "$dir"
fail() { printf '%s\n' "$*"; cat "$dir/stdout" "$dir/stderr" 2>/dev/null; exit 1; }
# Job control: a background job then keeps SIGINT (a shell ignores it in background jobs otherwise).
set -m
"$holon" plan --rules planner_general1 --from box:60x30 --to box:30x60 --scale 3 --quiet \
    --out "$dir/out" --plan-out "$dir/plan.jsonl" >"$dir/stdout" 2>"$dir/stderr" &
pid=$!
# snapshot-start.svg is written just before the first round.
for _ in $(seq 600); do
    [ -e "$dir/out/snapshot-start.svg" ] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
done
[ -e "$dir/out/snapshot-start.svg" ] || fail "the plan did not start"
sleep 1
kill -"$signal" "$pid" || fail "the plan ended before the signal"
wait "$pid"
got=$?
[ "$got" = "$want" ] || fail "expected exit $want after SIG$signal, got $got"
grep -q "NOT complete: interrupted by SIG$signal" "$dir/stdout" || fail "the summary does not say interrupted"
grep -q '"interrupted": true' "$dir/out/summary.json" || fail "summary.json is not marked interrupted"
for f in "$dir/out/completion.csv" "$dir/plan.jsonl"; do
    [ -s "$f" ] || fail "$f is missing or empty"
    [ "$(tail -c 1 "$f" | od -An -c | tr -d ' ')" = '\n' ] || fail "$f does not end with a whole line"
done
fields=$(head -n 1 "$dir/out/completion.csv" | tr ',' '\n' | wc -l)
[ "$(tail -n 1 "$dir/out/completion.csv" | tr ',' '\n' | wc -l)" = "$fields" ] || fail "the CSV's last line is cut"
tail -n 1 "$dir/plan.jsonl" | grep -Eq '^\{"after":.*"rule":"[a-z_0-9.]+"\}$' || fail "the plan's last line is not a whole record"
if ls "$dir" "$dir/out" | grep -q '\.tmp-'; then fail "temporaries left behind"; fi
exit 0
