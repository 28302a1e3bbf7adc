# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""archgeo.Session: a warm solve after a drag or a weight change is the cold
solve of the same start against the same reference, its Result as
archgeo.solve's; bad input raises InputError."""
import os

import numpy as np
import pytest

import archgeo
from conftest import SOURCE

# examples/planar_quads.yaml (its terms listed: a weight given as a keyword
# keeps the others) with the boundary held: the supports a designer drags.
SPEC = os.path.join(SOURCE, "examples", "planar_quads.yaml")
KEYS = {"fixed": "boundary", "output": {"mesh": "", "image": "", "report": ""}}
TOLERANCE = 1e-3  # tolerance.pq_normalized_max's default


def roof():
    return archgeo.generate("roof", nu=14, nv=10)


def cold(start, F, reference, warm, **keys):
    """archgeo.solve of `start` against `reference` with the continuation and
    the trust region where the session's solve `warm` started them."""
    settings = warm.report["settings"]
    return archgeo.solve(SPEC, start, F, reference=reference, **KEYS,
                         continuation__start=settings["continuation"]["start"],
                         solver__initial_trust_region_radius=settings["solver"][
                             "initial_trust_region_radius"],
                         **keys)


def mean_edge(V, F):
    F = np.asarray(F)
    return np.mean(np.linalg.norm(V[F] - V[np.roll(F, -1, axis=1)], axis=2))


def side_vertex(V, F):
    """A boundary vertex of valence 3 (a side's middle), away from the corners."""
    F = np.asarray(F)
    edges = np.sort(np.stack([F, np.roll(F, -1, axis=1)], axis=2).reshape(-1, 2), axis=1)
    unique, counts = np.unique(edges, axis=0, return_counts=True)
    valence = np.bincount(unique.ravel(), minlength=len(V))
    on_boundary = np.zeros(len(V), dtype=bool)
    on_boundary[unique[counts == 1].ravel()] = True
    candidates = np.flatnonzero(on_boundary & (valence == 3))
    return int(candidates[len(candidates) // 2])


def assert_planar_and_valid(result):
    """Valid, planar to the tolerance, within the deviation band. (A drag may
    raise E above the dragged start's: tolerance.energy_not_above_input then
    ends with exit 4, the cold solve's too.)"""
    assert result.exit_code in (0, 4) and result.valid, result.summary
    assert result.face_values["pq_normalized"].max() <= TOLERANCE
    tolerances = result.report["tolerances"]
    assert tolerances["tolerance.pq_normalized_max"]["met"]
    assert tolerances["tolerance.surface_distance_max"]["met"]


def test_a_drag_resolves_warm_as_the_cold_solve_of_the_same_start():
    V, F = roof()
    session = archgeo.Session(SPEC, V, F, **KEYS)
    first = session.solve()
    assert_planar_and_valid(first)
    assert first.report["cholesky_analyses"] >= 1
    v = side_vertex(V, F)
    move = mean_edge(V, F) / 10
    target = first.V[v] + [0.0, 0.0, move]
    session.move([v], [target])
    start = session.V
    assert np.array_equal(start[v], target)
    assert np.array_equal(np.delete(start, v, axis=0), np.delete(first.V, v, axis=0))

    warm = session.solve()
    assert_planar_and_valid(warm)
    assert warm.report["cholesky_analyses"] == 0  # the first solve's analysis, kept
    assert np.array_equal(warm.V[v], target)
    assert np.abs(warm.V - start).max() > 0
    # The cold solve of the same start, reference and weights: the same but
    # for the frame (tests/test_session.cpp says why within 1% of the drag).
    assert warm.report["settings"]["continuation"]["start"] > 1
    twin = cold(start, F, (V, F), warm)
    assert_planar_and_valid(twin)
    assert twin.exit_code == warm.exit_code
    assert np.linalg.norm(warm.V - twin.V, axis=1).max() < 0.01 * move
    assert np.array_equal(session.V, warm.V)  # the next solve starts here


def test_a_weight_change_takes_effect():
    V, F = roof()
    v = side_vertex(V, F)
    move = mean_edge(V, F) / 10
    light, heavy = archgeo.Session(SPEC, V, F, **KEYS), archgeo.Session(SPEC, V, F, **KEYS)
    first = light.solve()
    heavy.solve()
    target = first.V[v] + [0.0, 0.0, move]
    light.move([v], [target])
    heavy.move([v], [target])
    assert heavy.weight("anchor") == 1.0
    heavy.set_weight("anchor", 100)
    assert heavy.weight("anchor") == 100.0
    start = heavy.V
    a, b = light.solve(), heavy.solve()
    assert_planar_and_valid(a)
    assert_planar_and_valid(b)
    free = np.arange(len(V)) != v
    moved_light = np.linalg.norm(a.V - start, axis=1)[free].sum()
    moved_heavy = np.linalg.norm(b.V - start, axis=1)[free].sum()
    assert moved_heavy < 0.9 * moved_light
    twin = cold(start, F, (V, F), b, terms__anchor__weight=100)
    assert np.linalg.norm(b.V - twin.V, axis=1).max() < 0.01 * move
    assert b.report["settings"]["terms"]["anchor"]["weight"] == 100


def test_bad_input_raises_input_error():
    V, F = roof()
    session = archgeo.Session(SPEC, V, F, **KEYS)
    with pytest.raises(archgeo.InputError, match=f"vertex index {len(V)} out of range") as error:
        session.move([0, len(V)], [V[0], V[0]])
    assert error.value.key == "vertex"
    with pytest.raises(archgeo.InputError, match="not finite"):
        session.move([1], [[0.0, np.nan, 0.0]])
    with pytest.raises(ValueError):
        session.move([1, 2], [V[0]])
    assert np.array_equal(session.V, V)  # nothing moved
    with pytest.raises(archgeo.InputError, match="'no_such_term' is not a term of planar_quads") as error:
        session.set_weight("no_such_term", 1.0)
    assert error.value.key == "terms"
    with pytest.raises(archgeo.InputError):
        session.set_weight("anchor", -1)
    with pytest.raises(archgeo.InputError, match="multiresolution"):
        archgeo.Session(SPEC, V, F, multiresolution__levels=1, **KEYS)
