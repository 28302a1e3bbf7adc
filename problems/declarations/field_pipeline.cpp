// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/declarations/field_pipeline.h"

#include <glog/logging.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "core/magnitude.h"
#include "core/input_error.h"
#include "fields/field_io.h"
#include "geometry/reference.h"
#include "io/io.h"
#include "mesh/subdivision.h"
#include "problems/declarations/registry.h"
#include "problems/spec/schema.h"
#include "problems/runtime/solve.h"

namespace archgeo {
namespace {

bool StartsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// The parent's run keys, which a nested stage does not take over.
bool RunKey(const std::string& name) {
  return name == "problem" || name == "reference" || name == "fixed" ||
         StartsWith(name, "schedule.") || StartsWith(name, "multiresolution.") ||
         StartsWith(name, "output.");
}

// The nested solve of `problem` on `mesh` with the keys of `parent` and then
// `overrides`; throws InputError when it has no usable solution.
std::unique_ptr<Solution> Nested(const char* problem, const Settings& parent, const Mesh& mesh,
                                 const ProgressSink& progress,
                                 const std::map<std::string, Value>& overrides = {}) {
  const ProblemDecl* d = FindProblem(problem);
  CHECK(d) << problem << " is not registered";
  ProblemSpec spec = SubSpec(*d, parent);
  for (const auto& [name, value] : overrides) {
    CHECK(spec.settings.schema().Find(name)) << problem << " has no key " << name;
    spec.settings.Set(name, value, Origin{parent.spec_file(), 0});
  }
  std::unique_ptr<Solution> solution =
      Solve(spec, mesh, nullptr, Prefixed(progress, std::string(problem) + ": "));
  if (!solution->loop.usable) {
    throw InputError(parent.spec_file(), 0, "",
                     std::string("the ") + problem + " stage found no usable solution: " +
                         solution->loop.message);
  }
  return solution;
}

}  // namespace

std::vector<TermUse> FieldTerms() {
  return {{"tcd_dirichlet", 1},
          {"tcd_transversality", 0.1},
          {"tcd_singularity_avoidance", 0, {}, "tcd_free_faces"},
          {"tcd_singularity_placement", 100},
          {"tcd_prescribed_direction", 100},
          {"principal_fit", 1},
          {"principal_smoothing", 1}};
}

std::vector<Key> FieldKeys() {
  Key singularities;
  singularities.name = "field.singularities";
  singularities.type = Type::kIntegers;
  singularities.fallback = std::vector<long long>{};
  singularities.lo = 0;
  singularities.doc =
      "faces (0-based ids) where a singularity is placed: z_N = z_M there (faces with K > 0)";
  const Key directions = CustomKey(
      "field.directions", "[{face: 0, direction: [1, 0, 0]}]",
      "prescribed conjugate directions: a list of {face: id, direction: [x, y, z]} (file units; "
      "projected onto the face)");
  const Key moves = CustomKey(
      "field.moves", "[{from: 120, to: 180}]",
      "singularities moved locally after the solve [Zadravec 2010, §4, eq. 4]: a list of "
      "{from: face, to: face, inner_radius: r1, outer_radius: r2} (file units; the σ blend is 1 "
      "within r1 of `from` and 0 beyond r2; defaults r1 = 2 × the distance from `from` to `to`, "
      "r2 = 2 r1); z_N = z_M at `to`, then the faces of the transition band (r1 to r2) are "
      "re-optimised");
  const Key rotations = CustomKey(
      "field.rotations", "[{at: [0, 0, 1], radius: 2, angle: 30}]",
      "local rotations of the field (thesis §8.1.1): a list of {at: [x, y, z], radius: r, angle: "
      "degrees} (file units; |angle| < 90); after the free field, the faces within r of the face "
      "nearest `at` are re-solved with the free field turned by the angle at the centre, tapering to "
      "0 at r (every other face held, as for guide curves; weight field.guide_weight)");
  const Key sources = CustomKey(
      "field.sources", "[{at: [0, 0, 1], strength: 1}]",
      "a potential field's gradient as the whole field (thesis §8.1.1): a list of {at: [x, y, z], "
      "strength: s} (file units; s > 0 a source, s < 0 a sink); φ = Σ s log|x − at|, each face's "
      "direction ∇φ prescribed as one direction of its pair (like field.file; not with it)");
  const Key file = PathKey(
      "field.file", Type::kInputPath,
      "a complete field: Directional's raw field (.rawfield: \"N F\", then per face N vectors, file "
      "units, N = 1, 2 or 4; what output.field writes as .rawfield), one row per face; each "
      "face's first vector is prescribed as one direction of the pair (like field.directions)");
  const Key constraints = PathKey(
      "field.constraints", Type::kInputPath,
      "libigl DMAT file, one row per face: column 0 ≠ 0 marks a face whose prescribed "
      "direction is columns 1–3 (file units); further columns are not used");
  return {IntegerKey("jets.degree", 4, 2, 4,
                     "degree of the osculating jets fitted at every vertex (curvature)"),
          IntegerKey("jets.rings", 2, 1, 8,
                     "jet neighbourhood: vertices within this many edges (grown until it has "
                     "twice the jet's coefficients)"),
          singularities,
          moves,
          directions,
          constraints,
          file,
          rotations,
          sources,
          NumberKey("field.boundary_alignment", 1, 0, 1e6,
                    "weight of the boundary tangent as a prescribed direction of every boundary "
                    "face (through tcd_prescribed_direction, which must be on): level sets along "
                    "the boundary, fewer cut boundary faces; 0 = off"),
          PathKey("field.guide_curves", Type::kInputPath,
                  "OBJ polylines ('l' records, file units) on or near the surface: after the free "
                  "field is solved, a second stage re-solves the faces within field.guide_radius "
                  "of a curve (every other face held) with one direction following the curve's "
                  "tangent (weight field.guide_weight, smoothly weaker from half the radius out to "
                  "the radius); not with field.moves"),
          NumberKey("field.guide_radius", 0.1, 1e-6, 1,
                    "reach of the guide curves, relative to the bounding-box diagonal"),
          NumberKey("field.guide_weight", 10000, 0, 1e8,
                    "weight of a guide curve's direction at full strength, on the scale of "
                    "terms.tcd_prescribed_direction's weight (field.directions: 100); 100 times "
                    "that, so the field near a curve follows it within 2° against the smoothing "
                    "that pulls it back to the free field held beyond the radius"),
          BoolKey("field.preprocess", false,
                  "pre-process the principal field before the TCD field is built on it [Gebreiter "
                  "2012, §8.1.4]: the directions of unreliable faces (near-umbilic, near-flat) are "
                  "propagated from the reliable ones, then the whole line field is smoothed "
                  "(principal_fit, principal_smoothing; stage `principal`) and every face's "
                  "curvature takes the smoothed directions with its measured principal curvatures "
                  "(fields/principal_field.h)"),
          NumberKey("field.unreliable_anisotropy", 0.2, 0, 1,
                    "with field.preprocess, a face whose anisotropy (κ1 − κ2)/(|κ1| + |κ2|) is below "
                    "this is unreliable (near-umbilic; 0 at an umbilic, 1 where K ≤ 0)"),
          NumberKey("field.unreliable_flat", 0.1, 0, 1,
                    "with field.preprocess, a face whose curvature (|κ1| + |κ2|)/2 is below this "
                    "fraction of the median face's is unreliable (near-flat)"),
          NumberKey("field.smoothing", 0.5, 0, 1,
                    "with field.preprocess, ρ of the thesis' R = (1 − ρ) fit + ρ smoothing: 0 "
                    "keeps the measured directions of the reliable faces (propagation only), 1 "
                    "smooths without regard to them"),
          IntegerKey("field.rounds", 1, 1, 100,
                     "Ceres solves of the field (each at most solver.max_num_iterations)")};
}

std::vector<TermUse> LevelSetTerms() {
  return {{"level_set_alignment", 1},
          {"level_set_normalised", 1},
          {"level_set_conjugacy", 1},
          {"level_set_jump", 100},
          {"level_set_branch_point", 100},
          {"level_set_boundary", 100}};
}

std::vector<Key> LevelSetKeys() {
  // The field.* keys first: they follow FieldKeys() in every problem that has
  // both, and a spec template writes each section once.
  return {NumberKey("field.cancel_pairs", 2, 0, 1e3,
                    "singularities of opposite index (+k, −k) closer than this many level-set "
                    "spacings are cancelled before the level sets by re-solving the field's "
                    "difference z_N − z_M around the pair as a harmonic extension of its values "
                    "around (fields/pair_cancellation.h; the rest of the field unchanged); a "
                    "pair is kept when that would create or move another singularity; 0 = off"),
          NumberKey("field.cancel_region", 1.5, 0.5, 20,
                    "radius of the region re-solved around a pair, in the pair's distances "
                    "(tried at 1/3, 2/3, 1 and 2 times this, the smallest that cancels the pair)"),
          NumberKey("field.boundary_push", 0, 0, 1e3,
                    "a singularity closer than this many level-set spacings to the boundary "
                    "(after field.cancel_pairs) is pushed out of the domain by the same surgery, "
                    "the field free along the boundary [Gebreiter 2012, §8.1.1]; kept when that "
                    "would change any other singularity; 0 = off"),
          IntegerKey("level_sets.target_faces", 1600, 1, 100000000,
                     "faces the layout should have: the spacing is Δw = sqrt(Σ_f A_f sin∠(v, w) "
                     "/ target_faces)"),
          NumberKey("level_sets.edge_length", 0, 0, kMaxCoordinate,
                    "the spacing Δw of the level sets in file units (the layout's edge length) "
                    "instead of target_faces; 0 = from target_faces"),
          ChoiceKey("level_sets.rounding", "even", {"even", "odd"},
                    "jumps across cuts from ±1/2 singularities rounded to even multiples of Δw "
                    "(quads around the singularity) or odd ones (valence-4 vertices and an "
                    "extraordinary face)"),
          BoolKey("level_sets.boundary_rows", false,
                  "one family of layout lines runs along the boundary of an open surface "
                  "(fields/boundary_rows.h): the field follows the boundary tangent "
                  "(level_sets.boundary_rows_alignment), and on each boundary run (cut where the "
                  "family along the boundary changes: corners, asymptotic tangents) the function "
                  "whose level sets follow it is kept equal along it (level_set_boundary) and, "
                  "for the last solve, held on a level, a multiple of its spacing; the boundary "
                  "faces become quads with an edge on the boundary. Off by default: on, it takes "
                  "Concerthall from exit 0 to exit 4 (docs/results.md, boundary rows)"),
          NumberKey("level_sets.boundary_rows_alignment", 10000, 0, 1e8,
                    "with level_sets.boundary_rows, the weight of the boundary tangent in the "
                    "field (field.boundary_alignment's scale; the larger of the two is used): "
                    "one direction of every boundary face runs along the boundary, so that the "
                    "held level follows the field"),
          NumberKey("level_sets.boundary_rows_max_shift", 2, 0, 1e6,
                    "with level_sets.boundary_rows, a boundary run is held on a level only if "
                    "no value moves by more than this many spacings from the level sets solved "
                    "without it (else the level sets do not follow the boundary there and "
                    "holding it would bend the rows beside it; the run is left free and counted)"),
          NumberKey("level_sets.size_reach", 3, 0, 1e6,
                    "curl correction of the level sets' sizes (thesis §8.1.4): log sizes per "
                    "vertex that make the field scaled by them curl-free, held to the spacing over "
                    "about this many spacings, scale eq. 5's target (even panels that vary "
                    "smoothly where the field has curl); 0 = off"),
          NumberKey("level_sets.size_ratio_max", 2, 1.01, 100,
                    "with size_reach: each family's spacing held between 1/ratio and ratio "
                    "times the spacing asked for (cell areas within ratio^±2)"),
          IntegerKey("level_sets.rounds", 1, 1, 100,
                     "Ceres solves per stage (eq. 5; eq. 6; with the jumps fixed)"),
          NumberKey("extraction.merge_fraction", 0.05, 0, 0.5,
                    "layout vertices joined by an edge shorter than this fraction of the median "
                    "edge are merged"),
          NumberKey("extraction.boundary_snap", 0.35, 0, 0.5,
                    "a layout vertex joined to a boundary vertex by an edge shorter than this "
                    "fraction of the median edge is moved onto it (fewer cut-off boundary "
                    "triangles) and a boundary edge shorter than half of it is collapsed (no "
                    "sliver sides); 0 = off"),
          BoolKey("extraction.merge_valence_two", true,
                  "an interior layout vertex on two faces only (a +1/2 singularity on a level "
                  "of both functions) is removed by merging its two faces (two quads give a "
                  "quad); off: it stays, with two corners of about 180°"),
          NumberKey("extraction.cap_angle", 160, 0, 180,
                    "an interior layout triangle with a corner above this (degrees: its vertices "
                    "nearly on a line, e.g. between two singularities closer than the spacing) "
                    "is merged into the face across its longest side; 0 = off"),
          NumberKey("extraction.slit_angle", 3, 0, 90,
                    "a layout corner whose two sides leave within this angle (degrees: two level "
                    "lines side by side from a singular vertex) leaves its face, the longer side "
                    "split at the shorter side's end in the face across (no hairline face to fold "
                    "over); 0 = off"),
          NumberKey("extraction.reflex_margin", 2, -1, 180,
                    "a layout face bent inward at an interior vertex by more than this (degrees "
                    "beyond 180°) is split along a diagonal from that corner into two convex-cornered "
                    "faces (the PQ step cannot make it planar without folding it further); -1 = off"),
          NumberKey("extraction.corner_angle", 30, 0, 180,
                    "boundary vertices where the boundary turns by more than this (degrees) are "
                    "kept as corners of the layout")};
}

std::vector<Key> StreamlineKeys() {
  return {NumberKey("streamlines.separation", 0.03, 0.002, 1,
                    "streamline separation d_sep as a fraction of the diagonal of the design "
                    "surface's bounding box along its principal axes (output.streamlines; "
                    "Jobard-Lefer seeding)"),
          NumberKey("streamlines.test_ratio", 0.5, 0.05, 1,
                    "a streamline stops closer than d_test = test_ratio × d_sep to a line of "
                    "its family (or to itself)"),
          NumberKey("streamlines.step", 0.1, 0.01, 1,
                    "RK4 step of the streamlines as a fraction of d_sep (a step is also cut at "
                    "every triangle edge it crosses)"),
          BoolKey("streamlines.separatrices", true,
                  "trace the separatrices of every singularity (its radial directions, "
                  "2|1 - index| per family) before the streamlines")};
}

EdgeFieldAngle LayoutFieldAngle(const FieldResult& field, const Mesh& layout) {
  std::vector<Eigen::Vector3d> points;
  std::vector<std::vector<int>> faces;
  for (VertexIndex v : layout.vertices()) {
    const Point& p = layout.point(v);
    points.emplace_back(p.x(), p.y(), p.z());
  }
  for (FaceIndex f : layout.faces()) {
    std::vector<int> face;
    for (VertexIndex v : CGAL::vertices_around_face(layout.halfedge(f), layout)) face.push_back(int(v.idx()));
    faces.push_back(face);
  }
  return MeasureEdgeFieldAngle(StreamlineInputOf(field.mesh, field.geometry, field.field), points,
                               faces);
}

ExtractOptions ExtractOptionsOf(const Settings& s) {
  ExtractOptions options;
  options.merge_fraction = s.Number("extraction.merge_fraction");
  options.corner_angle_deg = s.Number("extraction.corner_angle");
  options.boundary_snap_fraction = s.Number("extraction.boundary_snap");
  options.merge_valence_two = s.Bool("extraction.merge_valence_two");
  options.cap_angle_deg = s.Number("extraction.cap_angle");
  options.slit_angle_deg = s.Number("extraction.slit_angle");
  options.reflex_margin_deg = s.Number("extraction.reflex_margin");
  return options;
}

StreamlineResult FieldStreamlines(const Settings& s, const FieldResult& field,
                                  nlohmann::json* details, std::string* headline) {
  if (!s.schema().Find("output.streamlines") || s.String("output.streamlines").empty()) return {};
  const StreamlineInput input = StreamlineInputOf(field.mesh, field.geometry, field.field);
  StreamlineOptions o;
  o.separation = s.Number("streamlines.separation") * PrincipalBoxDiagonal(field.mesh);
  o.test_ratio = s.Number("streamlines.test_ratio");
  o.step = s.Number("streamlines.step");
  o.separatrices = s.Bool("streamlines.separatrices");
  StreamlineResult r = TraceStreamlines(input, o);
  const double unit = field.frame.scale;  // canonical -> file units
  int count[3] = {0, 0, 0};
  double length = 0;
  for (const Streamline& l : r.lines) {
    ++count[l.separatrix ? 2 : l.family];
    length += l.length;
  }
  const double separation = SmallestSeparation(r.lines, r.d_sep);
  const double self = SmallestSelfDistance(r.lines, 3 * r.d_test, r.d_sep);
  nlohmann::json singular = nlohmann::json::array();
  int unexpected = 0;
  for (size_t j = 0; j < input.singularities.size(); ++j) {
    const int expected = ExpectedSeparatrices(input.singularities[j].index);
    const auto& found = r.separatrix_directions[j];
    if (expected >= 0 && (found[0] != expected || found[1] != expected)) ++unexpected;
    singular.push_back({{"vertex", input.singularities[j].vertex},
                        {"index", input.singularities[j].index},
                        {"directions_v", found[0]},
                        {"directions_w", found[1]},
                        {"expected", expected}});
  }
  // Distances beyond the measuring radius (d_sep) are reported as null.
  auto finite = [&](double x) -> nlohmann::json {
    return std::isfinite(x) ? nlohmann::json(x * unit) : nlohmann::json(nullptr);
  };
  (*details)["streamlines"] = {
      {"d_sep", r.d_sep * unit},
      {"d_test", r.d_test * unit},
      {"lines_v", count[0]},
      {"lines_w", count[1]},
      {"separatrices", count[2]},
      {"total_length", length * unit},
      {"closed", std::count_if(r.lines.begin(), r.lines.end(),
                               [](const Streamline& l) { return l.closed; })},
      {"smallest_separation", finite(separation)},
      {"smallest_separation_over_d_sep", std::isfinite(separation) ? nlohmann::json(separation / r.d_sep)
                                                                   : nlohmann::json(nullptr)},
      {"smallest_self_distance", finite(self)},
      {"singularities", singular},
      {"singularities_with_unexpected_separatrices", unexpected}};
  char line[400];
  std::snprintf(line, sizeof line,
                "streamlines: d_sep %.4g, %d v-lines, %d w-lines, %d separatrices, total length "
                "%.4g; smallest same-family separation %s d_sep\n",
                r.d_sep * unit, count[0], count[1], count[2], length * unit,
                std::isfinite(separation) ? std::to_string(separation / r.d_sep).c_str() : "> 1");
  *headline += line;
  return r;
}

void CheckLevelSetKeys(const Settings& s) {
  CheckFieldOutputs(s);
  if (s.Given("level_sets.target_faces") && s.Given("level_sets.edge_length") &&
      s.Number("level_sets.edge_length") > 0) {
    throw s.Error("level_sets.edge_length",
                  "give either level_sets.target_faces or level_sets.edge_length, not both");
  }
  // Eq. 5 is what gives g and h their slope (eq. 6 and 7 are invariant to
  // scaling g and h): without it both stay constant and there is no layout.
  if (!(s.Number("terms.level_set_alignment.weight") > 0)) {
    throw s.Error("terms.level_set_alignment",
                  "level_sets needs level_set_alignment (eq. 5) with a weight > 0: it sets the "
                  "spacing of the level sets; a `terms:` section that does not list it turns it off");
  }
}

void CheckFieldOutputs(const Settings& s) {
  if (s.schema().Find("output.layout") && !s.String("output.layout").empty()) {
    try {
      CheckMeshExtension(s.String("output.layout"));
    } catch (const InputError& e) {
      throw s.Error("output.layout", "'" + s.String("output.layout") + "': " + e.message());
    }
  }
  if (s.schema().Find("output.streamlines") && !s.String("output.streamlines").empty()) {
    const std::string& path = s.String("output.streamlines");
    std::string extension = path.size() >= 4 ? path.substr(path.size() - 4) : "";
    for (char& ch : extension) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    if (extension != ".obj") {
      throw s.Error("output.streamlines",
                    "'" + path + "': the streamlines are written as OBJ polylines (.obj)");
    }
  }
  if (s.schema().Find("output.field") && !s.String("output.field").empty()) {
    const std::string& path = s.String("output.field");
    std::string extension = path.size() >= 4 ? path.substr(path.size() - 4) : "";
    for (char& ch : extension) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    const bool raw = path.size() >= 9 && [&] {
      std::string end = path.substr(path.size() - 9);
      for (char& ch : end) ch = char(std::tolower(static_cast<unsigned char>(ch)));
      return end == ".rawfield";
    }();
    if (extension != ".ply" && !raw) {
      throw s.Error("output.field", "'" + path + "': the field is written as PLY (.ply, to view) or as "
                                    "Directional's raw field (.rawfield, to read back with field.file)");
    }
  }
}

void CheckNoMultiresolution(const Settings& s, const std::string& problem) {
  if (s.Integer("multiresolution.levels") > 0) {
    throw s.Error("multiresolution.levels",
                  problem + " computes its field on the input mesh: multiresolution is not "
                            "supported");
  }
}

ProblemSpec SubSpec(const ProblemDecl& sub, const Settings& parent) {
  ProblemSpec spec;
  spec.spec_path = parent.spec_file();
  spec.declaration = std::shared_ptr<const ProblemDecl>(&sub, [](const ProblemDecl*) {});
  spec.settings = Settings(ProblemSchema(sub));
  spec.settings.set_spec_file(parent.spec_file());
  // Only what the user gave: the stages declare their keys once (same
  // defaults), and Settings::Given must stay true only for given keys.
  for (const Key& k : spec.settings.schema().keys()) {
    if (RunKey(k.name) || !parent.schema().Find(k.name) || !parent.Given(k.name)) continue;
    if (k.type == Type::kCustom) {
      const CustomValue* value = parent.Custom(k.name);
      CHECK(value) << k.name << " is given without its value";
      spec.settings.SetCustom(k.name, *value, parent.Where(k.name));
    } else {
      spec.settings.Set(k.name, parent.Get(k.name), parent.Where(k.name));
    }
  }
  return spec;
}

std::shared_ptr<const FieldResult> SolveField(const Settings& parent, const Mesh& mesh,
                                              const ProgressSink& progress,
                                              const std::map<std::string, Value>& overrides) {
  std::shared_ptr<const FieldResult> field =
      Nested("conjugate_field", parent, mesh, progress, overrides)->hooks.field;
  CHECK(field) << "conjugate_field left no field";
  return field;
}

std::shared_ptr<const LevelSetResult> SolveLevelSets(const Settings& parent, const Mesh& mesh,
                                                     const ProgressSink& progress,
                                                     const std::map<std::string, Value>& overrides) {
  std::shared_ptr<const LevelSetResult> level_sets =
      Nested("level_sets", parent, mesh, progress, overrides)->hooks.level_sets;
  CHECK(level_sets) << "level_sets left no level sets";
  return level_sets;
}

namespace {

// Whether the field key `key` names faces: given, and not an empty list or
// path (`archgeo spec` writes `singularities: []`).
bool NamesFaces(const Settings& s, const std::string& key) {
  if (!s.schema().Find(key) || !s.Given(key)) return false;
  const nlohmann::json all = s.SectionJson("field");
  const std::string name = key.substr(std::string("field.").size());
  if (!all.contains(name)) return true;
  const nlohmann::json& value = all[name];
  return !(value.is_null() || (value.is_array() && value.empty()) ||
           (value.is_string() && value.get<std::string>().empty()));
}

// Triangles of the design surface per face of the layout at least: the
// level-set functions are linear on each triangle, so a layout finer than
// the triangles has lines that bend at every triangle edge and quads far
// from planar (a 1024-triangle torus at 1600 faces: δ_PQ,n mean 6.4e-3
// against 2.1e-3 on the same surface split once, and 218 solver
// iterations of the planar step against 21).
constexpr double kTrianglesPerLayoutFace = 2;
// A design of fewer triangles is not split: it holds too little of a
// surface to be laid out finer than itself (a closed tetrahedron's level
// sets cut out no face, an input error; split, they cut a layout of its
// flat faces that the planar step cannot resolve in minutes).
constexpr int kFewestTrianglesToSplit = 100;

// The layout's face count asked for: `faces` if given, else
// level_sets.target_faces, or with level_sets.edge_length the design's area
// over the squared spacing (areas in units of the spacing: no square of
// file units).
double LayoutFacesAskedFor(const Settings& s, const Mesh& triangles, long long faces) {
  if (faces > 0) return double(faces);
  const double spacing = s.Number("level_sets.edge_length");
  if (!(spacing > 0)) return double(s.Integer("level_sets.target_faces"));
  double area = 0;
  for (FaceIndex f : triangles.faces()) {
    const HalfedgeIndex h = triangles.halfedge(f);
    const Point& o = triangles.point(triangles.source(h));
    const Vector a = (triangles.point(triangles.target(h)) - o) / spacing;
    const Vector b = (triangles.point(triangles.target(triangles.next(h))) - o) / spacing;
    area += 0.5 * std::sqrt(CGAL::cross_product(a, b).squared_length());
  }
  return area;
}

bool NamesDesignFaces(const Settings& s) {
  for (const char* key : {"field.singularities", "field.moves", "field.directions",
                          "field.constraints", "field.file"}) {
    if (NamesFaces(s, key)) return true;
  }
  return false;
}

}  // namespace

Mesh DesignSurface(const Settings& parent, const Mesh& mesh, long long layout_faces,
                   int* refinements) {
  bool triangles = true;
  for (FaceIndex f : mesh.faces()) triangles = triangles && mesh.degree(f) == 3;
  if (!triangles) {
    for (const char* key : {"field.singularities", "field.moves", "field.directions",
                            "field.constraints", "field.file"}) {
      if (NamesFaces(parent, key)) {
        throw parent.Error(key, "names faces of a triangle mesh, but the mesh has polygons (its "
                                "triangulation is the design surface): give the design surface "
                                "as a triangle mesh to use this key");
      }
    }
  }
  Mesh design = triangles ? mesh : TriangulatedCopy(mesh);
  int split = 0;
  if (!NamesDesignFaces(parent) && int(design.number_of_faces()) >= kFewestTrianglesToSplit) {
    const double wanted = kTrianglesPerLayoutFace * LayoutFacesAskedFor(parent, design, layout_faces);
    const double most = double(parent.Integer("limits.max_subdivided_faces"));
    while (double(design.number_of_faces()) < wanted &&
           4.0 * double(design.number_of_faces()) <= most) {
      design = MidpointSubdivision(design);
      ++split;
    }
  }
  if (refinements) *refinements = split;
  return design;
}

std::map<std::string, Value> SplitDesignOverrides(const Settings& parent, int refinements) {
  if (refinements <= 0) return {};
  const long long rings = parent.Integer("jets.rings") << refinements;
  return {{"jets.rings", std::min(rings, 8LL)}};
}

Mesh InFileUnits(const Mesh& mesh, const Similarity& frame) {
  Mesh out = mesh;
  FromCanonical(frame, out);
  return out;
}

ProgressSink Prefixed(const ProgressSink& progress, const std::string& prefix) {
  if (!progress) return progress;
  return [progress, prefix](const ProgressEvent& event) {
    ProgressEvent prefixed = event;
    prefixed.line = prefix + event.line;
    // The stage as "conjugate_field" or "level_sets relax" (the prefix's name).
    const std::string name = prefix.substr(0, prefix.find(':'));
    prefixed.stage = event.stage.empty() ? name : name + " " + event.stage;
    progress(prefixed);
  };
}

}  // namespace archgeo
