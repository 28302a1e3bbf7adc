// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/declarations/base_complex_input.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <glog/logging.h>

#include "core/magnitude.h"
#include "geometry/reference.h"
#include "io/base_complex_ids.h"
#include "io/io.h"
#include "mesh/similarity.h"
#include "spectral/quad_relax.h"
#include "spectral/quad_untangle.h"

namespace archgeo {
namespace {

// Each base vertex on its nearest surface vertex (brute force: a base
// complex has few vertices).
UserBaseComplex BcSnapMesh(const std::string& path, const std::vector<Eigen::Vector3d>& points,
                           double tolerance) {
  const Mesh coarse = ReadMesh(path);
  UserBaseComplex out;
  out.file = path;
  out.key = "base_complex.mesh";
  for (VertexIndex v : coarse.vertices()) {
    const Eigen::Vector3d q(coarse.point(v).x(), coarse.point(v).y(), coarse.point(v).z());
    int best = -1;
    double distance = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < points.size(); ++i) {
      const double d = (points[i] - q).squaredNorm();
      if (d < distance) {
        distance = d;
        best = int(i);
      }
    }
    distance = std::sqrt(distance);
    if (!(distance <= tolerance)) {
      char text[320];
      std::snprintf(text, sizeof text,
                    "base vertex %u (%.6g, %.6g, %.6g) is %.3g from the nearest vertex of the "
                    "surface, beyond base_complex.tolerance (%.3g in file units): it is not on "
                    "the surface",
                    unsigned(v.idx()), q.x(), q.y(), q.z(), distance, tolerance);
      throw InputError(path, 0, out.key, text);
    }
    out.snap_distance = std::max(out.snap_distance, distance);
    out.complex.nodes.push_back(best);
  }
  for (FaceIndex f : coarse.faces()) {
    std::vector<int> face;
    for (VertexIndex v : CGAL::vertices_around_face(coarse.halfedge(f), coarse)) {
      face.push_back(int(v.idx()));
    }
    out.complex.faces.push_back(face);
  }
  return out;
}

constexpr double kBcOnSurface = 1e-9;  // of the diagonal: output vertices on the input

Mesh BcQuadMesh(const QuadExtraction& q) {
  Mesh out;
  for (const Eigen::Vector3d& p : q.points) out.add_vertex(Point(p.x(), p.y(), p.z()));
  for (const auto& quad : q.quads) {
    const FaceIndex f = out.add_face(VertexIndex(quad[0]), VertexIndex(quad[1]),
                                     VertexIndex(quad[2]), VertexIndex(quad[3]));
    CHECK(f != Mesh::null_face()) << "chart step: the extracted quads are not a manifold";
  }
  for (const auto& t : q.triangles) {
    const FaceIndex f = out.add_face(VertexIndex(t[0]), VertexIndex(t[1]), VertexIndex(t[2]));
    CHECK(f != Mesh::null_face()) << "chart step: the boundary strips' triangles are not a manifold";
  }
  return out;
}

nlohmann::json BcDetails(const ChartQuadsResult& r, double distance, double diagonal,
                         const std::string& weights) {
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
          {"n", r.n},
          {"weights", weights},
          {"charts", r.layout.charts.size()},
          {"chart_triangles_min", triangles_min},
          {"chart_triangles_max", triangles_max},
          {"flipped_parameter_triangles", r.flipped},
          {"parameter_area_min_relative", r.min_area},
          {"output_vertices", r.quads.points.size()},
          {"output_quads", r.quads.quads.size()},
          {"output_triangles", r.quads.triangles.size()},
          {"strip_charts", r.strips},
          {"irregular_vertices", r.irregular.size()},
          {"expected_irregular_vertices", r.expected_irregular.size()},
          {"irregular_as_predicted", r.irregular == r.expected_irregular},
          {"boundary_edges", r.boundary_edges},
          {"expected_boundary_edges", r.expected_boundary_edges},
          {"surface_refinements", r.refinements},
          {"non_manifold_edges", r.non_manifold_edges},
          {"t_junctions", r.t_junctions},
          {"shared_edge_mismatch_relative", r.quads.shared_edge_mismatch / diagonal},
          {"unlocated_samples", r.quads.unlocated},
          {"surface_distance_max_relative", distance / diagonal},
          {"seconds", {{"charts", r.seconds_charts},
                       {"parameterisation", r.seconds_parameterisation},
                       {"extraction", r.seconds_extraction}}}};
}

