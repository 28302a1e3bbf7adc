// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `total_absolute_curvature`: form finding of a surface of small
// total absolute curvature C(Φ) = ∫ |κ1| + |κ2| dA under boundary conditions
// [Pellis 2019, §4, §5.3; Fig. 13, 15, 19].
//
// Terms (½ Σ w r², canonical frame: unit mean edge length):
//   total_absolute_curvature  Σ_v Σ_j λ_{j,v}² / (|λ⁽ⁱ⁻¹⁾_{j,v}| + ε), the
//                             tangential eigenvalues of W′_v = ½ Σ (n_f ×
//                             n_f′)(w − v)ᵀ (energies/total_absolute_curvature.h)
//   fairness                  umbrella triples (w_i, v, w_{i+⌊k/2⌋}) with
//                             normal_part: free — only the tangential part of
//                             the second differences is penalised, so the
//                             fairness keeps the triangulation regular without
//                             pulling towards a minimal surface [§5.3: "a sum of
//                             squares of umbrella vectors", Kobbelt 1998]
//   tangent_plane             the input's tangent planes along the boundary
//                             (boundary.tangent_planes: term or both)
//   proximity                 optional pull to the reference (off by default)
//   step                      w_reg ‖v − v⁽ⁱ⁻¹⁾‖² [§5.1, R(X)]
// Rounds (the weight iteration of §5.3): at most schedule.outer_iterations,
// fewer when a round moves no vertex by more than irls.rest_move mean edge
// lengths or changes C by less than the fraction irls.rest_change.
// Measured on the cone of Fig. 13 (24 × 11 vertices, max radial deviation
// from the cone / height): fairness 0.05 gives 0.24% with either normal part;
// fairness 5 gives 0.29% with normal_part: free, 1.29% with penalised.
//
// Boundary conditions [Fig. 15]: hard-fixed vertices from `fixed:` (normally
// `boundary`); the tangent planes along the boundary (normal n_b = unit sum
// of the unit normals of the faces at the boundary vertex b) either free,
// fixed through the second ring (every non-boundary neighbour of a boundary
// vertex keeps its input position), held by the tangent_plane term, or both.
// Triangle meshes only.
#include "core/problem.h"
#include "analysis/smoothness_metrics.h"
#include "mesh/topology.h"
#include "problems/declarations/design_band.h"
#include "problems/runtime/model.h"

namespace archgeo::problems {
namespace {

// The tangent planes of the input at its boundary vertices (element set
// "tangent_planes": a second-ring vertex w with the plane (b, n_b)), and the
// second ring fixed for fix_second_ring / both.
void TangentPlanes(HookContext& c) {
  const std::string mode = c.settings->String("boundary.tangent_planes");
  const bool fix_ring = mode == "fix_second_ring" || mode == "both";
  const bool term = mode == "term" || mode == "both";
  const Mesh& mesh = c.store->mesh();
  ElementSet planes;
  planes.data_width = 6;
  if (fix_ring || term) {
    const std::vector<bool> boundary = BoundaryVertices(mesh);
    const std::vector<Vec3> normals = FaceNormals(mesh);
    for (VertexIndex b : mesh.vertices()) {
      if (!boundary[b.idx()]) continue;
      const Vec3 nb = VertexNormal(mesh, normals, b);
      for (VertexIndex w : CGAL::vertices_around_target(mesh.halfedge(b), mesh)) {
        if (boundary[w.idx()]) continue;
        if (fix_ring) c.fixed[w.idx()] = true;
        if (term && (nb[0] != 0 || nb[1] != 0 || nb[2] != 0)) {
          const Point& p = mesh.point(b);
          planes.Add({int(w.idx())}, int(w.idx()), -1, -1, 0,
                     {p.x(), p.y(), p.z(), nb[0], nb[1], nb[2]});
        }
      }
    }
  }
  c.SetElements("tangent_planes", std::move(planes));
}

}  // namespace

ProblemDecl total_absolute_curvature() {
  ProblemDecl d;
  d.name = "total_absolute_curvature";
  d.summary = "form finding: the surface of least ∫ |κ1| + |κ2| for given boundary conditions";
  d.paper = "[Pellis 2019, §4, §5.3, Fig. 13, 15, 19]";
  // Each step one CHOLMOD factorisation by LeanSolve (core/lean_solve.h): the
  // same rounds and objective as Ceres' steps, without their per-solve set-up.
  d.defaults = {{"solver.back_end", std::string("lean")}};
  d.input = InputKind::kTriangles;
  d.terms = {{"total_absolute_curvature", 1},
             {"fairness", 0.05, {{"normal_part", std::string("free")}}, "umbrella_triples"},
             {"tangent_plane", 10},
             {"proximity", 0, {{"point_weight", 0.0}}},
             {"step", 0.01}};
  d.keys = {ChoiceKey("boundary.tangent_planes", "free",
                      {"free", "fix_second_ring", "term", "both"},
                      "how the boundary's tangent planes are prescribed (Fig. 15)"),
            NumberKey("irls.rest_move", 1e-3, 0, 1e6,
                      "stop when a round moves every vertex less than this (mean edge lengths)"),
            NumberKey("irls.rest_change", 1e-3, 0, 1,
                      "... or changes C by less than this fraction")};
  d.init = &TangentPlanes;
  d.stages = [](const Settings&) {
    Stage s;
    s.rounds_key = "schedule.outer_iterations";
    s.rest_move_key = "irls.rest_move";
    s.rest_change_measure = "C";
    s.rest_change_key = "irls.rest_change";
    s.logged = {"C"};
    return std::vector<Stage>{s};
  };
  d.analyses = {"smoothness"};
  d.colors = "curvature";
  // Form finding leaves the start by design: the deviation band only if set
  // (problems/declarations/design_band.h).
  return WithDesignBand(std::move(d), 0);
}

}  // namespace archgeo::problems
