#!/usr/bin/env bash
# Runs the archgeo test suite (GoogleTest via ctest) on the build from tools/setup.sh.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake --build build -j "$(nproc)"
ctest --test-dir build --output-on-failure -j "$(nproc)"
