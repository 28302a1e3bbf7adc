#!/usr/bin/env bash
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Slurm job array for `archgeo bench --emit-jobs JOBS` (docs/bench.md): array
# task k runs job k of JOBS, which writes its record into the records folder.
# Only the number k is passed on: archgeo reads the job's paths from JOBS
# itself, so no shell parses them.
#   sbatch --array=1-$(wc -l < jobs.txt) docs/bench_sbatch.sh jobs.txt
# The archgeo binary: $ARCHGEO if set, else `archgeo` on the PATH.
#SBATCH --job-name=archgeo-bench
#SBATCH --cpus-per-task=2
#SBATCH --mem=8G
#SBATCH --time=01:00:00
#SBATCH --output=archgeo-bench-%A_%a.out
set -euo pipefail
jobs=${1:?usage: sbatch --array=1-N bench_sbatch.sh JOBS}
task=${SLURM_ARRAY_TASK_ID:?not a Slurm array task (sbatch --array=1-N)}
exec "${ARCHGEO:-archgeo}" bench --run-jobs "$jobs" --job "$task"
