# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""read_mesh / write_mesh (OBJ, OFF, PLY with the command line's readers and
writers; COMPAS JSON) on numpy arrays, and the errors they raise."""
import json
import subprocess

import numpy as np
import pytest

import archgeo
from conftest import BINARY, CONJUGATE, read_off


def read_binary_ply(path, face_properties, vertex_properties, k):
    """Vertices, faces and the float properties of archgeo's binary PLY
    (vertex: double x y z, floats; face: uchar k, int × k, floats)."""
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode()
    nv = int(header.split("element vertex ")[1].split()[0])
    nf = int(header.split("element face ")[1].split()[0])
    vertex = np.dtype([("xyz", "<f8", 3)] + [(n, "<f4") for n in vertex_properties])
    face = np.dtype([("k", "u1"), ("indices", "<i4", k)] + [(n, "<f4") for n in face_properties])
    vertices = np.frombuffer(data, vertex, nv, end)
    faces = np.frombuffer(data, face, nf, end + nv * vertex.itemsize)
    assert end + nv * vertex.itemsize + nf * face.itemsize == len(data)
    return header, vertices, faces


def test_read_mesh_reads_the_shared_conjugate_mesh():
    V, F = archgeo.read_mesh(CONJUGATE)
    V_off, F_off = read_off(CONJUGATE)
    assert V.dtype == np.float64 and V.shape == (1749, 3)
    assert F.shape == (1633, 4)
    assert np.array_equal(V, V_off)
    assert F.tolist() == F_off


@pytest.mark.parametrize("extension", ["obj", "off", "ply"])
def test_write_then_read_is_exact(tmp_path, extension):
    V, F = archgeo.generate("roof", nu=6, nv=5, noise=0.3, seed=7)
    V = V * np.pi  # digits that a short format would round
    path = tmp_path / f"roof.{extension}"
    archgeo.write_mesh(path, V, F)
    V2, F2 = archgeo.read_mesh(path)
    assert np.array_equal(V2, V)
    assert np.array_equal(F2, F)


def test_mixed_polygons_round_trip_as_lists(tmp_path):
    V = np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0], [2, 1, 0], [1, 1, 0], [0, 1, 0],
                  [1.5, 1.8, 0]], dtype=float)
    F = [[0, 1, 4, 5], [1, 2, 3, 6, 4]]
    archgeo.write_mesh(tmp_path / "mixed.obj", V, F)
    V2, F2 = archgeo.read_mesh(tmp_path / "mixed.obj")
    assert isinstance(F2, list) and F2 == F
    assert np.array_equal(V2, V)


def test_per_face_and_per_vertex_values_go_to_ply_properties(tmp_path):
    V, F = archgeo.generate("roof", nu=4, nv=3)
    pq = archgeo.measure(V, F)["face_values"]["pq_normalized"]
    height = V[:, 2].copy()
    path = tmp_path / "roof.ply"
    archgeo.write_mesh(path, V, F, pq_normalized=pq, vertex_values={"height": height})
    header, vertices, faces = read_binary_ply(path, ["pq_normalized"], ["height"], 4)
    assert "property float pq_normalized" in header and "property float height" in header
    assert np.array_equal(vertices["xyz"], V)
    assert np.array_equal(faces["indices"], F)
    assert np.array_equal(faces["pq_normalized"], pq.astype(np.float32))
    assert np.array_equal(vertices["height"], height.astype(np.float32))
    with pytest.raises(archgeo.InputError, match="values for"):
        archgeo.write_mesh(tmp_path / "bad.ply", V, F, pq_normalized=pq[:-1])
    with pytest.raises(archgeo.InputError, match=r"\.ply only"):
        archgeo.write_mesh(tmp_path / "bad.obj", V, F, pq_normalized=pq)
    assert not (tmp_path / "bad.ply").exists() and not (tmp_path / "bad.obj").exists()


def test_compas_data_in_and_out(tmp_path):
    V, F = archgeo.generate("roof", nu=4, nv=3)
    data = archgeo.to_compas(V, F)
    assert data["vertices"] == V.tolist() and data["faces"] == F.tolist()
    json_path = tmp_path / "roof.json"
    archgeo.write_mesh(json_path, V, F, pq_normalized=np.arange(len(F)))
    stored = json.loads(json_path.read_text())
    assert stored["faces"] == F.tolist() and stored["pq_normalized"] == list(range(len(F)))
    V2, F2 = archgeo.read_mesh(json_path)
    assert np.array_equal(V2, V) and F2 == F.tolist()

    class CompasLikeMesh:  # compas.datastructures.Mesh's method
        def to_vertices_and_faces(self):
            return V.tolist(), F.tolist()

    V3, F3 = archgeo.from_compas(CompasLikeMesh())
    assert np.array_equal(V3, V) and F3 == F.tolist()
    with pytest.raises(archgeo.InputError):
        archgeo.from_compas({"vertices": [[0, 0]], "faces": []})


def test_read_errors_name_file_and_line_as_the_cli(tmp_path):
    bad = tmp_path / "bad.off"
    bad.write_text("OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 9\n")
    with pytest.raises(archgeo.InputError) as error:
        archgeo.read_mesh(bad)
    assert error.value.file == str(bad) and error.value.line == 7
    cli = subprocess.run([BINARY, "measure", str(bad)], capture_output=True, text=True)
    assert cli.returncode == 2
    assert cli.stderr.strip() == "archgeo: error: " + str(error.value)
    with pytest.raises(archgeo.InputError) as missing:
        archgeo.read_mesh(tmp_path / "missing.obj")
    assert missing.value.file == str(tmp_path / "missing.obj")


def test_mesh_errors_in_memory_name_the_face_not_a_file():
    V, F = archgeo.generate("roof", nu=3, nv=3)
    F = F.copy()
    F[5, 2] = len(V) + 3
    with pytest.raises(archgeo.InputError) as error:
        archgeo.measure(V, F)
    assert str(error.value).startswith("<mesh>: face 5: ")
    assert ".off" not in str(error.value)
