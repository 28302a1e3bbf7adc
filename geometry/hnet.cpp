// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — hyperbolic nets on a quad mesh [Shi, Wang, Pottmann 2014, §2.3,
// §3.2 step 2, §3.3, §4].
#include "geometry/hnet.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <glog/logging.h>

#include "core/input_error.h"
#include "io/output_stream.h"
#include "mesh/topology.h"

namespace archgeo {
namespace {

// Newton steps polishing a quartic root found by bisection (a step or two
// settle the last bits; the rest are cheap insurance).
constexpr int kNewtonSteps = 8;

Eigen::Vector3d HnetE(const Point& p) { return {p.x(), p.y(), p.z()}; }
Vec3 ToVec(const Eigen::Vector3d& x) { return {x[0], x[1], x[2]}; }
Eigen::Vector3d HnetE(const Vec3& x) { return {x[0], x[1], x[2]}; }

// Per interior edge, the layout of [Shi 2014, Fig. 2]: b0 (preferably of
// colour 0), b3 the other end point; left face (b0,b1,b2,b3) holds halfedge
// b3 → b0, right face (b0,b3,b4,b5) holds b0 → b3.
struct EdgeLayout {
  int b0 = -1, b3 = -1, left = -1, right = -1;
  JoinDeterminants determinants;
};

}  // namespace

double StarPlanarity(const Mesh& mesh, VertexIndex v) {
  if (mesh.is_isolated(v)) return 0.0;
  std::vector<Eigen::Vector3d> neighbours;
  for (VertexIndex w : mesh.vertices_around_target(mesh.halfedge(v))) {
    neighbours.push_back(HnetE(mesh.point(w)));
  }
  const Eigen::Vector3d p = HnetE(mesh.point(v));
  Eigen::Vector3d centroid = p;
  double mean_length = 0;
  for (const auto& w : neighbours) {
    centroid += w;
    mean_length += (w - p).norm();
  }
  centroid /= double(neighbours.size() + 1);
  mean_length /= double(neighbours.size());
  Eigen::Matrix3d covariance = (p - centroid) * (p - centroid).transpose();
  for (const auto& w : neighbours) covariance += (w - centroid) * (w - centroid).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const Eigen::Vector3d normal = solver.eigenvectors().col(0);  // smallest eigenvalue
  double max_distance = 0;
  for (const auto& w : neighbours) {
    max_distance = std::max(max_distance, std::abs(normal.dot(w - centroid)));
  }
  return mean_length > 0 ? max_distance / mean_length : 0.0;
}

StarPlanarities InteriorStarPlanarity(const Mesh& mesh) {
  const std::vector<bool> boundary = BoundaryVertices(mesh);
  StarPlanarities stars;
  stars.per_vertex.assign(mesh.num_vertices(), -1.0);
  double sum = 0;
  int count = 0;
  for (VertexIndex v : mesh.vertices()) {
    if (boundary[v.idx()] || mesh.is_isolated(v)) continue;
    const double planarity = StarPlanarity(mesh, v);
    stars.per_vertex[v.idx()] = planarity;
    stars.max = std::max(stars.max, planarity);
    sum += planarity;
    ++count;
  }
  if (count > 0) stars.mean = sum / count;
  return stars;
}

namespace {

// Patch corner order c0..c3 of a quad with c0c2 the chosen diagonal (see HNet).
std::array<int, 4> PatchVertices(const Mesh& mesh, const std::vector<int>& colour, FaceIndex f) {
  std::array<int, 4> v{};
  int k = 0;
  for (VertexIndex w : mesh.vertices_around_face(mesh.halfedge(f))) v[k++] = int(w.idx());
  const auto c = [&](int i) { return colour[v[i % 4]]; };
  int start = -1;
  for (int i = 0; i < 4 && start < 0; ++i) {
    if (c(i) == 0 && c(i + 2) == 0 && c(i + 1) == 1 && c(i + 3) == 1) start = i;
  }
  for (int i = 0; i < 4 && start < 0; ++i) {
    if (c(i) == 0 && c(i + 2) == 0) start = i;
  }
  for (int i = 0; i < 4 && start < 0; ++i) {
    if (c(i) == 0) start = i;
  }
  if (start < 0) start = 0;
  return {v[start], v[(start + 1) % 4], v[(start + 2) % 4], v[(start + 3) % 4]};
}

// Whether vertex `v` lies on the chosen diagonal c0c2 of a face.
bool OnDiagonal(const std::array<int, 4>& corners, int v) {
  return corners[0] == v || corners[2] == v;
}

// The face's shape parameter for its diagonal through vertex v (eq. 4: the
// other diagonal has 1/W).
double ShapeThrough(const std::array<int, 4>& corners, double W, int v) {
  return OnDiagonal(corners, v) ? W : 1.0 / W;
}

// Index i with corners[i] == from and corners[i+1] == to (patch edge i).
int PatchEdge(const std::array<int, 4>& corners, int from, int to) {
  for (int i = 0; i < 4; ++i) {
    if (corners[i] == from && corners[(i + 1) % 4] == to) return i;
  }
  LOG(FATAL) << "PatchEdge: " << from << " -> " << to << " is not an edge of the patch";
  return -1;
}

// Quartic p(λ) = A λ⁴ − B λ³ + C λ − D and its derivative.
struct ShapeQuartic {
  double A = 0, B = 0, C = 0, D = 0;
  double Value(double x) const { return ((A * x - B) * x * x + C) * x - D; }
  double Derivative(double x) const { return (4 * A * x - 3 * B) * x * x + C; }
};

SampledPatchwork RecomputeNormals(SampledPatchwork patchwork) {
  std::vector<Eigen::Vector3d> sums(patchwork.positions.size(), Eigen::Vector3d::Zero());
  for (const auto& t : patchwork.triangles) {
    const Eigen::Vector3d a = HnetE(patchwork.positions[t[0]]), b = HnetE(patchwork.positions[t[1]]),
                          c = HnetE(patchwork.positions[t[2]]);
    const Eigen::Vector3d n = (b - a).cross(c - a);  // 2 × area × unit normal
    for (int k : t) sums[k] += n;
  }
  patchwork.normals.assign(patchwork.positions.size(), Vec3{0, 0, 0});
  for (size_t i = 0; i < sums.size(); ++i) {
    const double norm = sums[i].norm();
    if (norm > 0) patchwork.normals[i] = ToVec(sums[i] / norm);
  }
  return patchwork;
}

}  // namespace

double ShapeEnergy(double lambda, const std::vector<double>& W) {
  CHECK(std::isfinite(lambda) && lambda > 0) << "lambda " << lambda;
  double energy = 0;
  for (double w : W) {
    CHECK(std::isfinite(w) && w > 0) << "shape parameter " << w;
    const double a = lambda * w - 1, b = 1 / (lambda * w) - 1;
    energy += a * a + b * b;
  }
  return energy;
}

namespace {

// The root of f in [lo, hi], where f(lo) and f(hi) have opposite signs (or
// one is 0), by bisection to the last bit.
template <class F>
double HnetBisect(const F& f, double lo, double hi) {
  const bool rising = f(lo) <= 0;
  for (int i = 0; i < 1100 && lo < hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    ((f(mid) <= 0) == rising ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// The positive roots where p crosses from below zero to above it: the minima
// of the shape energy, since dF/dλ = 2 p(λ) / λ³. A, B, C, D > 0, so
// p'' = 6λ(2Aλ − B) makes p' fall on (0, B/2A) and rise after it, with
// p'(0) = C > 0: p rises, then (if p'(B/2A) < 0) falls between the two
// roots of p', then rises; p(0) = −D < 0, and every root is below Cauchy's
// bound. Each rising stretch that crosses zero holds one such root.
std::vector<double> RisingRoots(const ShapeQuartic& q) {
  const auto p = [&](double x) { return q.Value(x); };
  const auto dp = [&](double x) { return q.Derivative(x); };
  const double bound = 1 + std::max({q.B, q.C, q.D}) / q.A;
  const double m = q.B / (2 * q.A);
  std::vector<std::pair<double, double>> rising = {{0.0, bound}};
  if (dp(m) < 0) rising = {{0.0, HnetBisect(dp, 0.0, m)}, {HnetBisect(dp, m, bound), bound}};
  std::vector<double> roots;
  for (const auto& [lo, hi] : rising) {
    if (p(lo) <= 0 && p(hi) >= 0) roots.push_back(HnetBisect(p, lo, hi));
  }
  return roots;
}

}  // namespace

double OptimalShapeScale(const std::vector<double>& W) {
  CHECK(!W.empty()) << "OptimalShapeScale of no shape parameters";
  ShapeQuartic q;
  for (double w : W) {
    CHECK(std::isfinite(w) && w > 0) << "shape parameter " << w;
    q.A += w * w;
    q.B += w;
    q.C += 1 / w;
    q.D += 1 / (w * w);
  }
  // [Shi 2014, eq. 11]: dF/dλ = 2(Aλ − B + C/λ² − D/λ³) = 0 ⇔ p(λ) = 0; the
  // energy's minima are p's rising roots, the best of them is the scale.
  double best = -1, best_energy = std::numeric_limits<double>::infinity();
  for (double x : RisingRoots(q)) {
    for (int step = 0; step < kNewtonSteps; ++step) {
      const double d = q.Derivative(x);
      if (d == 0) break;
      const double next = x - q.Value(x) / d;
      if (!(next > 0)) break;
      x = next;
    }
    const double energy = ShapeEnergy(x, W);
    if (energy < best_energy) {
      best_energy = energy;
      best = x;
    }
  }
  return best;
}

HNet BuildHNet(const Mesh& mesh, const HNetOptions& options) {
  CHECK(!mesh.has_garbage()) << "BuildHNet: collect_garbage() first";
  if (mesh.num_faces() == 0) throw InputError("", 0, "", "H-net: the mesh has no faces");
  if (options.start_face < 0 || options.start_face >= int(mesh.num_faces())) {
    throw InputError("", 0, "start_face",
                     "H-net: start face " + std::to_string(options.start_face) +
                         " is not a face index (0.." + std::to_string(mesh.num_faces() - 1) + ")");
  }
  if (options.kink_samples < 5) {
    throw InputError("", 0, "kink_samples", "H-net: need at least 5 kink samples per edge");
  }
  const int num_faces = int(mesh.num_faces());
  HNet hnet;
  hnet.start_face = options.start_face;

  // --- Checks: pure quad, odd valences, star planarity.
  for (FaceIndex f : mesh.faces()) {
    if (mesh.degree(f) != 4) hnet.non_quad_faces.push_back(int(f.idx()));
  }
  hnet.pure_quad = hnet.non_quad_faces.empty();
  if (!hnet.pure_quad) {
    throw InputError("", 0, "",
                     "H-net: the mesh is not pure quad (" +
                         std::to_string(hnet.non_quad_faces.size()) + " faces with != 4 sides, " +
                         "the first is face " + std::to_string(hnet.non_quad_faces[0]) + ")");
  }
  const StarPlanarities stars = InteriorStarPlanarity(mesh);
  hnet.star_planarity = stars.per_vertex;
  hnet.star_planarity_max = std::max(0.0, stars.max);
  hnet.star_planarity_mean = std::max(0.0, stars.mean);
  for (VertexIndex v : mesh.vertices()) {
    if (stars.per_vertex[v.idx()] >= 0 && mesh.degree(v) % 2 == 1) {
      hnet.odd_valence_vertices.push_back(int(v.idx()));
    }
  }

  // --- Diagonals from a 2-colouring [Shi 2014, Remark 5].
  hnet.colour = TwoColouring(mesh, &hnet.monochrome_edges);  // [Shi 2014, Remark 5]
  hnet.bipartite = hnet.monochrome_edges.empty();
  hnet.patch_vertices.resize(num_faces);
  for (FaceIndex f : mesh.faces()) hnet.patch_vertices[f.idx()] = PatchVertices(mesh, hnet.colour, f);

  // --- Edge layouts and the equitwist check [Shi 2014, eq. 7, Remark 2].
  std::vector<EdgeLayout> layout(mesh.num_edges());
  hnet.join.assign(mesh.num_edges(), EdgeJoin::kBoundary);
  for (EdgeIndex e : mesh.edges()) {
    if (mesh.is_border(e)) continue;
    HalfedgeIndex h = mesh.halfedge(e);  // b3 → b0
    if (hnet.colour[mesh.target(h).idx()] != 0 && hnet.colour[mesh.source(h).idx()] == 0) {
      h = mesh.opposite(h);
    }
    const HalfedgeIndex g = mesh.opposite(h);  // b0 → b3
    EdgeLayout& l = layout[e.idx()];
    l.b0 = int(mesh.target(h).idx());
    l.b3 = int(mesh.source(h).idx());
    l.left = int(mesh.face(h).idx());
    l.right = int(mesh.face(g).idx());
    const auto p = [&](VertexIndex v) { return HnetE(mesh.point(v)); };
    l.determinants = SmoothJoinDeterminants(
        p(mesh.target(h)), p(mesh.target(mesh.next(h))), p(mesh.target(mesh.next(mesh.next(h)))),
        p(mesh.source(h)), p(mesh.target(mesh.next(g))), p(mesh.target(mesh.next(mesh.next(g)))));
    if (l.determinants.equitwist()) {
      hnet.join[e.idx()] = EdgeJoin::kEquitwist;
    } else {
      hnet.join[e.idx()] = EdgeJoin::kNotEquitwist;
      hnet.not_equitwist_edges.push_back(int(e.idx()));
    }
  }

  // --- Propagation of W over the dual graph by BFS [Shi 2014, §3.2 step 2].
  // Along the traversal each face carries a "propagated" diagonal, chosen so
  // that the two faces of every crossed edge have diagonals through the same
  // end point of that edge (Remark 5's condition). Its shape parameter Wp
  // then obeys eq. 7 as a plain ratio, and λ·Wp keeps every crossed edge exact.
  // flipped[f]: the propagated diagonal is c1c3 (Wp = 1/W), not c0c2 (Wp = W);
  // it stays false everywhere when the colouring is consistent (bipartite net).
  std::vector<double> Wp(num_faces, 0.0);
  std::vector<bool> flipped(num_faces, false);
  hnet.component.assign(num_faces, -1);
  std::vector<bool> crossed(mesh.num_edges(), false);
  std::vector<int> roots{options.start_face};
  for (int f = 0; f < num_faces; ++f) roots.push_back(f);
  int num_components = 0;
  std::vector<int> component_root;
  for (int root : roots) {
    if (hnet.component[root] >= 0) continue;
    const int id = num_components++;
    component_root.push_back(root);
    hnet.component[root] = id;
    Wp[root] = 1.0;
    std::queue<int> queue;
    queue.push(root);
    while (!queue.empty()) {
      const int f = queue.front();
      queue.pop();
      for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(FaceIndex(f)))) {
        const EdgeIndex e = mesh.edge(h);
        if (hnet.join[e.idx()] != EdgeJoin::kEquitwist) continue;
        const EdgeLayout& l = layout[e.idx()];
        const int other = l.left == f ? l.right : l.left;
        if (hnet.component[other] >= 0) continue;
        // Eq. 7 for the shape parameters of the diagonals through b0 (a
        // diagonal through b3 has the reciprocal shape parameter, eq. 4).
        const bool via_b0 = OnDiagonal(hnet.patch_vertices[f], l.b0) != flipped[f];
        const double through = via_b0 ? Wp[f] : 1.0 / Wp[f];
        const double ratio = l.determinants.ratio();  // W_r(b0) / W_l(b0)
        const double other_through = l.left == f ? through * ratio : through / ratio;
        Wp[other] = via_b0 ? other_through : 1.0 / other_through;
        flipped[other] = OnDiagonal(hnet.patch_vertices[other], l.b0) != via_b0;
        hnet.component[other] = id;
        crossed[e.idx()] = true;
        queue.push(other);
      }
    }
  }

  // --- Least squares over every equitwist edge (HNetShape::kLeastSquares).
  if (options.shape == HNetShape::kLeastSquares) {
    // The propagated diagonal of face f passes through vertex v: log W_f(v) = y_f, else −y_f.
    const auto sign = [&](int f, int v) {
      return OnDiagonal(hnet.patch_vertices[f], v) != flipped[f] ? 1.0 : -1.0;
    };
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(num_faces);
    for (EdgeIndex e : mesh.edges()) {
      if (hnet.join[e.idx()] != EdgeJoin::kEquitwist) continue;
      const EdgeLayout& l = layout[e.idx()];
      // Eq. 7 in logarithms: s_r y_r − s_l y_l = log(W_r(b0) / W_l(b0)).
      const int idx[2] = {l.right, l.left};
      const double a[2] = {sign(l.right, l.b0), -sign(l.left, l.b0)};
      const double c = std::log(l.determinants.ratio());
      for (int i = 0; i < 2; ++i) {
        rhs[idx[i]] += a[i] * c;
        for (int j = 0; j < 2; ++j) entries.emplace_back(idx[i], idx[j], a[i] * a[j]);
      }
    }
    // The gauge: each component keeps y = 0 at its root (λ rescales below).
    for (int root : component_root) entries.emplace_back(root, root, 1.0);
    Eigen::SparseMatrix<double> normal(num_faces, num_faces);
    normal.setFromTriplets(entries.begin(), entries.end());
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
    CHECK(solver.info() == Eigen::Success) << "BuildHNet: least-squares shape parameters";
    const Eigen::VectorXd solution = solver.solve(rhs);
    for (int f = 0; f < num_faces; ++f) {
      if (std::isfinite(solution[f])) Wp[f] = std::exp(solution[f]);
    }
  }

  // --- λ per component [Shi 2014, eq. 11]. F_shape is invariant under
  // W ↔ 1/W per face, so minimising it over λ·Wp minimises it for the stored W.
  std::vector<std::vector<double>> component_W(num_components);
  for (int f = 0; f < num_faces; ++f) component_W[hnet.component[f]].push_back(Wp[f]);
  for (const auto& values : component_W) hnet.lambda_of_component.push_back(OptimalShapeScale(values));
  hnet.lambda = hnet.lambda_of_component[hnet.component[options.start_face]];
  hnet.W_initial.resize(num_faces);
  hnet.W.resize(num_faces);
  for (int f = 0; f < num_faces; ++f) {
    const double scaled = hnet.lambda_of_component[hnet.component[f]] * Wp[f];
    hnet.W_initial[f] = flipped[f] ? 1.0 / Wp[f] : Wp[f];
    hnet.W[f] = flipped[f] ? 1.0 / scaled : scaled;
  }
  hnet.W_min = *std::min_element(hnet.W.begin(), hnet.W.end());
  hnet.W_max = *std::max_element(hnet.W.begin(), hnet.W.end());

  // --- Mismatch of eq. 7 per interior edge.
  hnet.edge_mismatch.assign(mesh.num_edges(), -1.0);
  for (EdgeIndex e : mesh.edges()) {
    if (hnet.join[e.idx()] != EdgeJoin::kEquitwist) continue;
    const EdgeLayout& l = layout[e.idx()];
    const double left = ShapeThrough(hnet.patch_vertices[l.left], hnet.W[l.left], l.b0);
    const double right = ShapeThrough(hnet.patch_vertices[l.right], hnet.W[l.right], l.b0);
    const double mismatch = std::abs(right / left / l.determinants.ratio() - 1.0);
    hnet.edge_mismatch[e.idx()] = mismatch;
    hnet.mismatch_max = std::max(hnet.mismatch_max, mismatch);
    if (!crossed[e.idx()]) hnet.closing_edges.push_back(int(e.idx()));
  }

  // --- Weights, frame points, kinks.
  hnet.weights.resize(num_faces);
  hnet.frame_points.resize(num_faces);
  for (int f = 0; f < num_faces; ++f) hnet.weights[f] = WeightsFromShapeParameter(hnet.W[f]);
  for (FaceIndex f : mesh.faces()) {
    const auto frame = FramePoints(FacePatch(mesh, hnet, f));
    for (int i = 0; i < 4; ++i) hnet.frame_points[f.idx()][i] = ToVec(frame[i]);
  }
  hnet.kink_degrees.assign(mesh.num_edges(), -1.0);
  int interior_edges = 0;
  for (EdgeIndex e : mesh.edges()) {
    if (mesh.is_border(e)) continue;
    const EdgeLayout& l = layout[e.idx()];
    const auto& left = hnet.patch_vertices[l.left];
    const auto& right = hnet.patch_vertices[l.right];
    const double kink = SharedEdgeKinkDegrees(
        FacePatch(mesh, hnet, FaceIndex(l.left)), PatchEdge(left, l.b3, l.b0),
        FacePatch(mesh, hnet, FaceIndex(l.right)), PatchEdge(right, l.b0, l.b3),
        options.kink_samples);
    hnet.kink_degrees[e.idx()] = kink;
    if (kink < 0) continue;
    hnet.kink_max = std::max(hnet.kink_max, kink);
    hnet.kink_mean += kink;
    ++interior_edges;
  }
  if (interior_edges > 0) hnet.kink_mean /= interior_edges;
  return hnet;
}

BilinearPatch FacePatch(const Mesh& mesh, const HNet& hnet, FaceIndex f) {
  CHECK_LT(f.idx(), hnet.patch_vertices.size()) << "FacePatch: face not in the H-net";
  BilinearPatch patch;
  for (int i = 0; i < 4; ++i) {
    patch.b[i] = HnetE(mesh.point(VertexIndex(hnet.patch_vertices[f.idx()][i])));
  }
  CHECK_LT(f.idx(), hnet.weights.size()) << "FacePatch: H-net without weights";
  patch.w = hnet.weights[f.idx()];
  return patch;
}

SampledPatchwork SamplePatchwork(const Mesh& mesh, const HNet& hnet, int n) {
  CHECK_GE(n, 1);
  SampledPatchwork out;
  const int side = n + 1;
  bool undefined_normal = false;
  std::vector<bool> defined;
  for (FaceIndex f : mesh.faces()) {
    const BilinearPatch patch = FacePatch(mesh, hnet, f);
    const int base = int(out.positions.size());
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        const double u = double(i) / n, v = double(j) / n;
        const PatchJet jet = PatchDerivatives(patch, u, v);
        const Eigen::Vector3d normal = PatchNormal(patch, u, v);
        out.positions.push_back(ToVec(jet.x));
        out.normals.push_back(ToVec(normal));
        defined.push_back(normal.squaredNorm() > 0);
        undefined_normal |= !defined.back();
      }
    }
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const int a = base + j * side + i, b = a + 1, c = a + side + 1, d = a + side;
        out.triangles.push_back({a, b, c});
        out.triangles.push_back({a, c, d});
        out.triangle_face.push_back(int(f.idx()));
        out.triangle_face.push_back(int(f.idx()));
      }
    }
  }
  if (undefined_normal) {
    const SampledPatchwork fallback = RecomputeNormals(out);
    for (size_t i = 0; i < defined.size(); ++i) {
      if (!defined[i]) out.normals[i] = fallback.normals[i];
    }
  }
  return out;
}

