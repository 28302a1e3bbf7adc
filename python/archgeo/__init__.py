# SPDX-FileCopyrightText: The archgeo authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""archgeo: optimisation of freeform-architecture meshes (planar quads, smooth
meshes, principal-symmetric and H-nets, grids) on numpy arrays.

Meshes are V, an (n, 3) float64 array of vertex positions in file units, and
F, an (m, k) integer array of 0-based vertex indices or a list of polygons.

    import archgeo
    V, F = archgeo.read_mesh("roof.off")
    result = archgeo.solve({"problem": "planar_quads"}, V, F,
                           on_iteration=lambda info: print(info["line"]))
    result.face_values["pq_normalized"].max()   # == result.report["after"]["pq_normalized_max"]

docs/python.md has an example per problem family.
"""
import json
import os

import numpy as np

# libgomp reads OMP_WAIT_POLICY once, when the extension loads it: unless the
# user chose, its idle threads wait passively instead of spinning on the cores
# the solve needs (as the archgeo tool does).
os.environ.setdefault("OMP_WAIT_POLICY", "passive")
from . import _archgeo  # noqa: E402
from ._archgeo import STOP, InputError, __version__, generate, problems

__all__ = ["STOP", "InputError", "NoValidResult", "Result", "Session", "solve", "measure", "read_mesh",
           "write_mesh", "from_compas", "to_compas", "generate", "problems", "keys",
           "__version__"]


class NoValidResult(RuntimeError):
    """The solve found no usable or no valid result (the command line's exit
    status 3; nothing was written). `result` is the Result (V is None) with
    the report saying why."""

    def __init__(self, message, result):
        super().__init__(message)
        self.result = result


class Result:
    """The outcome of archgeo.solve.

    V               (n, 3) float64: the optimised vertices, file units (None
                    when there is no valid result)
    F               the faces of V: (m, k) int64, or a list for mixed polygons
    face_values     {name: (m,) float64}: per-face values of the result, the
                    same numbers the report's metrics are the max and mean of:
                    "pq_normalized" (δ_PQ,n), "pq" (diagonal distance, file
                    units), "warp" on meshes with quads or larger faces, and
                    the problem's colour value (e.g. "energy_share")
    vertex_values   {name: (n,) float64}: "displacement" from the input (file
                    units) when the result has the input's vertices
    report          the JSON report (docs/report.schema.json) as a dict
    exit_code       the command line's exit status: 0 valid and every
                    tolerance met, 4 valid with a tolerance missed, 5 written
                    with panels as defective as the input's
    valid           the result passed every validity check
    tolerances_met  every tolerance of the problem was met
    stopped         the solve was stopped (Ctrl-C, an exception or
                    archgeo.STOP from on_iteration) and this is the last valid
                    state; the spec's output files were then not written
    summary         the text `archgeo solve` prints
    """

    def __init__(self, status, V, F, report, summary, stopped):
        arrays = report.pop("arrays", {"face": {}, "vertex": {}})
        self.V = V
        self.F = F
        self.face_values = {k: np.asarray(v, dtype=float) for k, v in arrays["face"].items()}
        self.vertex_values = {k: np.asarray(v, dtype=float) for k, v in arrays["vertex"].items()}
        self.report = report
        self.exit_code = status
        self.valid = bool(report.get("validity", {}).get("valid", False))
        self.tolerances_met = all(t["met"] for t in report.get("tolerances", {}).values())
        self.stopped = stopped
        self.summary = summary

    def to_compas(self):
        """The result as COMPAS mesh data: {"vertices": [...], "faces": [...]}."""
        return to_compas(self.V, self.F)

    def __repr__(self):
        return (f"Result(exit_code={self.exit_code}, valid={self.valid}, "
                f"tolerances_met={self.tolerances_met}, stopped={self.stopped})")


def keys(problem):
    """A problem's spec keys: [{"name", "default", "doc"}, ...]."""
    return json.loads(_archgeo.keys(problem))


def _input_error(message, key=""):
    """An InputError raised from Python (no file or line)."""
    error = InputError(message)
    error.file, error.line, error.key = "", 0, key
    return error


