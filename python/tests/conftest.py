# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Paths shared by the tests of the package archgeo (python/).

Run by ctest (test python_archgeo, with PYTHONPATH at the built package,
ARCHGEO_BINARY and ARCHGEO_SOURCE_DIR set) or by hand:
  PYTHONPATH=build/python ARCHGEO_BINARY=build/archgeo \
  ARCHGEO_SOURCE_DIR=. /usr/bin/python3 -m pytest -q python/tests
"""
import os

import numpy as np

SOURCE = os.environ.get("ARCHGEO_SOURCE_DIR",
                        os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("ARCHGEO_BINARY", "archgeo")
CONJUGATE = os.path.join(SOURCE, "..", "shared", "data",
                         "libigl_inspired_mesh_quads_Conjugate.off")
GENTLE = os.path.join(SOURCE, "examples", "planar_quads_gentle.yaml")


def read_off(path):
    """Vertices (n, 3) and faces (lists) of an OFF file, parsed here."""
    tokens = open(path).read().split()
    assert tokens[0] == "OFF"
    nv, nf = int(tokens[1]), int(tokens[2])
    at = 4
    V = np.array(tokens[at:at + 3 * nv], dtype=float).reshape(nv, 3)
    at += 3 * nv
    F = []
    for _ in range(nf):
        k = int(tokens[at])
        F.append([int(t) for t in tokens[at + 1:at + 1 + k]])
        at += 1 + k
    return V, F
