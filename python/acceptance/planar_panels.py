# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Planar panels for a mesh file: python3 planar_panels.py MESH [panels.csv]"""
import sys

import numpy as np

import archgeo

V, F = archgeo.read_mesh(sys.argv[1])
result = archgeo.solve({"problem": "planar_quads"}, V, F,
                       on_iteration=lambda info: print(info["line"], flush=True))
flatness = result.face_values["pq_normalized"]  # δ_PQ,n per panel, from the report's computation
assert abs(flatness.max() - result.report["after"]["pq_normalized_max"]) <= 1e-12
table = np.column_stack([np.arange(len(F)), F, flatness, result.face_values["pq"]])
np.savetxt(sys.argv[2] if len(sys.argv) > 2 else "panels.csv", table, delimiter=",",
           fmt=["%d"] * (1 + F.shape[1]) + ["%.17g"] * 2, comments="",
           header="panel," + ",".join(f"v{k}" for k in range(F.shape[1])) + ",pq_normalized,pq")
print(result, "max δ_PQ,n", flatness.max())
