#!/usr/bin/env bash
# Writes every obligation listed in proofs/obligations.txt as SMT-LIB2 into DIR (default
# proofs/smt) with a manifest: system, region, property, expected verdict, sha256; and those of
# proofs/every-size.txt (holon verify --every-size) into DIR/every-size the same way.
# Usage: proofs/regenerate.sh [DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-proofs/smt}
holon=./build/cli/holon
rm -rf "$dir" && mkdir -p "$dir/every-size"

# export LIST DIR OPTION: one `holon verify` per line of LIST ("file WHERE extra..."), WHERE given
# as OPTION (--region R, or --lattice L with --every-size); the files and a manifest go to DIR.
export_list() {
    local list=$1 out=$2 option=$3 manifest first=1
    manifest=$(mktemp)
    echo "[" > "$manifest"
    while read -r file where extra; do
        [[ -z "$file" || "$file" == \#* ]] && continue
        # shellcheck disable=SC2086
        json=$("$holon" verify "$file" $option "$where" $extra --smt-out "$out" --json) || [ $? -eq 1 ]
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
                    "$(basename "$f")" "$file" "$where" "$name" "$expected" "$hash" >> "$manifest"
            done
        done < <(python3 -c 'import json,sys
for p in json.load(sys.stdin)["properties"]:
    if p["smt_file"]: print("%s\t%s\t%s" % (p["name"], p["verdict"], p["smt_file"]))' <<<"$json")
    done < "$list"
    printf '\n]\n' >> "$manifest"
    mv "$manifest" "$out/manifest.json"
    chmod 644 "$out/manifest.json"
    echo "wrote $(ls "$out"/*.smt2 | wc -l) obligations to $out"
}
export_list proofs/obligations.txt "$dir" --region
# For every region of a lattice (the "region" field holds the lattice).
export_list proofs/every-size.txt "$dir/every-size" "--every-size --no-certificate --lattice"
