// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `conjugate_field`: a field of transverse conjugate directions (a
// TCD field) on a triangle mesh of the design surface [Zadravec 2010, §2–4].
//
// Per face f: the second fundamental form M_f from osculating jets
// (jets.degree, jets.rings; fields/face_curvature.h), a smooth frame (e1, e2)
// and z_M,f (Prop. 1); the variable block z_n (width 2, output) is z_N,f in
// that frame. The pair (v, w) of a face is the pair of common conjugate
// directions of M_f and N_f (Prop. 2): conjugate by construction, whatever
// z_N is. Terms (½ Σ w r², unit-free):
//   tcd_dirichlet              Σ_e w_e |ζ_f − R(2τ_fg) ζ_g|², ζ = z_N − e1
//   tcd_transversality         λ_trans Σ_f ‖z_N − e1‖⁴ (eq. 1)
//   tcd_singularity_avoidance  Σ_f Ψ(‖z_N − z_M‖/ρ) over the faces the user
//                              does not constrain (tcd_free_faces)
//   tcd_singularity_placement  z_N = z_M at field.singularities
//   tcd_prescribed_direction   z_N on the line of Prop. 1 of a prescribed
//                              direction at field.directions / field.constraints
// Start: z_N = e1, the principal directions (the paper's initialisation
// optimises ‖z_N − e1‖² from zero, which gives the same). Without
// constraints the principal field (ζ ≡ 0) is the minimum of the first two
// terms, so the result is the principal field; constraints and avoidance move
// it, and the Dirichlet energy spreads their effect smoothly.
//
// Pre-processing (field.preprocess, off by default; Gebreiter 2012, §8.1.4):
// a first stage `principal` smooths the principal directions of unreliable
// faces (near-umbilic, near-flat) with the terms principal_fit and
// principal_smoothing over the block `principal`; before the field stage
// every face's curvature takes the smoothed directions with its measured
// κ1, κ2 and the TCD terms are built on it (fields/principal_field.h).
//
// Moving a singularity (field.moves, §4 "local correction"): after the
// global solve, a last stage `move` subtracts the σ-blended correction of
// eq. 4 around each move's `from` face so that z_N = z_M at its `to` face
// (fields/singularities.h MoveSingularity), then re-optimises only the faces
// in each blend's transition band (0 < β < 1), every other face held.
//
// Report: the singularities (index, vertex, position in file units; index of
// a vertex from the rotation of the bisector of (v, w) around it, §3), the
// index sum, the conjugacy error max |vᵀ M w| / (|κ|max ‖v‖‖w‖) (≈ 1e-16, by
// construction), the angles between v and w, the mean deviation from the
// principal directions and the prescribed directions met.
//
// A surface without curvature (every face flat, e.g. a plane): every pair is
// conjugate; the field falls back to the smooth orthogonal field of the face
// frames (e1, e2) with a warning. Output: output.field (fields/field_io.h:
// PLY line segments per face, singularities as points) and
// output.streamlines (OBJ polylines of both families and the separatrices,
// fields/streamlines.h [Gebreiter 2012, §8.2]; streamlines.* keys).
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>

#include <Eigen/Geometry>

#include "core/problem.h"
#include "energies/tcd_prescribed_direction.h"
#include "fields/field_io.h"
#include "fields/guide_curves.h"
#include "fields/principal_field.h"
#include "geometry/curves.h"
#include "fields/singularities.h"
#include "core/input_error.h"
#include "mesh/topology.h"
#include "problems/declarations/field_pipeline.h"
#include "problems/runtime/model.h"

