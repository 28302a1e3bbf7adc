// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — what the three problems of the design-surface-to-layout pipeline
// [Zadravec 2010, Fig. 1] share: conjugate_field (a TCD field on a triangle
// mesh, §2–4), level_sets (two functions whose level sets follow the field and
// the quad-dominant layout they cut out, §5) and conjugate_layout (field →
// level sets → layout → planar_quads, §6).
//
// A later stage runs the earlier ones as nested solves (problems/runtime/solve.h
// Solve) on specs made from its own settings (SubSpec): every key the stages
// share is declared once here (FieldKeys, LevelSetKeys) and carried over with
// the place it was given, so a bad value is reported at its line in the
// user's spec whichever stage reads it.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/loop.h"
#include "core/problem.h"
#include "core/settings.h"
#include "fields/cuts.h"
#include "fields/extract.h"
#include "fields/streamline_mesh.h"
#include "fields/streamlines.h"
#include "fields/tcd_field.h"
#include "mesh/similarity.h"
#include "mesh/surface_mesh.h"
#include "problems/spec/spec.h"

namespace archgeo {

namespace problems {
ProblemDecl planar_quads();
// planar_quads without its relayout suggestion, flatness key and deviation
// band, which WithPlanarQuadsBounds adds (measure_need: when the band binds,
// solve again without it and report the deviation that needs).
ProblemDecl PlanarQuadsGoals();
ProblemDecl WithPlanarQuadsBounds(ProblemDecl d, bool measure_need);
ProblemDecl conjugate_field();
ProblemDecl level_sets();
}  // namespace problems

// The field stage's terms (with their default weights) and keys.
std::vector<TermUse> FieldTerms();
std::vector<Key> FieldKeys();
// The level-set stage's terms and keys (extraction included).
std::vector<TermUse> LevelSetTerms();
std::vector<Key> LevelSetKeys();
// The extraction.* keys of `s` as options of the clean-up (fields/extract.h).
ExtractOptions ExtractOptionsOf(const Settings& s);
// The streamline keys (streamlines.*: fields/streamlines.h) of conjugate_field
// and conjugate_layout.
std::vector<Key> StreamlineKeys();
// Cross-key checks of the level-set keys (ProblemDecl::check), including
// CheckFieldOutputs.
void CheckLevelSetKeys(const Settings& s);
// output.layout is a mesh file name (.obj, .off, .ply), output.field a .ply,
// output.streamlines an .obj.
void CheckFieldOutputs(const Settings& s);
// Refuses multiresolution for the field stages (the field lives on the input).
void CheckNoMultiresolution(const Settings& s, const std::string& problem);

// A spec of `sub` whose keys take the parent's values (and where they were
// given) for every key both declare that the user gave, except the parent's
// own run keys: problem, reference, fixed, schedule.*, multiresolution.* and
// output.* (solver.* keys apply to every stage).
ProblemSpec SubSpec(const ProblemDecl& sub, const Settings& parent);

// The field of a conjugate_field solve, canonical frame of its input.
struct FieldResult {
  Mesh mesh;                                // the triangle mesh, canonical frame
  FieldGeometry geometry;
  TcdField field;
  Similarity frame;                         // file units -> canonical
  nlohmann::json details = nlohmann::json::object();
  std::string headline;
};

// The mean and largest angle between the interior edges of `layout`
// (canonical frame, as the field's mesh) and the field
// (fields/streamline_mesh.h MeasureEdgeFieldAngle): the same figure for
// either layout.method.
EdgeFieldAngle LayoutFieldAngle(const FieldResult& field, const Mesh& layout);

// The level sets and the layout of a level_sets solve (canonical frame).
struct LevelSetResult {
  std::shared_ptr<const FieldResult> field;
  CutGraph cut;
  LevelSetFunctions functions;  // functions.cut points to `cut`
  Extraction layout;            // canonical frame
  Similarity frame;
  nlohmann::json details = nlohmann::json::object();
  std::string headline;
};

// The streamlines of `field` with the streamlines.* keys of `s` when
// output.streamlines is given (else nothing is traced and the result is
// empty): d_sep = streamlines.separation × the diagonal of the bounding box
// of the field's mesh along its principal axes (PrincipalBoxDiagonal). Adds
// the counts and the separations measured on the lines to `details`
// ("streamlines") and a line to `headline`.
StreamlineResult FieldStreamlines(const Settings& s, const FieldResult& field,
                                  nlohmann::json* details, std::string* headline);

// Nested solves: conjugate_field / level_sets on `mesh` (file units) with the
// keys of `parent` (and then `overrides`, keys of level_sets). Throw
// InputError as the stages do.
std::shared_ptr<const FieldResult> SolveField(const Settings& parent, const Mesh& mesh,
                                              const ProgressSink& progress,
                                              const std::map<std::string, Value>& overrides = {});
std::shared_ptr<const LevelSetResult> SolveLevelSets(
    const Settings& parent, const Mesh& mesh, const ProgressSink& progress,
    const std::map<std::string, Value>& overrides = {});

// The design surface a layout is computed on: `mesh` itself if it is a
// triangle mesh, else its triangulation with the same vertices
// (geometry/reference.h TriangulatedCopy: CGAL's rule for each quad's
// diagonal, CGAL's triangulate_faces for other polygons).
// Keys that name faces (field.singularities, .moves, .directions,
// .constraints) refer to a triangle mesh: with polygons they are refused
// (InputError on the key). Without them, a design surface of at least 100
// triangles but fewer than two per face of the layout asked for (`layout_faces`, or 0:
// level_sets.target_faces or the count level_sets.edge_length gives) has
// its triangles split at their edge midpoints (mesh/subdivision.h
// MidpointSubdivision: the same surface) until it has, within
// limits.max_subdivided_faces: the level-set functions are linear on each
// triangle, and a layout finer than them bends its lines at every triangle
// edge. `refinements` (if not null) receives the number of splits.
Mesh DesignSurface(const Settings& parent, const Mesh& mesh, long long layout_faces = 0,
                   int* refinements = nullptr);

// What SolveLevelSets needs on a design surface split `refinements` times:
// jets.rings doubled per split (at most 8), so that each vertex's jet covers
// as much of the surface as before the split (inside a flat triangle a
// 2-ring of the split mesh sees a plane).
std::map<std::string, Value> SplitDesignOverrides(const Settings& parent, int refinements);

// `mesh` (canonical frame) in file units.
Mesh InFileUnits(const Mesh& mesh, const Similarity& frame);

// A progress sink that prefixes every line with `prefix`.
ProgressSink Prefixed(const ProgressSink& progress, const std::string& prefix);

}  // namespace archgeo
