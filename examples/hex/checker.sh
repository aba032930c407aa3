#!/usr/bin/env bash
# Seed 003's local moves checked with holon's own checker (rules/library/hex_holes.holon: hole
# move and deletion; hex_growth.holon: hole creation; hex_collapse.holon: column collapse):
#  1. three holes wandering in a hex:r6 disk: every interleaving keeps every hole whole and the
#     module count (115,417 states);
#  2. deletion as the paper words it empties a shepherd of a neighbouring hole:
#     out/checker/shared_shepherd.svg;
#  3. even with that fixed, deletion pinches off a protruding element (Fig. 6):
#     out/checker/pinch_off.svg, crossed modules are cut off;
#  4. column collapse, every gravity and order, from an 8-module blob (112,668 states) and around a
#     hole: the mass stays connected and the hole whole;
#  5. hole creation from a blob where three growth nodes compete: every hole made is whole, the
#     module count kept; and for every configuration of hex:r3 (Z3);
#  6. holon's migration (hex_migrate.holon): a wall one module thick outside the target, and four
#     modules above a slot one cell wide: every interleaving keeps every hole whole and the mass in
#     one piece. goal_reachable fails in some states: left to itself, `advance` moves voids inward as
#     well as out (holon hex fires it only outward, a non-local choice); without `advance` the wall
#     drains from every state it reaches, and the slot fills only with it
#     (tests/checker/PropertiesTest.cpp); for every configuration of hex:r3 (Z3) both rules keep
#     every hole whole and the mass in one piece.
# Every trace is replayed through the reference interpreter. Needs a build (bash scripts/build).
set -u
cd "$(dirname "$0")/../.."
holon=${HOLON:-build/cli/holon}
[ -x "$holon" ] || scripts/build >/dev/null
in=examples/hex/checker
out=examples/hex/out/checker
mkdir -p "$out"
"$holon" check rules/library/hex_holes.holon --region hex:r6 --from $in/three_holes.txt \
    --property holes --property mass_conservation
echo
"$holon" check tests/checker/broken/hex_delete_shared.holon --region hex:r5 --from $in/two_holes.txt \
    --property holes --svg "$out/shared_shepherd.svg" | sed -n '1,6p'
echo
"$holon" check rules/library/hex_holes.holon --region hex:r4 --from $in/neck.txt \
    --property one_mass --svg "$out/pinch_off.svg" --trace-out "$out/pinch_off.itf.json" | sed -n '1,6p'
echo
"$holon" check rules/library/hex_collapse.holon --region hex:r3 --from $in/blob.txt --input target=none | sed -n '1,8p'
echo
"$holon" check rules/library/hex_collapse.holon --region hex:r4 --from $in/hole_and_blob.txt --input target=none | sed -n '1,8p'
echo
"$holon" check rules/library/hex_growth.holon --region hex:r4 --from $in/growth_blob.txt --input target=$in/target_r4.txt \
    --property holes --property mass_conservation
echo
"$holon" verify rules/library/hex_growth.holon --region hex:r3
echo
"$holon" check rules/library/hex_migrate.holon --region hex:r3 --from $in/wall.txt --input target=$in/lower_rows.txt | sed -n '1,9p'
echo
"$holon" check rules/library/hex_migrate.holon --region hex:r3 --from $in/slot.txt --input target=$in/below_row0.txt | sed -n '1,9p'
echo
"$holon" verify rules/library/hex_migrate.holon --region hex:r3
echo "(pictures in $out/)"