namespace archgeo::problems {
namespace {

using V2 = Eigen::Vector2d;
using V3 = Eigen::Vector3d;

struct Prescribed {
  int face = 0;
  V3 direction = V3::Zero();  // file units
  std::string key;            // for messages
  int line = 0;
  bool from_file = false;
};

// A face index (0 to 2^30) if `node` is one.
std::optional<int> FaceIndexOf(const CustomValue* node) {
  if (!node || !node->integer || *node->integer < 0 || *node->integer > (1LL << 30)) {
    return std::nullopt;
  }
  return int(*node->integer);
}

// field.directions: a list of {face: id, direction: [x, y, z]}.
std::vector<Prescribed> ReadDirections(const Settings& s) {
  std::vector<Prescribed> out;
  const char* name = "field.directions";
  if (!s.Given(name)) return out;
  const CustomValue& list = *s.Custom(name);
  const Origin at = s.Where(name);
  if (!list.IsList()) throw s.ErrorAt(name, list, name, "expected a list of {face, direction}");
  for (size_t i = 0; i < list.items.size(); ++i) {
    const CustomValue& d = list.items[i];
    const std::string key = std::string(name) + "[" + std::to_string(i) + "]";
    if (!d.IsMap()) throw s.ErrorAt(name, d, key, "expected {face: id, direction: [x, y, z]}");
    for (const CustomValue::Entry& e : d.entries) {
      const std::string& k = e.key.text;
      if (k != "face" && k != "direction") {
        throw s.ErrorAt(name, e.key, key + "." + k, "unknown key (allowed: face, direction)");
      }
    }
    const std::optional<int> face = FaceIndexOf(d.Find("face"));
    if (!face) throw s.ErrorAt(name, d, key + ".face", "expected a face index ≥ 0");
    const CustomValue* xyz = d.Find("direction");
    if (!xyz || !xyz->IsList() || xyz->items.size() != 3) {
      throw s.ErrorAt(name, d, key + ".direction", "expected [x, y, z]");
    }
    Prescribed p;
    p.face = *face;
    for (int k = 0; k < 3; ++k) {
      const std::optional<double>& x = xyz->items[k].number;
      if (!x || !std::isfinite(*x)) {
        throw s.ErrorAt(name, xyz->items[k], key + ".direction", "expected a finite number");
      }
      p.direction[k] = *x;
    }
    p.key = key;
    p.line = at.file == "--set" ? 0 : d.line;
    out.push_back(p);
  }
  return out;
}

// field.moves: a list of {from: face, to: face, inner_radius: r1, outer_radius: r2}.
struct Move {
  int from = 0, to = 0;
  double inner = 0, outer = 0;  // file units; 0 = default
  std::string key;
  int line = 0;
};

// One move of field.moves (the list checked by ReadMoves), `key` its place.
Move ReadMove(const Settings& s, const CustomValue& m, const std::string& key) {
  const char* name = "field.moves";
  Move move;
  move.key = key;
  move.line = s.Where(name).file == "--set" ? 0 : m.line;
  if (!m.IsMap()) {
    throw s.ErrorAt(name, m, key, "expected {from: face, to: face, inner_radius, outer_radius}");
  }
  for (const CustomValue::Entry& e : m.entries) {
    const std::string& k = e.key.text;
    if (k != "from" && k != "to" && k != "inner_radius" && k != "outer_radius") {
      throw s.ErrorAt(name, e.key, key + "." + k,
                      "unknown key (allowed: from, to, inner_radius, outer_radius)");
    }
  }
  for (const auto& [field, target] :
       {std::make_pair("from", &move.from), std::make_pair("to", &move.to)}) {
    const std::optional<int> face = FaceIndexOf(m.Find(field));
    if (!face) throw s.ErrorAt(name, m, key + "." + field, "expected a face index ≥ 0");
    *target = *face;
  }
  for (const auto& [field, target] : {std::make_pair("inner_radius", &move.inner),
                                      std::make_pair("outer_radius", &move.outer)}) {
    const CustomValue* radius = m.Find(field);
    if (!radius) continue;
    if (!radius->number || !std::isfinite(*radius->number) || *radius->number <= 0) {
      throw s.ErrorAt(name, *radius, key + "." + field, "expected a length > 0 (file units)");
    }
    *target = *radius->number;
  }
  if (move.from == move.to) {
    throw s.ErrorAt(name, m, key + ".to", "`to` is the `from` face: nothing to move");
  }
  if (move.inner > 0 && move.outer > 0 && move.outer <= move.inner) {
    throw s.ErrorAt(name, m, key + ".outer_radius", "must be larger than inner_radius");
  }
  return move;
}

std::vector<Move> ReadMoves(const Settings& s) {
  std::vector<Move> out;
  if (!s.Given("field.moves")) return out;
  const CustomValue& list = *s.Custom("field.moves");
  if (!list.IsList()) {
    throw s.ErrorAt("field.moves", list, "field.moves", "expected a list of {from, to}");
  }
  for (size_t i = 0; i < list.items.size(); ++i) {
    out.push_back(ReadMove(s, list.items[i], "field.moves[" + std::to_string(i) + "]"));
  }
  return out;
}

// The `at: [x, y, z]` of the list entry `m` (file units) of the key `name`;
// `key` names the entry in messages.
V3 ReadPoint(const Settings& s, const char* name, const CustomValue& m, const std::string& key) {
  const CustomValue* at = m.Find("at");
  if (!at || !at->IsList() || at->items.size() != 3) {
    throw s.ErrorAt(name, at ? *at : m, key + ".at", "expected a point [x, y, z] (file units)");
  }
  V3 p;
  for (int k = 0; k < 3; ++k) {
    const CustomValue& x = at->items[size_t(k)];
    if (!x.number || !std::isfinite(*x.number)) throw s.ErrorAt(name, x, key + ".at", "expected a finite number");
    p[k] = *x.number;
  }
  return p;
}

// A local rotation of the field (field.rotations, thesis §8.1.1): inside
// `radius` of the face nearest `at`, the free field turned by `angle`
// degrees at the centre, tapering to 0 at the radius (fields/guide_curves.h's
// falloff).
struct Rotation {
  V3 at = V3::Zero();  // file units
  double radius = 0, angle = 0;
  std::string key;
  int line = 0;
};

std::vector<Rotation> ReadRotations(const Settings& s) {
  std::vector<Rotation> out;
  const char* name = "field.rotations";
  if (!s.Given(name)) return out;
  const CustomValue& list = *s.Custom(name);
  if (!list.IsList()) throw s.ErrorAt(name, list, name, "expected a list of {at: [x, y, z], radius, angle}");
  for (size_t i = 0; i < list.items.size(); ++i) {
    const CustomValue& m = list.items[i];
    Rotation r;
    r.key = std::string(name) + "[" + std::to_string(i) + "]";
    r.line = s.Where(name).file == "--set" ? 0 : m.line;
    if (!m.IsMap()) throw s.ErrorAt(name, m, r.key, "expected {at: [x, y, z], radius: r, angle: degrees}");
    for (const CustomValue::Entry& e : m.entries) {
      const std::string& k = e.key.text;
      if (k != "at" && k != "radius" && k != "angle") {
        throw s.ErrorAt(name, e.key, r.key + "." + k, "unknown key (allowed: at, radius, angle)");
      }
    }
    r.at = ReadPoint(s, name, m, r.key);
    const CustomValue* radius = m.Find("radius");
    if (!radius || !radius->number || !std::isfinite(*radius->number) || *radius->number <= 0) {
      throw s.ErrorAt(name, radius ? *radius : m, r.key + ".radius", "expected a length > 0 (file units)");
    }
    r.radius = *radius->number;
    const CustomValue* angle = m.Find("angle");
    if (!angle || !angle->number || !std::isfinite(*angle->number) || std::abs(*angle->number) >= 90) {
      throw s.ErrorAt(name, angle ? *angle : m, r.key + ".angle",
                      "expected an angle in degrees, |angle| < 90 (a line field turned by 90° is "
                      "its partner direction)");
    }
    r.angle = *angle->number;
    out.push_back(r);
  }
  return out;
}

// The sources and sinks of a potential field (field.sources, thesis §8.1.1):
// φ(x) = Σ s_k log |x − a_k|, whose gradient Σ s_k (x − a_k)/|x − a_k|² runs
// out of a source (s > 0) and into a sink (s < 0).
struct Source {
  V3 at = V3::Zero();  // file units, then canonical
  double strength = 0;
};

std::vector<Source> ReadSources(const Settings& s) {
  std::vector<Source> out;
  const char* name = "field.sources";
  if (!s.Given(name)) return out;
  const CustomValue& list = *s.Custom(name);
  if (!list.IsList()) throw s.ErrorAt(name, list, name, "expected a list of {at: [x, y, z], strength}");
  for (size_t i = 0; i < list.items.size(); ++i) {
    const CustomValue& m = list.items[i];
    const std::string key = std::string(name) + "[" + std::to_string(i) + "]";
    if (!m.IsMap()) throw s.ErrorAt(name, m, key, "expected {at: [x, y, z], strength: s}");
    for (const CustomValue::Entry& e : m.entries) {
      if (e.key.text != "at" && e.key.text != "strength") {
        throw s.ErrorAt(name, e.key, key + "." + e.key.text, "unknown key (allowed: at, strength)");
      }
    }
    Source src;
    src.at = ReadPoint(s, name, m, key);
    const CustomValue* strength = m.Find("strength");
    if (!strength || !strength->number || !std::isfinite(*strength->number) || *strength->number == 0) {
      throw s.ErrorAt(name, strength ? *strength : m, key + ".strength",
                      "expected a number ≠ 0 (> 0: a source, < 0: a sink)");
    }
    src.strength = *strength->number;
    out.push_back(src);
  }
  return out;
}

JetOptions Jets(const Settings& s) {
  JetOptions o;
  o.degree = int(s.Integer("jets.degree"));
  o.rings = int(s.Integer("jets.rings"));
  return o;
}

// A 3-D direction in file units as a canonical direction.
V3 ToCanonicalDirection(const Similarity& frame, const V3& d) {
  V3 out;
  for (int k = 0; k < 3; ++k) {
    out[k] = frame.axes[k][0] * d.x() + frame.axes[k][1] * d.y() + frame.axes[k][2] * d.z();
  }
  return out;
}

std::uint8_t FaceFlags(const Mesh& mesh, const std::vector<bool>& boundary, FaceIndex f) {
  for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
    if (boundary[v.idx()]) return kBoundary;
  }
  return 0;
}

std::vector<int> FaceVertices(const Mesh& mesh, FaceIndex f) {
  std::vector<int> vs;
  for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) vs.push_back(int(v.idx()));
  return vs;
}

