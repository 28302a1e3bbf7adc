// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `principal_symmetric`: make a triangle mesh principal-symmetric
// [Pellis 2019, §2.3, §5.2; Fig. 5, 14].
//
// Principal edges: exactly two opposite edges of each valence-6 vertex follow
// a principal curvature direction (one third of all edges of a regular mesh).
// They are given (a) by `principal_edges: FILE`, an edge-label file for a
// triangle mesh (geometry/principal_edges.h), or (b) by `split:`, which
// triangulates a quad mesh by one diagonal per quad and labels one of its
// three edge families:
//   split.diagonal: first | second     v0–v2 or v1–v3 of each quad (file order)
//   split.principal: diagonals | first | second
//       diagonals: the new diagonals (a quad mesh along directions symmetric to
//       the principal ones, e.g. an asymptotic net of a saddle); first /
//       second: a family of quad edges (a 60° rhombus mesh along curvature
//       lines); an inconsistent family is an input error.
// Exactly one of them. With split, the split mesh is the net solved (measured
// before and after, written). Interior valence-6 vertices with principal
// edges must have exactly two, opposite; others get no conditions (Fig. 14h).
// The labels follow Loop subdivision (multiresolution, scheme loop).
//
// Variables: per constrained vertex a sphere (unit normal sphere_normal,
// curvature sphere_curvature), per principal edge between two of them a unit
// strip_normal, per saddle two dummies (saddle_dummy). Terms, in residual
// order: co_spherical and saddle_sign (star by star), principal_strip,
// dihedral_energy (off by default), boundary_proximity, proximity, anchor,
// fairness (straight_triples), step. The conditions act as constraints:
// their weights are 10⁴–10⁶ times the regularisers' (measured on the example:
// with 100 against proximity 0.1 the co-sphericity stalled at ~7e-5; with
// 10⁴ against 0.01 it reaches 1e-6).
//
// Rounds (schedule.outer_iterations) re-project onto the reference, restart
// the saddle dummies (the saddles — angle sum > 2π in the input — are fixed
// for the run: re-classifying near parabolic lines made the set flicker) and
// solve, until every condition holds to tolerance.residual_max: the
// co-sphericity residual (distance to the sphere over the mean edge length),
// the strip coplanarity |det(unit(w − v), n(v), n(w))|, and at saddles
// κ n·(w − v) (a principal neighbour on the sphere's side beyond the
// tolerance is a violation).
#include <cmath>

#include <Eigen/Geometry>

#include "core/problem.h"
#include "core/input_error.h"
#include "io/io.h"
#include "io/output_files.h"
#include "geometry/principal_edges.h"
#include "analysis/smoothness_metrics.h"
#include "problems/declarations/design_band.h"
#include "problems/runtime/model.h"
#include "problems/declarations/suitability.h"

