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
#include <cmath>
#include <cstdio>

#include "core/problem.h"
#include "core/input_error.h"
#include "core/magnitude.h"
#include "geometry/reference.h"
#include "mesh/similarity.h"
#include "problems/declarations/base_complex_input.h"
#include "problems/runtime/model.h"
#include "spectral/base_complex_charts.h"

namespace archgeo::problems {
namespace {

constexpr double kBcOnSurface = 1e-9;  // of the diagonal: output vertices on the input

struct BcState : ProblemState {
  int flipped = 0, boundary_edges = 0, t_junctions = 0, non_manifold_edges = 0;
  bool irregular_as_predicted = false;
  double distance_relative = 0;
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

Mesh BcQuadMesh(const QuadExtraction& q) {
  Mesh out;
  for (const Eigen::Vector3d& p : q.points) out.add_vertex(Point(p.x(), p.y(), p.z()));
  for (const auto& quad : q.quads) {
    const FaceIndex f = out.add_face(VertexIndex(quad[0]), VertexIndex(quad[1]),
                                     VertexIndex(quad[2]), VertexIndex(quad[3]));
    CHECK(f != Mesh::null_face()) << "base_complex_quads: the extracted quads are not a manifold";
  }
  return out;
}

nlohmann::json BcDetails(const ChartQuadsResult& r, const UserBaseComplex& user,
                         double distance, double diagonal, const std::string& weights) {
  int base_triangles = 0, triangles_min = 1 << 30, triangles_max = 0;
  for (const auto& sides : r.layout.sides) base_triangles += sides.size() == 3;
  for (const Chart& c : r.layout.charts) {
    triangles_min = std::min(triangles_min, int(c.triangles.size()));
    triangles_max = std::max(triangles_max, int(c.triangles.size()));
  }
  int base_irregular = 0;
  for (int v : r.expected_irregular) base_irregular += v < int(r.quads.node_vertex.size());
  return {{"base_vertices", r.quads.node_vertex.size()},
          {"base_faces", r.layout.sides.size()},
          {"base_triangles", base_triangles},
          {"base_quads", int(r.layout.sides.size()) - base_triangles},
          {"base_edges", r.layout.edges.size()},
          {"base_irregular_nodes", base_irregular},
          {"base_faces_turned", r.layout.turned},
          {"snap_distance_max_relative", user.snap_distance / diagonal},
          {"n", r.n},
          {"weights", weights},
          {"charts", r.layout.charts.size()},
          {"chart_triangles_min", triangles_min},
          {"chart_triangles_max", triangles_max},
          {"flipped_parameter_triangles", r.flipped},
          {"parameter_area_min_relative", r.min_area},
          {"output_vertices", r.quads.points.size()},
          {"output_quads", r.quads.quads.size()},
          {"irregular_vertices", r.irregular.size()},
          {"expected_irregular_vertices", r.expected_irregular.size()},
          {"irregular_as_predicted", r.irregular == r.expected_irregular},
          {"boundary_edges", r.boundary_edges},
          {"non_manifold_edges", r.non_manifold_edges},
          {"t_junctions", r.t_junctions},
          {"shared_edge_mismatch_relative", r.quads.shared_edge_mismatch / diagonal},
          {"unlocated_samples", r.quads.unlocated},
          {"surface_distance_max_relative", distance / diagonal},
          {"seconds", {{"charts", r.seconds_charts},
                       {"parameterisation", r.seconds_parameterisation},
                       {"extraction", r.seconds_extraction}}}};
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
  const std::string weights = s.String("charts.weights");
  ChartQuadsResult r;
  try {
    r = ChartQuads(points, triangles, user.complex, int(s.Integer("charts.n")),
                   s.Number("charts.edge_length"),
                   weights == "mean_value" ? ChartWeights::kMeanValue : ChartWeights::kCotangent);
  } catch (const BaseComplexError& e) {
    throw InputError(user.file, 0, user.key, e.what());
  } catch (const std::invalid_argument& e) {
    throw s.Error("charts.n", e.what());
  }
  const ReferenceSurface surface(design);
  double distance = 0;
  for (const Eigen::Vector3d& p : r.quads.points) {
    const Vec3 closest = surface.Closest(Vec3{p.x(), p.y(), p.z()}).point;
    distance = std::max(distance, (Eigen::Vector3d(closest[0], closest[1], closest[2]) - p).norm());
  }
  BcState& st = c.State<BcState>();
  st.flipped = r.flipped;
  st.boundary_edges = r.boundary_edges;
  st.t_junctions = r.t_junctions;
  st.non_manifold_edges = r.non_manifold_edges;
  st.irregular_as_predicted = r.irregular == r.expected_irregular;
  st.distance_relative = distance / diagonal;
  c.net.derived = true;
  c.net.mesh = BcQuadMesh(r.quads);
  c.net.source.clear();  // output vertices are not input vertices
  c.details["charts"] = BcDetails(r, user, distance, diagonal, weights);
  char line[512];
  std::snprintf(line, sizeof line,
                "base complex: %zu vertices, %zu faces from %s; %zu charts, n = %d, flipped "
                "parameter triangles %d\nquads: %zu vertices, %zu quads, irregular vertices %zu "
                "(base complex predicts %zu: %s), boundary edges %d, T-junctions %d, distance to "
                "the input %.2e of the diagonal\n",
                user.complex.nodes.size(), user.complex.faces.size(), user.file.c_str(),
                r.layout.charts.size(), r.n, r.flipped, r.quads.points.size(),
                r.quads.quads.size(), r.irregular.size(), r.expected_irregular.size(),
                st.irregular_as_predicted ? "the same vertices" : "differ", r.boundary_edges,
                r.t_junctions, distance / diagonal);
  c.net.headline = line;
}

std::string BcInvalid(HookContext& c) {
  const BcState& st = c.State<BcState>();
  std::string out;
  if (st.flipped > 0) out += std::to_string(st.flipped) + " flipped parameter triangles\n";
  if (!st.irregular_as_predicted) {
    out += "the irregular vertices are not the base complex's (nodes of valence ≠ 4, triangle centres)\n";
  }
  if (st.boundary_edges > 0 || st.non_manifold_edges > 0 || st.t_junctions > 0) {
    out += "the quad mesh is not conforming (" + std::to_string(st.boundary_edges) +
           " boundary edges, " + std::to_string(st.non_manifold_edges) + " non-manifold edges, " +
           std::to_string(st.t_junctions) + " T-junctions)\n";
  }
  if (!(st.distance_relative <= kBcOnSurface)) {
    out += "a vertex is off the input surface by " + std::to_string(st.distance_relative) +
           " of the diagonal\n";
  }
  return out;
}

void BcCheck(const Settings& s) {
  if (s.Number("charts.edge_length") > 0 && s.Given("charts.n")) {
    throw s.Error("charts.edge_length", "give charts.n or charts.edge_length, not both");
  }
}

Key BcPathKey(const char* name, const char* doc) {
  Key k;
  k.name = name;
  k.type = Type::kInputPath;
  k.doc = doc;
  return k;
}

}  // namespace

ProblemDecl base_complex_quads() {
  ProblemDecl d;
  d.name = "base_complex_quads";
  d.summary = "base complex on a closed triangle mesh → charts → parameterisation → all-quad mesh";
  d.paper = "[Gebreiter 2012, §4.1]";
  d.input = InputKind::kTriangles;
  d.keys = {
      BcPathKey("base_complex.mesh",
                "the base complex as a triangle/quad mesh (OBJ, OFF, PLY): each vertex is snapped "
                "to the nearest vertex of the design mesh"),
      BcPathKey("base_complex.ids",
                "or the base complex as surface vertex ids and faces: lines 'v ID' (0-based) and "
                "'f I J K [L]' (1-based base vertices, counter-clockwise)"),
      NumberKey("base_complex.tolerance", 0.01, 0, 1,
                "a base vertex farther than this (fraction of the design mesh's diagonal) from "
                "every vertex of the design mesh is refused"),
      IntegerKey("charts.n", 8, 1, 100000,
                 "samples per base edge: an n × n grid per quad chart, three (n/2) × (n/2) grids "
                 "per triangle chart (n even then)"),
      NumberKey("charts.edge_length", 0, 0, kMaxCoordinate,
                "or the output's edge length in file units: n = mean base-edge path length / this, "
                "rounded (to an even number with triangle faces); 0 = charts.n"),
      ChoiceKey("charts.weights", "cotan", {"cotan", "mean_value"},
                "interior weights of the harmonic parameterisation: cotangent (can flip on obtuse "
                "triangles) or Floater's mean-value weights (positive: never flip)")};
  d.check = &BcCheck;
  d.net = &BcNet;
  d.stages = [](const Settings&) {
    // The quads are made by the `net` hook; one round records them (no solve).
    Stage extract;
    extract.name = "extract";
    extract.rounds_key = "schedule.outer_iterations";
    extract.step = [](HookContext&) {
      StepResult r;
      r.stop = "the quad mesh is the result (no solve)";
      return r;
    };
    return std::vector<Stage>{extract};
  };
  d.invalid = &BcInvalid;
  d.colors = "none";
  return d;
}

}  // namespace archgeo::problems