struct Constraints {
  std::vector<int> placements;
  std::vector<Move> moves;
  bool moved = false;
  nlohmann::json moves_done = nlohmann::json::array();
  std::vector<std::pair<int, V2>> prescribed;  // face, direction in the face frame
  int file_rows = 0, file_flagged = 0, file_skipped = 0;
  int raw_faces = 0, raw_skipped = 0;  // rows of field.file, those not prescribed
  std::vector<std::pair<int, V2>> from_field_file;  // face, direction in the face frame
  std::vector<std::pair<int, V2>> from_potential;   // field.sources: the potential's gradient
  int sources = 0, potential_skipped = 0;
  int boundary_faces = 0;  // boundary tangents prescribed (field.boundary_alignment)
  // Guide curves (field.guide_curves): face, direction in the face frame,
  // factor on the term's weight, falloff weight w (fields/guide_curves.h).
  struct Guided {
    int face;
    V2 direction;
    double factor, weight;
  };
  std::vector<Guided> guided;
  bool guides_applied = false;
  // field.rotations, centres and radii canonical; per rotation the faces it
  // turned and how far the face nearest its centre turned (set in the
  // guide stage from the free field).
  std::vector<Rotation> rotations;
  std::vector<int> rotation_faces;
  int rotation_skipped = 0;  // turned directions within 30° of an asymptotic one: not prescribed
  std::vector<int> rotation_centre;  // face nearest `at`
  std::vector<V2> free_v;            // the free field's v per face (frame), before the guide stage
  int guide_skipped = 0;  // faces whose guide direction has no transverse conjugate partner
  int guide_curves = 0;
  double guide_radius = 0;  // file units
};

// The factor on tcd_prescribed_direction's weight of a field.file direction:
// a complete field from a file is the field, not a wish the smoothing may
// trade against (as one field.directions entry is).
constexpr double kFieldFileFactor = 100;

// A guide direction whose conjugate partner is closer than this to it (a
// saddle's asymptotic direction has itself as partner) is not prescribed.
constexpr double kGuideMinPairDeg = 30;

// Whether the direction conjugate to d (⟂ M d, face frame) is at least
// kGuideMinPairDeg from d: not near a saddle's asymptotic direction, where
// prescribing d would fold the pair.
bool TransversePartner(const Eigen::Matrix2d& M, const V2& d) {
  const V2 md = M * d, partner(-md.y(), md.x());
  return partner.norm() > 0 &&
         std::abs(d.dot(partner)) / (d.norm() * partner.norm()) <= std::cos(kGuideMinPairDeg * M_PI / 180);
}

// Guide curves (field.guide_curves): every face within field.guide_radius
// of a curve gets the curve's tangent as a prescribed direction, its weight
// field.guide_weight × the falloff (fields/guide_curves.h).
void AddGuideCurves(const HookContext& c, const FieldGeometry& g, double prescribed_weight,
                    Constraints& con) {
  const Settings& s = *c.settings;
  const std::string file = s.String("field.guide_curves");
  if (file.empty()) return;
  if (!(prescribed_weight > 0) || !(s.Number("field.guide_weight") > 0)) {
    throw s.Error("field.guide_weight", "guide curves need terms.tcd_prescribed_direction on and "
                                        "field.guide_weight > 0");
  }
  std::vector<Polyline> read;
  try {
    read = ReadPolylines(file);
  } catch (const InputError& e) {
    throw InputError(e.file(), e.line(), "field.guide_curves", e.message());
  }
  std::vector<std::vector<V3>> curves;
  std::vector<bool> closed;
  for (const Polyline& p : read) {
    std::vector<V3> q;
    for (const Vec3& x : p.points) {
      const Vec3 y = c.frame.ToCanonical(x);
      q.emplace_back(y[0], y[1], y[2]);
    }
    curves.push_back(std::move(q));
    closed.push_back(p.closed);
  }
  const Mesh& mesh = c.store->mesh();
  V3 lo = V3::Constant(INFINITY), hi = V3::Constant(-INFINITY);
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    lo = lo.cwiseMin(V3(p.x(), p.y(), p.z()));
    hi = hi.cwiseMax(V3(p.x(), p.y(), p.z()));
  }
  const double radius = s.Number("field.guide_radius") * (hi - lo).norm();
  const std::vector<GuideFace> near = GuideFaces(g.frames.centroid, curves, closed, radius);
  std::vector<int> per_curve(curves.size(), 0);
  for (const GuideFace& f : near) ++per_curve[size_t(f.curve)];
  for (size_t k = 0; k < curves.size(); ++k) {
    if (per_curve[k] == 0) {
      throw InputError(file, 0, "field.guide_curves",
                       "curve " + std::to_string(k + 1) + " is farther than field.guide_radius (" +
                           std::to_string(radius * c.frame.scale) +
                           " file units) from every face of the surface: it guides nothing");
    }
  }
  const double factor = s.Number("field.guide_weight") / prescribed_weight;
  for (const GuideFace& f : near) {
    const V2 d = ToFrame(g.frames, FaceIndex(f.face), f.tangent);
    const Eigen::Matrix2d& M = g.curvature[size_t(f.face)].M;
    const double m[3] = {M(0, 0), M(0, 1), M(1, 1)};
    V2 point, line;
    if (!(d.norm() > 1e-9) || !TcdPrescribedLine(m, d.data(), &point, &line)) {
      ++con.guide_skipped;
      continue;
    }
    if (!TransversePartner(M, d)) {
      ++con.guide_skipped;
      continue;
    }
    con.guided.push_back({f.face, d.normalized(), factor * f.weight, f.weight});
  }
  con.guide_curves = int(curves.size());
  con.guide_radius = radius * c.frame.scale;
}

// The run's data: the input's field geometry and the validated constraints.
struct FieldState : ProblemState {
  FieldGeometry geometry;
  Constraints constraints;
  // field.preprocess (fields/principal_field.h): the measured curvature, kept
  // when the smoothed one replaces it, and the reliability of every face.
  std::vector<FaceCurvature> measured;
  PrincipalReliability reliability;
  bool principal_applied = false;
  ElementSet prescribed;  // tcd_prescribed without the guide curves' faces
  StreamlineResult streamlines;  // output.streamlines (fields/streamlines.h)
};

void BuildFieldElements(HookContext& c);

// The terms of the TCD field's stages (the principal stage has its own).
const std::vector<std::string>& TcdTerms() {
  static const std::vector<std::string> terms = {"tcd_dirichlet", "tcd_transversality",
                                                 "tcd_singularity_avoidance",
                                                 "tcd_singularity_placement", "tcd_prescribed_direction"};
  return terms;
}

// field.preprocess (fields/principal_field.h, steps 1–3): the reliability of
// every face, the start of the smoothing (the measured directions,
// propagated into the unreliable faces) and the element sets of principal_fit
// and principal_smoothing (empty when off).
void InitPrincipal(HookContext& c) {
  const Settings& s = *c.settings;
  const Mesh& mesh = c.store->mesh();
  FieldState& state = c.State<FieldState>();
  const FieldGeometry& g = state.geometry;
  state.principal_applied = false;
  state.measured.clear();
  state.reliability = PrincipalReliability{};
  ElementSet faces, edges;
  faces.site = Site::kFace;
  edges.site = Site::kEdge;
  faces.data_width = edges.data_width = 2;
  if (s.Bool("field.preprocess") && !AllFlat(g)) {
    state.reliability = Reliability(g.curvature, s.Number("field.unreliable_anisotropy"),
                                    s.Number("field.unreliable_flat"));
    const std::vector<double> theta = PropagatedAngles(mesh, g.transports, g.curvature, state.reliability);
    const double rho = s.Number("field.smoothing");
    const double mean_area = g.total_area / std::max<double>(1, double(mesh.number_of_faces()));
    const std::vector<bool> boundary = BoundaryVertices(mesh);
    for (FaceIndex f : mesh.faces()) {
      *c.store->At("principal", int(f.idx())) = theta[f.idx()];
      faces.Add(FaceVertices(mesh, f), int(f.idx()), int(f.idx()), -1, FaceFlags(mesh, boundary, f),
                {PrincipalAngle(g.curvature[f.idx()]),
                 (1 - rho) * state.reliability.weight[f.idx()] * g.frames.area[f.idx()] / mean_area});
    }
    for (const EdgeTransport& t : g.transports) {
      const HalfedgeIndex h = mesh.halfedge(t.edge);
      edges.Add({int(mesh.source(h).idx()), int(mesh.target(h).idx())}, int(t.edge.idx()),
                int(t.f.idx()), int(t.edge.idx()),
                boundary[mesh.source(h).idx()] || boundary[mesh.target(h).idx()] ? kBoundary : 0,
                {t.angle, rho * t.weight}, int(t.g.idx()));
    }
  }
  c.SetElements("principal_faces", std::move(faces));
  c.SetElements("principal_edges", std::move(edges));
}

