// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `base_complex_quads`: a triangle mesh of the design surface
// (closed, or open with the base complex's boundary along its boundary) and
// a base complex on it (from the user: base_complex.mesh or
// base_complex.ids, problems/declarations/base_complex_input.h; or the
// surface decimated to base_complex.decimate vertices [Gebreiter 2012,
// §3.1.1], spectral/decimate.h) → charts →
// their parameterisation over the equilateral triangle or the unit square →
// an all-quad mesh sampled from them (a quad complex's triangles on the open
// boundary: quads and a row of boundary triangles, §4.1.4) [Gebreiter 2012, §4.1]
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
// irregular vertices are exactly the predicted ones, the only boundary edges
// are the n samples of each boundary base edge, there is no T-junction or
// non-manifold edge, and every output vertex is within 1e-9 of the diagonal
// of the input surface.
#include <chrono>
#include <cmath>
#include <string>

#include "core/no_result.h"
#include "core/problem.h"
#include "core/input_error.h"
#include "mesh/similarity.h"
#include "problems/declarations/base_complex_input.h"
#include "problems/runtime/model.h"
#include "spectral/base_complex_charts.h"
#include "spectral/decimate.h"

namespace archgeo::problems {
namespace {

constexpr double kSliverDegrees = 20;  // a base triangle with a smaller angle is a sliver
// Why a decimation stops above its target.
const std::string kDecimationStop =
    "no collapse left keeps the surface manifold, its normals within bounds and its valences at "
    "least 3";

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

// The design mesh decimated to `target` vertices (spectral/decimate.h) as
// the base complex; its figures into `details`. Where no collapse is left
// above the target, the complex is the one reached and `missed` says so
// (the run ends exit 4 with that line, the layout made from it) — up to
// twice the target: a complex larger than that is far from the coarse one
// asked for (a tessellated part stops at thousands) and its charts would take
// minutes, so the count is refused, naming the one reached.
UserBaseComplex DecimatedBaseComplex(const Settings& s, const std::vector<Eigen::Vector3d>& points,
                                     const std::vector<std::array<int, 3>>& triangles, int target,
                                     nlohmann::json& details, std::string& missed) {
  DecimateOptions options;
  options.target_vertices = target;
  const auto start = std::chrono::steady_clock::now();
  DecimateResult r;
  try {
    r = Decimate(points, triangles, options);
  } catch (const std::invalid_argument& e) {
    throw s.Error("base_complex.decimate", e.what());
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!r.reached && r.nodes.size() > 2 * size_t(target)) {
    throw s.Error("base_complex.decimate",
                  "decimation stopped at " + std::to_string(r.nodes.size()) + " vertices for " +
                      std::to_string(target) +
                      ": " + kDecimationStop + "; a complex more than twice the count asked "
                      "is not charted: give base_complex.decimate of at least " +
                      std::to_string(r.nodes.size()));
  }
  if (!r.reached) {
    missed = "base_complex.decimate: decimated to " + std::to_string(r.nodes.size()) +
             " vertices, " + std::to_string(target) +
             " asked (" + kDecimationStop + ")";
  }
  const FeatureProximity near = MeasureFeatureProximity(points, triangles, r);
  // The base triangles' shapes (straight between their nodes): slivers give thin charts.
  double smallest = 180;
  int slivers = 0;
  for (const auto& t : r.triangles) {
    double angle = 180;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d& x = points[size_t(r.nodes[size_t(t[k])])];
      const Eigen::Vector3d a = points[size_t(r.nodes[size_t(t[(k + 1) % 3])])] - x;
      const Eigen::Vector3d b = points[size_t(r.nodes[size_t(t[(k + 2) % 3])])] - x;
      angle = std::min(angle, std::atan2(a.cross(b).norm(), a.dot(b)) * 180 / M_PI);
    }
    smallest = std::min(smallest, angle);
    slivers += angle < kSliverDegrees;
  }
  details = {{"target_vertices", target},
             {"vertices", r.nodes.size()},
             {"reached", r.reached},
             {"triangles", r.triangles.size()},
             {"boundary_corners", r.corners},
             {"feature_corners", r.feature_corners},
             {"flips", r.flips},
             {"relocations", r.relocations},
             {"shape_flips", r.shape_flips},
             {"min_angle_degrees", smallest},
             {"triangles_under_20_degrees", slivers},
             {"irregular_vertices", near.irregular},
             {"irregular_near_feature", near.irregular_near},
             {"vertices_near_feature", near.near},
             {"curvature_extrema", near.extrema},
             {"seconds", seconds}};
  UserBaseComplex out;
  out.complex = r.Complex();
  out.file = s.String("mesh");
  out.key = "base_complex.decimate";
  return out;
}

void BcCheck(const Settings& s) {
  CheckChartKeys(s);
  if (s.Integer("base_complex.decimate") > 0 &&
      (!s.String("base_complex.mesh").empty() || !s.String("base_complex.ids").empty())) {
    throw s.Error("base_complex.decimate",
                  "give the base complex as exactly one of base_complex.mesh, base_complex.ids and "
                  "base_complex.decimate");
  }
}

void BcNet(HookContext& c) {
  const Settings& s = *c.settings;
  const Mesh& design = *c.input;
  std::vector<Eigen::Vector3d> points;
  std::vector<std::array<int, 3>> triangles;
  BcArrays(design, points, triangles);
  const double diagonal = PrincipalBoxDiagonal(design);
  const int decimate = int(s.Integer("base_complex.decimate"));
  UserBaseComplex user;
  nlohmann::json decimation;
  std::string missed;
  if (decimate > 0) {
    user = DecimatedBaseComplex(s, points, triangles, decimate, decimation, missed);
  } else {
    user = ReadUserBaseComplex(s, points, diagonal);
  }
  ChartStep step;
  try {
    step = RunChartStep(s, design, points, triangles, user.complex, false);
  } catch (const BaseComplexError& e) {
    if (decimate > 0) {
      throw NoResult("the decimated base complex (" + std::to_string(user.complex.nodes.size()) +
                     " vertices) cannot be charted: " + e.what() +
                     ". The charts join the base vertices by shortest paths on the design "
                     "mesh's edges that share no vertex, even on the mesh split twice; try "
                     "another base_complex.decimate, or give the base complex with "
                     "base_complex.mesh");
    }
    throw InputError(user.file, 0, user.key, e.what());
  } catch (const std::invalid_argument& e) {
    throw s.Error("charts.n", e.what());
  }
  c.State<BcState>().invalid = step.invalid;
  c.missed = missed;
  c.net.derived = true;
  c.net.mesh = std::move(step.mesh);
  c.net.source.clear();  // output vertices are not input vertices
  c.details["charts"] = std::move(step.details);
  c.details["charts"]["snap_distance_max_relative"] = user.snap_distance / diagonal;
  if (decimate > 0) c.details["decimation"] = std::move(decimation);
  c.net.headline = "base complex: " + std::to_string(user.complex.nodes.size()) + " vertices, " +
                   std::to_string(user.complex.faces.size()) + " faces " +
                   (decimate > 0 ? "decimated from " : "from ") + user.file + "\n" +
                   step.headline;
}

std::string BcInvalid(HookContext& c) { return c.State<BcState>().invalid; }

}  // namespace

