// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "analysis/validity.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>

#include <Eigen/Geometry>

#include "core/newell.h"
#include "core/solver_options.h"
#include "geometry/reference.h"
#include "mesh/topology.h"

namespace archgeo {
namespace {

constexpr double kDegrees = 180.0 / 3.14159265358979323846;
// An edge the input had this short (× its mean edge length) is collapsed: a
// short edge the input had by design (a thin part of the surface) is not.
constexpr double kCollapsed = 1e-3;

using V = Eigen::Vector3d;

std::vector<V> Corners(const Mesh& mesh, FaceIndex f) {
  std::vector<V> p;
  for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
    const Point& x = mesh.point(v);
    p.emplace_back(x.x(), x.y(), x.z());
  }
  return p;
}

// The unit Newell normal, or zero for a panel without area.
V Newell(const std::vector<V>& p) {
  return NewellNormal(int(p.size()), [&](int i) -> const V& { return p[size_t(i)]; });
}

// A panel's shape in the plane of its Newell normal.
struct Panel {
  std::vector<double> interior;  // interior angle per corner, degrees
  bool bow_tie = false;
  double aspect = 1;             // longest / shortest side
};

bool Cross2(const std::array<double, 2>& a, const std::array<double, 2>& b,
            const std::array<double, 2>& c, const std::array<double, 2>& d) {
  auto orient = [](const std::array<double, 2>& p, const std::array<double, 2>& q,
                   const std::array<double, 2>& r) {
    return (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
  };
  const double o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a),
               o4 = orient(c, d, b);
  return ((o1 > 0) != (o2 > 0)) && ((o3 > 0) != (o4 > 0)) && o1 != 0 && o2 != 0 && o3 != 0 &&
         o4 != 0;
}

Panel Shape(const std::vector<V>& p) {
  Panel panel;
  const size_t k = p.size();
  const V n = Newell(p);
  const V side1 = p[1] - p[0];
  const V in_plane = side1 - side1.dot(n) * n;
  const double length = in_plane.norm();
  // e1 is zero where the first side has no length in the plane (or is NaN).
  const V e1 = length > 0 ? V(in_plane / length) : V::Zero();
  const V e2 = n.cross(e1);
  std::vector<std::array<double, 2>> q(k);
  for (size_t i = 0; i < k; ++i) {
    const V d = p[i] - p[0];
    q[i] = {d.dot(e1), d.dot(e2)};
  }
  double area = 0;
  for (size_t i = 0; i < k; ++i) {
    area += q[i][0] * q[(i + 1) % k][1] - q[(i + 1) % k][0] * q[i][1];
  }
  const double s = area >= 0 ? 1.0 : -1.0;
  double shortest = 1e300, longest = 0;
  for (size_t i = 0; i < k; ++i) {
    const auto& a = q[(i + k - 1) % k];
    const auto& b = q[i];
    const auto& c = q[(i + 1) % k];
    const double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - b[0], vy = c[1] - b[1];
    const double turn = std::atan2(s * (ux * vy - uy * vx), ux * vx + uy * vy);  // left turn > 0
    panel.interior.push_back(180.0 - turn * kDegrees);
    const double side = (p[(i + 1) % k] - p[i]).norm();
    shortest = std::min(shortest, side);
    longest = std::max(longest, side);
  }
  panel.aspect = shortest > 0 ? longest / shortest : 1e300;
  for (size_t i = 0; i < k && !panel.bow_tie; ++i) {
    for (size_t j = i + 2; j < k; ++j) {
      if ((j + 1) % k == i) continue;  // adjacent through the wrap
      if (Cross2(q[i], q[(i + 1) % k], q[j], q[(j + 1) % k])) {
        panel.bow_tie = true;
        break;
      }
    }
  }
  return panel;
}

double Angle(const V& a, const V& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * kDegrees;
}

void Note(ValidityCheck& c, double value, int element, bool worse_is_larger = true) {
  if (c.count == 0 || (worse_is_larger ? value > c.worst : value < c.worst)) {
    c.worst = value;
    c.example = element;
  }
  ++c.count;
  if (c.elements.size() < ValidityCheck::kMaxListed) c.elements.push_back(element);
}

// A defect the input had too: counted as inherited, and as a failure unless
// the limits allow input defects.
void NoteInherited(ValidityCheck& c, double value, int element, bool allowed,
                   bool worse_is_larger = true) {
  ++c.inherited;
  if (!allowed) Note(c, value, element, worse_is_larger);
}

// One face's validity figures against its input shape (`before` empty: no
// input); what is new in the output only.
struct FaceFigures {
  bool bow_tie_new = false, reflex_new = false, small_new = false, aspect_new = false;
  bool bow_tie_old = false, reflex_old = false;  // the input's face had it too
  double worst_reflex = 0, worst_small = 180, aspect = 1;
};

FaceFigures Figures(const std::vector<V>& p, const std::vector<V>& before_corners,
                    const ValidityLimits& limits) {
  FaceFigures g;
  if (p.size() < 4) return g;
  const bool in = !before_corners.empty();
  const Panel now = Shape(p);
  const Panel before = in ? Shape(before_corners) : Panel{};
  g.bow_tie_new = now.bow_tie && !before.bow_tie;
  g.bow_tie_old = now.bow_tie && before.bow_tie;
  for (size_t i = 0; i < now.interior.size(); ++i) {
    const double bent = now.interior[i] - 180.0;
    const bool was_bent = in && before.interior[i] - 180.0 > limits.max_reflex_degrees;
    if (bent > limits.max_reflex_degrees) {
      (was_bent ? g.reflex_old : g.reflex_new) = true;
      g.worst_reflex = std::max(g.worst_reflex, bent);
    }
    const bool was_small = in && before.interior[i] < limits.min_corner_degrees;
    if (now.interior[i] < limits.min_corner_degrees && !was_small) {
      g.small_new = true;
      g.worst_small = std::min(g.worst_small, now.interior[i]);
    }
  }
  g.aspect = now.aspect;
  g.aspect_new = now.aspect > limits.max_aspect && !(in && before.aspect > limits.max_aspect);
  return g;
}

// Intersecting pairs of the mesh's triangulation, with exact predicates: the
// mesh's own kernel (Simple_cartesian<double>) calls nearly coplanar
// neighbours of a smooth surface intersecting.
size_t SelfIntersections(const Mesh& mesh) {
  using Exact = CGAL::Exact_predicates_inexact_constructions_kernel;
  using ExactMesh = CGAL::Surface_mesh<Exact::Point_3>;
  const Mesh triangles = TriangulatedCopy(mesh);
  ExactMesh exact;
  std::vector<ExactMesh::Vertex_index> map(triangles.num_vertices());
  for (VertexIndex v : triangles.vertices()) {
    const Point& p = triangles.point(v);
    map[v.idx()] = exact.add_vertex(Exact::Point_3(p.x(), p.y(), p.z()));
  }
  for (FaceIndex f : triangles.faces()) {
    std::vector<ExactMesh::Vertex_index> corners;
    for (VertexIndex v : CGAL::vertices_around_face(triangles.halfedge(f), triangles)) {
      corners.push_back(map[v.idx()]);
    }
    exact.add_face(corners);
  }
  std::vector<std::pair<ExactMesh::Face_index, ExactMesh::Face_index>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections(exact, std::back_inserter(pairs));
  return pairs.size();
}

}  // namespace

