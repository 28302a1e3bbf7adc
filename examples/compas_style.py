#!/usr/bin/env python3
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Planar quads from Python, the way a COMPAS script holds a mesh.

A COMPAS mesh goes to plain lists with `mesh.to_vertices_and_faces()` and
comes back with `Mesh.from_vertices_and_faces(vertices, faces)`; this script
reads such lists from JSON, makes every quad planar with archgeo and writes
the result as JSON in the same form (plus the planarity reached):

    /usr/bin/python3 examples/compas_style.py [IN.json] [OUT.json]

Without IN.json (or if it does not exist) it first writes one: a noisy roof
from archgeo.generate. Needs the module on PYTHONPATH (build/python after
the README's two commands, or an installed package).
"""
import json
import os
import sys

import numpy as np

import archgeo


def main():
    source = sys.argv[1] if len(sys.argv) > 1 else "roof_in.json"
    target = sys.argv[2] if len(sys.argv) > 2 else "roof_planar.json"
    if not os.path.exists(source):
        V, F = archgeo.generate("roof", nu=12, nv=9, noise=0.1, scale=10.0)
        with open(source, "w") as f:
            json.dump({"vertices": V.tolist(), "faces": F.tolist()}, f)

    with open(source) as f:
        data = json.load(f)
    vertices = np.array(data["vertices"], dtype=float)
    faces = data["faces"]  # lists: any polygon size

    tolerance = 1e-3
    spec = {"problem": "planar_quads",
            "tolerance": {"pq_normalized_max": tolerance},
            "solver": {"num_threads": 1}}
    V_out, report = archgeo.solve(spec, vertices, faces)
    if V_out is None:
        sys.exit("archgeo: no valid result: " + report.get("message", ""))

    with open(target, "w") as f:
        json.dump({"vertices": V_out.tolist(), "faces": faces,
                   "pq_normalized_max": report["after"]["pq_normalized_max"],
                   "tolerance": tolerance}, f)
    print(f"wrote {target}: δ_PQ,n max {report['before']['pq_normalized_max']:.3g} -> "
          f"{report['after']['pq_normalized_max']:.3g} (tolerance {tolerance})")


if __name__ == "__main__":
    main()
