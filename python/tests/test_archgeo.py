# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The package against the command line: the same solve, the same errors,
keys and generated meshes (see conftest.py for how the tests run)."""
import json
import os
import subprocess
import sys

import numpy as np
import pytest

import archgeo
from conftest import BINARY, CONJUGATE, GENTLE, SOURCE, read_off


def read_obj_vertices(path):
    return np.array([[float(x) for x in line.split()[1:4]]
                     for line in open(path) if line.startswith("v ")])


def test_problems_and_keys():
    assert {"planar_quads", "smooth_mesh", "hnet"} <= set(archgeo.problems())
    keys = {k["name"]: k for k in archgeo.keys("planar_quads")}
    assert keys["tolerance.pq_normalized_max"]["default"] == 1e-3
    with pytest.raises(archgeo.InputError):
        archgeo.keys("no_such_problem")
    # Every listed problem has its keys: its own besides those every problem
    # has (a tolerance, terms, or keys of its own such as base_complex_quads'
    # charts.n); custom's are those of `archgeo spec custom`.
    names = archgeo.problems()
    keysets = {name: {k["name"] for k in archgeo.keys(name)} for name in names}
    common = set.intersection(*keysets.values())
    assert "mesh" in common
    for name in names:
        assert keysets[name] - common, name
    assert "charts.n" in keysets["base_complex_quads"]
    assert "terms.face_planarity.weight" in {k["name"] for k in archgeo.keys("custom")}


def test_solve_docstring_comes_from_the_schema():
    doc = archgeo.solve.__doc__
    for k in archgeo.keys("planar_quads"):
        assert f"  {k['name']} = {json.dumps(k['default'])}   [" in doc
    assert "solver.max_num_iterations" in doc and "terms.pq_diagonal.weight" in doc


def test_generate_gives_numpy_arrays():
    V, F = archgeo.generate("roof", nu=4, nv=3, scale=2.0)
    assert V.shape == (20, 3) and V.dtype == np.float64
    assert F.shape == (12, 4)
    assert F.min() == 0 and F.max() == 19


def test_solve_conjugate_equals_the_cli(tmp_path):
    V, F = read_off(CONJUGATE)
    result = archgeo.solve(GENTLE, V, F, output__mesh="", output__report="",
                           solver__num_threads=1)
    report = result.report
    assert report["schema_version"] == 1 and report["problem"] == "planar_quads"
    assert result.exit_code in (0, 4) and result.valid
    assert result.V.shape == V.shape and result.V.dtype == np.float64
    out = tmp_path / "cli.obj"
    subprocess.run([BINARY, "solve", GENTLE, "--quiet", "--set", f"output.mesh={out}",
                    "--set", "output.report=", "--set", "solver.num_threads=1"], check=False)
    V_cli = read_obj_vertices(out)
    assert np.max(np.abs(result.V - V_cli)) <= 1e-12
    # The solve did something: planarity improved.
    assert report["after"]["pq_normalized_max"] < report["before"]["pq_normalized_max"]


def test_input_errors_carry_the_cli_message(tmp_path):
    V, F = archgeo.generate("roof", nu=3, nv=3)
    spec = tmp_path / "bad.yaml"
    spec.write_text("problem: planar_quads\nmesh: roof.obj\nnot_a_key: 1\n")
    with pytest.raises(archgeo.InputError) as error:
        archgeo.solve(str(spec), V, F)
    assert isinstance(error.value, ValueError)
    assert (error.value.file, error.value.line, error.value.key) == (str(spec), 3, "not_a_key")
    cli = subprocess.run([BINARY, "solve", str(spec)], capture_output=True, text=True)
    assert cli.returncode == 2
    assert cli.stderr.strip() == "archgeo: error: " + str(error.value)


def test_measure_dict_and_per_face_arrays():
    V, F = archgeo.generate("roof", nu=5, nv=4)
    m = archgeo.measure(V, F)
    assert m["schema_version"] == 1 and m["archgeo"] == "measure"
    assert m["metrics"]["faces"] == 20 and isinstance(m["metrics"]["faces"], int)
    pq = m["face_values"]["pq_normalized"]
    assert pq.shape == (20,) and pq.dtype == np.float64
    assert pq.max() == m["metrics"]["pq_normalized_max"]
    assert abs(pq.mean() - m["metrics"]["pq_normalized_mean"]) <= 1e-15
    assert m["face_values"]["pq"].max() == m["metrics"]["pq_max"]
    # Per face: the diagonal distance over the mean diagonal (conftest-free check).
    q = V[F[7]]
    d1, d2 = q[2] - q[0], q[3] - q[1]
    n = np.cross(d1, d2)
    distance = abs(np.dot(q[1] - q[0], n)) / np.linalg.norm(n)
    mean_diagonal = 0.5 * (np.linalg.norm(d1) + np.linalg.norm(d2))
    assert abs(pq[7] - distance / mean_diagonal) <= 1e-12
    flat = V.copy()
    flat[:, 2] = 0
    assert archgeo.measure(flat, F)["face_values"]["pq_normalized"].max() < 1e-12
    # Against a reference with the same vertices: the displacement per vertex.
    moved = V.copy()
    moved[3, 2] += 0.25
    d = archgeo.measure(moved, F, reference=(V, F))["vertex_values"]["displacement"]
    assert d.shape == (len(V),) and abs(d[3] - 0.25) <= 1e-12 and np.count_nonzero(d) == 1


def test_compas_style_example(tmp_path):
    script = os.path.join(SOURCE, "examples", "compas_style.py")
    result = subprocess.run([sys.executable, script, str(tmp_path / "in.json"),
                             str(tmp_path / "out.json")], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    data = json.loads((tmp_path / "out.json").read_text())
    assert len(data["vertices"]) == len(json.loads((tmp_path / "in.json").read_text())["vertices"])
    assert data["pq_normalized_max"] <= data["tolerance"]


def test_openmp_threads_wait_passively_unless_the_user_chose():
    def spin_count(policy):
        env = {k: v for k, v in os.environ.items() if k != "OMP_WAIT_POLICY"}
        env["OMP_DISPLAY_ENV"] = "verbose"
        if policy:
            env["OMP_WAIT_POLICY"] = policy
        out = subprocess.run([sys.executable, "-c", "import archgeo"], env=env,
                             capture_output=True, text=True, check=True).stderr
        return out.split("GOMP_SPINCOUNT = '")[-1].split("'")[0]
    assert spin_count(None) == "0"
    assert spin_count("active") != "0"
