# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Tests of the Python module archgeo (python/archgeo_module.cpp).

Run by ctest (test python_archgeo, with PYTHONPATH at the built module,
ARCHGEO_BINARY and ARCHGEO_SOURCE_DIR set) or by hand:
  PYTHONPATH=build-py/python ARCHGEO_BINARY=build-py/archgeo \
  ARCHGEO_SOURCE_DIR=. /usr/bin/python3 -m pytest -q python/tests
"""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

import archgeo

SOURCE = os.environ.get("ARCHGEO_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))
BINARY = os.environ.get("ARCHGEO_BINARY", "archgeo")
CONJUGATE = os.path.join(SOURCE, "..", "shared", "data",
                         "libigl_inspired_mesh_quads_Conjugate.off")
GENTLE = os.path.join(SOURCE, "examples", "planar_quads_gentle.yaml")


def read_off(path):
    """Vertices (n, 3) and faces (lists) of an OFF file."""
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


def read_obj_vertices(path):
    return np.array([[float(x) for x in line.split()[1:4]]
                     for line in open(path) if line.startswith("v ")])


def test_problems_and_keys():
    assert {"planar_quads", "smooth_mesh", "hnet"} <= set(archgeo.problems())
    keys = {k["name"]: k for k in archgeo.keys("planar_quads")}
    assert keys["tolerance.pq_normalized_max"]["default"] == 1e-3
    with pytest.raises(archgeo.InputError):
        archgeo.keys("no_such_problem")


def test_generate_gives_numpy_arrays():
    V, F = archgeo.generate("roof", nu=4, nv=3, scale=2.0)
    assert V.shape == (20, 3) and V.dtype == np.float64
    assert F.shape == (12, 4)
    assert F.min() == 0 and F.max() == 19


@pytest.mark.skipif(not os.path.exists(CONJUGATE), reason="../shared/data not present")
def test_solve_conjugate_equals_the_cli(tmp_path):
    V, F = read_off(CONJUGATE)
    off = ["output.mesh=", "output.report=", "solver.num_threads=1"]
    V_out, report = archgeo.solve(GENTLE, V, F, overrides=off)
    assert report["schema_version"] == 1 and report["problem"] == "planar_quads"
    assert report["status"] in (0, 4)
    assert V_out.shape == V.shape
    out = tmp_path / "cli.obj"
    subprocess.run([BINARY, "solve", GENTLE, "--quiet", "--set", f"output.mesh={out}",
                    "--set", "output.report=", "--set", "solver.num_threads=1"], check=False)
    V_cli = read_obj_vertices(out)
    assert np.max(np.abs(V_out - V_cli)) <= 1e-12
    # The solve did something: planarity improved.
    assert report["after"]["pq_normalized_max"] < report["before"]["pq_normalized_max"]


def test_input_errors_carry_the_cli_message(tmp_path):
    V, F = archgeo.generate("roof", nu=3, nv=3)
    spec = tmp_path / "bad.yaml"
    spec.write_text("problem: planar_quads\nmesh: roof.obj\nnot_a_key: 1\n")
    with pytest.raises(archgeo.InputError) as error:
        archgeo.solve(str(spec), V, F)
    assert isinstance(error.value, ValueError)
    cli = subprocess.run([BINARY, "solve", str(spec)], capture_output=True, text=True)
    assert cli.returncode == 2
    assert cli.stderr.strip() == "archgeo: error: " + str(error.value)
    assert "not_a_key" in str(error.value)


def test_measure_dict():
    V, F = archgeo.generate("roof", nu=5, nv=4)
    m = archgeo.measure(V, F)
    assert m["schema_version"] == 1 and m["archgeo"] == "measure"
    assert m["metrics"]["faces"] == 20 and isinstance(m["metrics"]["faces"], int)
    flat = V.copy()
    flat[:, 2] = 0
    assert archgeo.measure(flat, F)["metrics"]["pq_normalized_max"] < 1e-12


def test_compas_style_example(tmp_path):
    script = os.path.join(SOURCE, "examples", "compas_style.py")
    result = subprocess.run([sys.executable, script, str(tmp_path / "in.json"),
                             str(tmp_path / "out.json")], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    data = json.loads((tmp_path / "out.json").read_text())
    assert len(data["vertices"]) == len(json.loads((tmp_path / "in.json").read_text())["vertices"])
    assert data["pq_normalized_max"] <= data["tolerance"]
