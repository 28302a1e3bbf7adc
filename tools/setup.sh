#!/usr/bin/env bash
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Sets archgeo up on a fresh Debian 12 machine: installs the Debian packages,
# builds (Release, into build/), and runs the demo (examples/demo.yaml).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)"
echo "== demo: build/archgeo solve examples/demo.yaml"
build/archgeo solve examples/demo.yaml --quiet