def _yaml(value):
    """A value as YAML text (JSON is YAML) for a "key=value" override."""
    if isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, np.ndarray):
        value = value.tolist()
    return json.dumps(value)


def _overrides(prefix, values, out):
    """Keyword arguments and nested dicts as ["dotted.key=value", ...]:
    solver__max_num_iterations=50 and solver={"max_num_iterations": 50} are
    the same key."""
    for name, value in values.items():
        key = prefix + name.replace("__", ".")
        if isinstance(value, dict):
            _overrides(key + ".", value, out)
        else:
            out.append(f"{key}={_yaml(value)}")
    return out


def _is_spec_path(spec):
    return "\n" not in spec and spec.lower().endswith((".yaml", ".yml"))


def _mesh(V, F):
    """(V, F) from arrays, COMPAS data (a dict, a .json path, an object with
    to_vertices_and_faces()) given as V with F None."""
    if F is None:
        if V is None:
            return None, None
        return from_compas(V)
    return np.asarray(V, dtype=float), F


def solve(spec, V=None, F=None, *, reference=None, on_iteration=None, **keys):
    """Solves a problem and returns a Result.

    spec          a dict of spec keys, YAML text, or the path of a .yaml spec
                  (its relative paths anchor at its folder; with V given its
                  `mesh` key only names the mesh in messages)
    V, F          the mesh: V (n, 3) float64, F (m, k) int or a list of
                  polygons; or COMPAS mesh data as V (a dict with "vertices"
                  and "faces", a .json path, or an object with
                  to_vertices_and_faces()) and F None; both None: the spec's
                  `mesh` file, or none for a problem that makes its own (grid)
    reference     the surface to stay close to: (V, F) or COMPAS data (None:
                  the mesh itself, or the spec's `reference`)
    on_iteration  called with a dict per progress event: "kind" ("iteration"
                  per solver iteration, "round" at a round's end, "note"
                  for a stage's line), "line" (the log line), "stage",
                  "round" (rounds so far), "stage_round" k of "stage_rounds"
                  n, "iteration" (within the round), "measure" (the goal
                  tolerance, e.g. "pq_normalized_max"), its "value" and
                  "target", "elapsed" (seconds); None where an event has
                  none. Returning archgeo.STOP stops the solve with the
                  last valid state (Result.stopped)
    **keys        any spec key: solver__max_num_iterations=50 (the dots as
                  "__") or solver={"max_num_iterations": 50}; they override
                  the spec's (as `archgeo solve --set`)

    Output keys (output.mesh, output.report, ...) are written as by
    `archgeo solve`, relative to the spec's folder for a spec path, else to
    the current folder.

    Ctrl-C (SIGINT) stops the solve after the current iteration: the
    KeyboardInterrupt is raised once the solve has returned, with the last
    valid state as its `result` attribute (the output files are not
    written). An exception raised by on_iteration stops the solve the same
    way and is raised with `result`.

    Raises InputError (attributes file, line, key) for a bad spec key or
    mesh, NoValidResult when there is no usable or valid result.
    """
    overrides = _overrides("", keys, ["output.arrays=true"])
    V, F = _mesh(V, F)
    if V is None and not isinstance(spec, dict) and _is_spec_path(spec):
        return _result(_archgeo.solve_file(spec, overrides, on_iteration))
    text, name = _spec_text(spec)
    ref_V, ref_F = _reference_mesh(reference)
    return _result(_archgeo.solve(text, name, V, F, ref_V, ref_F, overrides, on_iteration))


def _spec_text(spec):
    """(YAML or JSON text, name for messages) of a dict, a spec path or text."""
    if isinstance(spec, dict):
        return json.dumps(spec), "<spec>"
    if _is_spec_path(spec):
        with open(spec, encoding="utf-8") as f:
            return f.read(), spec
    return spec, "<spec>"


def _reference_mesh(reference):
    """(V, F) of a reference given as a (V, F) pair, a path or None."""
    if isinstance(reference, tuple):
        return _mesh(reference[0], reference[1])
    return _mesh(reference, None)


