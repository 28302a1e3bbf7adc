#!/usr/bin/env bash
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Mutation check of the energies: for every registered term, run the test
# suite with that term's residuals zeroed (a build with
# -DARCHGEO_MUTATION_TESTING=ON and ARCHGEO_ZERO_TERM=<term>) and report the
# first tests that fail. A term whose removal no test notices is reported and
# the script exits 1. Each term's run stops at its first failing test
# (ctest --stop-on-failure), so a noticed term costs seconds and only an
# unnoticed one costs the whole suite; ARCHGEO_MUTATION_FULL=1 runs every
# test for every term and counts them (about 40 × 2 minutes on 2 cores).
# ARCHGEO_MUTATION_TERMS='a b' checks only those terms. Not part of CI.
#   bash tools/mutation_check.sh [build-dir]   (default: build-mutation)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build-mutation}
cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DARCHGEO_MUTATION_TESTING=ON > /dev/null
cmake --build "$dir" -j "$(nproc)" > "$dir/build.log" 2>&1 || { tail -20 "$dir/build.log"; exit 2; }
terms=${ARCHGEO_MUTATION_TERMS:-$("$dir/archgeo" terms | grep -E '^[a-z_]+  \(energies/' | cut -d' ' -f1)}
# The unmutated suite must pass, or every term would look noticed.
if ! ctest --test-dir "$dir" -j "$(nproc)" --timeout 300 > "$dir/mutation_none.log" 2>&1; then
  tail -20 "$dir/mutation_none.log"
  echo "mutation check: the suite fails with no term zeroed"
  exit 2
fi
printf '%-28s %8s  %s\n' term failed "first failing tests"
missed=0
for term in $terms; do
  log="$dir/mutation_$term.log"
  stop=(--stop-on-failure)
  if [ "${ARCHGEO_MUTATION_FULL:-0}" = 1 ]; then stop=(); fi
  ARCHGEO_ZERO_TERM="$term" ctest --test-dir "$dir" -j "$(nproc)" --timeout 300 "${stop[@]}" \
    > "$log" 2>&1 || true
  failing=$(grep -cE '^\s+[0-9]+ - ' "$log" || true)
  names=$(grep -E '^\s+[0-9]+ - ' "$log" | sed -E 's/^\s+[0-9]+ - ([^ ]+).*/\1/' | head -3 | tr '\n' ' ' || true)
  printf '%-28s %8s  %s\n' "$term" "$failing" "$names"
  if [ "$failing" -eq 0 ]; then missed=$((missed + 1)); fi
done
if [ "$missed" -gt 0 ]; then
  echo "mutation check: $missed term(s) whose removal no test notices"
  exit 1
fi
echo "mutation check: every term is noticed by at least one test"
