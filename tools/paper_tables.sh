#!/usr/bin/env bash
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The papers' tables, fast variants (CI runs this from tools/test.sh): each
# benchmark program prints the paper's rows beside ours and exits non-zero
# when its acceptance fails; this script runs them all and fails if any does.
# The full tables: docs/results.md. Extra arguments (e.g.
# --set terms.dihedral_energy.weight=0) are passed to every program.
#   bash tools/paper_tables.sh [--set KEY=VALUE ...]     (about 2-3 minutes on 2 cores)
set -uo pipefail
cd "$(dirname "$0")/.."
build=${ARCHGEO_BUILD:-build}
cmake --build "$build" -j "$(nproc)" --target archgeo archgeo_benchmarks >/dev/null || exit 2
runs=(
  "pellis_fig7_torus"
  "pellis_fig11"
  "pellis_fig19"
  "pellis_fig20 --quick"
  "shi_table1 --quick"
  "zadravec_fig10 --quick"
  "zadravec_conjugate_layout --quick"
  "grids_table1 --no-timing --method least_squares"
  "goal_examples"
)
failed=()
log=$(mktemp -d "${TMPDIR:-/tmp}/archgeo_paper_tables.XXXXXX")
for run in "${runs[@]}"; do
  name=${run%% *}
  start=$(date +%s)
  # shellcheck disable=SC2086
  if "$build/benchmarks/"$run "$@" > "$log/$name.txt" 2>&1; then
    echo "paper table $name: pass ($(( $(date +%s) - start )) s)"
  else
    echo "paper table $name: FAIL ($(( $(date +%s) - start )) s); its output:"
    tail -30 "$log/$name.txt"
    failed+=("$name")
  fi
done
rm -rf "$log"
if [ "${#failed[@]}" -gt 0 ]; then
  echo "paper tables failing: ${failed[*]}"
  exit 1
fi
echo "paper tables: every acceptance holds"