// Before the field stage, with field.preprocess (step 4): every face's
// curvature takes the smoothed directions, and the TCD terms are built on it.
void ApplyPrincipal(HookContext& c) {
  FieldState& state = c.State<FieldState>();
  if (state.principal_applied) return;
  state.principal_applied = true;
  // A surface without curvature has no principal directions to smooth
  // (InitPrincipal left no reliability): the smooth fallback field applies.
  if (state.reliability.reliable.empty()) return;
  const double sign_tolerance = Jets(*c.settings).sign_tolerance;
  state.measured = state.geometry.curvature;
  for (FaceIndex f : c.store->mesh().faces()) {
    const double theta = *c.store->At("principal", int(f.idx()));
    state.geometry.curvature[f.idx()] = TurnedCurvature(state.measured[f.idx()], theta, sign_tolerance);
  }
  BuildFieldElements(c);
}

// Element sets, the start z_N = e1 and the validated constraints.
void InitConjugateField(HookContext& c) {
  const Settings& s = *c.settings;
  const Mesh& mesh = c.store->mesh();
  FieldState& state = c.State<FieldState>();
  state.geometry = ComputeFieldGeometry(mesh, Jets(s));
  const FieldGeometry& g = state.geometry;
  const int faces = int(mesh.number_of_faces());
  const std::vector<bool> boundary = BoundaryVertices(mesh);
  Constraints& con = state.constraints;
  con = Constraints{};

  auto no_face = [&](const std::string& key, long long id) {
    return s.Error(key, "face " + std::to_string(id) + " does not exist: " +
                            (s.String("mesh").empty() ? std::string("the mesh") : s.String("mesh")) +
                            " has " + std::to_string(faces) + " faces (ids are 0-based)");
  };
  for (long long id : s.Integers("field.singularities")) {
    if (id >= faces) throw no_face("field.singularities", id);
    const FaceCurvature& k = g.curvature[size_t(id)];
    if (!k.z_m_finite) {
      throw s.Error("field.singularities",
                    "face " + std::to_string(id) + " has mean curvature 0 (z_M at infinity): no "
                    "singularity can be placed there");
    }
    if ((k.z_m - V2(1, 0)).norm() >= 1.0) {
      throw s.Error("field.singularities",
                    "face " + std::to_string(id) + " has K ≤ 0: singularities there are fixed by "
                    "the surface [Zadravec 2010, Prop. 4]");
    }
    con.placements.push_back(int(id));
  }

  con.moves = ReadMoves(s);
  con.rotations = ReadRotations(s);
  for (Rotation& r : con.rotations) {
    const Vec3 y = c.frame.ToCanonical(Vec3{r.at.x(), r.at.y(), r.at.z()});
    const V3 centre(y[0], y[1], y[2]);
    int nearest = 0;
    for (int f = 0; f < faces; ++f) {
      if ((g.frames.centroid[size_t(f)] - centre).norm() < (g.frames.centroid[size_t(nearest)] - centre).norm()) {
        nearest = f;
      }
    }
    const double radius = r.radius / c.frame.scale;
    if ((g.frames.centroid[size_t(nearest)] - centre).norm() > radius) {
      const Origin at = s.Where("field.rotations");
      throw InputError(at.file, r.line, r.key + ".at",
                       "farther than the radius from every face of the surface: it turns nothing");
    }
    con.rotation_centre.push_back(nearest);
    r.at = g.frames.centroid[size_t(nearest)];
    r.radius = radius;
  }
  for (const Move& m : con.moves) {
    const Origin at = s.Where("field.moves");
    for (const auto& [name, f] : {std::make_pair(".from", m.from), std::make_pair(".to", m.to)}) {
      if (f >= faces) {
        throw InputError(at.file, m.line, m.key + name,
                         "face " + std::to_string(f) + " does not exist: the mesh has " +
                             std::to_string(faces) + " faces (ids are 0-based)");
      }
    }
    const FaceCurvature& k = g.curvature[size_t(m.to)];
    if (!k.z_m_finite || (k.z_m - V2(1, 0)).norm() >= 1.0) {
      throw InputError(at.file, m.line, m.key + ".to",
                       "face " + std::to_string(m.to) + " has K ≤ 0 or mean curvature 0: no "
                       "singularity can be moved there [Zadravec 2010, Prop. 4]");
    }
  }

  std::vector<Prescribed> prescribed = ReadDirections(s);
  for (const Prescribed& p : prescribed) {
    if (p.face >= faces) {
      const Origin at = s.Where("field.directions");
      throw InputError(at.file, p.line, p.key + ".face",
                       "face " + std::to_string(p.face) + " does not exist: the mesh has " +
                           std::to_string(faces) + " faces (ids are 0-based)");
    }
  }
  const std::string file = s.String("field.constraints");
  if (!file.empty()) {
    const Eigen::MatrixXd m = ReadDmat(file, "field.constraints");
    if (m.rows() != faces || m.cols() < 4) {
      throw InputError(file, 1, "field.constraints",
                       "expected one row per face (" + std::to_string(faces) +
                           ") and at least 4 columns (flag, direction); the file has " +
                           std::to_string(m.rows()) + " x " + std::to_string(m.cols()));
    }
    con.file_rows = int(m.rows());
    for (int f = 0; f < faces; ++f) {
      if (m(f, 0) == 0) continue;
      ++con.file_flagged;
      Prescribed p;
      p.face = f;
      p.direction = V3(m(f, 1), m(f, 2), m(f, 3));
      p.from_file = true;
      prescribed.push_back(p);
    }
  }
  const std::string raw_file = s.String("field.file");
  if (!raw_file.empty()) {
    const RawField raw = ReadRawField(raw_file, "field.file");
    if (raw.n != 1 && raw.n != 2 && raw.n != 4) {
      throw InputError(raw_file, 1, "field.file",
                       "a field of " + std::to_string(raw.n) + " directions per face has no pair of "
                       "lines to prescribe: give a line field (N = 1 or 2) or a cross or conjugate "
                       "field (N = 4: v, w, -v, -w)");
    }
    if (raw.vectors.rows() != faces) {
      throw InputError(raw_file, 1, "field.file",
                       "expected one row per face (" + std::to_string(faces) + "); the file has " +
                           std::to_string(raw.vectors.rows()));
    }
    con.raw_faces = faces;
    for (int f = 0; f < faces; ++f) {
      Prescribed p;
      p.face = f;
      p.direction = V3(raw.vectors(f, 0), raw.vectors(f, 1), raw.vectors(f, 2));
      p.from_file = true;
      p.key = "field.file";
      if (p.direction.squaredNorm() > 0) {
        prescribed.push_back(p);
      } else {
        ++con.raw_skipped;  // a face the file leaves without a direction
      }
    }
  }
  std::vector<Source> sources = ReadSources(s);
  for (Source& src : sources) {
    const Vec3 y = c.frame.ToCanonical(Vec3{src.at.x(), src.at.y(), src.at.z()});
    src.at = V3(y[0], y[1], y[2]);
  }
  for (int f = 0; f < faces && !sources.empty(); ++f) {
    const V3& x = g.frames.centroid[size_t(f)];
    V3 gradient = V3::Zero();
    for (const Source& src : sources) {
      const V3 r = x - src.at;
      gradient += src.strength * r / std::max(r.squaredNorm(), 1e-300);
    }
    const V2 d = ToFrame(g.frames, FaceIndex(f), gradient);
    const Eigen::Matrix2d& M = g.curvature[size_t(f)].M;
    const double m[3] = {M(0, 0), M(0, 1), M(1, 1)};
    V2 point, line;
    if (!(d.norm() > 1e-12 * std::max(1e-300, gradient.norm())) || !TcdPrescribedLine(m, d.data(), &point, &line) ||
        !TransversePartner(M, d)) {
      ++con.potential_skipped;
      continue;
    }
    con.from_potential.push_back({f, d.normalized()});
  }
  con.sources = int(sources.size());
  for (const Prescribed& p : prescribed) {
    const FaceIndex f(p.face);
    const V2 d = ToFrame(g.frames, f, ToCanonicalDirection(c.frame, p.direction));
    const double m[3] = {g.curvature[p.face].M(0, 0), g.curvature[p.face].M(0, 1),
                         g.curvature[p.face].M(1, 1)};
    V2 point, line;
    const bool ok = d.norm() > 1e-9 * std::max(1e-300, p.direction.norm()) &&
                    TcdPrescribedLine(m, d.data(), &point, &line);
    if (!ok) {
      if (p.from_file) {
        ++(p.key == "field.file" ? con.raw_skipped : con.file_skipped);
        continue;
      }
      const Origin at = s.Where("field.directions");
      throw InputError(at.file, p.line, p.key + ".direction",
                       "face " + std::to_string(p.face) +
                           ": the direction is normal to the face or every direction is conjugate "
                           "to it (zero curvature along it): it cannot be prescribed");
    }
    (p.key == "field.file" ? con.from_field_file : con.prescribed).push_back({p.face, d.normalized()});
  }

  AddGuideCurves(c, g, s.Number("terms.tcd_prescribed_direction.weight"), con);
  InitPrincipal(c);
  BuildFieldElements(c);
}

