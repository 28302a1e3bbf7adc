// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `base_complex_quads`: a closed triangle mesh of the design
// surface and a base complex on it (from the user: base_complex.mesh or
// base_complex.ids, problems/declarations/base_complex_input.h) → charts →
// their parameterisation over the equilateral triangle or the unit square →
// an all-quad mesh sampled from them [Gebreiter 2012, §4.1]
// (spectral/base_complex_charts.h).
//
// The `net` hook builds the quad mesh; it is the net the run measures and
// writes (output.mesh). No solve follows: its one stage, `extract`, records
// it in one round and stops. The report's
// details.charts gives the charts, flipped parameter triangles, the output's
// irregular vertices against the base complex's prediction, boundary edges,
// T-junctions, how far the two charts of a base edge disagree on its
// samples, and the output vertices' distance to the input surface. The
// result is invalid (exit 4) unless no parameter triangle is flipped, the
// irregular vertices are exactly the predicted ones, there is no boundary
// edge, T-junction or non-manifold edge, and every output vertex is within
// 1e-9 of the diagonal of the input surface.
#include "core/problem.h"
#include "core/input_error.h"
#include "mesh/similarity.h"
#include "problems/declarations/base_complex_input.h"
#include "problems/runtime/model.h"
#include "spectral/base_complex_charts.h"

namespace archgeo::problems {
namespace {

struct BcState : ProblemState {
  std::string invalid;  // ChartStep::invalid
};

void BcArrays(const Mesh& mesh, std::vector<Eigen::Vector3d>& points,
              std::vector<std::array<int, 3>>& triangles) {
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    points.emplace_back(p.x(), p.y(), p.z());
  }
  for (FaceIndex f : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) t[size_t(k++)] = int(v.idx());
    triangles.push_back(t);
  }
}

void BcNet(HookContext& c) {
  const Settings& s = *c.settings;
  const Mesh& design = *c.input;
  for (HalfedgeIndex h : design.halfedges()) {
    if (design.is_border(h)) {
      throw s.Error("mesh", s.String("mesh") +
                                " has a boundary: base complexes on open surfaces (the boundary "
                                "triangles of Gebreiter 2012, §4.1.4) are not done; give a closed mesh");
    }
  }
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  BcArrays(design, points, triangles);
  const double diagonal = PrincipalBoxDiagonal(design);
  const UserBaseComplex user = ReadUserBaseComplex(s, points, diagonal);
  ChartStep step;
  try {
    step = RunChartStep(s, design, points, triangles, user.complex);
  } catch (const BaseComplexError& e) {
    throw InputError(user.file, 0, user.key, e.what());
  } catch (const std::invalid_argument& e) {
    throw s.Error("charts.n", e.what());
  }
  c.State<BcState>().invalid = step.invalid;
  c.net.derived = true;
  c.net.mesh = std::move(step.mesh);
  c.net.source.clear();  // output vertices are not input vertices
  c.details["charts"] = std::move(step.details);
  c.details["charts"]["snap_distance_max_relative"] = user.snap_distance / diagonal;
  c.net.headline = "base complex: " + std::to_string(user.complex.nodes.size()) + " vertices, " +
                   std::to_string(user.complex.faces.size()) + " faces from " + user.file + "\n" +
                   step.headline;
}

std::string BcInvalid(HookContext& c) { return c.State<BcState>().invalid; }

}  // namespace

ProblemDecl base_complex_quads() {
  ProblemDecl d;
  d.name = "base_complex_quads";
  d.summary = "base complex on a closed triangle mesh → charts → parameterisation → all-quad mesh";
  d.paper = "[Gebreiter 2012, §4.1]";
  d.input = InputKind::kTriangles;
  d.keys = {
      PathKey("base_complex.mesh", Type::kInputPath,
              "the base complex as a triangle/quad mesh (OBJ, OFF, PLY): each vertex is snapped "
              "to the nearest vertex of the design mesh"),
      PathKey("base_complex.ids", Type::kInputPath,
              "or the base complex as surface vertex ids and faces: lines 'v ID' (0-based) and "
              "'f I J K [L]' (1-based base vertices, counter-clockwise)"),
      NumberKey("base_complex.tolerance", 0.01, 0, 1,
                "a base vertex farther than this (fraction of the design mesh's diagonal) from "
                "every vertex of the design mesh is refused")};
  for (Key& k : ChartKeys()) d.keys.push_back(std::move(k));
  d.check = &CheckChartKeys;
  d.net = &BcNet;
  d.stages = &NetIsTheResult;
  d.invalid = &BcInvalid;
  d.colors = "none";
  return d;
}

}  // namespace archgeo::problems
