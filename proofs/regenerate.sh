#!/usr/bin/env bash
# Writes every obligation listed in proofs/obligations.txt as SMT-LIB2 into DIR (default
# proofs/smt) with a manifest: system, region, property, expected verdict, sha256.
# Usage: proofs/regenerate.sh [DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-proofs/smt}
holon=./build/cli/holon
rm -rf "$dir" && mkdir -p "$dir"
manifest=$(mktemp)
echo "[" > "$manifest"
first=1
while read -r file region extra; do
    [[ -z "$file" || "$file" == \#* ]] && continue
    # shellcheck disable=SC2086
    json=$("$holon" verify "$file" --region "$region" $extra --smt-out "$dir" --json) || [ $? -eq 1 ]
    while IFS=$'\t' read -r name verdict smt; do
        for f in $smt; do
            expected=unsat
            [ "$verdict" = counterexample ] && expected=sat
            # A split invariant is proved part by part; only the failing part is sat.
            if [ "$verdict" = counterexample ] && [ "$(echo $smt | wc -w)" -gt 1 ] && [ "$f" != "${smt##* }" ]; then expected=unsat; fi
            hash=$(sha256sum "$f" | cut -d' ' -f1)
            [ $first -eq 1 ] || echo "," >> "$manifest"
            first=0
            printf '  {"file": "%s", "source": "%s", "region": "%s", "property": "%s", "expected": "%s", "sha256": "%s"}' \
                "$(basename "$f")" "$file" "$region" "$name" "$expected" "$hash" >> "$manifest"
        done
    done < <(python3 -c 'import json,sys
for p in json.load(sys.stdin)["properties"]:
    if p["smt_file"]: print("%s\t%s\t%s" % (p["name"], p["verdict"], p["smt_file"]))' <<<"$json")
done < proofs/obligations.txt
printf '\n]\n' >> "$manifest"
mv "$manifest" "$dir/manifest.json"
chmod 644 "$dir/manifest.json"
echo "wrote $(ls "$dir"/*.smt2 | wc -l) obligations to $dir"