namespace archgeo::problems {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Labels : ProblemState {
  std::vector<VertexPair> edges;
  int vertices = 0;  // of the mesh they label
  int rounds = 0;    // rounds of the current level
  std::vector<double> input_residuals;  // ResidualPerFace of the input, for the pictures
};

bool Split(const Settings& s) { return s.Given("split.diagonal") || s.Given("split.principal"); }
bool EdgeFile(const Settings& s) { return !s.String("principal_edges").empty(); }

using V = Eigen::Vector3d;

V E(const Point& p) { return {p.x(), p.y(), p.z()}; }
V E(const Vec3& x) { return {x[0], x[1], x[2]}; }
V P(const Mesh& mesh, int v) { return E(mesh.point(VertexIndex(v))); }
V B(Store& store, const char* name, int i) { return Eigen::Map<const V>(store.At(name, i)); }

// x / |x|, or zero where |x| is 0 or NaN (Eigen's normalized() returns x
// itself there): a sphere normal a diverged solve left at zero or NaN.
V UnitOrZero(const V& x) {
  const double length = x.norm();
  return length > 0 ? V(x / length) : V::Zero();
}

double AngleSum(const Mesh& mesh, VertexIndex v) {
  double sum = 0;
  for (HalfedgeIndex h : CGAL::halfedges_around_target(mesh.halfedge(v), mesh)) {
    if (mesh.is_border(h)) continue;
    const V a = E(mesh.point(mesh.source(h))) - E(mesh.point(v));
    const V b = E(mesh.point(mesh.target(mesh.next(h)))) - E(mesh.point(v));
    sum += std::atan2(a.cross(b).norm(), a.dot(b));
  }
  return sum;
}

// The net solved: the input, or its quads split (labels from the split or
// the edge-label file); the star rule checked.
void Net(HookContext& c) {
  const Settings& s = *c.settings;
  Labels& labels = c.State<Labels>();
  Mesh triangles;
  if (Split(s)) {
    bool quads = false;
    for (FaceIndex f : c.input->faces()) quads = quads || c.input->degree(f) == 4;
    if (!quads) throw s.Error("mesh", "split: needs a mesh with quads");
    const Origin at = s.Where(s.Given("split.principal") ? "split.principal" : "split.diagonal");
    triangles = SplitQuads(*c.input, s.String("split.diagonal") == "second",
                           s.String("split.principal"), &labels.edges, at.file, "split");
    c.net.derived = true;
    c.net.mesh = triangles;
    c.net.source.resize(triangles.number_of_vertices());
    for (size_t i = 0; i < c.net.source.size(); ++i) c.net.source[i] = int(i);
    c.net.details = {{"net", "split"},
                     {"diagonal", s.String("split.diagonal")},
                     {"principal", s.String("split.principal")},
                     {"triangles", triangles.number_of_faces()}};
    c.net.headline = "solving the input split into " + std::to_string(triangles.number_of_faces()) +
                     " triangles (principal: " + s.String("split.principal") + ")\n";
  } else {
    for (FaceIndex f : c.input->faces()) {
      if (c.input->degree(f) != 3) {
        throw s.Error("mesh", "principal_edges needs a triangle mesh (use split: for quads)");
      }
    }
    labels.edges = ReadPrincipalEdges(s.String("principal_edges"), "principal_edges", *c.input);
    triangles = *c.input;
  }
  const std::string problem = CheckPrincipalStars(triangles, labels.edges);
  if (!problem.empty()) {
    throw s.Error(Split(s) ? "split.principal" : "principal_edges", problem);
  }
  labels.vertices = int(triangles.number_of_vertices());
  CheckPrincipalLabels(c, triangles, labels.edges);
}

// `classify`: marks the saddles (angle sum > 2π); then starts the dummies of
// the saddles at δ = sqrt(max(0, −κ n·(w − v))).
void UpdateSaddles(HookContext& c, bool classify) {
  Store& st = *c.store;
  const Mesh& mesh = st.mesh();
  const ElementSet& stars = c.model->Elements("principal_stars");
  for (size_t i = 0; i < stars.size(); ++i) {
    const int* s = stars.Vertices(i);
    double* saddle = st.At("saddle", s[0]);
    if (classify) saddle[0] = AngleSum(mesh, VertexIndex(s[0])) > 2 * kPi ? 1 : 0;
    if (saddle[0] == 0) continue;
    const V n = UnitOrZero(B(st, "sphere_normal", s[0]));
    const double kappa = st.At("sphere_curvature", s[0])[0];
    for (int k = 0; k < 2; ++k) {
      const double side = kappa * n.dot(P(mesh, s[1 + k]) - P(mesh, s[0]));
      st.At("saddle_dummy", s[0])[k] = std::sqrt(std::max(0.0, -side));
    }
  }
}

// Per level: the labels (followed through Loop subdivision), the element
// sets, the spheres fitted to the stars, the strip normals, the saddles.
void InitPrincipalSymmetric(HookContext& c) {
  Labels& labels = c.State<Labels>();
  Store& st = *c.store;
  const Mesh& mesh = st.mesh();
  if (int(mesh.number_of_vertices()) != labels.vertices) {
    labels.edges = FollowLoopSubdivision(mesh, labels.edges, labels.vertices,
                                         c.settings->spec_file());
    labels.vertices = int(mesh.number_of_vertices());
  }
  labels.rounds = 0;
  const std::set<VertexPair> principal(labels.edges.begin(), labels.edges.end());
  std::string problem;
  const std::vector<PrincipalStar> stars = PrincipalStars(mesh, principal, &problem);
  CHECK(problem.empty()) << problem;
  ElementSet star_set, strip_set;
  star_set.site = Site::kVertex;
  strip_set.site = Site::kEdge;
  std::vector<bool> sphere(mesh.number_of_vertices(), false);
  for (const PrincipalStar& s : stars) {
    star_set.Add({int(s.v.idx()), int(s.principal[0].idx()), int(s.principal[1].idx()),
                  int(s.other[0].idx()), int(s.other[1].idx()), int(s.other[2].idx()),
                  int(s.other[3].idx())},
                 int(s.v.idx()));
    sphere[s.v.idx()] = true;
  }
  for (const VertexPair& e : principal) {
    if (!sphere[e.first] || !sphere[e.second]) continue;
    const EdgeIndex edge = mesh.edge(mesh.halfedge(VertexIndex(e.first), VertexIndex(e.second)));
    strip_set.Add({e.first, e.second}, int(edge.idx()), -1, int(edge.idx()));
  }
  // Spheres fitted to the stars: the vertex normal, and the curvature of
  // the least-squares sphere through the four other neighbours.
  const std::vector<Vec3> face_normals = FaceNormals(mesh);
  for (const PrincipalStar& s : stars) {
    V n = E(VertexNormal(mesh, face_normals, s.v));
    if (n.norm() == 0) n = V::UnitZ();
    double ab = 0, aa = 0;
    for (VertexIndex w : s.other) {
      const V d = E(mesh.point(w)) - E(mesh.point(s.v));
      const double a = d.squaredNorm(), b = n.dot(d);
      ab += a * b;
      aa += a * a;
    }
    double* block = st.At("sphere_normal", int(s.v.idx()));
    for (int k = 0; k < 3; ++k) block[k] = n[k];
    st.At("sphere_curvature", int(s.v.idx()))[0] = aa > 0 ? 2 * ab / aa : 0.0;
    double* delta = st.At("saddle_dummy", int(s.v.idx()));
    delta[0] = delta[1] = 0;
  }
  for (size_t i = 0; i < strip_set.size(); ++i) {
    const int v = strip_set.Vertices(i)[0], w = strip_set.Vertices(i)[1];
    const V along = P(mesh, w) - P(mesh, v);
    V m = along.cross(B(st, "sphere_normal", v) + B(st, "sphere_normal", w));
    if (m.norm() == 0) m = along.cross(V::UnitX());
    const V u = UnitOrZero(m);
    double* block = st.At("strip_normal", strip_set.edge[i]);
    for (int k = 0; k < 3; ++k) block[k] = u[k];
  }
  c.SetElements("principal_stars", std::move(star_set));
  c.SetElements("principal_strips", std::move(strip_set));
  UpdateSaddles(c, true);
}

struct Conditions {
  int spheres = 0, strips = 0, saddle_terms = 0, saddle_violations = 0;
  double co_spherical_max = 0, strip_max = 0, saddle_excess = 0;
};

Conditions Measure(HookContext& c) {
  Store& st = *c.store;
  const Mesh& mesh = st.mesh();
  const double slack = c.settings->Number("tolerance.residual_max");
  Conditions r;
  const ElementSet& stars = c.model->Elements("principal_stars");
  const ElementSet& strips = c.model->Elements("principal_strips");
  r.spheres = int(stars.size());
  r.strips = int(strips.size());
  for (size_t i = 0; i < stars.size(); ++i) {
    const int* s = stars.Vertices(i);
    const V n = UnitOrZero(B(st, "sphere_normal", s[0]));
    const double kappa = st.At("sphere_curvature", s[0])[0];
    for (int k = 3; k < 7; ++k) {
      const V d = P(mesh, s[k]) - P(mesh, s[0]);
      r.co_spherical_max =
          std::max(r.co_spherical_max, std::abs(0.5 * kappa * d.squaredNorm() - n.dot(d)));
    }
    if (st.At("saddle", s[0])[0] == 0) continue;
    for (int k = 1; k < 3; ++k) {
      ++r.saddle_terms;
      const double side = kappa * n.dot(P(mesh, s[k]) - P(mesh, s[0]));
      r.saddle_excess = std::max(r.saddle_excess, side);
      if (side > slack) ++r.saddle_violations;
    }
  }
  for (size_t i = 0; i < strips.size(); ++i) {
    const int v = strips.Vertices(i)[0], w = strips.Vertices(i)[1];
    const V t = UnitOrZero(P(mesh, w) - P(mesh, v));
    const V nv = UnitOrZero(B(st, "sphere_normal", v)), nw = UnitOrZero(B(st, "sphere_normal", w));
    const double det = t.dot(nv.cross(nw));
    r.strip_max = std::max(r.strip_max, std::abs(det));
  }
  return r;
}

// Per face, the largest co-sphericity residual |½ κ |d|² − n·d| (mean edge
// lengths) of the constrained stars at its corners: the condition the
// problem drives to zero, as its pictures show it.
std::vector<double> ResidualPerFace(HookContext& c) {
  Store& st = *c.store;
  const Mesh& mesh = st.mesh();
  const ElementSet& stars = c.model->Elements("principal_stars");
  std::vector<double> at(mesh.num_vertices(), 0.0);
  for (size_t i = 0; i < stars.size(); ++i) {
    const int* s = stars.Vertices(i);
    const V n = UnitOrZero(B(st, "sphere_normal", s[0]));
    const double kappa = st.At("sphere_curvature", s[0])[0];
    for (int k = 3; k < 7; ++k) {
      const V d = P(mesh, s[k]) - P(mesh, s[0]);
      at[size_t(s[0])] = std::max(at[size_t(s[0])], std::abs(0.5 * kappa * d.squaredNorm() - n.dot(d)));
    }
  }
  std::vector<double> values(mesh.num_faces(), 0.0);
  for (FaceIndex f : mesh.faces()) {
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) {
      values[f.idx()] = std::max(values[f.idx()], at[v.idx()]);
    }
  }
  return values;
}