bool Validity::valid() const {
  for (const ValidityCheck& c : checks) {
    if (c.hard && !c.passed()) return false;
  }
  return true;
}

bool Validity::OnlyInherited() const {
  bool failed = false;
  for (const ValidityCheck& c : checks) {
    if (!c.hard || c.passed()) continue;
    if (c.count > c.inherited) return false;
    failed = true;
  }
  return failed;
}

std::string Validity::Reason() const {
  std::string text;
  for (const ValidityCheck& c : checks) {
    if (!c.hard || c.passed()) continue;
    char line[256];
    std::snprintf(line, sizeof line, "%s: %d (worst %.4g %s, limit %.4g%s)", c.name.c_str(),
                  c.count, c.worst, c.unit.c_str(), c.limit,
                  c.inherited > 0
                      ? ("; " + std::to_string(std::min(c.inherited, c.count)) + " as in the input")
                            .c_str()
                      : "");
    text += line;
    if (!c.elements.empty()) {
      const bool faces = c.name == "reflex_corners" || c.name == "bow_ties" ||
                         c.name == "flipped_faces";
      text += faces ? "; faces" : c.name == "finite" ? "; vertices" : "; elements";
      const size_t shown = std::min<size_t>(c.elements.size(), 12);
      for (size_t i = 0; i < shown; ++i) text += (i ? ", " : " ") + std::to_string(c.elements[i]);
      if (size_t(c.count) > shown) text += ", …";
    }
    text += "\n";
  }
  return text;
}

