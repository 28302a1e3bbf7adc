// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — visual-smoothness analysis [Pellis 2019, §2–§5.3].
#include "analysis/smoothness_metrics.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <Eigen/Geometry>
#include <glog/logging.h>

#include "core/solver_options.h"
#include "core/newell.h"
#include "mesh/eigen_point.h"

namespace archgeo {
namespace {

using V = Eigen::Vector3d;

bool IsZero(const V& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }
Vec3 ToArray(const V& x) { return {x[0], x[1], x[2]}; }

// Consecutive normals closer than this are one vertex of the normal pyramid.
constexpr double kSameNormal = 1e-9;
// Sign tests of the arc-crossing predicate on unit vectors.
constexpr double kArcSide = 1e-12;

// Out-halfedges v → w_j of v in counter-clockwise order (seen from the
// normals' side): face(h_j) lies between w_j and w_{j+1}, and the next
// out-halfedge is opposite(prev(h_j)). Empty for an isolated vertex.
std::vector<HalfedgeIndex> OutHalfedges(const Mesh& mesh, VertexIndex v) {
  std::vector<HalfedgeIndex> out;
  const HalfedgeIndex in = mesh.halfedge(v);
  if (in == Mesh::null_halfedge()) return out;
  HalfedgeIndex h = mesh.opposite(in);
  // On a boundary, start at the out-halfedge whose right side is the border
  // so that the walk covers the whole fan before reaching the border.
  for (HalfedgeIndex g : CGAL::halfedges_around_source(h, mesh)) {
    if (mesh.is_border(mesh.opposite(g))) h = g;
  }
  const HalfedgeIndex start = h;
  do {
    out.push_back(h);
    if (mesh.is_border(h)) break;
    h = mesh.opposite(mesh.prev(h));
  } while (h != start);
  return out;
}

// Do the great-circle arcs ab and cd (unit vectors, each shorter than π)
// cross at an interior point of both? c, d strictly on different sides of the
// plane of ab, a, b strictly on different sides of the plane of cd, and the
// crossing point of arc ab with the great circle cd is the one on arc cd.
bool ArcsCross(const V& a, const V& b, const V& c, const V& d) {
  const V n1 = a.cross(b), n2 = c.cross(d);
  const double sc = n1.dot(c), sd = n1.dot(d), sa = n2.dot(a), sb = n2.dot(b);
  const bool split_cd = (sc > kArcSide && sd < -kArcSide) || (sc < -kArcSide && sd > kArcSide);
  const bool split_ab = (sa > kArcSide && sb < -kArcSide) || (sa < -kArcSide && sb > kArcSide);
  if (!split_cd || !split_ab) return false;
  const V on_ab = std::abs(sb) * a + std::abs(sa) * b;
  const V on_cd = std::abs(sd) * c + std::abs(sc) * d;
  return on_ab.dot(on_cd) > 0;
}

// The normal-pyramid test of VertexStar::self_intersecting_pyramid.
bool PyramidSelfIntersects(const std::vector<V>& normals) {
  std::vector<V> p;
  for (const V& n : normals) {
    if (p.empty() || (n - p.back()).norm() > kSameNormal) p.push_back(n);
  }
  while (p.size() > 1 && (p.front() - p.back()).norm() <= kSameNormal) p.pop_back();
  const size_t m = p.size();
  for (size_t i = 0; i < m && m > 1; ++i) {
    if ((p[i] + p[(i + 1) % m]).norm() <= kSameNormal) return true;  // antipodal side
  }
  if (m < 4) return false;
  for (size_t i = 0; i < m; ++i) {
    for (size_t j = i + 2; j < m; ++j) {
      if (i == 0 && j == m - 1) continue;  // adjacent through the closing side
      if (ArcsCross(p[i], p[(i + 1) % m], p[j], p[(j + 1) % m])) return true;
    }
  }
  return false;
}

int Sign(double h, double length) {
  if (std::abs(h) <= kOnPlane * length) return 0;
  return h > 0 ? 1 : -1;
}

// The good-saddle conditions of VertexStar::good_saddle for a valence-6
// triangle star w (positions relative to v) with unit test normal n and face
// normals fn[j] of v w_j w_{j+1}.
bool IsGoodSaddle(const std::vector<V>& w, const std::vector<V>& fn, const V& n,
                  const std::vector<int>& sign) {
  const int k = 6;
  for (int s : sign) {
    if (s == 0) return false;
  }
  // Groups of equal signs, cyclically, starting after a sign change.
  int start = 0;
  while (sign[start] == sign[(start + k - 1) % k]) ++start;
  std::vector<int> groups;
  for (int j = 0; j < k; ++j) {
    const int s = sign[(start + j) % k];
    if (j == 0 || s != sign[(start + j - 1) % k]) {
      groups.push_back(1);
    } else {
      ++groups.back();
    }
  }
  if (groups.size() != 4) return false;
  const bool alternate12 = (groups[0] == 1 && groups[1] == 2 && groups[2] == 1 && groups[3] == 2) ||
                           (groups[0] == 2 && groups[1] == 1 && groups[2] == 2 && groups[3] == 1);
  if (!alternate12) return false;

  // 1-1 projection: every face keeps its orientation in the test plane.
  for (int j = 0; j < k; ++j) {
    if (w[j].cross(w[(j + 1) % k]).dot(n) <= 0) return false;
  }
  // The 4 crossing segments (from v to the zero of the height on w_j w_{j+1}),
  // projected to the plane, are not in a common half-plane: the largest
  // angular gap between consecutive ones is < π.
  V t1 = n.cross(std::abs(n[0]) < 0.9 ? V::UnitX() : V::UnitY());
  t1 = (1 / t1.norm()) * t1;
  const V t2 = n.cross(t1);
  std::vector<double> angles;
  for (int j = 0; j < k; ++j) {
    const V& a = w[j];
    const V& b = w[(j + 1) % k];
    const double ha = n.dot(a), hb = n.dot(b);
    if (sign[j] == sign[(j + 1) % k]) continue;
    const V x = a + ha / (ha - hb) * (b - a);
    angles.push_back(std::atan2(x.dot(t2), x.dot(t1)));
  }
  CHECK_EQ(angles.size(), 4u);
  std::sort(angles.begin(), angles.end());
  double gap = angles.front() + 2 * M_PI - angles.back();
  for (size_t i = 1; i < angles.size(); ++i) gap = std::max(gap, angles[i] - angles[i - 1]);
  if (gap >= M_PI) return false;

  // The faces missing the plane (both neighbours on one side) are no
  // inflection faces.
  for (int j = 0; j < k; ++j) {
    if (sign[j] != sign[(j + 1) % k]) continue;
    const double before = fn[j].dot(w[(j + k - 1) % k]);
    const double after = fn[j].dot(w[(j + 2) % k]);
    const double scale_before = w[(j + k - 1) % k].norm(), scale_after = w[(j + 2) % k].norm();
    const int s_before = Sign(before, scale_before), s_after = Sign(after, scale_after);
    if (s_before * s_after < 0) return false;
  }
  return true;
}

unsigned char Channel(double x) {
  return static_cast<unsigned char>(std::lround(255 * std::clamp(x, 0.0, 1.0)));
}

}  // namespace

Vec3 FaceNormal(const Mesh& mesh, FaceIndex f) {
  std::vector<V> p;
  for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) p.push_back(EigenPoint(mesh, v));
  const size_t k = p.size();
  V n = V::Zero();
  if (k == 3) {
    n = (p[1] - p[0]).cross(p[2] - p[0]);  // exact
  } else if (k == 4) {
    n = (p[2] - p[0]).cross(p[3] - p[1]);  // diagonals
  } else {
    n = NewellVector(int(k), [&](int i) -> const V& { return p[size_t(i)]; });
  }
  double longest = 0;
  for (size_t i = 0; i < k; ++i) longest = std::max(longest, (p[(i + 1) % k] - p[i]).norm());
  const double length = n.norm();
  if (!(length > kDegenerateNormal * longest * longest) || !std::isfinite(length)) {
    return {0, 0, 0};
  }
  return ToArray((1 / length) * n);
}

