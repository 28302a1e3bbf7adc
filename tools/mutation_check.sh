#!/usr/bin/env bash
# Mutation check of the energies: for every registered term, run the whole
# test suite with that term's residuals zeroed (a build with
# -DARCHGEO_MUTATION_TESTING=ON and ARCHGEO_ZERO_TERM=<term>) and count the
# tests that fail. A term whose removal no test notices is reported and the
# script exits 1. Not part of CI (it runs the suite once per term: about
# 20 × 1 minute on 2 cores).
#   bash tools/mutation_check.sh [build-dir]   (default: build-mutation)
set -euo pipefail
cd "$(dirname "$0")/.."
dir=${1:-build-mutation}
cmake -S . -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE=Release -DARCHGEO_MUTATION_TESTING=ON > /dev/null
cmake --build "$dir" -j "$(nproc)" > "$dir/build.log" 2>&1 || { tail -20 "$dir/build.log"; exit 2; }
terms=$("$dir/archgeo" terms | grep -E '^[a-z_]+  \(energies/' | cut -d' ' -f1)
printf '%-28s %8s  %s\n' term failing "first failing tests"
missed=0
for term in $terms; do
  log="$dir/mutation_$term.log"
  ARCHGEO_ZERO_TERM="$term" ctest --test-dir "$dir" -j "$(nproc)" --timeout 300 > "$log" 2>&1 || true
  failing=$(grep -cE '^\s+[0-9]+ - ' "$log" || true)
  names=$(grep -E '^\s+[0-9]+ - ' "$log" | sed -E 's/^\s+[0-9]+ - ([^ ]+).*/\1/' | head -3 | tr '\n' ' ')
  printf '%-28s %8s  %s\n' "$term" "$failing" "$names"
  if [ "$failing" -eq 0 ]; then missed=$((missed + 1)); fi
done
if [ "$missed" -gt 0 ]; then
  echo "mutation check: $missed term(s) whose removal no test notices"
  exit 1
fi
echo "mutation check: every term is noticed by at least one test"
