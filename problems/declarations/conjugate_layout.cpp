// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `conjugate_layout`: from a triangle mesh of the design surface to
// a planar-quad layout, the pipeline of [Zadravec 2010, Fig. 1]:
//
//   (a) a TCD field (conjugate_field: §2–4),
//   (b) level sets along it and the quad-dominant layout they cut out
//       (level_sets: §5; fields/extract.h),
//   (c) optimisation of the layout for planar faces (planar_quads: §6, eq. 8).
//
// With layout.method: streamlines, (b) is instead the streamline-intersection
// layout of [Gebreiter 2012, §8.2] (streamline_layout.h): the field's evenly
// spaced streamlines of both families, their crossings as vertices, the same
// clean-up, then (c) as above.
//
// The input may also be a polygon mesh (e.g. a quad net too far from
// conjugate to be planarised): its triangulation is the design surface
// (field_pipeline.h DesignSurface).
//
// It is the planar_quads declaration (same terms, keys, stage and
// tolerance) whose `net` hook runs (a) and (b) as nested solves on the input
// (`mesh`, a triangle mesh) with this spec's field and level-set keys and
// returns the layout as the net solved: the report's "before" is the layout
// (δ_PQ,n before the PQ step), "after" the final mesh, and displacements are
// measured from the layout. Without a `reference` the design surface (the
// input as read) is the reference surface of the PQ step (band, projections,
// proximity) and of the report's distances (problems/runtime/solve.cpp,
// Solution::on_design), and the final mesh is judged against it as `archgeo
// measure FINAL --reference DESIGN` judges it (problems/commands/run.cpp).
//
// The layout's panels with a corner straight or bent inward (a boundary
// corner too) are split there before the PQ step (relayout.h
// SplitBentPanels; details.net.split_bent_panels): the convexity barrier
// cannot straighten a corner the net already has bent.
//
// Outputs: output.mesh (the final planar mesh), output.layout (the layout
// the PQ step starts from), output.field (fields/field_io.h),
// output.streamlines (the field's streamlines and separatrices as OBJ
// polylines, fields/streamlines.h), output.report.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Geometry>

#include "analysis/validity.h"
#include "core/no_result.h"
#include "core/problem.h"
#include "fields/field_io.h"
#include "core/input_error.h"
#include "io/io.h"
#include "problems/declarations/field_pipeline.h"
#include "problems/declarations/relayout.h"
#include "problems/declarations/streamline_layout.h"
#include "problems/declarations/worst_quads.h"
#include "problems/runtime/model.h"

