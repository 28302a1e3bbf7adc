// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — problem `remesh`: incremental isotropic remeshing of a design
// surface to a target edge length [Gebreiter 2012, §3.1.2; Botsch & Kobbelt
// 2004, §4] (geometry/isotropic_remesh.h). No solve: the remeshed triangle
// mesh is the result, measured against the input as the design surface.
#include <cmath>
#include <cstdio>
#include <string>

#include "core/input_error.h"
#include "core/problem.h"
#include "geometry/curves.h"
#include "geometry/isotropic_remesh.h"
#include "geometry/reference.h"
#include "problems/runtime/model.h"

namespace archgeo::problems {
namespace {

double RemeshMeanEdge(const Mesh& mesh) {
  double sum = 0;
  long count = 0;
  for (EdgeIndex e : mesh.edges()) {
    const HalfedgeIndex h = mesh.halfedge(e);
    sum += std::sqrt(CGAL::squared_distance(mesh.point(mesh.source(h)), mesh.point(mesh.target(h))));
    ++count;
  }
  return count ? sum / double(count) : 0;
}

constexpr double kCurveTolerance = 0.05;  // of the mean input edge: an edge along a feature curve

void RemeshNet(HookContext& c) {
  const Settings& s = *c.settings;
  const double input_mean = RemeshMeanEdge(*c.input);
  RemeshOptions options;
  options.target_edge_length = s.Number("remesh.edge_length") * input_mean;
  options.iterations = int(s.Integer("remesh.iterations"));
  options.corner_angle_degrees = s.Number("remesh.corner_angle");
  options.feature_angle_degrees = s.Number("remesh.feature_angle");
  const CGAL::Bbox_3 box = CGAL::bbox_3(c.input->points().begin(), c.input->points().end());
  const double diagonal = std::sqrt(std::pow(box.xmax() - box.xmin(), 2) + std::pow(box.ymax() - box.ymin(), 2) +
                                    std::pow(box.zmax() - box.zmin(), 2));
  options.tolerance = s.Number("remesh.tolerance") * diagonal;
  if (!(options.target_edge_length > 0)) {
    throw s.Error("remesh.edge_length", "the input's mean edge length is 0: nothing to remesh");
  }
  const std::string& features = s.String("remesh.features");
  if (!features.empty()) {
    for (const Polyline& p : ReadPolylines(features)) options.feature_curves.push_back(p.points);
    options.curve_tolerance = kCurveTolerance * input_mean;
  }
  RemeshResult r = IsotropicRemesh(*c.input, options);
  for (size_t k = 0; k < r.curve_edges.size(); ++k) {
    if (r.curve_edges[k] > 0) continue;
    throw InputError(features, 0, "remesh.features",
                     "polyline " + std::to_string(k + 1) + " ('l' record " + std::to_string(k + 1) +
                         ") runs along no interior edge of the input: its points must follow the "
                         "input's edges, within 5% of their mean length");
  }
  const TriangleQuality q = MeasureTriangles(r.mesh);
  const Mesh input_triangles = TriangulatedCopy(*c.input);
  const TriangleQuality in = MeasureTriangles(input_triangles);
  char line[768];
  std::snprintf(line, sizeof line,
                "isotropic remeshing to edge length %.4g (%.3g × the input's mean edge %.4g), %d iterations, "
                "%d input feature edges, %d corners kept\n"
                "triangles: input %zu, %.2f%% with every angle ≥ 30° (smallest %.1f°), edge length CV %.3f; "
                "output %zu (%zu vertices), %.2f%% (smallest %.1f°), edge length mean %.4g, CV %.3f\n",
                options.target_edge_length, s.Number("remesh.edge_length"), input_mean, options.iterations,
                r.feature_edges, r.corners, size_t(input_triangles.number_of_faces()),
                100 * in.min_angle_30_fraction, in.min_angle_degrees, in.edge_cv,
                size_t(r.mesh.number_of_faces()), size_t(r.mesh.number_of_vertices()),
                100 * q.min_angle_30_fraction, q.min_angle_degrees, q.edge_mean, q.edge_cv);
  c.details["remesh"] = {{"target_edge_length", options.target_edge_length},
                         {"input_mean_edge_length", input_mean},
                         {"iterations", options.iterations},
                         {"tolerance", options.tolerance},
                         {"corners", r.corners},
                         {"feature_edges", r.feature_edges},
                         {"feature_curve_edges", r.curve_edges},
                         {"splits", r.splits},
                         {"collapses", r.collapses},
                         {"flips", r.flips},
                         {"min_angle_30_fraction", q.min_angle_30_fraction},
                         {"min_angle_degrees", q.min_angle_degrees},
                         {"edge_length_mean", q.edge_mean},
                         {"edge_length_cv", q.edge_cv},
                         {"input", {{"triangles", input_triangles.number_of_faces()},
                                    {"min_angle_30_fraction", in.min_angle_30_fraction},
                                    {"min_angle_degrees", in.min_angle_degrees},
                                    {"edge_length_mean", in.edge_mean},
                                    {"edge_length_cv", in.edge_cv}}},
                         {"output", {{"vertices", r.mesh.number_of_vertices()},
                                     {"faces", r.mesh.number_of_faces()}}}};
  c.net.mesh = std::move(r.mesh);
  c.net.headline = line;
  c.net.derived = true;
  c.net.source.clear();
}

std::vector<Stage> RemeshStages(const Settings&) {
  return {ResultWithoutSolve("remesh", "the remeshed surface is the result (no solve)")};
}

}  // namespace

ProblemDecl remesh() {
  ProblemDecl d;
  d.name = "remesh";
  d.summary = "isotropic remeshing of a design surface to a target edge length (split, collapse, flip, relax)";
  d.paper = "[Gebreiter 2012, §3.1.2]";
  d.input = InputKind::kAny;
  d.keys = {NumberKey("remesh.edge_length", 1, 1e-3, 1e3,
                      "target edge length, relative to the input's mean edge length"),
            IntegerKey("remesh.iterations", 10, 1, 100, "split / collapse / flip / relax iterations"),
            NumberKey("remesh.tolerance", 0, 0, 0.1,
                      "curvature-adaptive edge lengths: the chord deviation allowed, relative to the bounding-box "
                      "diagonal; edges shrink (down to 1/16 of the target) where the input curves; 0: uniform"),
            NumberKey("remesh.feature_angle", 30, 0, 180,
                      "an input edge whose faces' normals differ by more than this (degrees) is a feature, "
                      "kept like the boundary (0: no features)"),
            PathKey("remesh.features", Type::kInputPath,
                    "feature curves as OBJ polylines ('l' records): every interior input edge "
                    "along one (its ends and midpoint within 5% of the mean edge length) is a "
                    "feature, kept like the boundary, besides those of remesh.feature_angle; a "
                    "polyline along no edge is refused"),
            NumberKey("remesh.corner_angle", 30, 0, 180,
                      "a boundary vertex where the boundary turns by more than this (degrees) is a corner: "
                      "kept in place")};
  d.net = &RemeshNet;
  d.stages = &RemeshStages;
  d.colors = "none";
  return d;
}

}  // namespace archgeo::problems
