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
#include <utility>

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

// layout.method: streamlines — the field's streamlines, their crossings as
// the layout (streamline_layout.h).
void StreamlineNet(HookContext& c, const Mesh& design, int refinements) {
  const Settings& s = *c.settings;
  StreamlineResult lines;
  const std::shared_ptr<const LevelSetResult> result = SolveStreamlineLayout(
      s, design, c.progress, SplitDesignOverrides(s, refinements), &lines);
  UseLayoutAsNet(c, result, "conjugate layout (streamlines)");
  c.net.details["field"] = result->field->details;
  c.net.details["design_surface"] = {{"triangles", design.number_of_faces()},
                                     {"midpoint_splits", refinements}};
  c.State<LayoutState>().streamlines = std::move(lines);
  c.net.headline = result->headline + "solving the layout for planar faces (planar_quads)\n";
}

void Net(HookContext& c) {
  const Settings& s = *c.settings;
  int refinements = 0;
  const Mesh design = DesignSurface(s, *c.input, 0, &refinements);
  if (s.String("layout.method") == "streamlines") {
    StreamlineNet(c, design, refinements);
    return;
  }
  const std::shared_ptr<const LevelSetResult> result =
      SolveLevelSets(s, design, c.progress, SplitDesignOverrides(s, refinements));
  if (!result->layout.ok) {
    throw s.Error("level_sets", "the layout could not be extracted from the level sets: " +
                                    result->layout.error);
  }
  UseLayoutAsNet(c, result, "conjugate layout");
  c.net.details["field"] = result->field->details;
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
  c.net.headline = split + result->field->headline + streamlines + result->headline +
                   "solving the layout for planar faces (planar_quads)\n";
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
  }
  // The layout is the way out relayout offers: not a key here.
  d.keys.erase(std::remove_if(d.keys.begin(), d.keys.end(),
                              [](const Key& k) { return k.name == "relayout"; }),
               d.keys.end());
  d.name = "conjugate_layout";
  d.summary = "design surface (triangles) → TCD field → level sets → layout → planar quads";
  d.paper = "[Zadravec 2010, Fig. 1, §2–6]";
  d.input = InputKind::kAny;  // a polygon mesh: its triangulation (DesignSurface)
  for (const TermUse& t : FieldTerms()) d.terms.push_back(t);
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
