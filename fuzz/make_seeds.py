#!/usr/bin/env python3
# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Writes the seed inputs of fuzz/corpus/{obj,off,ply,spec}/ (seed-* files).

Deterministic: crops of the meshes in ../shared/data and examples/ (the first
faces of each file with the vertices, texture coordinates and normals they
use, in the file's own syntax: CRLF, comments, `v//n`, OFF faces wrapped one
index per line as in libigl's quads), the same crops as binary OFF and as
ASCII / binary little- and big-endian PLY with extra properties and elements,
truncated copies (the first 1 KB of each shared file), and the example specs.
Regression inputs of fuzzing findings (regression-* files) are added by hand
and never rewritten here. Run from the repository root:
    python3 fuzz/make_seeds.py
"""
import os
import struct
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "..", "shared", "data")
EXAMPLES = os.path.join(ROOT, "examples")
CORPUS = os.path.join(ROOT, "fuzz", "corpus")
FACES = 10  # faces per crop


def write(kind, name, data):
    os.makedirs(os.path.join(CORPUS, kind), exist_ok=True)
    if isinstance(data, str):
        data = data.encode()
    with open(os.path.join(CORPUS, kind, "seed-" + name), "wb") as f:
        f.write(data)


def patch(polygons):
    """Indices of FACES faces forming a connected patch around face 0
    (breadth-first over shared edges), in that order."""
    by_edge = {}
    for j, face in enumerate(polygons):
        for a, b in zip(face, face[1:] + face[:1]):
            by_edge.setdefault((min(a, b), max(a, b)), []).append(j)
    chosen, queue = [0], [0]
    while queue and len(chosen) < FACES:
        face = polygons[queue.pop(0)]
        for a, b in zip(face, face[1:] + face[:1]):
            for k in by_edge[(min(a, b), max(a, b))]:
                if k not in chosen and len(chosen) < FACES:
                    chosen.append(k)
                    queue.append(k)
    return chosen


def crop_obj(text):
    """The first FACES faces and what they use, as OBJ text in the same style,
    plus the crop as (points, faces) for the other formats."""
    lines = text.splitlines(keepends=True)
    records = {"v": [], "vt": [], "vn": []}
    all_faces, other = [], []
    for line in lines:
        tokens = line.split()
        if not tokens:
            continue
        if tokens[0] in records:
            records[tokens[0]].append(line)
        elif tokens[0] == "f":
            all_faces.append(tokens[1:])
        elif len(other) < 5:
            other.append(line)
    vertex_ids = [[int(t.split("/")[0]) for t in face] for face in all_faces]
    faces = [all_faces[j] for j in patch(vertex_ids)]
    maps = {"v": {}, "vt": {}, "vn": {}}
    out_faces = []
    for face in faces:
        out = []
        for token in face:
            parts = token.split("/")
            new = []
            for kind, part in zip(("v", "vt", "vn"), parts):
                if part == "":
                    new.append("")
                    continue
                index = int(part)
                index = index - 1 if index > 0 else len(records[kind]) + index
                maps[kind].setdefault(index, len(maps[kind]))
                new.append(str(maps[kind][index] + 1))
            out.append("/".join(new))
        out_faces.append(out)
    eol = "\r\n" if text.count("\r\n") > 0 else "\n"
    body = "".join(other)
    for kind in ("v", "vt", "vn"):
        for old in sorted(maps[kind], key=lambda k: maps[kind][k]):
            body += records[kind][old].rstrip("\r\n") + eol
    body += "".join("f " + " ".join(face) + eol for face in out_faces)
    points = [tuple(float(x) for x in records["v"][old].split()[1:4])
              for old in sorted(maps["v"], key=lambda k: maps["v"][k])]
    polygons = [[int(t.split("/")[0]) - 1 for t in face] for face in out_faces]
    return body, points, polygons


def crop_off(text):
    """The first FACES faces of an ASCII OFF file (counts on the line after
    the keyword; faces possibly wrapped over lines)."""
    tokens = []
    for line in text.splitlines():
        line = line.split("#")[0]
        tokens.extend(line.split())
    assert tokens[0] == "OFF"
    nv, nf = int(tokens[1]), int(tokens[2])
    at = 4
    vertex_text = [l for l in text.splitlines()[2:2 + nv]]
    at += 3 * nv
    all_faces = []
    for _ in range(nf):
        n = int(tokens[at])
        all_faces.append([int(t) for t in tokens[at + 1:at + 1 + n]])
        at += 1 + n
    faces = [all_faces[j] for j in patch(all_faces)]
    used = {}
    for face in faces:
        for i in face:
            used.setdefault(i, len(used))
    order = sorted(used, key=lambda k: used[k])
    points = [tuple(float(x) for x in vertex_text[i].split()[:3]) for i in order]
    polygons = [[used[i] for i in face] for face in faces]
    return vertex_text, order, points, polygons


def off_text(vertex_lines, polygons, wrapped):
    text = "OFF\n%d %d 0\n" % (len(vertex_lines), len(polygons))
    text += "".join(l + "\n" for l in vertex_lines)
    for face in polygons:
        if wrapped:  # libigl's quads: the count, then one index per line
            text += "%d %d \n" % (len(face), face[0]) + "".join("%d \n" % i for i in face[1:])
        else:
            text += "%d %s\n" % (len(face), " ".join(map(str, face)))
    return text


def binary_off(points, polygons):
    data = b"OFF BINARY\n" + struct.pack(">iii", len(points), len(polygons), 0)
    for p in points:
        data += struct.pack(">fff", *p)
    for face in polygons:
        data += struct.pack(">i%di" % len(face), len(face), *face) + struct.pack(">i", 0)
    return data


def ply(points, polygons, fmt, extras):
    """PLY in `fmt` (ascii, binary_little_endian, binary_big_endian); with
    `extras`: double coordinates, normals, colours, a texcoord list and an
    edge element."""
    header = "ply\nformat %s 1.0\ncomment archgeo fuzz seed\nelement vertex %d\n" % (
        fmt, len(points))
    coord = "double" if extras else "float"
    header += "".join("property %s %s\n" % (coord, c) for c in "xyz")
    if extras:
        header += "property float nx\nproperty float ny\nproperty float nz\n"
        header += "property uchar red\nproperty uchar green\nproperty uchar blue\n"
    header += "element face %d\nproperty list uchar int vertex_indices\n" % len(polygons)
    if extras:
        header += "property list uchar float texcoord\nelement edge 1\n"
        header += "property int vertex1\nproperty int vertex2\n"
    header += "end_header\n"
    if fmt == "ascii":
        body = ""
        for p in points:
            body += " ".join(repr(x) for x in p)
            body += " 0 0 1 200 10 30\n" if extras else "\n"
        for face in polygons:
            body += "%d %s" % (len(face), " ".join(map(str, face)))
            body += " 2 0.25 0.75\n" if extras else "\n"
        if extras:
            body += "0 1\n"
        return header.encode() + body.encode()
    e = "<" if fmt == "binary_little_endian" else ">"
    body = b""
    for p in points:
        body += struct.pack(e + ("ddd" if extras else "fff"), *p)
        if extras:
            body += struct.pack(e + "fffBBB", 0, 0, 1, 200, 10, 30)
    for face in polygons:
        body += struct.pack(e + "B%di" % len(face), len(face), *face)
        if extras:
            body += struct.pack(e + "Bff", 2, 0.25, 0.75)
    if extras:
        body += struct.pack(e + "ii", 0, 1)
    return header.encode() + body


def main():
    crops = []
    for name in sorted(os.listdir(DATA)) + ["examples/" + n for n in sorted(os.listdir(EXAMPLES))]:
        path = os.path.join(ROOT, name) if name.startswith("examples/") else os.path.join(DATA, name)
        base = os.path.splitext(os.path.basename(name))[0]
        if name.endswith(".obj"):
            text = open(path, newline="").read()
            body, points, polygons = crop_obj(text)
            write("obj", base + ".obj", body)
            crops.append((base, points, polygons))
        elif name.endswith(".off"):
            text = open(path).read()
            vertex_text, order, points, polygons = crop_off(text)
            wrapped = "quads" in name
            write("off", base + ".off",
                  off_text([vertex_text[i] for i in order], polygons, wrapped))
            write("off", base + "-binary.off", binary_off(points, polygons))
            crops.append((base, points, polygons))
        elif name.endswith(".yaml"):
            write("spec", base + ".yaml", open(path, "rb").read())
        else:
            continue
        if not name.startswith("examples/"):
            kind = os.path.splitext(name)[1][1:]
            write(kind, base + "-first-1k." + kind, open(path, "rb").read()[:1024])
    for i, (base, points, polygons) in enumerate(crops):
        fmt = ("ascii", "binary_little_endian", "binary_big_endian")[i % 3]
        write("ply", "%s-%s.ply" % (base, fmt), ply(points, polygons, fmt, False))
        write("ply", "%s-%s-extras.ply" % (base, fmt), ply(points, polygons, fmt, True))
    # Hand-written syntax variants.
    write("obj", "relative-crlf-tabs.obj",
          "mtllib m.mtl\r\no roof\r\nv 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nvn 0 0 1\r\nvt 0 0\r\n"
          "g panels\r\nusemtl glass\r\ns off\r\nf\t1/1/1\t2/1/1\t3/1/1\r\nv 0 1 0\r\n"
          "f -4//1 -2//1 -1//1\r\n")
    write("off", "variants.off",
          "# comment\nOFF 5 2 0\n0 0 0\n1 0 0 # edge\n1 1 0\n0 1 0\n\n0.5 2 0\n"
          "4 0 1 2 3 255 0 0\n3\n\n3 2\n4\n")
    write("off", "coff.off", "COFF\n4 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n1 1 0 0 0 1 1\n"
          "0 1 0 1 1 1 1\n4 0 1 2 3\n")
    write("off", "4off.off", "4OFF\n3 1 0\n0 0 0 1\n2 0 0 2\n0 3 0 3\n3 0 1 2\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
