#!/usr/bin/env bash
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Regenerates the key tables of docs/keys.md from the settings schema: every
# block
#   <!-- keys: PROBLEM -->
#   ...
#   <!-- /keys -->
# is replaced by `archgeo spec PROBLEM --keys` (PROBLEM `common`: the keys every
# problem has, `archgeo spec planar_quads --keys --common`). tests/test_readme.cpp
# fails when a table is out of date.
#   bash tools/update_keys.sh [build/archgeo]
set -euo pipefail
cd "$(dirname "$0")/.."
archgeo="${1:-build/archgeo}"
keys=docs/keys.md
tmp="$(mktemp)"
trap 'rm -f "$tmp"' EXIT
while IFS= read -r line; do
  if [[ "$line" =~ ^\<\!--\ keys:\ ([a-z_]+)\ --\>$ ]]; then
    name="${BASH_REMATCH[1]}"
    printf '%s\n' "$line" >> "$tmp"
    if [[ "$name" == common ]]; then
      "$archgeo" spec planar_quads --keys --common >> "$tmp"
    else
      "$archgeo" spec "$name" --keys >> "$tmp"
    fi
    skipping=1
    continue
  fi
  if [[ "${skipping:-0}" == 1 ]]; then
    [[ "$line" == "<!-- /keys -->" ]] || continue
    skipping=0
  fi
  printf '%s\n' "$line" >> "$tmp"
done < "$keys"
cat "$tmp" > "$keys"
