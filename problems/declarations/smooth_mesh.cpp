// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `smooth_mesh`: lower the visual-smoothness energy E = Σ_e ℓ_e ℓ*_e
// of a triangle or hybrid (triangle + planar polygon) mesh while it keeps to
// its reference surface or follows moved handles.
//
//   [Pellis 2019, §3 (E), §5.1 (energy-minimal meshes: target functional E,
//    proximity to a reference or to handles, fairness, regulariser
//    R(X) = w_reg ‖X − X_prev‖² + w_fair E_fair + w_target E_target),
//    Fig. 12 (design by handles), Fig. 18 (hybrid mesh, planar quads kept
//    planar), Fig. 20 (statistics)]
//
// Terms (½ Σ w r², canonical frame, unit-free weights), in residual order:
// face_planarity (faces with more than 3 sides keep a plane: a unit normal
// and an offset per face, Fig. 18), smoothed_dihedral_energy (E with |ℓ*|
// rounded to sqrt(ℓ*² + ε²), minimised directly: each Ceres iteration
// reweights), dihedral_energy (the older IRLS surrogate of E, weights renewed
// every round; weight 0 by default since issue 14), boundary_proximity,
// proximity (+ point_weight) and anchor (the reference, re-projected each
// round), handles, fairness (straight_triples: opposite neighbours at
// even-valence vertices and boundary neighbours), displacement_guard and
// step (R's w_reg ‖X − X_prev‖²).
//
// Rounds: until a round changes the true E by less than the fraction
// tolerance.energy_change of E (the rounds re-project onto the reference and
// re-centre the step term; once E has settled, further rounds gain ~0.1–0.3%
// each), or 3 rounds in a row have not lowered the lowest true E so far by
// more than tolerance.energy_relative, or a round moves nothing; the output
// is the round with the lowest true E. tolerance.displacement_relative
// bounds how far any vertex moves from its input position (a fraction of the
// bounding-box diagonal): past half the bound a vertex is anchored (×10 per
// round), past the bound it is put back inside (unless it belongs to a
// polygon: clamping would break its plane). On directional_train-station.off
// the unguarded run moved a vertex 1.8% of the diagonal.
//
// handles: design by pulling handles (Fig. 12), a list of
//   - {vertex: 12, position: [x, y, z]}   target in file units, or
//   - {vertex: 40, offset: [dx, dy, dz]}  move by this vector (file units);
// vertex: 0-based index into the input mesh, each vertex at most once. With
// handles every round runs, the output is the last round and there is no
// displacement bound (a design moves the mesh on purpose); the reference
// still applies: set proximity, boundary_proximity and anchor to 0 for a free
// design.
#include <cmath>
#include <optional>
#include <set>

#include "core/problem.h"
#include "core/input_error.h"
#include "problems/declarations/design_band.h"
#include "problems/runtime/model.h"