std::vector<Vec3> FaceNormals(const Mesh& mesh) {
  std::vector<Vec3> normals(mesh.num_faces(), Vec3{0, 0, 0});
  const long n = long(mesh.num_faces());  // index slots, removed ones too
  const FullTeams teams;
#pragma omp parallel for schedule(static, 4096)
  for (long i = 0; i < n; ++i) {
    const FaceIndex f(static_cast<FaceIndex::size_type>(i));
    if (!mesh.is_removed(f)) normals[size_t(i)] = FaceNormal(mesh, f);
  }
  return normals;
}

Vec3 VertexNormal(const Mesh& mesh, const std::vector<Vec3>& face_normals, VertexIndex v) {
  CHECK_EQ(face_normals.size(), mesh.num_faces());
  if (mesh.halfedge(v) == Mesh::null_halfedge()) return {0, 0, 0};
  V sum = V::Zero();
  for (FaceIndex f : mesh.faces_around_target(mesh.halfedge(v))) {
    if (f != Mesh::null_face()) sum += EigenVector(face_normals[f.idx()]);
  }
  const double length = sum.norm();
  if (!(length > 1e-12)) return {0, 0, 0};
  return ToArray((1 / length) * sum);
}

EdgeSmoothness MeasureEdgeSmoothness(const Mesh& mesh, const std::vector<Vec3>& face_normals) {
  CHECK_EQ(face_normals.size(), mesh.num_faces());
  EdgeSmoothness result;
  const size_t n = mesh.num_edges();
  result.length.assign(n, 0.0);
  result.dual_length.assign(n, 0.0);
  result.angle.assign(n, 0.0);
  result.energy.assign(n, 0.0);
  result.measured.assign(n, 0);
  const FullTeams teams;
#pragma omp parallel for schedule(static, 4096)
  for (long i = 0; i < long(n); ++i) {
    const EdgeIndex e(static_cast<EdgeIndex::size_type>(i));
    if (mesh.is_removed(e)) continue;
    const HalfedgeIndex h = mesh.halfedge(e);
    const double length = (EigenPoint(mesh, mesh.target(h)) - EigenPoint(mesh, mesh.source(h))).norm();
    result.length[e.idx()] = length;
    if (mesh.is_border(e)) continue;
    const V nf = EigenVector(face_normals[mesh.face(h).idx()]);
    const V ng = EigenVector(face_normals[mesh.face(mesh.opposite(h)).idx()]);
    if (IsZero(nf) || IsZero(ng)) continue;
    const double angle = std::atan2(nf.cross(ng).norm(), nf.dot(ng));  // |α_e| [§3]
    result.measured[e.idx()] = 1;
    result.dual_length[e.idx()] = (nf - ng).norm();  // ℓ*_e [§3]
    result.angle[e.idx()] = angle;
    result.energy[e.idx()] = length * angle;
  }
  return result;
}

