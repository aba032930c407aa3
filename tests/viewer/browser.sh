#!/usr/bin/env bash
# A headless-browser test of holon's viewer (docs/viewer.md): writes the page for INPUT, opens it in
# Chromium at #step=K (and at the last step), and checks that the page met no JavaScript error,
# shows step K, and shows the configuration of step K: its #digest equals the one digest.py computes
# from INPUT alone. A screenshot of each step is kept beside the page as the test's artifact.
# Exit 77 (ctest: skipped) when chromium is not installed: bash scripts/setup-browser-tests.
#
# usage: browser.sh HOLON DIR NAME STEP INPUT [FRAGMENT]   (INPUT is made by the caller, in DIR)
set -u
holon=$1 dir=$2 name=$3 step=$4 input=$5 fragment=${6:-}
here=$(cd "$(dirname "$0")" && pwd)
browser=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$browser" ]; then
    echo "SKIPPED: chromium is not installed; bash scripts/setup-browser-tests installs it (Debian's chromium)"
    exit 77
fi
page=$dir/$name.html
"$holon" view "$input" -o "$page" || { echo "FAIL: holon view exited $?"; exit 1; }
profile=$(mktemp -d)
trap 'rm -rf "$profile"' EXIT
open() {  # open() K: the DOM after the page has loaded at step K, and a screenshot
    local url="file://$page#step=$1$fragment"
    timeout 120 "$browser" --headless --disable-gpu --no-sandbox --user-data-dir="$profile" --virtual-time-budget=10000 --dump-dom "$url" 2>/dev/null
    timeout 120 "$browser" --headless --disable-gpu --no-sandbox --user-data-dir="$profile" --virtual-time-budget=10000 --window-size=1200,900 \
        --screenshot="$dir/$name-step$1.png" "$url" >/dev/null 2>&1
}
expected_last=$(python3 "$here/digest.py" "$input" last) || { echo "FAIL: digest.py cannot read $input"; exit 1; }
last=$(( $(echo "$expected_last" | tail -1) - 1 ))
status=0
for k in "$step" "$last"; do
    dom=$(open "$k")
    errors=$(echo "$dom" | grep -o '<div id="errors" data-count="[0-9]*"' | grep -o '[0-9]*"$' | tr -d '"')
    shown=$(echo "$dom" | grep -o 'id="status" data-step="[-0-9]*"' | grep -o '[-0-9]*"$' | tr -d '"')
    digest=$(echo "$dom" | grep -o 'id="digest">[^<]*<' | sed 's/id="digest">//; s/<$//')
    expected=$(python3 "$here/digest.py" "$input" "$k")
    expected=${expected%%$'\n'*}
    echo "$name step $k: errors ${errors:-none found}, shown step ${shown:-none}, digest '$digest', expected '$expected'"
    if [ "$errors" != 0 ]; then echo "FAIL: the page reported JavaScript errors:"; echo "$dom" | grep -A5 'id="errors"'; status=1; fi
    if [ "$shown" != "$k" ]; then echo "FAIL: the page shows step '$shown', not $k"; status=1; fi
    if [ "$digest" != "$expected" ]; then echo "FAIL: the configuration shown differs from the input's step $k"; status=1; fi
done
echo "screenshots: $dir/$name-step$step.png $dir/$name-step$last.png"
exit $status
