#!/usr/bin/env python3
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Boundary rows of conjugate_layout (docs/methods/conjugate_layout.md), one
table row per design surface, measured from the files a run writes, so that
any archgeo binary (with or without level_sets.boundary_rows) is measured the
same way:

  benchmarks/boundary_rows.py ARCHGEO OUTDIR MESH [MESH ...] [-- --set KEY=VALUE ...]

Each MESH runs `ARCHGEO solve examples/conjugate_layout.yaml --set mesh=MESH`
with output.layout (the layout before the PQ step) and output.report.
Columns: boundary faces (faces with a vertex on the boundary of the layout)
and the share of them that are quads with a whole edge on the boundary;
quads (share of all faces); the field's singularities; interior vertices of
valence ≠ 4; δ_PQ,n max after the PQ step; exit code; wall time.
"""
import json
import os
import subprocess
import sys
import time
from collections import defaultdict


def read_obj_faces(path):
    faces = []
    with open(path) as f:
        for line in f:
            if line.startswith("f "):
                faces.append([int(t.split("/")[0]) - 1 for t in line.split()[1:]])
    return faces


def boundary_figures(faces):
    edge_count = defaultdict(int)
    for face in faces:
        for i in range(len(face)):
            a, b = face[i], face[(i + 1) % len(face)]
            edge_count[(min(a, b), max(a, b))] += 1
    border_edges = {e for e, n in edge_count.items() if n == 1}
    border_vertices = {v for e in border_edges for v in e}
    touching = good = 0
    for face in faces:
        if not any(v in border_vertices for v in face):
            continue
        touching += 1
        edges = [(min(face[i], face[(i + 1) % len(face)]), max(face[i], face[(i + 1) % len(face)]))
                 for i in range(len(face))]
        if len(face) == 4 and any(e in border_edges for e in edges):
            good += 1
    valence = defaultdict(int)
    for a, b in edge_count:
        valence[a] += 1
        valence[b] += 1
    irregular = sum(1 for v, k in valence.items() if v not in border_vertices and k != 4)
    quads = sum(1 for face in faces if len(face) == 4)
    return touching, good, quads, len(faces), irregular


def find(d, key):
    """First value of `key` anywhere in a JSON tree (depth first)."""
    if isinstance(d, dict):
        if key in d:
            return d[key]
        for v in d.values():
            r = find(v, key)
            if r is not None:
                return r
    elif isinstance(d, list):
        for v in d:
            r = find(v, key)
            if r is not None:
                return r
    return None


def main():
    args = sys.argv[1:]
    extra = []
    if "--" in args:
        extra = args[args.index("--") + 1:]
        args = args[:args.index("--")]
    archgeo, outdir, meshes = args[0], args[1], args[2:]
    os.makedirs(outdir, exist_ok=True)
    print("| surface | boundary faces | quads with an edge on the boundary | quads | "
          "singularities | interior irregular vertices | δ_PQ,n max after | exit | wall |")
    print("|---|---|---|---|---|---|---|---|---|")
    for mesh in meshes:
        name = os.path.splitext(os.path.basename(mesh))[0]
        layout = os.path.join(outdir, name + "_layout.obj")
        report = os.path.join(outdir, name + ".json")
        final = os.path.join(outdir, name + ".ply")
        for p in (layout, report, final):
            if os.path.exists(p):
                os.remove(p)
        cmd = [archgeo, "solve", "examples/conjugate_layout.yaml", "--set", "mesh=" + mesh,
               "--set", "output.layout=" + layout, "--set", "output.report=" + report,
               "--set", "output.mesh=" + final, "--set", "output.field=" + os.path.join(outdir, name + "_field.ply")]
        for e in extra:
            cmd.append(e)
        start = time.time()
        with open(os.path.join(outdir, name + ".log"), "w") as log:
            rc = subprocess.call(cmd, stdout=log, stderr=subprocess.STDOUT)
        wall = time.time() - start
        if not os.path.exists(layout):
            print(f"| {name} | – | – | – | – | – | – | {rc} | {wall:.1f} s |")
            continue
        touching, good, quads, faces, irregular = boundary_figures(read_obj_faces(layout))
        singular = pq = None
        if os.path.exists(report):
            with open(report) as f:
                r = json.load(f)
            singular = find(r, "singularities")
            if isinstance(singular, list):
                singular = len(singular)
            pq = find(r.get("after", r), "pq_normalized_max")
        share = 100.0 * good / touching if touching else 100.0
        print(f"| {name} | {touching} | {share:.1f}% ({good}) | {100.0 * quads / faces:.1f}% of {faces} | "
              f"{singular} | {irregular} | {pq if pq is None else f'{pq:.2e}'} | {rc} | {wall:.1f} s |",
              flush=True)


if __name__ == "__main__":
    main()
