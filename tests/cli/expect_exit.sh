#!/usr/bin/env bash
# Usage: expect_exit.sh CODE PATTERN COMMAND... : runs COMMAND, requires exit code CODE and, unless
# PATTERN is empty, a line of its combined output matching the extended regex PATTERN.
set -u
want=$1 pattern=$2
shift 2
out=$("$@" 2>&1)
got=$?
if [ "$got" != "$want" ]; then
    printf 'expected exit %s, got %s from: %s\n%s\n' "$want" "$got" "$*" "$out"
    exit 1
fi
if [ -n "$pattern" ] && ! grep -Eq -- "$pattern" <<<"$out"; then
    printf 'output of %s does not match /%s/:\n%s\n' "$*" "$pattern" "$out"
    exit 1
fi
exit 0
