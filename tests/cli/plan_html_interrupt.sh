#!/usr/bin/env bash
# Usage: plan_html_interrupt.sh HOLON WORKDIR: a plan with --html, signalled once its run is over
# and --out's summary is written, while the page is built (seconds on a large plan). The page must
# stop: exit 130, no page, no temporaries, and the summary still printed. It was built to its end
# and holon exited 0, as if no signal had come.
set -u
holon=$1 dir=$2
rm -rf "$dir" && mkdir -p "$dir"
fail() { printf '%s\n' "$*"; cat "$dir/stdout" "$dir/stderr" 2>/dev/null; exit 1; }
set -m  # a background job keeps SIGINT
"$holon" plan --rules planner_intermediate --from box:400x400 --to box:200x800 --quiet \
    --out "$dir/out" --plan-out "$dir/plan.jsonl" --html "$dir/plan.html" >"$dir/stdout" 2>"$dir/stderr" &
pid=$!
for _ in $(seq 1200); do
    [ -e "$dir/out/summary.json" ] && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.05
done
[ -e "$dir/out/summary.json" ] || fail "the run did not end"
kill -INT "$pid" || fail "the page was built before the signal"
wait "$pid"
got=$?
[ "$got" = 130 ] || fail "expected exit 130 after SIGINT during the page, got $got"
grep -q "html $dir/plan.html not written: interrupted by SIGINT while the page was built" "$dir/stderr" || fail "no word of the page not written"
grep -q "complete: the target is reached" "$dir/stdout" || fail "the summary was not printed"
[ -e "$dir/plan.html" ] && fail "a page was written"
if ls "$dir" "$dir/out" | grep -q '\.tmp-'; then fail "temporaries left behind"; fi
# --timeout holds while the page is built too: it was built to its end past the deadline (exit 0).
# Whether the deadline falls in the run or in the page, the page is not written and the exit is 3.
"$holon" plan --rules planner_intermediate --from box:400x400 --to box:200x800 --quiet \
    --plan-out "$dir/plan2.jsonl" --html "$dir/plan2.html" --timeout 1.5 >"$dir/stdout" 2>"$dir/stderr"
got=$?
[ "$got" = 3 ] || fail "expected exit 3 with --timeout 1.5, got $got"
[ -e "$dir/plan2.html" ] && fail "a page was written past the deadline"
exit 0
