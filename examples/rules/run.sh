#!/usr/bin/env bash
# Example: summarise the standard library as one table, then show what holon says about a design
# with mistakes. Needs a build (bash scripts/build).
set -u
cd "$(dirname "$0")/../.."
holon=${HOLON:-./build/cli/holon}
echo "== The standard library (rules/library), instances on square2d (hex2d for hex systems) under each system's symmetry"
printf '%-22s %-8s %-22s %6s %6s  %s\n' system lattice symmetry states rules instances
for f in rules/library/*.holon examples/rules/sliding_cube.holon; do
    "$holon" rules --json "$f" | python3 -c '
import json, sys
for s in json.load(sys.stdin):
    lattice = "square2d" if "square2d" in s["states"] else s["lattice"]
    print("%-22s %-8s %-22s %6d %6d  %d" % (s["system"], s["lattice"], s["symmetry"]["group"], s["states"][lattice],
                                          len(s["rules"]), s["instances"][lattice]))'
done
echo
echo "== A design with mistakes"
"$holon" rules examples/rules/broken_design.holon 2>&1
echo "(exit code $?)"