ProblemDecl base_complex_quads() {
  ProblemDecl d;
  d.name = "base_complex_quads";
  d.summary = "base complex (given or decimated) on a triangle mesh → charts → "
              "parameterisation → all-quad mesh";
  d.paper = "[Gebreiter 2012, §4.1]";
  d.input = InputKind::kTriangles;
  d.keys = {
      PathKey("base_complex.mesh", Type::kInputPath,
              "the base complex as a triangle/quad mesh (OBJ, OFF, PLY): each vertex is snapped "
              "to the nearest vertex of the design mesh"),
      PathKey("base_complex.ids", Type::kInputPath,
              "or the base complex as surface vertex ids and faces: lines 'v ID' (0-based) and "
              "'f I J K [L]' (1-based base vertices, counter-clockwise)"),
      IntegerKey("base_complex.decimate", 0, 0, 10000000,
                 "or decimate the design mesh to this many base vertices: half-edge collapses "
                 "onto surface vertices, the least quadric error (weighted by curvature) first; "
                 "boundary and feature corners stay (spectral/decimate.h); 0 = off"),
      NumberKey("base_complex.tolerance", 0.01, 0, 1,
                "a base vertex farther than this (fraction of the design mesh's diagonal) from "
                "every vertex of the design mesh is refused")};
  for (Key& k : ChartKeys()) d.keys.push_back(std::move(k));
  d.check = &BcCheck;
  d.net = &BcNet;
  d.stages = &NetIsTheResult;
  d.invalid = &BcInvalid;
  d.colors = "none";
  return d;
}

}  // namespace archgeo::problems