namespace archgeo::problems {
namespace {

struct LayoutState : ProblemState {
  StreamlineResult streamlines;  // output.streamlines
};

constexpr const char* kAvoidance = "terms.tcd_singularity_avoidance.weight";

// The smallest corner of any face of `mesh` (degrees, between its two sides
// in space: a spike turned back on itself has a small one too) and its face.
std::pair<double, int> SmallestCorner(const Mesh& mesh) {
  std::pair<double, int> smallest{180.0, -1};
  for (FaceIndex f : mesh.faces()) {
    std::vector<Vec3> p;
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) p.push_back(ToVec3(mesh.point(v)));
    for (size_t i = 0; i < p.size(); ++i) {
      const Vec3& a = p[(i + p.size() - 1) % p.size()];
      const Vec3& b = p[i];
      const Vec3& c = p[(i + 1) % p.size()];
      const Eigen::Vector3d u(a[0] - b[0], a[1] - b[1], a[2] - b[2]), w(c[0] - b[0], c[1] - b[1], c[2] - b[2]);
      const double angle = std::atan2(u.cross(w).norm(), u.dot(w)) * 180.0 / M_PI;
      if (angle < smallest.first) smallest = {angle, int(f.idx())};
    }
  }
  return smallest;
}

// Why a layout cannot be the net of the PQ step ("" if it can): not
// extracted, a panel no optimisation repairs once its corners are split as
// the net's are (UseLayoutAsNet): a bow-tie, a corner bent inward, a short
// edge, the surface crossing itself (analysis/validity.h, the limits of the
// spec), or a face with a corner under validity.min_corner_degrees (a
// sliver, or a spike turned back).
std::string LayoutDefect(const Settings& s, const LevelSetResult& result) {
  if (!result.layout.ok) return "no layout: " + result.layout.error;
  Mesh net = result.layout.mesh;
  SplitBentPanels(net, s.Number("terms.convexity.margin_degrees"));
  const ValidityLimits limits = LimitsOf(s);
  const Validity validity = CheckValidity(net, nullptr, limits, true);
  if (!validity.valid()) return validity.Reason();
  const auto [angle, face] = SmallestCorner(net);
  if (angle >= limits.min_corner_degrees) return "";
  char line[160];
  std::snprintf(line, sizeof line, "face %d has a corner of %.2f degrees (limit %g)\n", face, angle,
                limits.min_corner_degrees);
  return line;
}

// The terminal line of a layout made again without singularity avoidance
// ("" when its own layout was kept).
std::string AvoidanceLine(const nlohmann::json& report) {
  if (report.at("kept").get<bool>() || !report.contains("defect_with_it")) return "";
  std::string defect = report.at("defect_with_it").get<std::string>();
  defect = defect.substr(0, defect.find('\n'));
  const std::string singularities =
      report.contains("singularities_with_it")
          ? " (" + std::to_string(report.at("singularities_with_it").get<int>()) + " singularities)"
          : "";
  return "singularity avoidance: its layout" + singularities + " had a defect (" + defect +
         "); laid out again without it\n";
}

// The layout `solve` makes with the spec's singularity avoidance (on by
// default here: fewer singularities where the field is free), and when that
// layout has panels that cannot be built, the layout without it
// (details.net.singularity_avoidance says which was kept and why, and the
// wall time of the layout it did not keep: details.net.seconds are the kept
// one's).
template <typename Solve>
std::shared_ptr<const LevelSetResult> WithAvoidance(const Settings& s,
                                                    std::map<std::string, Value> overrides,
                                                    const Solve& solve, nlohmann::json* report) {
  const double weight = s.Number(kAvoidance);
  overrides[kAvoidance] = weight;
  const auto start = std::chrono::steady_clock::now();
  *report = {{"weight", weight}, {"kept", weight > 0}};
  if (!(weight > 0)) return solve(overrides);
  std::shared_ptr<const LevelSetResult> result;
  std::string defect;
  try {
    result = solve(overrides);
    defect = LayoutDefect(s, *result);
  } catch (const InputError& e) {
    // A stage without a usable solution with it; bad input fails without
    // it too, and is reported from there.
    defect = "no layout: " + e.message();
  }
  if (defect.empty()) return result;
  (*report)["kept"] = false;
  (*report)["defect_with_it"] = defect;
  if (result) (*report)["singularities_with_it"] = result->field->field.singularities.size();
  (*report)["seconds_with_it"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  overrides[kAvoidance] = 0.0;
  return solve(overrides);
}

// layout.method: streamlines — the field's streamlines, their crossings as
// the layout (streamline_layout.h).
void StreamlineNet(HookContext& c, const Mesh& design, int refinements) {
  const Settings& s = *c.settings;
  StreamlineResult lines;
  nlohmann::json avoidance;
  const std::shared_ptr<const LevelSetResult> result = WithAvoidance(
      s, SplitDesignOverrides(s, refinements),
      [&](const std::map<std::string, Value>& overrides) {
        lines = StreamlineResult{};
        return SolveStreamlineLayout(s, design, c.progress, overrides, &lines);
      },
      &avoidance);
  UseLayoutAsNet(c, result, "conjugate layout (streamlines)");
  c.net.details["field"] = result->field->details;
  c.net.details["singularity_avoidance"] = avoidance;
  c.net.details["design_surface"] = {{"triangles", design.number_of_faces()},
                                     {"midpoint_splits", refinements}};
  c.State<LayoutState>().streamlines = std::move(lines);
  c.net.headline = AvoidanceLine(avoidance) + result->headline +
                   "solving the layout for planar faces (planar_quads)\n";
}

void Net(HookContext& c) {
  const Settings& s = *c.settings;
  int refinements = 0;
  const Mesh design = DesignSurface(s, *c.input, 0, &refinements);
  if (s.String("layout.method") == "streamlines") {
    StreamlineNet(c, design, refinements);
    return;
  }
  nlohmann::json avoidance;
  const std::shared_ptr<const LevelSetResult> result = WithAvoidance(
      s, SplitDesignOverrides(s, refinements),
      [&](const std::map<std::string, Value>& overrides) {
        return SolveLevelSets(s, design, c.progress, overrides);
      },
      &avoidance);
  if (!result->layout.ok) {
    throw NoResult("the layout could not be extracted from the level sets: " +
                   result->layout.error);
  }
  UseLayoutAsNet(c, result, "conjugate layout");
  c.net.details["field"] = result->field->details;
  c.net.details["singularity_avoidance"] = avoidance;
  c.net.details["design_surface"] = {{"triangles", design.number_of_faces()},
                                     {"midpoint_splits", refinements}};
  const std::string split =
      refinements == 0 ? ""
                       : "design surface: each triangle split at its edge midpoints " +
                             std::to_string(refinements) + " time(s), " +
                             std::to_string(design.number_of_faces()) +
                             " triangles (at least two per layout face: the level sets are "
                             "linear on each)\n";
  std::string streamlines;
  c.State<LayoutState>().streamlines =
      FieldStreamlines(s, *result->field, &c.net.details, &streamlines);
  c.net.headline = split + AvoidanceLine(avoidance) + result->field->headline + streamlines +
                   result->headline + "solving the layout for planar faces (planar_quads)\n";
}

void WriteConjugateLayout(HookContext& c) {
  const auto& result = c.level_sets;
  if (const auto it = c.temporaries.find("layout"); it != c.temporaries.end()) {
    // The layout as solved: its bent panels split as in Net.
    Mesh layout = InFileUnits(result->layout.mesh, result->frame);
    SplitBentPanels(layout, c.settings->Number("terms.convexity.margin_degrees"));
    WriteMesh(it->second, layout);
  }
  if (const auto it = c.temporaries.find("field"); it != c.temporaries.end()) {
    const FieldResult& field = *result->field;
    WriteField(it->second, c.settings->String("output.field"), field.mesh, field.geometry, field.field,
               field.frame, "output.field");
  }
  if (const auto it = c.temporaries.find("streamlines"); it != c.temporaries.end()) {
    WriteStreamlinesObj(it->second, c.State<LayoutState>().streamlines.lines, result->field->frame,
                        "output.streamlines");
  }
}

}  // namespace

ProblemDecl conjugate_layout() {
  ProblemDecl d = PlanarQuadsGoals();
  // The field and level-set stages take only the keys the user gave, so they
  // keep their own defaults (Ceres); the PQ step's rounds are LeanSolve's
  // Cholesky steps as planar_quads', never PCG: the field stages on
  // Concerthall have more than 100k variables, and their figures
  // (docs/methods/conjugate_layout.md) were measured with Ceres' direct solve.
  d.defaults.erase("solver.pcg_above");
  // A layout is near planar: no worst-quads stage (relayout: never's, which
  // is not a key here), so not its term or its measure either.
  d.terms.erase(std::remove_if(d.terms.begin(), d.terms.end(),
                               [](const TermUse& t) { return t.term == "pq_worst"; }),
                d.terms.end());
  d.measures.erase(problems::kWorstStagePq);
  std::vector<std::string> planar;
  for (TermUse& t : d.terms) {
    planar.push_back(t.term);
    // A layout from the level sets is near planar and smooth already:
    // planarity starts lower and rises by continuation, fairness relative to
    // the layout is light, and the dihedral energy only keeps E from rising
    // (inspired mesh: max displacement 0.49% of the diagonal, E 87.65 ->
    // 87.07; with planar_quads' weights 0.55% and 82.3, without the dihedral
    // energy 0.27% and E up to 90.8).
    if (t.term == "pq_diagonal" || t.term == "face_planarity") t.weight = 1;
    if (t.term == "fairness") t.weight = 0.1;
    if (t.term == "dihedral_energy") t.weight = 0.05;
    // The layout's edges are the problem's own: validity against the design
    // surface flags every edge under 0.1 of the mean, so none may shrink
    // below that, however short it was made (the margin: the mean edge moves).
    if (t.term == "min_edge_length") t.options["floor"] = 0.12;
  }
  // The layout is the way out relayout offers: not a key here.
  d.keys.erase(std::remove_if(d.keys.begin(), d.keys.end(),
                              [](const Key& k) { return k.name == "relayout"; }),
               d.keys.end());
  d.name = "conjugate_layout";
  d.summary = "design surface (triangles) → TCD field → level sets → layout → planar quads";
  d.paper = "[Zadravec 2010, Fig. 1, §2–6]";
  d.input = InputKind::kAny;  // a polygon mesh: its triangulation (DesignSurface)
  for (TermUse t : FieldTerms()) {
    // Singularity avoidance on where the field is free, with the fallback of
    // WithAvoidance.
    if (t.term == "tcd_singularity_avoidance") t.weight = 1;
    d.terms.push_back(t);
  }
  for (const TermUse& t : LevelSetTerms()) d.terms.push_back(t);
  for (const Key& k : FieldKeys()) d.keys.push_back(k);
  for (const Key& k : LevelSetKeys()) d.keys.push_back(k);
  for (const Key& k : StreamlineKeys()) d.keys.push_back(k);
  d.keys.push_back(LayoutMethodKey());
  const auto stages = d.stages;
  d.stages = [stages, planar](const Settings& s) {
    std::vector<Stage> out = stages(s);
    for (Stage& stage : out) {
      stage.name = "planar";
      stage.terms = planar;
    }
    return out;
  };
  d.check = &CheckLevelSetKeys;
  d.net = &Net;
  d.output_keys = {"layout", "field", "streamlines"};
  d.write = &WriteConjugateLayout;
  // The band about the design surface, reported (details.surface_band, the
  // BAND BINDS line) but not solved again without it: that would lay the
  // surface out again.
  return WithPlanarQuadsBounds(std::move(d), false);
}

}  // namespace archgeo::problems