std::string BcInvalid(const ChartQuadsResult& r, double distance_relative) {
  std::string out;
  if (r.flipped > 0) out += std::to_string(r.flipped) + " flipped parameter triangles\n";
  if (r.irregular != r.expected_irregular) {
    out += "the irregular vertices are not the base complex's (its nodes of irregular "
           "valence, the centres of split triangles)\n";
  }
  if (r.boundary_edges != r.expected_boundary_edges || r.non_manifold_edges > 0 ||
      r.t_junctions > 0) {
    out += "the quad mesh is not conforming (" + std::to_string(r.boundary_edges) +
           " boundary edges where the base complex's boundary gives " +
           std::to_string(r.expected_boundary_edges) + ", " +
           std::to_string(r.non_manifold_edges) + " non-manifold edges, " +
           std::to_string(r.t_junctions) + " T-junctions)\n";
  }
  if (!(distance_relative <= kBcOnSurface)) {
    out += "a vertex is off the input surface by " + std::to_string(distance_relative) +
           " of the diagonal\n";
  }
  return out;
}

}  // namespace

BaseComplex QuasiDualBaseComplex(const QuadBaseComplex& q) {
  BaseComplex base;
  base.nodes = q.nodes;
  for (const auto& f : q.quads) base.faces.push_back({f[0], f[1], f[2], f[3]});
  for (const auto& e : q.quad_edges) base.edges.push_back({e[0], e[1], e[2], e[3]});
  return base;
}

std::vector<Key> ChartKeys() {
  return {IntegerKey("charts.n", 8, 1, 100000,
                     "samples per base edge: an n × n grid per quad chart, three (n/2) × (n/2) "
                     "grids per triangle chart (n even then), a lattice per boundary strip"),
          NumberKey("charts.edge_length", 0, 0, kMaxCoordinate,
                    "or the output's edge length in file units: n = mean base-edge path length / "
                    "this, rounded (to an even number with triangle faces); 0 = charts.n"),
          ChoiceKey("charts.weights", "cotan", {"cotan", "mean_value"},
                    "interior weights of the harmonic parameterisation: cotangent (can flip on "
                    "obtuse triangles) or Floater's mean-value weights (positive: never flip)"),
          IntegerKey("charts.smoothing", 20, 0, 100000,
                     "sweeps that straighten the grid lines where they cross chart boundaries: "
                     "each vertex of valence 4 half-way to the mean of its neighbours, then onto "
                     "the design surface; irregular vertices stay (spectral/quad_relax.h); 0 = "
                     "the charts' samples as mapped"),
          ChoiceKey("charts.boundary_triangles", "auto", {"auto", "strip", "split"},
                    "a triangle chart with one side on the open boundary: `strip` = quads lined "
                    "up with its two inner sides and n triangles along the boundary (thesis "
                    "§4.1.4; n may be odd), `split` = three quads around a valence-3 centre like "
                    "any triangle chart; `auto` = strip when the base complex has a quad face (with output: "
                    "triangles every chart is a triangle lattice and this key is not used)"),
          ChoiceKey("charts.output", "quads", {"quads", "triangles"},
                    "`triangles`: a triangle base complex's every chart sampled as the whole "
                    "lattice, n² triangles (thesis §4.1.4; at n = 2^k the connectivity of k Loop "
                    "steps of the base complex, its vertices on the design surface: remeshing "
                    "using subdivision, §9.2.4); no smoothing sweeps")};
}

void CheckChartKeys(const Settings& s) {
  if (s.Number("charts.edge_length") > 0 && s.Given("charts.n")) {
    throw s.Error("charts.edge_length", "give charts.n or charts.edge_length, not both");
  }
}

void CheckQuadComplexChartKeys(const Settings& s) {
  CheckChartKeys(s);
  if (s.String("charts.output") == "triangles") {
    throw s.Error("charts.output",
                  "triangles need a triangle base complex (base_complex_quads); this problem's "
                  "base complex, the quasi-dual of a Morse–Smale complex, is all quads");
  }
}