nlohmann::json Json(const Conditions& r) {
  return {{"spheres", r.spheres},
          {"strips", r.strips},
          {"saddle_terms", r.saddle_terms},
          {"co_spherical_max", r.co_spherical_max},
          {"strip_coplanarity_max", r.strip_max},
          {"saddle_violations", r.saddle_violations},
          {"saddle_excess_max", r.saddle_excess}};
}

}  // namespace

ProblemDecl principal_symmetric() {
  ProblemDecl d;
  d.name = "principal_symmetric";
  d.summary = "triangle meshes whose vertex stars have the symmetry of the principal directions";
  d.paper = "[Pellis 2019, §2.3, §5.2, Fig. 5, 14]";
  // Each step one CHOLMOD factorisation by LeanSolve (core/lean_solve.h):
  // the example meets its tolerances in 9 rounds / 484 iterations, where
  // Ceres spends every round's 100 iterations.
  d.defaults = {{"solver.back_end", std::string("lean")}};
  d.terms = {{"co_spherical", 1e4},
             {"saddle_sign", 1e6},
             {"principal_strip", 1e4},
             {"dihedral_energy", 0},
             {"boundary_proximity", 0.01},
             {"proximity", 0.01, {{"point_weight", 1e-4}}},
             {"anchor", 0},
             {"fairness", 1e-4, {{"relative_to_original", false}}, "straight_triples"},
             {"step", 0.001}};
  d.blocks = {
      {"sphere_normal", Site::kVertex, 3, FrameMap::kDirection, true, Carry::kReinitialise, false,
       false, "unit normal of a vertex's sphere"},
      {"sphere_curvature", Site::kVertex, 1, FrameMap::kInverseLength, false,
       Carry::kReinitialise, false, false, "signed curvature of a vertex's sphere"},
      {"strip_normal", Site::kEdge, 3, FrameMap::kDirection, true, Carry::kReinitialise, false,
       false, "unit normal of a principal edge's strip plane"},
      {"saddle_dummy", Site::kVertex, 2, FrameMap::kInvariant, false, Carry::kReinitialise, false,
       false, "the dummies δ of a saddle's two principal neighbours"},
      {"saddle", Site::kVertex, 1, FrameMap::kInvariant, false, Carry::kReinitialise, false, true,
       "1 at a saddle (angle sum > 2π in the input)"}};
  Key edges;
  edges.name = "principal_edges";
  edges.type = Type::kInputPath;
  edges.doc = "edge-label file: one principal edge \"i j\" per line (triangle meshes)";
  d.keys = {edges,
            ChoiceKey("split.diagonal", "first", {"first", "second"},
                      "split each quad by its first (v0–v2) or second (v1–v3) diagonal"),
            ChoiceKey("split.principal", "diagonals", {"diagonals", "first", "second"},
                      "the principal family after the split"),
            NumberKey("tolerance.residual_max", 1e-5, 0, 1,
                      "stop when every condition residual is at most this")};
  d.output_keys = {"principal_edges"};
  d.check = [](const Settings& s) {
    if (Split(s) == EdgeFile(s)) {
      throw s.Error(Split(s) ? "split" : "principal_edges",
                    Split(s) ? "give either split or principal_edges, not both"
                             : "principal_symmetric needs principal_edges: FILE or split: "
                               "{diagonal, principal}");
    }
  };
  d.net = &Net;
  d.init = [](HookContext& c) {
    InitPrincipalSymmetric(c);
    if (c.level == 0) {
      c.details["conditions_before"] = Json(Measure(c));
      c.State<Labels>().input_residuals = ResidualPerFace(c);
    }
  };
  d.measures = {
      {"co_spherical_max", [](HookContext& c) { return Measure(c).co_spherical_max; }},
      {"strip_max", [](HookContext& c) { return Measure(c).strip_max; }},
      {"saddle_excess", [](HookContext& c) { return Measure(c).saddle_excess; }},
      {"saddle_violations", [](HookContext& c) { return double(Measure(c).saddle_violations); }}};
  d.stages = [](const Settings&) {
    Stage s;
    s.rounds_key = "schedule.outer_iterations";
    s.tolerances = {{"co_spherical_max", "tolerance.residual_max"},
                    {"strip_max", "tolerance.residual_max"},
                    {"saddle_excess", "tolerance.residual_max"}};
    s.logged = {"co_spherical_max", "strip_max", "saddle_violations", "E"};
    s.before_round = [](HookContext& c) {
      if (c.State<Labels>().rounds++ > 0) UpdateSaddles(c, false);
    };
    return std::vector<Stage>{s};
  };
  d.finish = [](HookContext& c) {
    const Conditions r = Measure(c);
    c.details["principal_edges"] = int(c.State<Labels>().edges.size());
    c.details["conditions_after"] = Json(r);
    char line[300];
    std::snprintf(line, sizeof line,
                  "principal-symmetric: %d spheres, %d strips, %d saddle terms; co-sphericity "
                  "max %.3e, strip coplanarity max %.3e, saddle violations %d\n",
                  r.spheres, r.strips, r.saddle_terms, r.co_spherical_max, r.strip_max,
                  r.saddle_violations);
    c.headline += line;
  };
  d.write = [](HookContext& c) {
    const auto it = c.temporaries.find("principal_edges");
    if (it == c.temporaries.end()) return;
    std::string text =
        "# principal edges of the output mesh (archgeo principal_symmetric): \"i j\", "
        "0-based vertex indices\n";
    for (const VertexPair& e : c.State<Labels>().edges) {
      text += std::to_string(e.first) + " " + std::to_string(e.second) + "\n";
    }
    WriteTextFile(it->second, text, "output.principal_edges");
  };
  d.analyses = {"smoothness"};
  d.state_colors = {"co_spherical_residual",
                    "co-sphericity: the largest |½κ|d|² − n·d| of the stars at the face's corners",
                    "mean edge lengths", [](HookContext& c, bool input) {
                      return input ? c.State<Labels>().input_residuals : ResidualPerFace(c);
                    }};
  // The deviation band (problems/declarations/design_band.h) only if set;
  // its examples state one.
  return WithDesignBand(std::move(d), 0);
}

}  // namespace archgeo::problems