std::array<double, 2> ShapeOperatorEigenvalues(const Mesh& mesh,
                                               const std::vector<Vec3>& face_normals,
                                               VertexIndex v) {
  CHECK_EQ(face_normals.size(), mesh.num_faces());
  const V n = EigenVector(VertexNormal(mesh, face_normals, v));
  if (IsZero(n)) return {0, 0};
  // W′_v = ½ Σ (n_f × n_f′)(w − v)ᵀ over measured out-edges   [Pellis 2019, §5.3]
  double w[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  const V pv = EigenPoint(mesh, v);
  for (HalfedgeIndex h : OutHalfedges(mesh, v)) {
    if (mesh.is_border(mesh.edge(h))) continue;
    const V nf = EigenVector(face_normals[mesh.face(h).idx()]);                   // left of v → w
    const V ng = EigenVector(face_normals[mesh.face(mesh.opposite(h)).idx()]);    // right of v → w
    if (IsZero(nf) || IsZero(ng)) return {0, 0};
    const V s = nf.cross(ng);
    const V d = EigenPoint(mesh, mesh.target(h)) - pv;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) w[i][j] += 0.5 * s[i] * d[j];
    }
  }
  // Compression of ½(W′ + W′ᵀ) to the tangent plane, in a basis t1, t2 ⊥ n.
  V t1 = n.cross(std::abs(n[0]) < 0.9 ? V::UnitX() : V::UnitY());
  t1 = (1 / t1.norm()) * t1;
  const V t2 = n.cross(t1);
  const auto form = [&](const V& a, const V& b) {
    double sum = 0;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) sum += a[i] * 0.5 * (w[i][j] + w[j][i]) * b[j];
    }
    return sum;
  };
  const double a = form(t1, t1), b = form(t1, t2), c = form(t2, t2);
  const double mean = 0.5 * (a + c), radius = std::hypot(0.5 * (a - c), b);
  return {mean + radius, mean - radius};
}

