#!/usr/bin/env bash
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The papers' tables, fast variants (CI runs this from tools/test.sh): each
# benchmark program prints the paper's rows beside ours and exits non-zero
# when its acceptance fails; this script runs them all and fails if any does.
# The full tables: docs/results.md. Extra arguments (e.g.
# --set terms.dihedral_energy.weight=0) are passed to every program.
#   bash tools/paper_tables.sh [--set KEY=VALUE ...]     (about 1 minute on 2 cores)
set -uo pipefail
cd "$(dirname "$0")/.."
build=${ARCHGEO_BUILD:-build}
cmake --build "$build" -j "$(nproc)" --target archgeo archgeo_benchmarks >/dev/null || exit 2
# Longest first: the programs run nproc at a time (each keeps about one core
# busy), so the long ones start at once and the short ones fill in after.
runs=(
  "zadravec_conjugate_layout --quick"
  "pellis_fig19"
  "goal_examples"
  "shi_table1 --quick"
  "grids_table1 --no-timing --method least_squares"
  "pellis_fig20 --quick"
  "zadravec_fig10 --quick"
  "pellis_fig7_torus"
  "pellis_fig11"
)
log=$(mktemp -d "${TMPDIR:-/tmp}/archgeo_paper_tables.XXXXXX")
# One table: its output to $log/NAME.txt, its verdict line to $log/NAME.status.
table() {
  local run=$1 name=${1%% *} start
  shift
  start=$(date +%s)
  # shellcheck disable=SC2086
  if "$build/benchmarks/"$run "$@" > "$log/$name.txt" 2>&1; then
    echo "paper table $name: pass ($(( $(date +%s) - start )) s)" > "$log/$name.status"
  else
    echo "paper table $name: FAIL ($(( $(date +%s) - start )) s)" > "$log/$name.status"
  fi
}
lanes=$(nproc)
for run in "${runs[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$lanes" ]; do wait -n || true; done
  table "$run" "$@" &
done
wait
failed=()
for run in "${runs[@]}"; do
  name=${run%% *}
  cat "$log/$name.status"
  if grep -q ': FAIL' "$log/$name.status"; then
    echo "its output:"
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