namespace archgeo::problems {
namespace {

struct Handle {
  int vertex = 0;
  bool offset = false;
  double value[3] = {0, 0, 0};
  int line = 0;
};

std::vector<Handle> ReadHandles(const Settings& s) {
  std::vector<Handle> handles;
  if (!s.Given("handles")) return handles;
  const CustomValue& list = *s.Custom("handles");
  if (!list.IsList()) {
    throw s.ErrorAt("handles", list, "handles", "expected a list of {vertex, position | offset}");
  }
  std::set<int> seen;
  for (size_t i = 0; i < list.items.size(); ++i) {
    const CustomValue& h = list.items[i];
    const std::string key = "handles[" + std::to_string(i) + "]";
    if (!h.IsMap()) {
      throw s.ErrorAt(
          "handles", h, key,
          "expected {vertex: i, position: [x, y, z]} or {vertex: i, offset: [dx, dy, dz]}");
    }
    for (const CustomValue::Entry& e : h.entries) {
      const std::string& k = e.key.text;
      if (k != "vertex" && k != "position" && k != "offset") {
        throw s.ErrorAt("handles", e.key, key + "." + k,
                        "unknown key (allowed: vertex, position, offset)");
      }
    }
    const CustomValue* vertex = h.Find("vertex");
    const CustomValue* position = h.Find("position");
    const CustomValue* offset = h.Find("offset");
    if (!vertex) throw s.ErrorAt("handles", h, key, "missing 'vertex'");
    if ((position != nullptr) == (offset != nullptr)) {
      throw s.ErrorAt("handles", h, key, "give exactly one of 'position' and 'offset'");
    }
    if (!vertex->integer || *vertex->integer < 0 || *vertex->integer > (1 << 30)) {
      throw s.ErrorAt("handles", *vertex, key + ".vertex", "expected a vertex index ≥ 0");
    }
    Handle handle;
    handle.vertex = int(*vertex->integer);
    if (!seen.insert(handle.vertex).second) {
      throw s.ErrorAt("handles", h, key,
                      "vertex " + std::to_string(handle.vertex) + " is listed twice");
    }
    handle.offset = offset != nullptr;
    const CustomValue& xyz = handle.offset ? *offset : *position;
    const std::string xyz_key = key + (handle.offset ? ".offset" : ".position");
    if (!xyz.IsList() || xyz.items.size() != 3) {
      throw s.ErrorAt("handles", xyz, xyz_key, "expected [x, y, z]");
    }
    for (int k = 0; k < 3; ++k) {
      const std::optional<double>& x = xyz.items[k].number;
      if (!x || !std::isfinite(*x)) {
        throw s.ErrorAt("handles", xyz.items[k], xyz_key, "expected a finite number");
      }
      handle.value[k] = *x;
    }
    handle.line = h.line;
    handles.push_back(handle);
  }
  return handles;
}

// The element set "handles": each handle vertex with its target in the
// canonical frame (offsets from the input position).
void Handles(HookContext& c) {
  ElementSet set;
  set.data_width = 3;
  for (const Handle& h : ReadHandles(*c.settings)) {
    if (h.vertex >= int(c.input->number_of_vertices())) {
      const Origin at = c.settings->Where("handles");
      throw InputError(at.file, at.file == "--set" ? 0 : h.line, "handles",
                       "vertex index " + std::to_string(h.vertex) + " out of range: the mesh has " +
                           std::to_string(c.input->number_of_vertices()) + " vertices");
    }
    Vec3 target{h.value[0], h.value[1], h.value[2]};
    if (h.offset) {
      const Point& p = c.input->point(VertexIndex(h.vertex));
      target = {p.x() + h.value[0], p.y() + h.value[1], p.z() + h.value[2]};
    }
    const Vec3 t = c.frame.ToCanonical(target);
    set.Add({h.vertex}, h.vertex, -1, -1, 0, {t[0], t[1], t[2]});
  }
  c.SetElements("handles", std::move(set));
}

}  // namespace

ProblemDecl smooth_mesh() {
  ProblemDecl d;
  d.name = "smooth_mesh";
  d.summary = "lower the edge-length × dihedral energy E = Σ ℓ ℓ* close to the design";
  d.paper = "[Pellis 2019, §3, §5.1, Fig. 12, 18, 20]";
  d.input = InputKind::kInteriorEdge;
  d.terms = {{"face_planarity", 1e6, {}, "non_triangles"},
             {"smoothed_dihedral_energy", 1},
             {"dihedral_energy", 0},
             {"boundary_proximity", 1},
             {"proximity", 1, {{"point_weight", 0.01}}},
             {"anchor", 0.3},
             {"handles", 100},
             {"fairness", 0.01, {{"relative_to_original", false}}, "straight_triples"},
             {"displacement_guard", 1, {}, "", true},
             {"step", 0.1}};
  const Key handles = CustomKey("handles", "[{vertex: 0, offset: [0, 0, 0.1]}]",
                                "design handles: a list of {vertex: i, position: [x, y, z]} or "
                                "{vertex: i, offset: [dx, dy, dz]} (file units)");
  d.keys = {NumberKey("tolerance.energy_relative", 1e-4, 0, 1,
                      "stop when 3 rounds in a row have not lowered the lowest true E by this "
                      "fraction (0: all rounds); not with handles"),
            NumberKey("tolerance.energy_change", 5e-3, 0, 1,
                      "stop when a round changes the true E by less than this fraction of E "
                      "(0: off); not with handles"),
            NumberKey("tolerance.displacement_relative", 0.005, 0, 1,
                      "bound on every vertex's distance from its input position, a fraction of "
                      "the bounding-box diagonal; 0 = none; not with handles"),
            handles};
  d.check = [](const Settings& s) { ReadHandles(s); };
  d.init = &Handles;
  d.stages = [](const Settings& s) {
    Stage st;
    st.rounds_key = "schedule.outer_iterations";
    st.rest_move = 1e-9;
    st.logged = {"E", "E_prime", "self_intersecting_pyramids", "bad_saddles", "displacement_max"};
    if (!s.Given("handles") || ReadHandles(s).empty()) {
      st.keep_best = "E";
      st.patience_measure = "E";
      st.patience_key = "tolerance.energy_relative";
      st.patience_rounds = 3;
      st.guard_key = "tolerance.displacement_relative";
      st.rest_change_measure = "E";
      st.rest_change_key = "tolerance.energy_change";
    }
    return std::vector<Stage>{st};
  };
  d.analyses = {"smoothness"};
  d.colors = "energy";
  // The deviation band (problems/declarations/design_band.h) only if set:
  // tolerance.displacement_relative already keeps every vertex within 0.5%
  // of the diagonal of its input position, hence of the design.
  return WithDesignBand(std::move(d), 0);
}

}  // namespace archgeo::problems
