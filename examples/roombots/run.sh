#!/usr/bin/env bash
# Seed 001 §V: experiment I (the 4-metamodule cube, 3 shifted starts) and experiment II (the
# 6-metamodule chair, 4 seeding recipes) for every metamodule configuration under the paper's three
# force-field strategies and holon's reservation strategy: tables like Tables I and II and Fig. 5,
# then foot traces (as Fig. 6) and assembly snapshots (as Fig. 7) of one chair run per strategy in
# examples/roombots/out; and the reserve run's coordination (the rule the engine executed, with the
# walks it took) explored over every interleaving by holon check.
# Usage: examples/roombots/run.sh [SEED]
set -euo pipefail
cd "$(dirname "$0")/../.."
SEED=${1:-1}
HOLON=${HOLON:-build/cli/holon}
[ -x "$HOLON" ] || scripts/build >/dev/null
for structure in cube chair; do
  echo "### $structure"
  echo '```'
  "$HOLON" roombots --structure "$structure" --strategy greedy,slope,step,reserve --seed "$SEED" --quiet
  echo '```'
done
out=examples/roombots/out
rm -rf "$out"
"$HOLON" roombots --structure chair --metamodule SRZ --strategy greedy,slope,reserve --runs 1 --seed "$SEED" --out "$out" --quiet >/dev/null
echo "pictures and per-step traces: $(ls "$out" | wc -l) files in $out"
coordination=$out/coordination_SRZ_reserve_0.json
region=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["region"])' "$coordination")
"$HOLON" check rules/library/roombots_reserve.holon --region "$region" --from "$coordination"
