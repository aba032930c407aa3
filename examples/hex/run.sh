#!/usr/bin/env bash
# Seed 003 §V: the 12 sculpting experiments (square->T, T->square, rectangle->circle on arrays of
# 100..400 lattice points per side), REPS repetitions of STEPS timesteps each, as a table like the
# paper's Table I. Usage: examples/hex/run.sh [REPS] [STEPS] [extra holon hex options...]
# SIZES="100 200" picks the array sides (default all four).
set -euo pipefail
cd "$(dirname "$0")/../.."
REPS=${1:-10}; STEPS=${2:-10000}; shift $(( $# > 2 ? 2 : $# )) || true
EXTRA=("$@")
HOLON=${HOLON:-build/cli/holon}
SIZES=${SIZES:-100 200 300 400}  # array sides to run, e.g. SIZES=100 for the quick rows
[ -x "$HOLON" ] || scripts/build >/dev/null
field() { sed -n "s/.*\"$1\":{\"mean\":\([^,]*\),\"std\":\([^}]*\)}.*/\1 \2/p"; }
echo "| plan | size | modules | tri-regions | max compliance % (std) | max completeness % | max stability % | islands (std) | s/run |"
echo "|---|---|---|---|---|---|---|---|---|"
for plan in "square T" "T square" "rectangle circle"; do
  read -r from to <<<"$plan"
  for n in $SIZES; do
    out=$("$HOLON" hex --from "$from" --to "$to" --size "$n" --reps "$REPS" --steps "$STEPS" --json "${EXTRA[@]}")
    read -r mod _ <<<"$(field modules <<<"$out")"; read -r cm cs <<<"$(field compliance <<<"$out")"
    read -r mm _ <<<"$(field completeness <<<"$out")"; read -r sm _ <<<"$(field stability <<<"$out")"
    read -r im is <<<"$(field islands <<<"$out")"; read -r sec _ <<<"$(field seconds <<<"$out")"
    tri=$(sed -n 's/.*"tri_regions":\([0-9]*\).*/\1/p' <<<"$out")
    # awk, not bc: the JSON may print a standard deviation as 1.2e-05
    awk -v f="$from" -v t="$to" -v n="$n" -v mod="$mod" -v tri="$tri" -v cm="$cm" -v cs="$cs" -v mm="$mm" -v sm="$sm" -v im="$im" -v is="$is" -v sec="$sec" \
      'BEGIN { printf "| %s -> %s | %d | %.0f | %s | %.2f (%.2f) | %.2f | %.2f | %.1f (%.1f) | %.1f |\n", f, t, n, mod, tri, 100*cm, 100*cs, 100*mm, 100*sm, im, is, sec }' 
  done
done
