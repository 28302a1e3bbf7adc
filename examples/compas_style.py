#!/usr/bin/env python3
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Planar quads from Python, the way a COMPAS script holds a mesh.

A COMPAS mesh goes to plain lists with `mesh.to_vertices_and_faces()` and
comes back with `Mesh.from_vertices_and_faces(vertices, faces)`; this script
reads such lists from JSON (archgeo.from_compas), makes every quad planar with
archgeo and writes the result as JSON in the same form (plus the planarity
reached):

    /usr/bin/python3 examples/compas_style.py [IN.json] [OUT.json]

Without IN.json (or if it does not exist) it first writes one: a noisy roof
from archgeo.generate. Needs the package: installed (docs/python.md), or
PYTHONPATH=build/python after the README's two commands.
"""
import json
import os
import sys

import archgeo


def main():
    source = sys.argv[1] if len(sys.argv) > 1 else "roof_in.json"
    target = sys.argv[2] if len(sys.argv) > 2 else "roof_planar.json"
    if not os.path.exists(source):
        V, F = archgeo.generate("roof", nu=12, nv=9, noise=0.1, scale=10.0)
        archgeo.write_mesh(source, V, F)  # .json: COMPAS mesh data

    tolerance = 1e-3
    spec = {"problem": "planar_quads",
            "tolerance": {"pq_normalized_max": tolerance},
            "solver": {"num_threads": 1}}
    try:
        result = archgeo.solve(spec, source)  # a COMPAS .json (or dict, or Mesh) as the mesh
    except archgeo.NoValidResult as error:
        sys.exit(f"archgeo: no valid result: {error}")

    data = result.to_compas()
    data["pq_normalized_max"] = float(result.face_values["pq_normalized"].max())
    data["tolerance"] = tolerance
    with open(target, "w") as f:
        json.dump(data, f)
    report = result.report
    print(f"wrote {target}: δ_PQ,n max {report['before']['pq_normalized_max']:.3g} -> "
          f"{report['after']['pq_normalized_max']:.3g} (tolerance {tolerance})")


if __name__ == "__main__":
    main()
