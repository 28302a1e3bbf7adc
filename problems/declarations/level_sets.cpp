// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `level_sets`: two functions g, h on a triangle mesh whose level
// sets follow a TCD field, and the quad-dominant layout they cut out
// [Zadravec 2010, §5].
//
// The field: a nested conjugate_field solve with this spec's field keys
// (problems/declarations/field_pipeline.h). Its pair (v, w) per face, oriented
// consistently on the surface cut open (fields/cut_jumps.h OrientPair), is
// the target of g (level sets along v) and h (along w); faces without a pair
// (flat or exactly singular) get the Dirichlet energy instead. Both are
// oriented from the bisector of the pair (fields/cut_jumps.h OrientPair), so
// their matchings across the cuts agree with the singularities' indices.
//
// Cuts (fields/cuts.h): from every singularity to the boundary or an earlier
// cut, plus cuts that make the surface simply connected. g and h are one
// value per wedge (global blocks level_set_g, level_set_h, length units,
// output); across cut chain C, g_left = α_C + s_C g_right with the matching
// s_C = ±1 of the field and α_C a variable (level_set_alpha_g, _h). One value
// of g and one of h is held constant (the functions are defined up to a
// constant).
//
// Stages (½ Σ w r², canonical frame):
//  eq5      level_set_alignment (eq. 5, unit v: even spacing Δw between the
//           levels) with the jumps (level_set_jump, level_set_branch_point);
//  eq6      from there, level_set_normalised (eq. 6: only the direction of
//           ∇g) with level_set_alignment keeping the spacing (the
//           curl-corrected one, level_sets.size_reach), level_set_conjugacy (eq. 7: conjugacy of the level sets
//           through M_f, weight 1) and the jumps;
//  rounded  the jump constants rounded (fields/cut_jumps.h RoundJumps): chains
//           from ±1/2 singularities to even (level_sets.rounding: even; quads
//           around the singularity) or odd multiples of Δw (valence-4
//           vertices and an extraordinary face), the others to multiples,
//           consistently at cut junctions; then held constant for a last
//           solve of the eq6 terms.
// λ_even: the paper adds λ_even Σ‖∇h‖² to eq. 7 for even spacing; here
// level_set_alignment plays that part (with the field's unit v it asks
// ‖∇g‖ = 1, i.e. spacing Δw; where the field is undefined it is exactly the
// Dirichlet term).
//
// Spacing Δw (the same for g and h): level_sets.edge_length (file units), or
// from level_sets.target_faces: Δw = sqrt(Σ_f A_f sin∠(v_f, w_f) / target),
// since a cell between consecutive levels has area Δw² / sin∠(v, w).
//
// The layout (fields/extract.h): vertices where levels g = iΔw and h = jΔw
// cross, faces the cells between, clipped at the boundary. Reported: its
// faces by degree and vertex valences, whether every singularity of the field
// became an irregular vertex or face (within 1.5 Δw), its distance to the
// input surface (vertices and symmetric Hausdorff distance, relative to the
// bounding-box diagonal), its δ_PQ,n, and the mean angle between ∇g and R v
// (and ∇h, R w). Outputs: output.layout (the layout), output.field.
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>

#include "core/clock.h"
#include "core/problem.h"
#include "energies/level_set_elements.h"
#include "energies/level_set_gradient.h"
#include "fields/boundary_rows.h"
#include "fields/cut_jumps.h"
#include "fields/field_io.h"
#include "fields/level_set_sizes.h"
#include "fields/pair_cancellation.h"
#include "io/io.h"
#include "analysis/metrics.h"
#include "geometry/reference.h"
#include "mesh/similarity.h"
#include "problems/declarations/field_pipeline.h"
#include "problems/runtime/model.h"