// The TCD terms' element sets and the start z_N = e1, from the field geometry
// (the measured curvature, or with field.preprocess the smoothed one) and
// the validated constraints.
void BuildFieldElements(HookContext& c) {
  const Settings& s = *c.settings;
  const Mesh& mesh = c.store->mesh();
  FieldState& state = c.State<FieldState>();
  const FieldGeometry& g = state.geometry;
  const int faces = int(mesh.number_of_faces());
  const std::vector<bool> boundary = BoundaryVertices(mesh);
  Constraints& con = state.constraints;

  // Boundary alignment: the boundary tangent as a prescribed direction of
  // every boundary face, weighted by field.boundary_alignment (a factor on
  // the prescribed-direction term's weight in the element data).
  const double prescribed_weight = s.Number("terms.tcd_prescribed_direction.weight");
  const double boundary_factor =
      prescribed_weight > 0 ? s.Number("field.boundary_alignment") / prescribed_weight : 0.0;
  std::vector<std::pair<int, V2>> along_boundary;
  if (boundary_factor > 0) {
    for (HalfedgeIndex h : mesh.halfedges()) {
      if (mesh.is_border(h) || !mesh.is_border(mesh.opposite(h))) continue;
      const FaceIndex f = mesh.face(h);
      const Point& a = mesh.point(mesh.source(h));
      const Point& b = mesh.point(mesh.target(h));
      const V2 d = ToFrame(g.frames, f, V3(b.x() - a.x(), b.y() - a.y(), b.z() - a.z()));
      const Eigen::Matrix2d& M = g.curvature[f.idx()].M;
      const double m[3] = {M(0, 0), M(0, 1), M(1, 1)};
      V2 point, line;
      if (d.norm() > 0 && TcdPrescribedLine(m, d.data(), &point, &line)) {
        along_boundary.push_back({int(f.idx()), d.normalized()});
      }
    }
  }
  con.boundary_faces = int(along_boundary.size());

  // The faces the user constrains (placements, moves, prescribed
  // directions): singularity avoidance (tcd_free_faces) leaves them alone.
  std::vector<bool> constrained(size_t(faces), false);
  for (int f : con.placements) constrained[size_t(f)] = true;
  for (const Move& m : con.moves) constrained[size_t(m.from)] = constrained[size_t(m.to)] = true;
  for (const auto& p : con.prescribed) constrained[size_t(p.first)] = true;
  for (const auto& p : con.from_field_file) constrained[size_t(p.first)] = true;
  for (const auto& p : con.from_potential) constrained[size_t(p.first)] = true;
  for (const auto& p : con.guided) constrained[size_t(p.face)] = true;

  ElementSet edges, all, free_faces, placements, directions;
  edges.site = Site::kEdge;
  edges.data_width = 2;
  for (const EdgeTransport& t : g.transports) {
    const HalfedgeIndex h = mesh.halfedge(t.edge);
    edges.Add({int(mesh.source(h).idx()), int(mesh.target(h).idx())}, int(t.edge.idx()),
              int(t.f.idx()), int(t.edge.idx()),
              boundary[mesh.source(h).idx()] || boundary[mesh.target(h).idx()] ? kBoundary : 0,
              {t.angle, t.weight}, int(t.g.idx()));
  }
  all.site = free_faces.site = placements.site = directions.site = Site::kFace;
  all.data_width = free_faces.data_width = 3;
  placements.data_width = 2;
  directions.data_width = 6;
  for (FaceIndex f : mesh.faces()) {
    const FaceCurvature& k = g.curvature[f.idx()];
    all.Add(FaceVertices(mesh, f), int(f.idx()), int(f.idx()), -1, FaceFlags(mesh, boundary, f),
            {k.z_m.x(), k.z_m.y(), k.z_m_finite ? 1.0 : 0.0});
    if (!constrained[f.idx()]) {
      free_faces.Add(FaceVertices(mesh, f), int(f.idx()), int(f.idx()), -1,
                     FaceFlags(mesh, boundary, f), {k.z_m.x(), k.z_m.y(), k.z_m_finite ? 1.0 : 0.0});
    }
    double* z = c.store->At("z_n", int(f.idx()));
    z[0] = 1.0;  // e1: the principal directions
    z[1] = 0.0;
  }
  for (int f : con.placements) {
    const FaceCurvature& k = g.curvature[size_t(f)];
    placements.Add(FaceVertices(mesh, FaceIndex(f)), f, f, -1, FaceFlags(mesh, boundary, FaceIndex(f)),
                   {k.z_m.x(), k.z_m.y()});
  }
  for (const auto& [list, factor] : {std::make_pair(&con.prescribed, 1.0),
                                     std::make_pair(&con.from_field_file, kFieldFileFactor),
                                     std::make_pair(&con.from_potential, kFieldFileFactor),
                                     std::make_pair(&along_boundary, boundary_factor)}) {
    for (const auto& [f, d] : *list) {
      const Eigen::Matrix2d& M = g.curvature[size_t(f)].M;
      directions.Add(FaceVertices(mesh, FaceIndex(f)), f, f, -1,
                     FaceFlags(mesh, boundary, FaceIndex(f)),
                     {M(0, 0), M(0, 1), M(1, 1), d.x(), d.y(), factor});
    }
  }
  state.prescribed = directions;  // the guide stage adds the guide curves' faces
  c.SetElements("tcd_edges", std::move(edges));
  c.SetElements("tcd_faces", std::move(all));
  c.SetElements("tcd_free_faces", std::move(free_faces));
  c.SetElements("tcd_placements", std::move(placements));
  c.SetElements("tcd_prescribed", std::move(directions));
}

