# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""archgeo.solve on numpy arrays: the Result, per-face values from the
report's own computation, keyword arguments for spec keys, exceptions and the
progress callback."""
import numpy as np
import pytest

import archgeo
from conftest import CONJUGATE, GENTLE

QUIET = {"output": {"mesh": "", "report": "", "image": ""}, "solver": {"num_threads": 1}}


def roof():
    return archgeo.generate("roof", nu=8, nv=6, noise=0.1, seed=3)


def test_result_on_the_conjugate_mesh():
    V, F = archgeo.read_mesh(CONJUGATE)
    result = archgeo.solve(GENTLE, V, F, **QUIET)
    assert result.exit_code == 0 and result.valid and result.tolerances_met
    assert not result.stopped
    assert result.V.shape == V.shape and np.array_equal(result.F, F)
    pq = result.face_values["pq_normalized"]
    assert pq.shape == (len(F),) and pq.dtype == np.float64
    assert abs(pq.max() - result.report["after"]["pq_normalized_max"]) <= 1e-12
    assert pq.max() <= result.report["tolerances"]["tolerance.pq_normalized_max"]["bound"]
    # The same numbers as measuring the result afresh (each run computes in
    # its own mesh's local frame, so equal to rounding, not to the bit).
    again = archgeo.measure(result.V, result.F)["face_values"]["pq_normalized"]
    assert np.allclose(again, pq, rtol=1e-12, atol=1e-15)
    moved = result.vertex_values["displacement"]
    assert np.allclose(moved, np.linalg.norm(result.V - V, axis=1), rtol=0, atol=1e-12)
    assert "arrays" not in result.report


def test_keyword_arguments_set_spec_keys():
    V, F = roof()
    spec = {"problem": "planar_quads", "schedule": {"outer_iterations": 2}}
    by_name = archgeo.solve(spec, V, F, solver__max_num_iterations=1, **QUIET)
    nested = archgeo.solve(spec, V, F, solver={"max_num_iterations": 1, "num_threads": 1},
                           output=QUIET["output"])
    for result in (by_name, nested):
        assert result.report["settings"]["solver"]["max_num_iterations"] == 1
        assert all(r["iterations"] <= 1 for r in result.report["rounds"])
    assert np.array_equal(by_name.V, nested.V)
    free = archgeo.solve(spec, V, F, **QUIET)
    assert max(r["iterations"] for r in free.report["rounds"]) > 1
    # A numpy value and a list value reach the spec as YAML.
    fixed = archgeo.solve(spec, V, F, fixed=np.array([0, 5]), schedule__outer_iterations=np.int64(1),
                          **QUIET)
    assert fixed.report["settings"]["fixed"] == [0, 5]
    assert np.array_equal(fixed.V[[0, 5]], V[[0, 5]])


def test_a_mistyped_key_is_an_input_error_with_its_key():
    V, F = roof()
    with pytest.raises(archgeo.InputError) as error:
        archgeo.solve({"problem": "planar_quads"}, V, F, solver__max_num_iteratons=5)
    assert error.value.key == "solver.max_num_iteratons"
    assert "max_num_iterations" in str(error.value)  # did you mean


def torus_patch(nu=16, nv=12):
    """A quad grid on a torus patch (R = 3, r = 1), its rows along the
    principal directions."""
    u, v = np.meshgrid(1.2 * np.arange(nu + 1) / nu, 2.5 * np.arange(nv + 1) / nv)
    V = np.stack([(3 + np.cos(v)) * np.cos(u), (3 + np.cos(v)) * np.sin(u), np.sin(v)], axis=-1)
    at = lambda i, j: j * (nu + 1) + i  # noqa: E731
    F = [[at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)]
         for j in range(nv) for i in range(nu)]
    return V.reshape(-1, 3), np.array(F)


def test_no_valid_result_raises_with_the_report():
    # Principal symmetry with the principal edges declared along the quads'
    # diagonals: the solve folds the torus (tests/test_suitability.cpp).
    V, F = torus_patch()
    with pytest.raises(archgeo.NoValidResult) as error:
        archgeo.solve({"problem": "principal_symmetric",
                       "split": {"diagonal": "first", "principal": "diagonals"}}, V, F,
                      schedule__outer_iterations=1, **QUIET)
    result = error.value.result
    assert result.exit_code == 3 and result.V is None and not result.valid
    assert result.report["message"] == "the result is not valid"
    assert "flipped_faces" in str(error.value)


def test_progress_callback_gets_every_iteration_and_round():
    V, F = roof()
    seen = []
    result = archgeo.solve({"problem": "planar_quads"}, V, F,
                           on_iteration=seen.append, **QUIET)
    iterations = [i for i in seen if i["kind"] == "iteration"]
    rounds = [r for r in result.report["rounds"] if r["round"] > 0]
    # One event per Ceres iteration, iteration 0 of each round included.
    assert len(iterations) == sum(r["iterations"] + 1 for r in rounds)
    assert all(" iter " in i["line"] for i in iterations)
    ends = [i for i in seen if i["kind"] == "round"]
    assert [e["round"] for e in ends] == [r["round"] for r in rounds]
    for end, row in zip(ends, rounds):
        # Round k of n against the goal tolerance, as the report logs it.
        assert end["stage_round"] == row["round"]
        assert end["stage_rounds"] == result.report["settings"]["schedule"]["outer_iterations"]
        assert end["measure"] == "pq_normalized_max" and end["target"] == 1e-3
        assert end["value"] == row["measures"]["pq_normalized_max"]
    assert [i["iteration"] for i in iterations if i["round"] == 1] == \
        list(range(rounds[0]["iterations"] + 1))
    timed = [i["elapsed"] for i in seen if i["kind"] != "note"]
    assert timed == sorted(timed) and timed[0] >= 0


def test_returning_stop_ends_with_the_last_valid_state():
    V, F = archgeo.read_mesh(CONJUGATE)
    calls = []

    def stop_at_third_iteration(info):
        calls.append(info)
        if info["kind"] == "iteration" and info["iteration"] == 2:
            return archgeo.STOP
        return False  # anything else: go on

    result = archgeo.solve(GENTLE, V, F, on_iteration=stop_at_third_iteration, **QUIET)
    assert result.stopped and result.report["stop"].startswith("stopped by request")
    assert result.valid and result.V is not None
    assert result.report["iterations"]["outer"] == 1
    assert result.report["iterations"]["inner"] == 2
    # The state returned is the one the report measured.
    assert result.face_values["pq_normalized"].max() == result.report["after"]["pq_normalized_max"]


def test_an_exception_in_the_callback_stops_and_is_raised_with_the_result():
    V, F = roof()

    def fail(info):
        if info["kind"] == "iteration":
            raise RuntimeError("seen enough")

    with pytest.raises(RuntimeError, match="seen enough") as error:
        archgeo.solve({"problem": "planar_quads"}, V, F, on_iteration=fail, **QUIET)
    result = error.value.result
    assert result.stopped and result.valid and result.report["iterations"]["outer"] == 1