namespace archgeo::problems {
namespace {

namespace ld = level_set_data;
using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

constexpr double kSingularityReach = 1.5;  // local spacings

struct LevelSetState : ProblemState {
  std::shared_ptr<const FieldResult> field;
  CutGraph cut;
  FieldOrientation ov, ow;
  std::vector<V2> v, w;  // oriented; (0, 0) where the field is undefined
  double spacing = 1;                   // Δw asked for (canonical frame)
  double spacing_g = 1, spacing_h = 1;  // the levels' spacings (see Round)
  bool rounded = false;
  bool rounding_ok = true;
  BoundaryRows boundary_rows;  // level_sets.boundary_rows (Round)
  LevelSetSizes sizes;         // level_sets.size_reach (fields/level_set_sizes.h)
  std::string rounding_message;
  double field_seconds = 0;         // the field's nested solve and its pair cancellation
  Clock::time_point solve_start;    // the level sets' own rounds start (end of InitLevelSets)
};

LevelSetState& St(HookContext& c) { return c.State<LevelSetState>(); }

BlockDecl Values(const char* name, const char* doc) {
  return {name, Site::kVertex, 1, FrameMap::kLength, false, Carry::kReinitialise, true, false, doc};
}

// Σ_f A_f sin∠(v_f, w_f): the area of the level sets' cells (Δw² per cell).
double LevelSetCellArea(const FieldGeometry& geo, const TcdField& field) {
  double area = 0;
  for (size_t f = 0; f < field.pairs.size(); ++f) {
    const ConjugatePair& p = field.pairs[f];
    area += geo.frames.area[f] * (p.valid ? std::abs(p.v.x() * p.w.y() - p.v.y() * p.w.x()) : 1.0);
  }
  return area;
}

// The spacing Δw (canonical frame) for a field.
double LevelSetSpacing(const Settings& s, const HookContext& c, const FieldResult& field) {
  const double edge = s.Number("level_sets.edge_length");
  return edge > 0 ? edge / c.frame.scale
                  : std::sqrt(LevelSetCellArea(field.geometry, field.field) /
                              double(s.Integer("level_sets.target_faces")));
}

// field.cancel_pairs: ± pairs closer than that many spacings cancelled by
// the surgery of fields/pair_cancellation.h before the level sets; the
// field re-evaluated, its report amended.
std::shared_ptr<const FieldResult> LevelSetCancelPairs(const Settings& s, const HookContext& c,
                                               std::shared_ptr<const FieldResult> field) {
  const double spacings = s.Number("field.cancel_pairs");
  const double spacing = LevelSetSpacing(s, c, *field);
  PairCancellationOptions options;
  options.max_distance = spacings * spacing;
  options.region = s.Number("field.cancel_region");
  options.boundary_distance = s.Number("field.boundary_push") * spacing;
  const PairCancellation pc =
      CancelSingularityPairs(field->mesh, field->geometry, field->field, options);
  const size_t before = field->field.singularities.size();
  auto out = std::make_shared<FieldResult>(*field);
  if (pc.cancelled > 0 || pc.pushed_out > 0) out->field = EvaluateField(out->mesh, out->geometry, pc.z_n);
  const TcdField& f = out->field;
  const size_t remaining =
      CloseOppositePairs(f.singularities, 2 * spacing).size();  // the acceptance's 2 spacings
  nlohmann::json pairs = nlohmann::json::array();
  for (const CancelledPair& p : pc.pairs) {
    pairs.push_back({{"plus_vertex", p.plus_vertex}, {"minus_vertex", p.minus_vertex},
                     {"index", p.index}, {"distance_spacings", p.distance / spacing},
                     {"cancelled", p.cancelled}, {"faces_changed", p.faces_changed},
                     {"radius", p.radius * c.frame.scale}, {"kept_because", p.kept_because}});
  }
  nlohmann::json& d = out->details;
  d["pair_cancellation"] = {{"max_distance_spacings", spacings},
                            {"found", pc.found},
                            {"cancelled", pc.cancelled},
                            {"singularities_before", before},
                            {"singularities_after", f.singularities.size()},
                            {"faces_changed", pc.faces_changed},
                            {"close_pairs_left_2_spacings", remaining},
                            {"boundary_push_spacings", s.Number("field.boundary_push")},
                            {"near_boundary", pc.near_boundary},
                            {"pushed_out", pc.pushed_out},
                            {"pairs", pairs}};
  nlohmann::json singular = nlohmann::json::array();
  for (const Singularity& x : f.singularities) {
    const Vec3 p = c.frame.FromCanonical(Vec3{x.position.x(), x.position.y(), x.position.z()});
    singular.push_back({{"vertex", int(x.vertex.idx())}, {"index", x.index}, {"position", {p[0], p[1], p[2]}}});
  }
  d["singularities"] = singular;
  d["index_sum"] = f.index_sum;
  char line[320];
  std::snprintf(line, sizeof line,
                "singularity pairs closer than %g spacings: %d found, %d cancelled (%zu → %zu "
                "singularities, %d faces changed); ± pairs closer than 2 spacings left: %zu; "
                "near the boundary %d, pushed out %d\n",
                spacings, pc.found, pc.cancelled, before, f.singularities.size(),
                pc.faces_changed, remaining, pc.near_boundary, pc.pushed_out);
  out->headline += line;
  return out;
}

void InitLevelSets(HookContext& c) {
  const Settings& s = *c.settings;
  LevelSetState& st = St(c);
  st = LevelSetState{};
  const Clock::time_point field_start = Clock::now();
  std::map<std::string, Value> field_overrides;
  if (s.Bool("level_sets.boundary_rows")) {
    field_overrides["field.boundary_alignment"] = std::max(
        s.Number("field.boundary_alignment"), s.Number("level_sets.boundary_rows_alignment"));
  }
  st.field = LevelSetCancelPairs(s, c, SolveField(s, *c.input, c.progress, field_overrides));
  st.field_seconds = SecondsSince(field_start);
  const FieldGeometry& geo = st.field->geometry;
  const TcdField& field = st.field->field;
  const Mesh& mesh = c.store->mesh();
  CHECK_EQ(field.pairs.size(), mesh.number_of_faces());

  std::vector<VertexIndex> singular;
  for (const Singularity& x : field.singularities) singular.push_back(x.vertex);
  st.cut = ComputeCutGraph(mesh, singular);
  const size_t faces = mesh.number_of_faces();
  std::vector<V2> v(faces, V2::Zero()), w(faces, V2::Zero());
  for (size_t f = 0; f < faces; ++f) {
    const ConjugatePair& p = field.pairs[f];
    if (p.valid) {
      v[f] = p.v;
      w[f] = p.w;
    }
  }
  const PairOrientation orientation =
      OrientPair(mesh, st.cut, geo.transports, geo.edge_to_transport, v, w);
  st.ov = orientation.v;
  st.ow = orientation.w;
  st.v.resize(faces);
  st.w.resize(faces);
  for (size_t f = 0; f < faces; ++f) {
    st.v[f] = double(st.ov.face_sign[f]) * v[f];
    st.w[f] = double(st.ow.face_sign[f]) * w[f];
  }
  st.spacing = LevelSetSpacing(s, c, *st.field);
  // The alignment's targets R v e^{−s̃}: the curl-corrected sizes.
  std::vector<V2> v_sized = st.v, w_sized = st.w;
  if (const double reach = s.Number("level_sets.size_reach"); reach > 0) {
    st.sizes = CorrectLevelSetSizes(mesh, geo.frames, st.cut, st.v, st.w, st.ov.chain_sign,
                                    st.ow.chain_sign, st.spacing, reach,
                                    s.Number("level_sets.size_ratio_max"));
    for (size_t f = 0; f < faces; ++f) {
      v_sized[f] *= std::exp(-st.sizes.g.log_size[f]);
      w_sized[f] *= std::exp(-st.sizes.h.log_size[f]);
    }
  }

  const int wedges = st.cut.num_wedges;
  const int chains = std::max<int>(1, int(st.cut.chains.size()));
  c.store->Declare(Values("level_set_g", "g per wedge of the cut surface (level sets along v)"),
                   wedges);
  c.store->Declare(Values("level_set_h", "h per wedge of the cut surface (level sets along w)"),
                   wedges);
  c.store->Declare(Values("level_set_alpha_g", "jump α_C of g per cut chain"), chains);
  c.store->Declare(Values("level_set_alpha_h", "jump α_C of h per cut chain"), chains);
  c.store->Declare(Values("level_set_boundary_zero", "0: the α of level_set_boundary"), 1);
  c.model->SetConstant("level_set_boundary_zero", 0);
  // The functions are defined up to g → g + c, which changes α_C by (1 − s_C) c:
  // with a chain from a ±1/2 singularity (s = −1) the gauge is fixed by
  // holding its α at an even (or odd) multiple of Δw — then rounding does not
  // move it, and the other chains' rounding is absorbed by the free constant —
  // else by holding one value.
  const double start = s.String("level_sets.rounding") == "odd" ? st.spacing : 0.0;
  for (const auto& [values, alpha, orientation] :
       {std::make_tuple("level_set_g", "level_set_alpha_g", &st.ov),
        std::make_tuple("level_set_h", "level_set_alpha_h", &st.ow)}) {
    int gauge = -1;
    for (size_t k = 0; k < st.cut.chains.size() && gauge < 0; ++k) {
      if (st.cut.chains[k].from_singularity && orientation->chain_sign[k] < 0) gauge = int(k);
    }
    if (gauge >= 0) {
      *c.store->At(alpha, gauge) = start;
      c.model->SetConstant(alpha, gauge);
    } else {
      c.model->SetConstant(values, 0);
    }
  }

  ElementSet elements, jumps, branches;
  elements.site = Site::kFace;
  elements.data_width = ld::kFaceWidth;
  jumps.site = branches.site = Site::kVertex;
  jumps.data_width = branches.data_width = ld::kRelationWidth;
  for (FaceIndex f : mesh.faces()) {
    const std::array<V2, 3> corners = FaceCorners2D(mesh, geo.frames, f);
    const HalfedgeIndex h0 = mesh.halfedge(f), h1 = mesh.next(h0), h2 = mesh.next(h1);
    const Eigen::Matrix2d& M = geo.curvature[f.idx()].M;
    const V2& vf = v_sized[f.idx()];
    const V2& wf = w_sized[f.idx()];
    std::vector<double> data = {corners[0].x(), corners[0].y(), corners[1].x(), corners[1].y(),
                                corners[2].x(), corners[2].y(), vf.x(), vf.y(), wf.x(), wf.y(),
                                double(st.cut.corner_wedge[h0.idx()]),
                                double(st.cut.corner_wedge[h1.idx()]),
                                double(st.cut.corner_wedge[h2.idx()]), M(0, 0), M(0, 1), M(1, 1),
                                1.0 / geo.total_area};
    elements.Add({int(mesh.target(h0).idx()), int(mesh.target(h1).idx()), int(mesh.target(h2).idx())},
                 int(f.idx()), int(f.idx()), -1, 0, data);
  }
  for (const JumpRelation& r : st.cut.relations) {
    const std::vector<double> data = {double(r.left_wedge), double(r.right_wedge), double(r.chain),
                                      double(st.ov.chain_sign[r.chain]),
                                      double(st.ow.chain_sign[r.chain]), 1.0 / st.spacing};
    (r.left_wedge == r.right_wedge ? branches : jumps)
        .Add({int(r.vertex.idx())}, int(r.vertex.idx()), -1, -1, 0, data);
  }
  ElementSet boundary;
  boundary.site = Site::kFace;
  boundary.data_width = ld::kBoundaryWidth;
  if (s.Bool("level_sets.boundary_rows")) {
    for (const BoundaryRowEdge& e : BoundaryRowEdges(mesh, geo.frames, st.v, st.w)) {
      const HalfedgeIndex in = mesh.opposite(e.border);
      const FaceIndex f = mesh.face(in);
      boundary.Add({int(mesh.source(e.border).idx()), int(mesh.target(e.border).idx())},
                   int(f.idx()), int(f.idx()), -1, 0,
                   {double(st.cut.corner_wedge[in.idx()]),
                    double(st.cut.corner_wedge[mesh.prev(in).idx()]), double(e.function),
                    1.0 / st.spacing});
    }
  }
  c.SetElements("level_set_boundary_edges", std::move(boundary));
  c.SetElements("level_set_faces", std::move(elements));
  c.SetElements("level_set_jumps", std::move(jumps));
  c.SetElements("level_set_branch_points", std::move(branches));
  st.solve_start = Clock::now();
}

// ∇g of face f (frame coordinates of the face) from the block's values at
// its three corner wedges.
V2 FaceGradient(HookContext& c, const char* block, FaceIndex f) {
  const LevelSetState& st = St(c);
  const Mesh& mesh = c.store->mesh();
  const std::array<V2, 3> p = FaceCorners2D(mesh, st.field->geometry.frames, f);
  const double corners[6] = {p[0].x(), p[0].y(), p[1].x(), p[1].y(), p[2].x(), p[2].y()};
  const HalfedgeIndex h0 = mesh.halfedge(f), h1 = mesh.next(h0), h2 = mesh.next(h1);
  return TriangleGradient(corners)(*c.store->At(block, st.cut.corner_wedge[h0.idx()]),
                                   *c.store->At(block, st.cut.corner_wedge[h1.idx()]),
                                   *c.store->At(block, st.cut.corner_wedge[h2.idx()]));
}

// Area-weighted mean ‖∇g‖ over the faces where the field is defined.
double MeanGradient(HookContext& c, const char* block, const std::vector<V2>& dir) {
  const LevelSetState& st = St(c);
  const FaceFrames& frames = st.field->geometry.frames;
  double sum = 0, area = 0;
  for (FaceIndex f : c.store->mesh().faces()) {
    if (dir[f.idx()].isZero()) continue;
    sum += FaceGradient(c, block, f).norm() * frames.area[f.idx()];
    area += frames.area[f.idx()];
  }
  return area > 0 ? sum / area : 1.0;
}

void RoundJumpConstants(HookContext& c);

// level_sets.boundary_rows: each boundary run held on a level of the
// function whose level sets follow it (fields/boundary_rows.h), with the
// rounded jumps; constant blocks in the last solve.
void HoldBoundaryRows(HookContext& c) {
  LevelSetState& st = St(c);
  const char* values[2] = {"level_set_g", "level_set_h"};
  const char* alphas[2] = {"level_set_alpha_g", "level_set_alpha_h"};
  std::vector<double> value[2], alpha[2];
  for (int f = 0; f < 2; ++f) {
    for (int k = 0; k < st.cut.num_wedges; ++k) value[f].push_back(*c.store->At(values[f], k));
    for (size_t k = 0; k < st.cut.chains.size(); ++k) {
      alpha[f].push_back(*c.store->At(alphas[f], int(k)));
    }
  }
  WedgeFunctions fn;
  for (int f = 0; f < 2; ++f) {
    fn.values[f] = &value[f];
    fn.alpha[f] = &alpha[f];
  }
  fn.sign[0] = &st.ov.chain_sign;
  fn.sign[1] = &st.ow.chain_sign;
  fn.spacing[0] = st.spacing_g;
  fn.spacing[1] = st.spacing_h;
  st.boundary_rows = BoundaryRowLevels(c.store->mesh(), st.cut, st.field->geometry.frames, st.v,
                                       st.w, fn, c.settings->Number("extraction.corner_angle"),
                                       c.settings->Number("level_sets.boundary_rows_max_shift"));
  for (const BoundaryLevel& b : st.boundary_rows.fixed) {
    *c.store->At(values[b.function], b.wedge) = b.value;
    c.model->SetConstant(values[b.function], b.wedge);
  }
}

// Before the last stage: the level spacings and the rounded jumps. Eq. 6 only
// asks for the direction of ∇g, eq. 5's smaller weight keeps its size near 1
// on average, not exactly: the levels are taken at multiples of Δw_g = Δw ·
// (area-weighted mean ‖∇g‖), and Δw_h likewise, so that the layout has the
// cell size asked for. The jump constants are rounded to multiples of these
// and held constant.
void Round(HookContext& c) {
  LevelSetState& st = St(c);
  if (st.rounded) return;
  st.rounded = true;
  st.spacing_g = st.spacing * MeanGradient(c, "level_set_g", st.v);
  st.spacing_h = st.spacing * MeanGradient(c, "level_set_h", st.w);
  RoundJumpConstants(c);
  if (c.settings->Bool("level_sets.boundary_rows") && st.spacing_g > 0 && st.spacing_h > 0) {
    HoldBoundaryRows(c);
  }
}

void RoundJumpConstants(HookContext& c) {
  LevelSetState& st = St(c);
  if (st.cut.chains.empty()) return;
  const int parity = c.settings->String("level_sets.rounding") == "odd" ? 1 : 0;
  for (const auto& [block, orientation, spacing] :
       {std::make_tuple("level_set_alpha_g", &st.ov, st.spacing_g),
        std::make_tuple("level_set_alpha_h", &st.ow, st.spacing_h)}) {
    std::vector<double> alpha, rounded;
    for (size_t k = 0; k < st.cut.chains.size(); ++k) alpha.push_back(*c.store->At(block, int(k)));
    std::string message;
    if (!RoundJumps(st.cut, orientation->chain_sign, alpha, spacing, parity, &rounded, &message)) {
      st.rounding_ok = false;
    }
    if (!message.empty()) st.rounding_message += std::string(block) + ": " + message + "; ";
    for (size_t k = 0; k < rounded.size(); ++k) {
      *c.store->At(block, int(k)) = rounded[k];
      c.model->SetConstant(block, int(k));
    }
  }
}

// Mean angle between ∇g and R v over the faces where the field is defined
// (plain and area-weighted), degrees.
std::array<double, 2> GradientAngle(HookContext& c, const char* block, const std::vector<V2>& dir) {
  const FaceFrames& frames = St(c).field->geometry.frames;
  double sum = 0, weighted = 0, area = 0;
  int n = 0;
  for (FaceIndex f : c.store->mesh().faces()) {
    const V2& d = dir[f.idx()];
    if (d.isZero()) continue;
    const V2 grad = FaceGradient(c, block, f);
    const V2 target(-d.y(), d.x());
    const double cosine = grad.norm() > 0 ? grad.dot(target) / (grad.norm() * target.norm()) : -1.0;
    const double angle = std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / M_PI;
    sum += angle;
    weighted += angle * frames.area[f.idx()];
    area += frames.area[f.idx()];
    ++n;
  }
  return {n > 0 ? sum / n : 0.0, area > 0 ? weighted / area : 0.0};
}

// How far the level sets of g and h are from conjugate [Zadravec 2010,
// eq. 7], area-weighted over the curved faces where the field is defined:
// |t_gᵀ M t_h| / max(|κ1|, |κ2|) with t_g, t_h the unit tangents R∇g/‖∇g‖,
// R∇h/‖∇h‖ (0: conjugate; at most 1). Unit-free.
double LevelSetConjugacy(HookContext& c) {
  const LevelSetState& st = St(c);
  const FieldGeometry& geo = st.field->geometry;
  double sum = 0, area = 0;
  for (FaceIndex f : c.store->mesh().faces()) {
    const FaceCurvature& k = geo.curvature[f.idx()];
    if (st.v[f.idx()].isZero() || k.flat) continue;
    const V2 g = FaceGradient(c, "level_set_g", f), h = FaceGradient(c, "level_set_h", f);
    const double scale = std::max(std::abs(k.k1), std::abs(k.k2));
    if (g.norm() == 0 || h.norm() == 0 || scale == 0) continue;
    const V2 tg = V2(-g.y(), g.x()) / g.norm(), th = V2(-h.y(), h.x()) / h.norm();
    sum += std::abs(tg.dot(k.M * th)) / scale * geo.frames.area[f.idx()];
    area += geo.frames.area[f.idx()];
  }
  return area > 0 ? sum / area : 0.0;
}

V3 Centroid(const Mesh& mesh, FaceIndex f) {
  V3 c = V3::Zero();
  int n = 0;
  for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
    const Point& p = mesh.point(v);
    c += V3(p.x(), p.y(), p.z());
    ++n;
  }
  return c / n;
}

void FinishLevelSets(HookContext& c) {
  LevelSetState& st = St(c);
  const double level_set_seconds = SecondsSince(st.solve_start);
  const Clock::time_point extraction_start = Clock::now();
  const Mesh& mesh = c.store->mesh();
  auto result = std::make_shared<LevelSetResult>();
  result->field = st.field;
  result->cut = st.cut;
  result->frame = c.frame;
  LevelSetFunctions& fn = result->functions;
  fn.cut = &result->cut;
  const int wedges = st.cut.num_wedges;
  for (int k = 0; k < wedges; ++k) {
    fn.g.push_back(*c.store->At("level_set_g", k));
    fn.h.push_back(*c.store->At("level_set_h", k));
  }
  for (size_t k = 0; k < st.cut.chains.size(); ++k) {
    fn.alpha_g.push_back(*c.store->At("level_set_alpha_g", int(k)));
    fn.alpha_h.push_back(*c.store->At("level_set_alpha_h", int(k)));
  }
  fn.sign_g = st.ov.chain_sign;
  fn.sign_h = st.ow.chain_sign;
  fn.spacing_g = st.spacing_g;
  fn.spacing_h = st.spacing_h;
  const ExtractOptions options = ExtractOptionsOf(*c.settings);
  if (st.spacing_g > 0 && st.spacing_h > 0) {
    result->layout = ExtractQuadMesh(mesh, fn, options);
  } else {
    result->layout.error = "g or h is constant (no level sets to cut along)";
  }
  const Extraction& x = result->layout;

  nlohmann::json& d = result->details;
  const std::array<double, 2> angle_g = GradientAngle(c, "level_set_g", st.v);
  const std::array<double, 2> angle_h = GradientAngle(c, "level_set_h", st.w);
  const CutSurfaceTopology topology = CutSurface(mesh, st.cut);
  d["spacing"] = st.spacing * c.frame.scale;
  d["spacing_g"] = st.spacing_g * c.frame.scale;
  d["spacing_h"] = st.spacing_h * c.frame.scale;
  d["cut"] = {{"chains", st.cut.chains.size()},
              {"wedges", st.cut.num_wedges},
              {"components_after_cutting", topology.components},
              {"euler_characteristic_after_cutting", topology.euler_characteristic},
              {"mismatched_cut_edges", {st.ov.mismatched_cut_edges, st.ow.mismatched_cut_edges}}};
  d["rounding"] = {{"parity", c.settings->String("level_sets.rounding")},
                   {"consistent", st.rounding_ok},
                   {"message", st.rounding_message}};
  d["gradient_angle_mean_deg"] = {{"g_vs_Rv", angle_g[0]},
                                  {"h_vs_Rw", angle_h[0]},
                                  {"g_vs_Rv_area_weighted", angle_g[1]},
                                  {"h_vs_Rw_area_weighted", angle_h[1]}};
  d["conjugacy_mean"] = LevelSetConjugacy(c);
  const BoundaryRows& rows = st.boundary_rows;
  d["boundary_rows"] = {{"on", c.settings->Bool("level_sets.boundary_rows")},
                        {"loops", rows.loops},
                        {"corners", rows.corners},
                        {"runs_g", rows.runs_g},
                        {"runs_h", rows.runs_h},
                        {"skipped_runs", rows.skipped_runs},
                        {"held_wedges", rows.fixed.size()},
                        {"max_shift_spacings", rows.max_shift},
                        {"field_angle_mean_deg", rows.angle_mean_deg},
                        {"field_angle_max_deg", rows.angle_max_deg}};
  const auto size_json = [](const LevelSetSizeFamily& x) {
    return nlohmann::json{{"vertices", x.vertices}, {"curl_before", x.curl_before},
                          {"curl_after", x.curl_after}, {"size_p5", x.size_p5},
                          {"size_p95", x.size_p95}, {"size_min", x.size_min},
                          {"size_max", x.size_max}};
  };
  d["size_correction"] = {{"reach_spacings", c.settings->Number("level_sets.size_reach")},
                          {"ratio_max", c.settings->Number("level_sets.size_ratio_max")},
                          {"g", size_json(st.sizes.g)},
                          {"h", size_json(st.sizes.h)}};
  char line[768];
  std::snprintf(line, sizeof line,
                "level sets: spacing %.4g (file units), %zu cut chains; mean angle ∇g vs Rv "
                "%.2f°, ∇h vs Rw %.2f°\n",
                st.spacing * c.frame.scale, st.cut.chains.size(), angle_g[0], angle_h[0]);
  result->headline = line;
  if (!st.rounding_ok) {
    result->headline += "warning: jump rounding: " + st.rounding_message + "\n";
  }
  if (!x.ok) {
    d["layout"] = {{"error", x.error}};
    result->headline += "the layout could not be extracted: " + x.error + "\n";
  } else {
    // Every singularity as an irregular vertex or face nearby.
    std::vector<V3> irregular;
    for (VertexIndex v : x.irregular_interior_vertices) {
      const Point& p = x.mesh.point(v);
      irregular.push_back(V3(p.x(), p.y(), p.z()));
    }
    for (FaceIndex f : x.mesh.faces()) {
      if (x.mesh.degree(f) != 4) irregular.push_back(Centroid(x.mesh, f));
    }
    // In the local spacing: the larger family's curl-corrected size at the
    // singular vertex (mean over its faces), Δw itself without sizes.
    const auto local_spacing = [&](VertexIndex v) {
      const std::vector<double>& g = st.sizes.g.log_size;
      const std::vector<double>& h = st.sizes.h.log_size;
      if (g.size() != mesh.number_of_faces() || h.size() != g.size()) return st.spacing;
      double sum = 0;
      int n = 0;
      for (FaceIndex f : mesh.faces_around_target(mesh.halfedge(v))) {
        if (f == Mesh::null_face()) continue;
        sum += std::exp(std::max(g[f.idx()], h[f.idx()]));
        ++n;
      }
      return n > 0 ? st.spacing * sum / n : st.spacing;
    };
    int matched = 0;
    double farthest = 0, farthest_nominal = 0;
    for (const Singularity& s : st.field->field.singularities) {
      double best = std::numeric_limits<double>::infinity();
      for (const V3& p : irregular) best = std::min(best, (p - s.position).norm());
      const double local = local_spacing(s.vertex);
      farthest = std::max(farthest, best / local);
      farthest_nominal = std::max(farthest_nominal, best / st.spacing);
      if (best <= kSingularityReach * local) ++matched;
    }
    MetricsOptions metrics_options;
    const Metrics m = ComputeMetrics(x.mesh, c.reference, nullptr, metrics_options);
    const double diagonal = PrincipalBoxDiagonal(mesh);
    const BoundaryFaceCounts on_boundary = CountBoundaryFaces(x.mesh);
    const int faces = int(x.mesh.number_of_faces());
    nlohmann::json valence = nlohmann::json::object();
    for (const auto& [k, n] : x.interior_valence) valence[std::to_string(k)] = n;
    nlohmann::json degrees = nlohmann::json::object();
    for (const auto& [k, n] : x.face_degrees) degrees[std::to_string(k)] = n;
    d["layout"] = {
        {"faces", faces},
        {"vertices", x.mesh.number_of_vertices()},
        {"quads", x.quads},
        {"triangles", x.triangles},
        {"pentagons", x.pentagons},
        {"other_faces", x.other_faces},
        {"quad_fraction", faces > 0 ? double(x.quads) / faces : 0.0},
        {"boundary_faces", on_boundary.boundary_faces},
        {"boundary_quads_with_edge", on_boundary.quads_on_boundary},
        {"boundary_quad_fraction", on_boundary.fraction()},
        {"face_degrees", degrees},
        {"interior_valence", valence},
        {"irregular_interior_vertices", x.irregular_interior_vertices.size()},
        {"irregular_interior_faces", x.irregular_interior_faces.size()},
        {"singularities", st.field->field.singularities.size()},
        {"singularities_matched", matched},
        {"singularity_distance_max_spacings", farthest},
        {"singularity_distance_max_nominal_spacings", farthest_nominal},
        {"surface_distance_max_relative", m.surface_distance_max / diagonal},
        {"hausdorff_relative", m.hausdorff / diagonal},
        {"pq_normalized_max", m.pq_normalized_max},
        {"pq_normalized_mean", m.pq_normalized_mean},
        {"merged_vertices", x.merged_vertices},
        {"snapped_vertices", x.snapped_vertices},
        {"dissolved_vertices", x.dissolved_vertices},
        {"merged_valence_two", x.merged_valence_two},
        {"merged_caps", x.merged_caps},
        {"removed_slits", x.removed_slits},
        {"split_reflex_corners", x.split_reflex_corners},
        {"collapsed_boundary_edges", x.collapsed_boundary_edges},
        {"dropped_small_faces", x.dropped_small_faces},
        {"dropped_non_disk_regions", x.dropped_non_disk_regions},
        {"duplicated_vertices", x.duplicated_vertices},
        {"anomalies", x.anomalies},
        {"max_jump_correction_spacings", x.max_jump_correction}};
    const EdgeFieldAngle angle = LayoutFieldAngle(*st.field, x.mesh);
    d["layout"]["edge_field_angle_mean_deg"] = angle.mean_deg;
    d["layout"]["edge_field_angle_max_deg"] = angle.max_deg;
    std::snprintf(line, sizeof line,
                  "layout: %d faces, %d quads (%.1f%%), %d triangles, %d pentagons, %d other; "
                  "boundary faces %d, quads with an edge on the boundary %.1f%%; "
                  "%zu irregular interior vertices; singularities as irregular vertices or faces "
                  "%d of %zu; distance to the input %.3g%% of the diagonal (Hausdorff %.3g%%); "
                  "δ_PQ,n max %.3e mean %.3e\n",
                  faces, x.quads, faces > 0 ? 100.0 * x.quads / faces : 0.0, x.triangles,
                  x.pentagons, x.other_faces, on_boundary.boundary_faces,
                  100 * on_boundary.fraction(), x.irregular_interior_vertices.size(), matched,
                  st.field->field.singularities.size(), 100 * m.surface_distance_max / diagonal,
                  100 * m.hausdorff / diagonal, m.pq_normalized_max, m.pq_normalized_mean);
    result->headline += line;
  }
  // The stages' wall times (the layout path's table; the planar step's is
  // the report's own `seconds`).
  d["seconds"] = {{"field", st.field_seconds},
                  {"level_sets", level_set_seconds},
                  {"extraction", SecondsSince(extraction_start)}};
  std::snprintf(line, sizeof line, "stages: field %.2f s, level sets %.2f s, extraction %.2f s\n",
                st.field_seconds, level_set_seconds, SecondsSince(extraction_start));
  result->headline += line;
  c.details["field"] = st.field->details;
  for (const auto& [k, v] : d.items()) c.details[k] = v;
  c.headline += st.field->headline + result->headline;
  c.level_sets = result;
}

// The problem's own validity (ProblemDecl::invalid): a layout asked for
// (output.layout) that the level sets do not give — the rounded values
// violate the jump conditions, or the extraction failed — is no result
// (exit 3, nothing written), not bad input. Empty during the rounds (the
// layout is made by `finish`).
std::string LayoutMissing(HookContext& c) {
  const auto& result = c.level_sets;
  if (!result || result->layout.ok || c.settings->String("output.layout").empty()) return "";
  return "no layout (output.layout): " + result->layout.error + "\n";
}

void WriteLevelSets(HookContext& c) {
  const auto& result = c.level_sets;
  if (const auto it = c.temporaries.find("layout"); it != c.temporaries.end()) {
    CHECK(result->layout.ok) << "level_sets: no layout to write (LayoutMissing lets none through)";
    WriteMesh(it->second, InFileUnits(result->layout.mesh, c.frame));
  }
  if (const auto it = c.temporaries.find("field"); it != c.temporaries.end()) {
    const FieldResult& field = *result->field;
    WriteField(it->second, c.settings->String("output.field"), field.mesh, field.geometry, field.field,
               field.frame, "output.field");
  }
}

}  // namespace