// Before the `move` stage: each move's σ-blended correction (eq. 4), then
// every face outside the blends' transition bands (0 < β < 1) held constant:
// the re-optimisation smooths the seam of each blend and keeps the moved
// field inside r1 (re-optimising the whole disc pulls the singularity back
// to where the energy had it, e.g. to an umbilic).
void ApplyMoves(HookContext& c) {
  FieldState& state = c.State<FieldState>();
  Constraints& con = state.constraints;
  if (con.moved) return;
  con.moved = true;
  const Mesh& mesh = c.store->mesh();
  const FieldGeometry& g = state.geometry;
  const Origin at = c.settings->Where("field.moves");
  std::vector<bool> touched(mesh.number_of_faces(), false), held(mesh.number_of_faces(), false);
  for (const Move& m : con.moves) {
    std::vector<V2> z(mesh.number_of_faces());
    for (FaceIndex f : mesh.faces()) z[f.idx()] = Eigen::Map<const V2>(c.store->At("z_n", int(f.idx())));
    const double apart =
        (g.frames.centroid[size_t(m.from)] - g.frames.centroid[size_t(m.to)]).norm();
    const double inner = m.inner > 0 ? m.inner / c.frame.scale : 2 * apart;
    const double outer = m.outer > 0 ? m.outer / c.frame.scale : 2 * inner;
    if (outer <= inner) {
      throw InputError(at.file, m.line, m.key + ".outer_radius",
                       "must be larger than inner_radius (" + std::to_string(inner * c.frame.scale) + ")");
    }
    const SingularityMove move = MoveSingularity(mesh, g.frames, g.transports, g.curvature, z,
                                                 FaceIndex(m.from), FaceIndex(m.to), inner, outer);
    if (!move.error.empty()) throw InputError(at.file, m.line, m.key, move.error);
    if (!move.reached) {
      throw InputError(at.file, m.line, m.key + ".inner_radius",
                       "face " + std::to_string(m.to) + " is farther from face " +
                           std::to_string(m.from) + " (through the mesh) than inner_radius " +
                           std::to_string(inner * c.frame.scale) + ": the blend does not reach it");
    }
    int count = 0;
    for (FaceIndex f : mesh.faces()) {
      Eigen::Map<V2>(c.store->At("z_n", int(f.idx()))) = move.z_n[f.idx()];
      if (move.beta[f.idx()] > 0) ++count;
      if (move.beta[f.idx()] > 0 && move.beta[f.idx()] < 1) touched[f.idx()] = true;
    }
    held[size_t(m.to)] = true;
    int band = 0;
    for (FaceIndex f : mesh.faces()) band += move.beta[f.idx()] > 0 && move.beta[f.idx()] < 1;
    con.moves_done.push_back({{"from", m.from}, {"to", m.to}, {"inner_radius", inner * c.frame.scale},
                              {"outer_radius", outer * c.frame.scale}, {"faces_blended", count},
                              {"faces_reoptimised", band}});
  }
  for (FaceIndex f : mesh.faces()) {
    if (!touched[f.idx()] || held[f.idx()]) c.model->SetConstant("z_n", int(f.idx()));
  }
}

// Before the `guide` stage (field.guide_curves): the guide curves' faces join
// the prescribed directions and every face beyond the guide radius is held,
// so the free field of the first stage is kept there and the faces near the
// curves turn to them, the falloff band smoothing the seam.
void ApplyGuides(HookContext& c) {
  FieldState& state = c.State<FieldState>();
  Constraints& con = state.constraints;
  if (con.guides_applied) return;
  con.guides_applied = true;
  const Mesh& mesh = c.store->mesh();
  const std::vector<bool> boundary = BoundaryVertices(mesh);
  ElementSet set = state.prescribed;
  std::vector<bool> guided(mesh.number_of_faces(), false);
  for (const Constraints::Guided& p : con.guided) {
    const Eigen::Matrix2d& M = state.geometry.curvature[size_t(p.face)].M;
    set.Add(FaceVertices(mesh, FaceIndex(p.face)), p.face, p.face, -1,
            FaceFlags(mesh, boundary, FaceIndex(p.face)),
            {M(0, 0), M(0, 1), M(1, 1), p.direction.x(), p.direction.y(), p.factor});
    guided[size_t(p.face)] = true;
  }
  if (!con.rotations.empty()) {
    // The free field as the first stage left it, turned locally.
    std::vector<V2> z(mesh.number_of_faces());
    for (FaceIndex f : mesh.faces()) z[f.idx()] = Eigen::Map<const V2>(c.store->At("z_n", int(f.idx())));
    const TcdField free = EvaluateField(mesh, state.geometry, std::move(z));
    const double factor = c.settings->Number("field.guide_weight") /
                          std::max(1e-300, c.settings->Number("terms.tcd_prescribed_direction.weight"));
    con.rotation_faces.assign(con.rotations.size(), 0);
    con.free_v.assign(mesh.number_of_faces(), V2::Zero());
    for (FaceIndex f : mesh.faces()) {
      const ConjugatePair& pair = free.pairs[f.idx()];
      con.free_v[f.idx()] = pair.v;
      double angle = 0;
      for (size_t k = 0; k < con.rotations.size(); ++k) {
        const Rotation& r = con.rotations[k];
        const double w = GuideWeight((state.geometry.frames.centroid[f.idx()] - r.at).norm(), r.radius);
        if (w > 0) ++con.rotation_faces[k];
        angle += w * r.angle * M_PI / 180;
      }
      if (angle == 0 || guided[f.idx()] || !pair.valid) continue;
      const V2 d = Eigen::Rotation2Dd(angle) * pair.v.normalized();
      const Eigen::Matrix2d& M = state.geometry.curvature[f.idx()].M;
      const double m[3] = {M(0, 0), M(0, 1), M(1, 1)};
      V2 point, line;
      if (!TcdPrescribedLine(m, d.data(), &point, &line) || !TransversePartner(M, d)) {
        ++con.rotation_skipped;
        continue;
      }
      set.Add(FaceVertices(mesh, f), int(f.idx()), int(f.idx()), -1, FaceFlags(mesh, boundary, f),
              {M(0, 0), M(0, 1), M(1, 1), d.x(), d.y(), factor});
      guided[f.idx()] = true;
    }
  }
  c.SetElements("tcd_prescribed", std::move(set));
  for (FaceIndex f : mesh.faces()) {
    if (!guided[f.idx()]) c.model->SetConstant("z_n", int(f.idx()));
  }
}

double LineDeg(const V2& a, const V2& b) {
  return std::abs(WrapLineAngle(LineAngle(a) - LineAngle(b))) * 180.0 / M_PI;
}