ChartStep RunChartStep(const Settings& s, const Mesh& design,
                       const std::vector<Eigen::Vector3d>& points,
                       const std::vector<std::array<int, 3>>& triangles, const BaseComplex& base,
                       bool move_nodes) {
  const std::string weights = s.String("charts.weights");
  const std::string& strips = s.String("charts.boundary_triangles");
  bool quad_face = false;
  for (const auto& f : base.faces) quad_face = quad_face || f.size() == 4;
  const ChartFill fill = s.String("charts.output") == "triangles" ? ChartFill::kTriangles
                         : strips == "strip" || (strips == "auto" && quad_face) ? ChartFill::kStrip
                                                                                : ChartFill::kSplit;
  ChartStep out;
  ChartQuadsResult& r = out.result;
  r = ChartQuads(points, triangles, base, int(s.Integer("charts.n")),
                 s.Number("charts.edge_length"),
                 weights == "mean_value" ? ChartWeights::kMeanValue : ChartWeights::kCotangent,
                 fill);
  const double diagonal = PrincipalBoxDiagonal(design);
  const ReferenceSurface surface(design);
  const GridLineKinks mapped = MeasureGridLineKinks(r.quads.points, r.quads.quads);
  const auto sample = [&surface](const Eigen::Vector3d& p) {
    const ReferenceSurface::SurfacePoint c = surface.Closest(Vec3{p.x(), p.y(), p.z()});
    return SurfaceSample{{c.point[0], c.point[1], c.point[2]}, {c.normal[0], c.normal[1], c.normal[2]}};
  };
  const auto onto = [&sample](const Eigen::Vector3d& p) { return sample(p).point; };
  RelaxQuads(r.quads.quads, int(s.Integer("charts.smoothing")), onto, &r.quads.points,
             r.quads.centre_vertex);
  const UntangleResult untangled =
      UntangleQuads(r.quads.quads, sample, &r.quads.points, r.quads.centre_vertex, move_nodes);
  const GridLineKinks relaxed = MeasureGridLineKinks(r.quads.points, r.quads.quads);
  double distance = 0;
  for (const Eigen::Vector3d& p : r.quads.points) distance = std::max(distance, (onto(p) - p).norm());
  out.mesh = BcQuadMesh(r.quads);
  out.details = BcDetails(r, distance, diagonal, weights);
  out.details["grid_line_kink_max_degrees"] = {{"mapped", mapped.max_degrees},
                                                {"output", relaxed.max_degrees}};
  out.details["grid_line_kink_mean_degrees"] = {{"mapped", mapped.mean_degrees},
                                                 {"output", relaxed.mean_degrees}};
  out.details["bent_quads"] = {{"relaxed", untangled.bent_before},
                               {"untangled", untangled.bent_after},
                               {"vertex_moves", untangled.moves}};
  out.invalid = BcInvalid(r, distance / diagonal);
  char line[768];
  std::snprintf(line, sizeof line,
                "charts: %zu, n = %d, flipped parameter triangles %d\noutput: %zu vertices, %zu "
                "quads, %zu triangles, irregular vertices %zu (base complex predicts %zu: %s), boundary edges "
                "%d (its boundary gives %d), T-junctions %d, distance to the input %.2e of the diagonal\n",
                r.layout.charts.size(), r.n, r.flipped, r.quads.points.size(), r.quads.quads.size(),
                r.quads.triangles.size(), r.irregular.size(), r.expected_irregular.size(),
                r.irregular == r.expected_irregular ? "the same vertices" : "differ",
                r.boundary_edges, r.expected_boundary_edges, r.t_junctions, distance / diagonal);
  out.headline = line;
  if (!r.quads.quads.empty()) {
    std::snprintf(line, sizeof line,
                  "grid lines turn at most %.1f° (mean %.2f°) after %d smoothing sweeps, %.1f° "
                  "(%.2f°) as mapped\n",
                  relaxed.max_degrees, relaxed.mean_degrees, int(s.Integer("charts.smoothing")),
                  mapped.max_degrees, mapped.mean_degrees);
    out.headline += line;
  }
  if (untangled.bent_before > 0) {
    std::snprintf(line, sizeof line,
                  "quads with a corner bent inward: %d after smoothing, %d after unfolding (%d vertex "
                  "moves)\n",
                  untangled.bent_before, untangled.bent_after, untangled.moves);
    out.headline += line;
  }
  return out;
}

UserBaseComplex ReadUserBaseComplex(const Settings& s, const std::vector<Eigen::Vector3d>& points,
                                    double diagonal) {
  const std::string& mesh = s.String("base_complex.mesh");
  const std::string& ids = s.String("base_complex.ids");
  if (mesh.empty() == ids.empty()) {
    throw s.Error(mesh.empty() ? "base_complex.mesh" : "base_complex.ids",
                  "give the base complex as exactly one of base_complex.mesh (a triangle/quad mesh "
                  "on the surface), base_complex.ids (surface vertex ids and faces) and "
                  "base_complex.decimate (a vertex count to decimate the surface to)");
  }
  if (!mesh.empty()) {
    return BcSnapMesh(mesh, points, s.Number("base_complex.tolerance") * diagonal);
  }
  const BaseComplexIds read = ReadBaseComplexIds(ids, "base_complex.ids");
  UserBaseComplex out;
  out.file = ids;
  out.key = "base_complex.ids";
  out.complex.nodes = read.nodes;
  out.complex.faces = read.faces;
  return out;
}

std::vector<Stage> NetIsTheResult(const Settings&) {
  return {ResultWithoutSolve("extract", "the charts' mesh is the result (no solve)")};
}

}  // namespace archgeo