ProblemDecl level_sets() {
  ProblemDecl d;
  d.name = "level_sets";
  d.summary = "level sets along a TCD field and the quad-dominant layout they cut out";
  d.paper = "[Zadravec 2010, §5, eq. 5–7]";
  d.input = InputKind::kTriangles;
  d.terms = FieldTerms();
  for (const TermUse& t : LevelSetTerms()) d.terms.push_back(t);
  d.keys = FieldKeys();
  for (const Key& k : LevelSetKeys()) d.keys.push_back(k);
  // Every round by LeanSolve's Cholesky steps (core/lean_solve.h), as
  // planar_quads: the same steps as Ceres' sparse_normal_cholesky without its
  // per-solve set-up (docs/performance.md, The layout path).
  d.defaults = {{"solver.back_end", std::string("lean")}};
  d.check = [](const Settings& s) {
    CheckNoMultiresolution(s, "level_sets");
    CheckLevelSetKeys(s);
  };
  d.init = &InitLevelSets;
  d.stages = [](const Settings&) {
    const std::vector<std::string> jumps = {"level_set_jump", "level_set_branch_point",
                                            "level_set_boundary"};
    Stage eq5;
    eq5.name = "eq5";
    eq5.rounds_key = "level_sets.rounds";
    eq5.terms = {"level_set_alignment"};
    eq5.terms.insert(eq5.terms.end(), jumps.begin(), jumps.end());
    Stage eq6 = eq5;
    eq6.name = "eq6";
    eq6.terms = {"level_set_normalised", "level_set_alignment", "level_set_conjugacy"};
    eq6.terms.insert(eq6.terms.end(), jumps.begin(), jumps.end());
    Stage rounded = eq6;
    rounded.name = "rounded";
    rounded.before_round = &Round;
    return std::vector<Stage>{eq5, eq6, rounded};
  };
  d.finish = &FinishLevelSets;
  d.output_keys = {"layout", "field"};
  d.write = &WriteLevelSets;
  d.invalid = &LayoutMissing;
  d.colors = "none";  // the mesh is not changed: the functions and the layout are the result
  return d;
}

}  // namespace archgeo::problems