VertexStar ClassifyVertexStar(const Mesh& mesh, const std::vector<Vec3>& face_normals,
                              VertexIndex v) {
  CHECK_EQ(face_normals.size(), mesh.num_faces());
  VertexStar star;
  const std::vector<HalfedgeIndex> out = OutHalfedges(mesh, v);
  if (out.empty()) return star;
  std::vector<V> w, fn;
  bool triangles = true;
  for (HalfedgeIndex h : out) {
    if (mesh.is_border(h)) return star;  // boundary vertex
    const FaceIndex f = mesh.face(h);
    const V nf = EigenVector(face_normals[f.idx()]);
    if (IsZero(nf)) return star;
    fn.push_back(nf);
    w.push_back(EigenPoint(mesh, mesh.target(h)) - EigenPoint(mesh, v));
    triangles = triangles && mesh.degree(f) == 3;
  }
  const V n = EigenVector(VertexNormal(mesh, face_normals, v));
  if (IsZero(n)) return star;
  star.measured = true;
  star.valence = int(out.size());
  star.triangle_star = triangles;

  const int k = star.valence;
  std::vector<int> sign(k);
  for (int j = 0; j < k; ++j) sign[j] = Sign(n.dot(w[j]), w[j].norm());
  std::vector<int> nonzero;
  for (int s : sign) {
    if (s != 0) nonzero.push_back(s);
  }
  for (size_t j = 0; j < nonzero.size(); ++j) {
    if (nonzero[j] != nonzero[(j + 1) % nonzero.size()]) ++star.sign_changes;
  }
  star.saddle = star.sign_changes >= 4;
  star.good_saddle = star.saddle && triangles && k == 6 && IsGoodSaddle(w, fn, n, sign);
  star.self_intersecting_pyramid = PyramidSelfIntersects(fn);
  return star;
}

namespace {

// ComputeEdgeSmoothnessMetrics with the face normals it uses.
SmoothnessMetrics EdgeMetrics(const Mesh& mesh, const std::vector<Vec3>& normals) {
  SmoothnessMetrics m;
  m.vertices = int(mesh.number_of_vertices());
  m.faces = int(mesh.number_of_faces());
  m.edges = int(mesh.number_of_edges());
  for (FaceIndex f : mesh.faces()) m.degenerate_faces += IsZero(EigenVector(normals[f.idx()])) ? 1 : 0;

  const EdgeSmoothness edges = MeasureEdgeSmoothness(mesh, normals);
  for (EdgeIndex e : mesh.edges()) {
    const size_t i = e.idx();
    if (!edges.measured[i]) continue;
    ++m.interior_edges;
    m.E += edges.length[i] * edges.dual_length[i];  // [§3]
    m.E_prime += edges.energy[i];                   // [§3]
    m.max_edge_energy = std::max(m.max_edge_energy, edges.energy[i]);
  }
  return m;
}

}  // namespace

SmoothnessMetrics ComputeEdgeSmoothnessMetrics(const Mesh& mesh) {
  return EdgeMetrics(mesh, FaceNormals(mesh));
}

SmoothnessMetrics ComputeSmoothnessMetrics(const Mesh& mesh) {
  const std::vector<Vec3> normals = FaceNormals(mesh);
  SmoothnessMetrics m = EdgeMetrics(mesh, normals);
  // Each vertex's figures in parallel (they read only the mesh and the
  // normals), then summed in vertex order: the same sums as a serial pass.
  const long n = long(mesh.num_vertices());  // index slots, removed ones too
  std::vector<double> c(static_cast<size_t>(n), 0.0);
  std::vector<VertexStar> stars(static_cast<size_t>(n));
  {
    const FullTeams teams;
#pragma omp parallel for schedule(dynamic, 4096)
    for (long i = 0; i < n; ++i) {
      const VertexIndex v(static_cast<VertexIndex::size_type>(i));
      if (mesh.is_removed(v)) continue;
      const std::array<double, 2> lambda = ShapeOperatorEigenvalues(mesh, normals, v);
      c[size_t(i)] = std::abs(lambda[0]) + std::abs(lambda[1]);  // [§5.3]
      stars[size_t(i)] = ClassifyVertexStar(mesh, normals, v);
    }
  }
  for (VertexIndex v : mesh.vertices()) {
    m.C += c[v.idx()];
    const VertexStar& star = stars[v.idx()];
    if (!star.measured) continue;
    ++m.interior_vertices;
    m.self_intersecting_pyramids += star.self_intersecting_pyramid ? 1 : 0;
    if (!star.saddle) continue;
    ++m.saddles;
    if (!star.triangle_star) {
      ++m.unclassified_saddles;
    } else if (star.good_saddle) {
      ++m.good_saddles;
    } else {
      ++m.bad_saddles;
    }
  }
  return m;
}

