#!/usr/bin/env bash
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
# The Python acceptance of issue 46 from a fresh clone of this repository's
# HEAD: `pip install --no-build-isolation .` into a new virtual environment
# of Debian's python3 (--system-site-packages: Debian's numpy; PEP 668 keeps
# pip out of the system's own folders), `pip wheel --no-build-isolation .`,
# then python/acceptance/test_installed.py from a folder outside the clone
# and docs/python.md's examples (python/tests/test_docs.py) on the installed
# package.
# A full build of the libraries: about 10 minutes on 2 cores (ctest label long).
#   bash tools/python_acceptance.sh
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
git clone -q "$source_dir" "$work/archgeo"
ln -s "$(cd "$source_dir/../shared" && pwd)" "$work/shared"  # the clone's ../shared
/usr/bin/python3 -m venv --system-site-packages "$work/venv"
cd "$work/archgeo"
"$work/venv/bin/python" -m pip install --no-build-isolation .
"$work/venv/bin/python" -m pip wheel --no-build-isolation --no-deps -w "$work/wheels" .
ls "$work"/wheels/archgeo-0.1.0-*.whl
cd "$work"
ARCHGEO_SOURCE_DIR="$work/archgeo" \
  ARCHGEO_CONJUGATE="$work/shared/data/libigl_inspired_mesh_quads_Conjugate.off" \
  "$work/venv/bin/python" -m pytest -q -s -p no:cacheprovider "$work/archgeo/python/acceptance" \
  "$work/archgeo/python/tests/test_docs.py"
