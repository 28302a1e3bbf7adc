#!/usr/bin/env bash
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# Installs every build, test and run dependency of archgeo from Debian 12 packages.
# Idempotent: packages already present are left alone; nothing is downloaded
# outside apt. Run as root (or with sudo available).
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config
  libceres-dev libsuitesparse-dev libeigen3-dev libgoogle-glog-dev libgflags-dev
  libcgal-dev libgmp-dev libmpfr-dev libtbb-dev libspectra-dev
  libyaml-cpp-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev googletest libbenchmark-dev
  libopenblas0-pthread libopenblas-pthread-dev
  # render/: PNG pictures (cairo) with DejaVu text.
  libcairo2-dev fonts-dejavu-core
  # tests: report schema (jsonschema), PLY readers (meshio), Debian's /usr/bin/python3.
  python3 python3-jsonschema python3-meshio python3-numpy
  # python/ (cmake -DARCHGEO_PYTHON=ON): the module and its pytest tests.
  pybind11-dev python3-dev python3-pytest
  # tests/test_render_html.cpp: the HTML view in a headless browser.
  chromium
  # tools/fuzz_smoke.sh: clang with libFuzzer and the sanitizer runtimes.
  clang libclang-rt-14-dev
  # tests: the licence check (ctest Licensing: reuse lint).
  reuse
)

sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ "${#missing[@]}" -gt 0 ]; then
  echo "install_deps: installing ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}"
else
  echo "install_deps: all ${#packages[@]} packages present"
fi

# OpenBLAS as the system BLAS/LAPACK (CHOLMOD factorises 3-4x faster than with
# the generic reference/ATLAS BLAS on this machine).
arch=$(dpkg-architecture -qDEB_HOST_MULTIARCH 2>/dev/null || echo x86_64-linux-gnu)
for lib in libblas.so.3 liblapack.so.3; do
  target="/usr/lib/${arch}/openblas-pthread/${lib}"
  if [ -e "$target" ]; then
    "${sudo_cmd[@]}" update-alternatives --set "${lib}-${arch}" "$target" >/dev/null
  fi
done
echo "install_deps: BLAS -> $(readlink -f /usr/lib/${arch}/libblas.so.3)"
