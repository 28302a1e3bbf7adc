#!/bin/sh
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The solver back ends of a planar_quads solve, in one run on the same
# machine (docs/performance.md, "Solver back ends"): LeanSolve (solver.pcg_above=1, 2
# threads), optionally a second archgeo binary's LeanSolve (e.g. an older
# build), and Ceres' CGNR (solver.pcg_above=0) with the jacobi and with the
# subset preconditioner, on generated noisy roofs of 100x100 and 317x317
# quads (--noise 0.1 --seed 1). One row per run: wall seconds, rounds,
# iterations (CG steps for LeanSolve), final δ_PQ,n max, exit code, and
# whether the tolerance (1e-3) was met. Each run is capped by
# schedule.max_seconds (600 s unless MAX_SECONDS is set).
#
#   [OTHER_LABEL=NAME] benchmarks/solver_backends.sh BUILD/archgeo [OTHER/archgeo] > table.md
#
# Scratch files go to ${TMPDIR:-/tmp}/archgeo_backends.
set -eu
archgeo=$1
other=${2:-}
max=${MAX_SECONDS:-600}
here=$(cd "$(dirname "$0")/.." && pwd)
spec=$here/examples/planar_quads.yaml
dir=${TMPDIR:-/tmp}/archgeo_backends
mkdir -p "$dir"

row() {  # row LABEL SIZE BINARY SETTINGS...
  label=$1 size=$2 binary=$3
  shift 3
  out=$dir/out_$$.ply report=$dir/out_$$.json
  rm -f "$report"
  start=$(date +%s.%N)
  set +e
  "$binary" solve "$spec" --quiet --set "mesh=$dir/roof_$size.obj" --set "output.mesh=$out" \
    --set "output.report=$report" --set output.image= --set "schedule.max_seconds=$max" \
    "$@" > "$dir/log_$$.txt" 2>&1
  code=$?
  set -e
  end=$(date +%s.%N)
  if [ -s "$report" ]; then
    jq -r --arg name "$label" --arg size "$size" --arg code "$code" \
      --arg wall "$(echo "$end - $start" | bc)" \
      '"| \($size) | \($name) | \($wall | tonumber | . * 10 | round / 10) | \(.iterations.outer) | \(.iterations.inner) (\(.pcg.cg_iterations) CG) | \(.after.pq_normalized_max | . * 1e6 | round / 1e6) | \($code) | \(.tolerances["tolerance.pq_normalized_max"].met) |"' \
      "$report"
  else
    echo "| $size | $label | - | - | - | - | $code | no report: $(tail -1 "$dir/log_$$.txt") |"
  fi
  cp "$out" "$dir/$(echo "${size}_$label" | tr -c 'A-Za-z0-9_\n' '_').ply" 2>/dev/null || true
}

echo "| quads | back end | wall s | rounds | iterations | δ_PQ,n max | exit | met |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
for n in 100 317; do
  size=${n}x$n
  [ -s "$dir/roof_$size.obj" ] ||
    "$archgeo" generate "$dir/roof_$size.obj" --nu $n --nv $n --noise 0.1 --seed 1 > /dev/null
  row "LeanSolve" "$size" "$archgeo" --set solver.pcg_above=1 --set solver.num_threads=2
  if [ -n "$other" ]; then
    row "LeanSolve (${OTHER_LABEL:-other build})" "$size" "$other" --set solver.pcg_above=1 --set solver.num_threads=2
  fi
  row "Ceres cgnr + jacobi" "$size" "$archgeo" --set solver.pcg_above=0 \
    --set solver.linear_solver_type=cgnr --set solver.preconditioner_type=jacobi
  row "Ceres cgnr + subset" "$size" "$archgeo" --set solver.pcg_above=0 \
    --set solver.linear_solver_type=cgnr --set solver.preconditioner_type=subset
done
