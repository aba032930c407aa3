#!/usr/bin/env bash
# Before and after, side by side: one square -> T run (seed 1) with the paper's algorithm and one with
# holon's improvements (--improved), the last frame of each in one SVG
# (examples/hex/out/before_after.svg; grey modules, black outside the target, red target points
# still empty). Usage: examples/hex/before_after.sh [SIZE] [STEPS]
set -euo pipefail
cd "$(dirname "$0")/../.."
SIZE=${1:-100}; STEPS=${2:-10000}
HOLON=${HOLON:-build/cli/holon}
[ -x "$HOLON" ] || scripts/build >/dev/null
out=examples/hex/out
mkdir -p "$out"
summary() { sed -n 's/.*max compliance \([0-9.]*\)%.*/\1/p;s/.*islands \([0-9.]*\) modules.*/\1/p' | paste -sd' '; }
read -r c1 i1 <<<"$("$HOLON" hex --from square --to T --size "$SIZE" --steps "$STEPS" --out "$out/paper" --quiet | summary)"
read -r c2 i2 <<<"$("$HOLON" hex --from square --to T --size "$SIZE" --steps "$STEPS" --improved --out "$out/holon" --quiet | summary)"
frame() { sed '1s/<svg [^>]*>/<svg x="'"$2"'" y="30">/' "$1/frame_$STEPS.svg"; }
width=$(sed -n "1s/.*width='\([0-9.]*\)'.*/\1/p" "$out/paper/frame_$STEPS.svg" | cut -d. -f1)
height=$(sed -n "1s/.*height='\([0-9.]*\)'.*/\1/p" "$out/paper/frame_$STEPS.svg" | cut -d. -f1)
{
  echo "<svg xmlns='http://www.w3.org/2000/svg' width='$((2 * width + 20))' height='$((height + 30))' font-size='16'>"
  echo "<rect width='100%' height='100%' fill='white'/>"
  echo "<text x='10' y='20'>seed 003 as written: ${c1}% compliance, ${i1} island modules</text>"
  echo "<text x='$((width + 30))' y='20'>holon (--improved): ${c2}%, ${i2} island modules</text>"
  frame "$out/paper" 0
  frame "$out/holon" "$((width + 20))"
  echo "</svg>"
} > "$out/before_after.svg"
echo "square -> T, N = $SIZE, $STEPS timesteps: paper ${c1}% / ${i1} islands; holon ${c2}% / ${i2} islands -> $out/before_after.svg"