std::string Validity::Warnings() const {
  std::string text;
  for (const ValidityCheck& c : checks) {
    if (c.hard || c.passed()) continue;
    char line[256];
    std::snprintf(line, sizeof line, "%s: %d (worst %.4g %s, limit %.4g)\n", c.name.c_str(),
                  c.count, c.worst, c.unit.c_str(), c.limit);
    text += line;
  }
  return text;
}

nlohmann::json Validity::ToJson() const {
  nlohmann::json j = {{"valid", valid()},
                      {"allow_input_defects", allow_input_defects},
                      {"checks", nlohmann::json::array()}};
  for (const ValidityCheck& c : checks) {
    j["checks"].push_back({{"name", c.name},
                           {"hard", c.hard},
                           {"passed", c.passed()},
                           {"count", c.count},
                           {"worst", c.worst},
                           {"limit", c.limit},
                           {"unit", c.unit},
                           {"example", c.example},
                           {"inherited", c.inherited},
                           {"elements", c.elements}});
  }
  return j;
}

PanelShapes MeasurePanelShapes(const Mesh& mesh) {
  // Counts and a maximum: the same in any order.
  const long faces = long(mesh.num_faces());
  int panels = 0, nonconvex = 0;
  double worst_reflex = 0;
  const FullTeams teams;
#pragma omp parallel for schedule(dynamic, 4096) reduction(+ : panels, nonconvex) \
    reduction(max : worst_reflex)
  for (long i = 0; i < faces; ++i) {
    const FaceIndex f(static_cast<FaceIndex::size_type>(i));
    if (mesh.is_removed(f) || mesh.degree(f) < 4) continue;
    ++panels;
    const Panel panel = Shape(Corners(mesh, f));
    double worst = 0;
    for (double interior : panel.interior) worst = std::max(worst, interior - 180.0);
    if (worst > 0 || panel.bow_tie) ++nonconvex;
    worst_reflex = std::max(worst_reflex, worst);
  }
  PanelShapes shapes;
  shapes.panels = panels;
  shapes.nonconvex = nonconvex;
  shapes.worst_reflex_degrees = worst_reflex;
  return shapes;
}

Validity CheckValidity(const Mesh& out, const Mesh* input, const ValidityLimits& limits,
                       bool full) {
  const Mesh* in = input && SameConnectivity(*input, out) ? input : nullptr;
  ValidityCheck finite{"finite", true, 0, 0, 0, "non-finite vertices"};
  ValidityCheck reflex{"reflex_corners", true, 0, 0, limits.max_reflex_degrees, "degrees bent inward"};
  ValidityCheck bow_ties{"bow_ties", true, 0, 0, 0, "self-intersecting panels"};
  ValidityCheck flipped{"flipped_faces", true, 0, 0, limits.max_flip_degrees, "degrees turned"};
  ValidityCheck short_edges{"short_edges", true, 0, 0, limits.min_edge_relative,
                            "of the input's mean edge length"};
  ValidityCheck creases{"creases", true, 0, 0, limits.max_crease_increase_degrees,
                        "degrees of dihedral angle gained"};
  ValidityCheck intersections{"self_intersections", true, 0, 0, 0, "intersecting face pairs"};
  ValidityCheck small{"small_corners", false, 0, 0, limits.min_corner_degrees, "degrees"};
  ValidityCheck aspect{"aspect", false, 0, 0, limits.max_aspect, "longest / shortest side"};

  for (VertexIndex v : out.vertices()) {
    const Point& p = out.point(v);
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      Note(finite, 1, int(v.idx()));
    }
  }
  Validity result;
  result.allow_input_defects = limits.allow_input_defects;
  if (finite.count > 0) {
    result.checks = {finite};
    return result;
  }
  // Each face's and edge's figures in parallel (they read only the meshes),
  // then noted in index order, so the worst and its example are those of a
  // serial pass.
  const FullTeams teams;
  const long faces = long(out.num_faces());  // index slots, removed ones too
  std::vector<V> normal_out(static_cast<size_t>(faces), V::Zero()), normal_in;
  if (in) normal_in.resize(size_t(faces), V::Zero());
  std::vector<FaceFigures> figures(static_cast<size_t>(faces));