// details.preprocess: the faces found unreliable, how far the smoothing
// turned the directions, and the field's conjugacy against the measured
// curvature (the field is conjugate to the smoothed one by construction).
nlohmann::json PreprocessDetails(const Mesh& mesh, const FieldState& state, const TcdField& field) {
  double reliable_max = 0, reliable_sum = 0, unreliable_sum = 0;
  int reliable = 0;
  for (FaceIndex f : mesh.faces()) {
    const double turned = std::abs(WrapLineAngle(PrincipalAngle(state.measured[f.idx()]) -
                                                 PrincipalAngle(state.geometry.curvature[f.idx()]))) *
                          180.0 / M_PI;
    if (state.reliability.reliable[f.idx()]) {
      reliable_max = std::max(reliable_max, turned);
      reliable_sum += turned;
      ++reliable;
    } else {
      unreliable_sum += turned;
    }
  }
  const int unreliable = int(mesh.number_of_faces()) - reliable;
  const TcdFieldStats measured = FieldStats(state.measured, field.pairs);
  return {{"reliable_faces", reliable},
          {"unreliable_umbilic_faces", state.reliability.umbilic},
          {"unreliable_flat_faces", state.reliability.flat},
          {"turned_reliable_max_deg", reliable_max},
          {"turned_reliable_mean_deg", reliable > 0 ? reliable_sum / reliable : 0.0},
          {"turned_unreliable_mean_deg", unreliable > 0 ? unreliable_sum / unreliable : 0.0},
          {"conjugacy_error_measured_max", measured.max_conjugacy_error}};
}

void FinishConjugateField(HookContext& c) {
  const Mesh& mesh = c.store->mesh();
  const FieldState& state = c.State<FieldState>();
  const FieldGeometry& geometry = state.geometry;
  const Constraints& con = state.constraints;
  std::vector<V2> z(mesh.number_of_faces());
  for (FaceIndex f : mesh.faces()) {
    const double* x = c.store->At("z_n", int(f.idx()));
    z[f.idx()] = V2(x[0], x[1]);
  }
  auto result = std::make_shared<FieldResult>();
  result->mesh = mesh;
  result->geometry = geometry;
  result->field = EvaluateField(mesh, geometry, std::move(z));
  result->frame = c.frame;
  const TcdField& field = result->field;

  // Deviation from the principal directions; prescribed directions met.
  double deviation = 0;
  int counted = 0;
  for (FaceIndex f : mesh.faces()) {
    const ConjugatePair& p = field.pairs[f.idx()];
    const FaceCurvature& k = geometry.curvature[f.idx()];
    if (!p.valid || k.flat || field.smooth_fallback) continue;
    deviation += std::min(LineDeg(p.v, k.d1), LineDeg(p.v, k.d2));
    ++counted;
  }
  double prescribed_max = 0, prescribed_mean = 0;
  for (const auto& [f, d] : con.prescribed) {
    const ConjugatePair& p = field.pairs[size_t(f)];
    const double e = p.valid ? std::min(LineDeg(d, p.v), LineDeg(d, p.w)) : 90.0;
    prescribed_max = std::max(prescribed_max, e);
    prescribed_mean += e / double(con.prescribed.size());
  }

  double file_max = 0, file_sum = 0;
  for (const auto& [f, dir] : con.from_field_file) {
    const ConjugatePair& p = field.pairs[size_t(f)];
    const double e = p.valid ? std::min(LineDeg(dir, p.v), LineDeg(dir, p.w)) : 90.0;
    file_max = std::max(file_max, e);
    file_sum += e;
  }
  const double file_mean = con.from_field_file.empty() ? 0.0 : file_sum / double(con.from_field_file.size());
  double potential_max = 0, potential_sum = 0;
  for (const auto& [f, dir] : con.from_potential) {
    const ConjugatePair& p = field.pairs[size_t(f)];
    const double e = p.valid ? std::min(LineDeg(dir, p.v), LineDeg(dir, p.w)) : 90.0;
    potential_max = std::max(potential_max, e);
    potential_sum += e;
  }
  double guide_max = 0, guide_sum = 0;
  int guide_full = 0;
  for (const Constraints::Guided& q : con.guided) {
    if (q.weight < 1) continue;
    const ConjugatePair& p = field.pairs[size_t(q.face)];
    const double e = p.valid ? std::min(LineDeg(q.direction, p.v), LineDeg(q.direction, p.w)) : 90.0;
    guide_max = std::max(guide_max, e);
    guide_sum += e;
    ++guide_full;
  }

  nlohmann::json& d = result->details;
  nlohmann::json singular = nlohmann::json::array();
  int plus = 0, minus = 0;
  for (const Singularity& s : field.singularities) {
    const Vec3 p = c.frame.FromCanonical(Vec3{s.position.x(), s.position.y(), s.position.z()});
    singular.push_back({{"vertex", int(s.vertex.idx())}, {"index", s.index}, {"position", {p[0], p[1], p[2]}}});
    (s.index > 0 ? plus : minus)++;
  }
  d["faces"] = mesh.number_of_faces();
  d["flat_faces"] = geometry.flat_faces;
  d["fallback"] = field.smooth_fallback ? "smooth orthogonal field of the face frames (e1, e2): "
                                          "the surface has no curvature"
                                        : "none";
  d["singularities"] = singular;
  d["index_sum"] = field.index_sum;
  d["valid_faces"] = field.stats.valid_faces;
  d["invalid_faces"] = field.stats.invalid_faces;
  d["conjugacy_error_max"] = field.stats.max_conjugacy_error;
  d["angle_min_deg"] = field.stats.min_angle_deg;
  d["angle_mean_deg"] = field.mean_angle_deg;
  d["principal_deviation_mean_deg"] = counted > 0 ? deviation / counted : 0.0;
  if (!state.measured.empty()) d["preprocess"] = PreprocessDetails(mesh, state, field);
  d["placements"] = con.placements.size();
  if (!con.moves_done.empty()) d["moves"] = con.moves_done;
  d["boundary_aligned_faces"] = con.boundary_faces;
  d["prescribed"] = {{"faces", con.prescribed.size()},
                     {"deviation_max_deg", prescribed_max},
                     {"deviation_mean_deg", prescribed_mean}};
  if (con.guide_curves > 0) {
    d["guide_curves"] = {{"curves", con.guide_curves},
                         {"radius", con.guide_radius},
                         {"faces", con.guided.size()},
                         {"faces_skipped", con.guide_skipped},
                         {"full_weight_faces", guide_full},
                         {"deviation_max_deg", guide_max},
                         {"deviation_mean_deg", guide_full ? guide_sum / guide_full : 0.0}};
  }
  if (!con.rotations.empty() && !con.free_v.empty()) {
    nlohmann::json rotations = nlohmann::json::array();
    for (size_t k = 0; k < con.rotations.size(); ++k) {
      const int f = con.rotation_centre[k];
      // The field's direction nearest to the free v turned by the angle:
      // how far it is from that target, and how far from the free v.
      const ConjugatePair& p = field.pairs[size_t(f)];
      const V2 target = Eigen::Rotation2Dd(con.rotations[k].angle * M_PI / 180) * con.free_v[size_t(f)];
      const V2 near = LineDeg(target, p.v) <= LineDeg(target, p.w) ? p.v : p.w;
      const double turned = p.valid ? LineDeg(con.free_v[size_t(f)], near) : 0.0;
      const double missed = p.valid ? LineDeg(target, near) : 90.0;
      const Vec3 at = c.frame.FromCanonical(Vec3{con.rotations[k].at.x(), con.rotations[k].at.y(),
                                                  con.rotations[k].at.z()});
      rotations.push_back({{"face", f},
                           {"at", {at[0], at[1], at[2]}},
                           {"radius", con.rotations[k].radius * c.frame.scale},
                           {"angle_deg", con.rotations[k].angle},
                           {"faces", con.rotation_faces[k]},
                           {"turned_at_centre_deg", turned},
                           {"deviation_at_centre_deg", missed}});
    }
    d["rotations"] = rotations;
    d["rotation_faces_skipped"] = con.rotation_skipped;
  }
  if (con.sources > 0) {
    d["potential"] = {{"sources", con.sources},
                      {"faces", con.from_potential.size()},
                      {"skipped", con.potential_skipped},
                      {"deviation_max_deg", potential_max},
                      {"deviation_mean_deg",
                       con.from_potential.empty() ? 0.0 : potential_sum / double(con.from_potential.size())}};
  }
  if (con.raw_faces > 0) {
    d["field_file"] = {{"faces", con.raw_faces},
                       {"skipped", con.raw_skipped},
                       {"deviation_max_deg", file_max},
                       {"deviation_mean_deg", file_mean}};
  }
  if (con.file_rows > 0) {
    d["constraints_file"] = {{"rows", con.file_rows},
                             {"flagged", con.file_flagged},
                             {"skipped", con.file_skipped}};
  }

  char line[512];
  std::string& h = result->headline;
  if (field.smooth_fallback) {
    h += "warning: the surface has no curvature (all " + std::to_string(mesh.number_of_faces()) +
         " faces flat): every pair of directions is conjugate; the field falls back to the smooth "
         "orthogonal field of the face frames (e1, e2)\n";
  }
  std::snprintf(line, sizeof line,
                "TCD field: %zu singularities (%d positive, %d negative), index sum %g; conjugacy "
                "error max %.2e; angle between v and w min %.1f°, mean %.1f°; deviation from the "
                "principal directions mean %.2f°\n",
                field.singularities.size(), plus, minus, field.index_sum,
                field.stats.max_conjugacy_error, field.stats.min_angle_deg, field.mean_angle_deg,
                counted > 0 ? deviation / counted : 0.0);
  h += line;
  if (con.sources > 0) {
    std::snprintf(line, sizeof line,
                  "potential field: %d sources and sinks, %zu faces prescribed (%d skipped), deviation "
                  "max %.2f°\n",
                  con.sources, con.from_potential.size(), con.potential_skipped, potential_max);
    h += line;
  }
  if (con.raw_faces > 0) {
    std::snprintf(line, sizeof line,
                  "field file: %zu of %d faces prescribed, deviation max %.2f°, mean %.2f°\n",
                  con.from_field_file.size(), con.raw_faces, file_max, file_mean);
    h += line;
  }
  if (con.guide_curves > 0) {
    std::snprintf(line, sizeof line,
                  "guide curves: %d, radius %.4g file units, %zu faces guided (%d at full weight: "
                  "deviation from the curve max %.2f°, mean %.2f°); %d faces not guided: the curve "
                  "runs within %.0f° of an asymptotic direction there (no transverse conjugate "
                  "partner)\n",
                  con.guide_curves, con.guide_radius, con.guided.size(), guide_full, guide_max,
                  guide_full ? guide_sum / guide_full : 0.0, con.guide_skipped, kGuideMinPairDeg);
    h += line;
  }
  if (!con.prescribed.empty()) {
    std::snprintf(line, sizeof line,
                  "prescribed directions: %zu faces, deviation max %.2f°, mean %.2f°%s\n",
                  con.prescribed.size(), prescribed_max, prescribed_mean,
                  con.file_skipped > 0
                      ? (" (" + std::to_string(con.file_skipped) + " rows of field.constraints "
                                                                   "skipped: not prescribable)")
                            .c_str()
                      : "");
    h += line;
  }
  if (field.stats.invalid_faces > 0) {
    std::snprintf(line, sizeof line,
                  "%d faces have no conjugate pair (flat, or exactly singular)\n",
                  field.stats.invalid_faces);
    h += line;
  }
  c.State<FieldState>().streamlines = FieldStreamlines(*c.settings, *result, &d, &h);
  for (const auto& [k, v] : d.items()) c.details[k] = v;
  c.headline += h;
  c.field = result;
}