def _result(answer):
    status, V, F, report, summary, stopped, error = answer
    result = Result(status, V, F, json.loads(report), summary, stopped)
    if error is not None:
        error.result = result
        raise error
    if status == 3:
        raise NoValidResult(result.report.get("message", "no valid result") + "\n" + summary,
                            result)
    return result


class Session:
    """A problem kept for solving again: drag a few vertices or change a term
    weight, then solve to tolerance from the last solution.

        session = archgeo.Session({"problem": "planar_quads", "fixed": "boundary"}, V, F)
        result = session.solve()                 # as archgeo.solve
        session.move([17], [[1.0, 2.0, 0.3]])    # a boundary vertex, file units
        result = session.solve()                 # from the last solution

    spec, V, F, reference and **keys as archgeo.solve (a spec path's `mesh`
    file when V is None). The first solve() is archgeo.solve(spec, V, F,
    reference=reference, **keys). After it the session keeps the problem: the
    spec, the mesh's variables and element sets, the reference surface
    (`reference`, else the first mesh) and the pattern of the normal
    equations with its sparse Cholesky analysis; a later solve() reads and
    sets up none of them again and, while the same vertices are fixed and
    the same terms on, analyses no new structure. Each later solve() starts
    from the last result returned (after a NoValidResult: from where that
    solve started) with the vertices moved since, and is the solve of that
    mesh against the session's reference: the same terms (anchor and
    fairness relative to that start), schedule, tolerance stops, validity
    checks, Result and spec outputs as archgeo.solve(spec, V_start, F,
    reference=reference or the first mesh) with continuation.start and
    solver.initial_trust_region_radius where the last solve left them (its
    report's settings: the planarity weights and the trust region that made
    the last result planar). Only its frame is the first mesh's.

    Problems that solve a net of their own (hnet, relayout: "auto", grid)
    and multiresolution are refused (InputError). One call at a time.
    """

    def __init__(self, spec, V=None, F=None, *, reference=None, **keys):
        overrides = _overrides("", keys, ["output.arrays=true"])
        V, F = _mesh(V, F)
        text, name = _spec_text(spec)
        ref_V, ref_F = _reference_mesh(reference)
        self._session = _archgeo.Session(text, name, V, F, ref_V, ref_F, overrides)

    def solve(self, on_iteration=None):
        """Solves (see the class) and returns a Result; on_iteration, Ctrl-C
        and the exceptions as archgeo.solve."""
        return _result(self._session.solve(on_iteration))

    def move(self, ids, positions):
        """Puts vertices ids[i] (0-based) at positions[i] ((n, 3), file units)
        for the next solve(): a fixed vertex (the spec's `fixed`) stays
        there, a free one starts there. Raises InputError (key "vertex") for
        an index out of range or a non-finite position; nothing moves then."""
        ids = np.atleast_1d(np.asarray(ids))
        if ids.size and not np.issubdtype(ids.dtype, np.integer):
            raise _input_error("vertex ids must be integers", "vertex")
        positions = np.asarray(positions, dtype=float).reshape(-1, 3)
        self._session.move(ids.astype(np.int64), positions)

    def set_weight(self, term, weight):
        """terms.<term>.weight for the next solve()s. Raises InputError for a
        term the problem does not have (key "terms") or a weight out of the
        key's range."""
        self._session.set_weight(term, float(weight))

    def weight(self, term):
        """The weight terms.<term>.weight has now."""
        return self._session.weight(term)

    @property
    def V(self):
        """(n, 3): the vertices the next solve() starts from (file units)."""
        return self._session.current()[0]

    @property
    def F(self):
        """The faces of V."""
        return self._session.current()[1]


def measure(V, F=None, reference=None):
    """The metrics of a mesh as `archgeo measure --json` (a dict), against
    `reference` ((V, F) or COMPAS data) if given, with per-face and per-vertex
    arrays: m["face_values"] {"pq", "pq_normalized", "warp"} (faces of 4 or
    more sides; the values whose max and mean m["metrics"] holds) and
    m["vertex_values"] {"displacement"} (a reference with the same vertex
    count)."""
    V, F = _mesh(V, F)
    ref_V, ref_F = (None, None)
    if isinstance(reference, tuple):
        ref_V, ref_F = _mesh(reference[0], reference[1])
    elif reference is not None:
        ref_V, ref_F = _mesh(reference, None)
    report = json.loads(_archgeo.measure(V, F, ref_V, ref_F))
    arrays = report.pop("arrays")
    report["face_values"] = {k: np.asarray(v, dtype=float) for k, v in arrays["face"].items()}
    report["vertex_values"] = {k: np.asarray(v, dtype=float) for k, v in arrays["vertex"].items()}
    return report


