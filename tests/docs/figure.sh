#!/usr/bin/env bash
# Usage: figure.sh PAGE CODE [-t TEXT | -p PATTERN | -l LINE]... -- COMMAND...
# A figure a page quotes, held to the command that produces it (issue 27). The page must contain
# each TEXT (a fixed string: the sentence or table row that states the figure); COMMAND must exit
# CODE, and its combined output must have a line matching each extended regex PATTERN (which
# contains the same figure); a LINE must be in both the page and the output, verbatim (a line of
# output the page quotes). So a figure that changes in the code or in the page fails the test.
set -u
page=$1 want=$2
shift 2
texts=() patterns=() lines=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do
    case $1 in
        -t) texts+=("$2") ;;
        -p) patterns+=("$2") ;;
        -l) lines+=("$2") ;;
        *) echo "figure.sh: unknown argument '$1'"; exit 2 ;;
    esac
    shift 2
done
shift
status=0
for t in "${texts[@]}" "${lines[@]}"; do
    grep -qF -- "$t" "$page" || { printf '%s no longer says: %s\n' "$page" "$t"; status=1; }
done
out=$("$@" 2>&1)
got=$?
if [ "$got" != "$want" ]; then
    printf 'expected exit %s, got %s from: %s\n' "$want" "$got" "$*"
    status=1
fi
for p in "${patterns[@]}"; do
    grep -Eq -- "$p" <<<"$out" || { printf 'the output has no line matching /%s/\n' "$p"; status=1; }
done
for l in "${lines[@]}"; do
    grep -qF -- "$l" <<<"$out" || { printf 'the output has no line: %s\n' "$l"; status=1; }
done
[ $status -eq 0 ] || printf -- '--- output of %s:\n%s\n' "$*" "$out"
exit $status