void WriteConjugateField(HookContext& c) {
  const auto& result = c.field;
  if (const auto it = c.temporaries.find("field"); it != c.temporaries.end()) {
    WriteField(it->second, c.settings->String("output.field"), result->mesh, result->geometry, result->field,
               result->frame, "output.field");
  }
  if (const auto it = c.temporaries.find("streamlines"); it != c.temporaries.end()) {
    WriteStreamlinesObj(it->second, c.State<FieldState>().streamlines.lines, result->frame,
                        "output.streamlines");
  }
}

}  // namespace

ProblemDecl conjugate_field() {
  ProblemDecl d;
  d.name = "conjugate_field";
  d.summary = "a field of transverse conjugate directions (TCD field) on a triangle mesh";
  d.paper = "[Zadravec 2010, §2–4]";
  d.input = InputKind::kTriangles;
  d.terms = FieldTerms();
  d.keys = FieldKeys();
  for (const Key& k : StreamlineKeys()) d.keys.push_back(k);
  // Every round by LeanSolve's Cholesky steps (core/lean_solve.h), as
  // planar_quads: the same steps as Ceres' sparse_normal_cholesky without its
  // per-solve set-up (docs/performance.md, The layout path).
  d.defaults = {{"solver.back_end", std::string("lean")}};
  d.blocks = {{"z_n", Site::kFace, 2, FrameMap::kInvariant, false, Carry::kReinitialise, true,
               false, "z_N of the face in its own frame (Prop. 2; e1 = (1, 0): principal)"},
              {"principal", Site::kFace, 1, FrameMap::kInvariant, false, Carry::kReinitialise, false,
               false, "field.preprocess: the smoothed direction of largest curvature, its angle in "
               "the face's frame (radians)"}};
  d.check = [](const Settings& s) {
    CheckNoMultiresolution(s, "conjugate_field");
    if (s.Given("field.sources") && !s.String("field.file").empty()) {
      throw s.Error("field.sources", "field.file and field.sources each give the whole field: give one");
    }
    if ((!s.String("field.guide_curves").empty() || s.Given("field.rotations")) && s.Given("field.moves")) {
      throw s.Error("field.moves", "moves and guide curves or rotations hold different faces: give "
                                   "field.moves or field.guide_curves / field.rotations");
    }
    CheckFieldOutputs(s);
  };
  d.init = &InitConjugateField;
  d.stages = [](const Settings& settings) {
    std::vector<Stage> stages;
    Stage s;
    s.rounds_key = "field.rounds";
    if (settings.Bool("field.preprocess")) {
      s.name = "principal";
      s.terms = {"principal_fit", "principal_smoothing"};
      stages.push_back(s);
      s.before_round = &ApplyPrincipal;
    }
    s.name = "field";
    s.terms = TcdTerms();
    stages.push_back(s);
    if (!settings.String("field.guide_curves").empty() || settings.Given("field.rotations")) {
      s.name = "guide";
      s.before_round = &ApplyGuides;
      stages.push_back(s);
    }
    if (settings.Given("field.moves")) {
      s.name = "move";
      s.before_round = &ApplyMoves;
      stages.push_back(s);
    }
    return stages;
  };
  d.finish = &FinishConjugateField;
  d.output_keys = {"field", "streamlines"};
  d.write = &WriteConjugateField;
  d.colors = "none";  // the mesh is not changed: the field is the result (output.field)
  return d;
}

}  // namespace archgeo::problems