def read_mesh(path):
    """(V, F) of a mesh file: .obj, .off, .ply with the command line's
    readers and limits (faces re-oriented, coincident vertices welded, as
    `archgeo solve` reads them), or .json COMPAS mesh data."""
    if str(path).lower().endswith(".json"):
        return from_compas(path)
    return _archgeo.read_mesh(os.fspath(path))


def write_mesh(path, V, F, vertex_values=None, **face_values):
    """Writes (V, F) as .obj, .off or .ply (as `archgeo solve` writes its
    meshes: full double precision, binary PLY) or .json (COMPAS mesh data).
    Keyword arguments are per-face arrays (e.g. pq_normalized=...), written
    as float face properties of a PLY (or keys of the JSON);
    `vertex_values` ({name: (n,) array}) as float vertex properties."""
    vertex_values = vertex_values or {}
    if str(path).lower().endswith(".json"):
        data = to_compas(V, F)
        data.update({k: np.asarray(v, dtype=float).tolist() for k, v in face_values.items()})
        data.update({k: np.asarray(v, dtype=float).tolist() for k, v in vertex_values.items()})
        with open(path, "w", encoding="utf-8") as f:
            json.dump(data, f)
        return
    _archgeo.write_mesh(os.fspath(path), V, F, face_values, vertex_values)


def from_compas(data):
    """(V, F) from COMPAS mesh data: a dict {"vertices": [[x, y, z], ...],
    "faces": [[i, j, k, ...], ...]} (mesh.to_vertices_and_faces() as JSON),
    the path of such a .json file, or an object with to_vertices_and_faces()
    (a compas.datastructures.Mesh)."""
    if hasattr(data, "to_vertices_and_faces"):
        vertices, faces = data.to_vertices_and_faces()
    else:
        if isinstance(data, (str, os.PathLike)):
            with open(data, encoding="utf-8") as f:
                data = json.load(f)
        vertices, faces = data["vertices"], data["faces"]
    V = np.asarray(vertices, dtype=float)
    if V.ndim != 2 or V.shape[1] != 3:
        raise _input_error("COMPAS mesh data: 'vertices' must be a list of [x, y, z]")
    return V, [list(map(int, f)) for f in faces]


def to_compas(V, F):
    """COMPAS mesh data {"vertices": [...], "faces": [...]} of (V, F), for
    compas.datastructures.Mesh.from_vertices_and_faces(**data)."""
    faces = F.tolist() if isinstance(F, np.ndarray) else [list(map(int, f)) for f in F]
    return {"vertices": np.asarray(V, dtype=float).tolist(), "faces": faces}


def _keys_doc():
    """Every problem's keys, for solve's docstring: "name = default
    [problems]" and the key's documentation."""
    found = {}
    names = []
    for problem in problems():
        try:
            problem_keys = keys(problem)
        except InputError:  # custom: its keys follow the terms it composes
            continue
        names.append(problem)
        for k in problem_keys:
            entry = found.setdefault(k["name"], {"default": k["default"], "doc": k["doc"],
                                                 "problems": []})
            entry["problems"].append(problem)
    lines = ["", "Spec keys (from the settings schema; archgeo.keys(PROBLEM) gives one "
                 "problem's, docs/keys.md the tables):"]
    for name in sorted(found):
        entry = found[name]
        where = ("every problem" if len(entry["problems"]) == len(names)
                 else ", ".join(entry["problems"]))
        lines.append(f"  {name} = {json.dumps(entry['default'])}   [{where}]")
        if entry["doc"]:
            lines.append(f"      {entry['doc']}")
    return "\n".join(lines)


solve.__doc__ += _keys_doc()
