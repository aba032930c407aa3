#!/usr/bin/env bash
# Usage: hostile.sh HOLON CASE: generates one hostile input in a temporary folder (issue 32: they are
# too large to commit) and runs holon on it; holon's exit code is the script's. For `garbage` the
# script prints how many bytes holon wrote, so a test can bound the flood.
set -u
holon=$1 case=$2
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
header=$'system s\nfield label: A | B\nrule r: A => B\n'
rep() { head -c "$2" /dev/zero | tr '\0' "$1"; }           # one character, N times
terms() { printf '%s' "$1"; yes " $2 $1" | head -n "$(($3 - 1))" | tr -d '\n'; }  # TERM OP TERM ... N terms
case $case in
parens) { printf '%s' "$header" 'constraint '; rep '(' 3000; printf true; rep ')' 3000; echo; } >"$dir/deep.holon" ;;
sum) { printf '%s' "$header" 'constraint '; terms 'count(A)' + 10000; echo ' >= 0'; } >"$dir/deep.holon" ;;
garbage) { echo 'system s'; yes $'\x01\x1b$?\xff\xc3' | tr -d '\n' | head -c 3000; echo; } >"$dir/deep.holon"
    "$holon" rules "$dir/deep.holon" >"$dir/out" 2>&1
    code=$?
    echo "holon wrote $(wc -c <"$dir/out") bytes"
    exit $code ;;
json) { printf '{"cells": [{"at": '; rep '[' 100000; rep ']' 100000; echo '}]}'; } >"$dir/deep.json"
    exec "$holon" check "$(dirname "$0")/../../rules/library/pixel.holon" --region square:2x2 --from "$dir/deep.json" ;;
*) echo "unknown case $case"; exit 64 ;;
esac
exec "$holon" rules "$dir/deep.holon"
