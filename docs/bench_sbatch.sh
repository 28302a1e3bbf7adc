#!/usr/bin/env bash
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Slurm job array for `archgeo bench --emit-jobs JOBS` (docs/bench.md): array
# task k runs line k of JOBS, which writes its record into the records folder.
#   sbatch --array=1-$(wc -l < jobs.txt) docs/bench_sbatch.sh jobs.txt
#SBATCH --job-name=archgeo-bench
#SBATCH --cpus-per-task=2
#SBATCH --mem=8G
#SBATCH --time=01:00:00
#SBATCH --output=archgeo-bench-%A_%a.out
set -euo pipefail
jobs=${1:?usage: sbatch --array=1-N bench_sbatch.sh JOBS}
command=$(sed -n "${SLURM_ARRAY_TASK_ID}p" "$jobs")
if [ -z "$command" ]; then
  echo "no line ${SLURM_ARRAY_TASK_ID} in $jobs" >&2
  exit 2
fi
exec sh -c "$command"