#pragma omp parallel for schedule(dynamic, 4096)
  for (long i = 0; i < faces; ++i) {
    const FaceIndex f(static_cast<FaceIndex::size_type>(i));
    if (out.is_removed(f)) continue;
    const std::vector<V> p = Corners(out, f);
    normal_out[size_t(i)] = Newell(p);
    if (in) normal_in[size_t(i)] = Newell(Corners(*in, f));
    figures[size_t(i)] = Figures(p, in ? Corners(*in, f) : std::vector<V>{}, limits);
  }
  for (long i = 0; i < faces; ++i) {
    if (out.is_removed(FaceIndex(static_cast<FaceIndex::size_type>(i)))) continue;
    const FaceFigures& g = figures[size_t(i)];
    if (in) {
      const double turned = Angle(normal_out[size_t(i)], normal_in[size_t(i)]);
      if (turned > limits.max_flip_degrees) Note(flipped, turned, int(i));
    }
    const bool allowed = limits.allow_input_defects;
    if (g.bow_tie_new) Note(bow_ties, 1, int(i));
    if (g.bow_tie_old) NoteInherited(bow_ties, 1, int(i), allowed);
    if (g.reflex_new) {
      Note(reflex, g.worst_reflex, int(i));
    } else if (g.reflex_old) {
      NoteInherited(reflex, g.worst_reflex, int(i), allowed);
    }
    if (g.small_new) Note(small, g.worst_small, int(i), false);
    if (g.aspect_new) Note(aspect, g.aspect, int(i));
  }
  double mean_in = 0;
  const Mesh& base = in ? *in : out;
  for (EdgeIndex e : base.edges()) mean_in += EdgeLength(base, e);
  mean_in /= std::max<size_t>(1, base.number_of_edges());
  const long edges = long(out.num_edges());
  std::vector<double> length(static_cast<size_t>(edges)), crease(static_cast<size_t>(edges), 0.0);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < edges; ++i) {
    const EdgeIndex e(static_cast<EdgeIndex::size_type>(i));
    if (out.is_removed(e)) continue;
    length[size_t(i)] = EdgeLength(out, e);
    if (!in || out.is_border(e)) continue;
    const FaceIndex a = out.face(out.halfedge(e, 0)), b = out.face(out.halfedge(e, 1));
    crease[size_t(i)] = Angle(normal_out[a.idx()], normal_out[b.idx()]) -
                        Angle(normal_in[a.idx()], normal_in[b.idx()]);
  }
  for (long i = 0; i < edges; ++i) {
    const EdgeIndex e(static_cast<EdgeIndex::size_type>(i));
    if (out.is_removed(e)) continue;
    const double length_in = in ? EdgeLength(*in, e) : 1e300;
    if (length[size_t(i)] < limits.min_edge_relative * mean_in) {
      if (length[size_t(i)] < 0.5 * length_in) {
        Note(short_edges, length[size_t(i)] / mean_in, int(i), false);
      } else if (length[size_t(i)] < kCollapsed * mean_in) {
        NoteInherited(short_edges, length[size_t(i)] / mean_in, int(i),
                      limits.allow_input_defects, false);
      }
    }
    if (crease[size_t(i)] > limits.max_crease_increase_degrees) Note(creases, crease[size_t(i)], int(i));
  }
  result.checks = {finite, reflex, bow_ties, flipped, short_edges, creases};
  if (full && limits.self_intersections) {
    const size_t pairs = SelfIntersections(out);
    // Relative whatever allow_input_defects says: a surface that crosses
    // itself by design (a Klein bottle) is the design, not a panel defect.
    if (pairs > 0 && !(input && SelfIntersections(*input) > 0)) {
      intersections.count = int(pairs);
      intersections.worst = double(pairs);
    }
    result.checks.push_back(intersections);
  }
  result.checks.push_back(small);
  result.checks.push_back(aspect);
  return result;
}

}  // namespace archgeo