std::vector<double> IsophoteAngles(const std::vector<Vec3>& normals, const Vec3& direction) {
  const Eigen::Vector3d d = HnetE(direction);
  if (!d.allFinite() || d.norm() == 0) {
    throw InputError("", 0, "direction", "isophote direction must be a finite non-zero vector");
  }
  const Eigen::Vector3d unit = d.normalized();
  std::vector<double> angles;
  angles.reserve(normals.size());
  for (const Vec3& n : normals) {
    const Eigen::Vector3d e = HnetE(n);
    angles.push_back(std::atan2(e.cross(unit).norm(), e.dot(unit)) * 180.0 / M_PI);
  }
  return angles;
}

std::vector<std::array<unsigned char, 3>> IsophoteColors(const std::vector<double>& angles,
                                                         double band_degrees) {
  if (!std::isfinite(band_degrees) || band_degrees <= 0) {
    throw InputError("", 0, "band_degrees", "isophote band width must be finite and > 0");
  }
  std::vector<std::array<unsigned char, 3>> colors;
  colors.reserve(angles.size());
  for (double angle : angles) {
    const long band = long(std::floor(angle / band_degrees));
    colors.push_back(band % 2 == 0 ? std::array<unsigned char, 3>{235, 235, 235}
                                   : std::array<unsigned char, 3>{40, 40, 40});
  }
  return colors;
}

