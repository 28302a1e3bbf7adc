#!/usr/bin/env bash
# Runs the archgeo test suite (GoogleTest via ctest) on the build from
# tools/setup.sh, then the fast variants of the papers' tables with their
# acceptances (tools/paper_tables.sh), then a fuzz smoke run of the readers
# (tools/fuzz_smoke.sh: clang with ASan and UBSan in build-fuzz/, each
# libFuzzer harness for 10 s from its committed corpus; fuzz/README.md).
# Exit non-zero if any fails.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build -j "$(nproc)"
ctest --test-dir build --output-on-failure -j "$(nproc)"
bash tools/paper_tables.sh
bash tools/fuzz_smoke.sh
