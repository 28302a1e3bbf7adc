#!/usr/bin/env bash
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Mutation check of the energies: with one registered term's residuals zeroed
# at run time (ARCHGEO_ZERO_TERM=<term>, energies/registry.h ZeroedTerm; no
# rebuild), the tests that name the term (ctest names containing it in
# snake_case or CamelCase, e.g. pq_diagonal or PqDiagonal; `long` ones too,
# not the opt-in `golden` suite) run, and at least
# one of them must fail. A term whose removal none of them notices is
# reported and the script exits 1.
#
#   bash tools/mutation_check.sh              # a sample of 5 terms (tools/test.sh)
#   bash tools/mutation_check.sh --all        # every term
#   bash tools/mutation_check.sh TERM ...     # those terms
#
# The sample rotates with the commit: the terms are taken five at a time, in
# registry order, starting at (number of commits × 5) mod (number of terms),
# so that successive commits check successive terms. ARCHGEO_BUILD names the
# build directory (default build/).
set -euo pipefail
cd "$(dirname "$0")/.."
build=${ARCHGEO_BUILD:-build}
sample=5

mapfile -t all < <("$build/archgeo" terms | grep -E '^[a-z_]+  \(energies/' | cut -d' ' -f1)
if [ "${#all[@]}" -eq 0 ]; then
  echo "mutation check: $build/archgeo lists no term"
  exit 2
fi
if [ "${1:-}" = "--all" ]; then
  terms=("${all[@]}")
elif [ "$#" -gt 0 ]; then
  terms=("$@")
else
  commits=$(git rev-list --count HEAD 2>/dev/null || echo 0)
  start=$(( commits * sample % ${#all[@]} ))
  terms=()
  for ((k = 0; k < sample; ++k)); do terms+=("${all[$(( (start + k) % ${#all[@]} ))]}"); done
fi

printf '%-28s %6s %6s  %s\n' term tests failed "first failing test"
missed=()
for term in "${terms[@]}"; do
  camel=$(sed -E 's/(^|_)([a-z])/\U\2/g' <<< "$term")
  regex="$term|$camel"
  log=$(mktemp)
  ARCHGEO_ZERO_TERM="$term" ctest --test-dir "$build" -R "$regex" -LE golden -j "$(nproc)" \
    --timeout 240 > "$log" 2>&1 || true
  ran=$(grep -oE 'tests passed, [0-9]+ tests failed out of [0-9]+' "$log" | grep -oE '[0-9]+$' || echo 0)
  failed=$(grep -oE '[0-9]+ tests failed' "$log" | grep -oE '^[0-9]+' || echo 0)
  first=$(grep -E '^\s+[0-9]+ - ' "$log" | head -1 | sed -E 's/^\s+[0-9]+ - ([^ ]+).*/\1/' || true)
  printf '%-28s %6s %6s  %s\n' "$term" "$ran" "$failed" "$first"
  if [ "$failed" -eq 0 ]; then missed+=("$term"); fi
  rm -f "$log"
done
if [ "${#missed[@]}" -gt 0 ]; then
  echo "mutation check: no test that names it notices the removal of: ${missed[*]}"
  exit 1
fi
echo "mutation check: every term checked is noticed by a test that names it"