Polylines PatchRulings(const Mesh& mesh, const HNet& hnet, int per_family, int points_per_line) {
  CHECK_GE(per_family, 1);
  CHECK_GE(points_per_line, 2);
  Polylines out;
  for (FaceIndex f : mesh.faces()) {
    const BilinearPatch patch = FacePatch(mesh, hnet, f);
    for (int family = 0; family < 2; ++family) {
      for (int k = 1; k <= per_family; ++k) {
        const double fixed = double(k) / (per_family + 1);
        std::vector<Vec3> line;
        for (int i = 0; i < points_per_line; ++i) {
          const double t = double(i) / (points_per_line - 1);
          line.push_back(ToVec(family == 0 ? PatchPoint(patch, fixed, t) : PatchPoint(patch, t, fixed)));
        }
        out.lines.push_back(std::move(line));
        out.face.push_back(int(f.idx()));
        out.family.push_back(family);
      }
    }
  }
  return out;
}

void WritePolylinesObj(const std::string& path, const std::vector<std::vector<Vec3>>& lines) {
  NoFollowOfstream file(path);
  if (!file) throw InputError(path, 0, "", "cannot open the polyline file for writing");
  file.precision(17);
  file << "# archgeo polylines: " << lines.size() << " lines\n";
  for (const auto& line : lines) {
    if (line.size() < 2) continue;
    for (const Vec3& p : line) file << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  size_t next = 1;
  for (const auto& line : lines) {
    if (line.size() < 2) continue;
    file << 'l';
    for (size_t i = 0; i < line.size(); ++i) file << ' ' << next + i;
    file << '\n';
    next += line.size();
  }
  file.close();
  if (file.fail()) throw InputError(path, 0, "", "error writing the polyline file");
}

SampledPatchwork DarbouxMapPatchwork(const SampledPatchwork& patchwork,
                                     const DarbouxTransform& transform,
                                     std::vector<int>* failed_vertices) {
  SampledPatchwork out;
  std::vector<bool> failed(patchwork.positions.size(), false);
  if (failed_vertices != nullptr) failed_vertices->clear();
  out.positions.reserve(patchwork.positions.size());
  for (size_t i = 0; i < patchwork.positions.size(); ++i) {
    const DarbouxResult image = ApplyDarboux(transform, HnetE(patchwork.positions[i]));
    out.positions.push_back(ToVec(image.point));
    if (image.status != DarbouxStatus::kOk) {
      failed[i] = true;
      if (failed_vertices != nullptr) failed_vertices->push_back(int(i));
    }
  }
  for (size_t t = 0; t < patchwork.triangles.size(); ++t) {
    const auto& tri = patchwork.triangles[t];
    if (failed[tri[0]] || failed[tri[1]] || failed[tri[2]]) continue;
    out.triangles.push_back(tri);
    out.triangle_face.push_back(patchwork.triangle_face[t]);
  }
  return RecomputeNormals(std::move(out));
}

}  // namespace archgeo
