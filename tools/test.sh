#!/usr/bin/env bash
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Runs the archgeo test suite on the build from tools/setup.sh, in this order:
#  1. ctest: every GoogleTest case but the long ones and the opt-in golden
#     suite (labels: tests/labels.cmake), then the long ones side by side;
#  2. the fast variants of the papers' tables with their acceptances
#     (tools/paper_tables.sh);
#  3. the mutation check on a rotating sample of 5 terms
#     (tools/mutation_check.sh; --all for every term);
#  4. a fuzz smoke run of the mesh readers (tools/fuzz_smoke.sh obj off ply:
#     clang with ASan and UBSan in build-fuzz/, 10 s per harness). The spec
#     reader's harness needs an instrumented build of every library (longer
#     than the rest of this script), so here its committed corpus is replayed
#     by ctest (FuzzCorpus) and `tools/fuzz_smoke.sh spec` fuzzes it.
# Exit non-zero if any fails.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc)
cmake --build build -j "$jobs"
ctest --test-dir build --output-on-failure -j "$jobs" -LE 'long|golden'
ctest --test-dir build --output-on-failure -j "$jobs" -L long
bash tools/paper_tables.sh
bash tools/mutation_check.sh
bash tools/fuzz_smoke.sh obj off ply