nlohmann::json SmoothnessMetricsToJson(const SmoothnessMetrics& m, double scale) {
  CHECK_GT(scale, 0.0) << "SmoothnessMetricsToJson: scale must be positive";
  nlohmann::json json;
  const auto length = [&](const char* name, double x) {
    json[name] = x;
    json[std::string(name) + "_relative"] = x / scale;
  };
  json["vertices"] = m.vertices;
  json["faces"] = m.faces;
  json["edges"] = m.edges;
  json["interior_edges"] = m.interior_edges;
  json["interior_vertices"] = m.interior_vertices;
  json["degenerate_faces"] = m.degenerate_faces;
  length("E", m.E);
  length("E_prime", m.E_prime);
  length("C", m.C);
  length("max_edge_energy", m.max_edge_energy);
  json["saddles"] = m.saddles;
  json["good_saddles"] = m.good_saddles;
  json["bad_saddles"] = m.bad_saddles;
  json["unclassified_saddles"] = m.unclassified_saddles;
  json["self_intersecting_pyramids"] = m.self_intersecting_pyramids;
  return json;
}

std::string FormatSmoothnessMetrics(const SmoothnessMetrics& m) {
  char buffer[512];
  std::string text;
  const auto line = [&](const char* format, auto... args) {
    std::snprintf(buffer, sizeof buffer, format, args...);
    text += buffer;
  };
  line("E = %.6g  (sum of l*|n_f - n_f'| over %d interior edges)\n", m.E, m.interior_edges);
  line("E' = %.6g  (sum of l*|alpha|)\n", m.E_prime);
  line("C = %.6g  (sum over vertices of |lambda1| + |lambda2| of W')\n", m.C);
  line("max l*|alpha| = %.6g\n", m.max_edge_energy);
  line("saddles = %d of %d interior vertices (good %d, bad %d, unclassified %d)\n", m.saddles,
       m.interior_vertices, m.good_saddles, m.bad_saddles, m.unclassified_saddles);
  line("self-intersecting normal pyramids = %d\n", m.self_intersecting_pyramids);
  if (m.degenerate_faces > 0) line("degenerate faces = %d (not measured)\n", m.degenerate_faces);
  return text;
}

std::vector<std::array<unsigned char, 3>> SmoothnessColors(const Mesh& mesh,
                                                          const EdgeSmoothness& edges,
                                                          double red_at) {
  CHECK_EQ(edges.energy.size(), mesh.num_edges());
  if (!(red_at > 0)) {
    red_at = 0;
    for (double x : edges.energy) red_at = std::max(red_at, x);
  }
  std::vector<std::array<unsigned char, 3>> colors(mesh.num_faces(), {0, 255, 0});
  for (FaceIndex f : mesh.faces()) {
    double value = 0;
    for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(f))) {
      value = std::max(value, edges.energy[mesh.edge(h).idx()]);
    }
    // green -> yellow -> red, as PlanarityColors
    const double t = red_at > 0 ? std::clamp(value / red_at, 0.0, 1.0) : 0.0;
    colors[f.idx()] = {Channel(2 * t), Channel(2 * (1 - t)), 0};
  }
  return colors;
}

std::vector<std::array<unsigned char, 3>> BendingColors(const Mesh& mesh, double red_angle) {
  double mean = 0;
  for (EdgeIndex e : mesh.edges()) {
    mean += std::sqrt(CGAL::squared_distance(mesh.point(mesh.vertex(e, 0)),
                                             mesh.point(mesh.vertex(e, 1))));
  }
  mean /= std::max<size_t>(1, mesh.number_of_edges());
  return SmoothnessColors(mesh, MeasureEdgeSmoothness(mesh, FaceNormals(mesh)), red_angle * mean);
}

}  // namespace archgeo
