// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fields/singularities.h"
#include "mesh/eigen_point.h"

#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <string>

#include <Eigen/Geometry>
#include <glog/logging.h>

namespace archgeo {
namespace {

double CornerAngle(const Mesh& mesh, HalfedgeIndex h) {  // at target(h) in face(h)
  const Eigen::Vector3d v = EigenPoint(mesh, mesh.target(h));
  const Eigen::Vector3d a = EigenPoint(mesh, mesh.source(h)) - v;
  const Eigen::Vector3d b = EigenPoint(mesh, mesh.target(mesh.next(h))) - v;
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

Eigen::Matrix2d Rotation(double angle) {
  Eigen::Matrix2d R;
  R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return R;
}

// Dijkstra over the dual graph (centroid distances) from `source`; fills the
// distance and the transport angle mapping source's frame to each face's frame
// along the shortest-path tree.
void DualDijkstra(const Mesh& mesh, const FaceFrames& frames,
                  const std::vector<EdgeTransport>& transports, FaceIndex source,
                  std::vector<double>* dist, std::vector<double>* angle) {
  const size_t n = mesh.number_of_faces();
  std::vector<std::vector<int>> incident(n);
  for (size_t k = 0; k < transports.size(); ++k) {
    incident[transports[k].f.idx()].push_back(static_cast<int>(k));
    incident[transports[k].g.idx()].push_back(static_cast<int>(k));
  }
  dist->assign(n, std::numeric_limits<double>::infinity());
  angle->assign(n, 0.0);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  (*dist)[source.idx()] = 0.0;
  queue.push({0.0, static_cast<int>(source.idx())});
  while (!queue.empty()) {
    const auto [d, f] = queue.top();
    queue.pop();
    if (d > (*dist)[f]) continue;
    for (int k : incident[f]) {
      const EdgeTransport& t = transports[k];
      const FaceIndex g = t.f.idx() == static_cast<size_t>(f) ? t.g : t.f;
      const double nd = d + (frames.centroid[f] - frames.centroid[g.idx()]).norm();
      if (nd < (*dist)[g.idx()]) {
        (*dist)[g.idx()] = nd;
        // A vector at angle α in f's frame has angle α + τ_gf in g's frame.
        (*angle)[g.idx()] = (*angle)[f] + TransportAngle(t, FaceIndex(f), g);
        queue.push({nd, static_cast<int>(g.idx())});
      }
    }
  }
}

// Undefined (NaN) angles replaced by the line of the spin-2 mean of the
// defined edge neighbours (transported into the face), in passes until no
// face with a defined neighbour is left; faces of components without any
// defined angle stay NaN.
std::vector<double> FillUndefined(const Mesh& mesh, const std::vector<EdgeTransport>& transports,
                                  const std::vector<int>& edge_to_transport,
                                  const std::vector<double>& line_angle) {
  std::vector<double> angle = line_angle;
  for (bool changed = true; changed;) {
    changed = false;
    std::vector<double> next = angle;
    for (FaceIndex f : mesh.faces()) {
      if (!std::isnan(angle[f.idx()])) continue;
      Eigen::Vector2d mean = Eigen::Vector2d::Zero();
      int count = 0;
      for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(f))) {
        const HalfedgeIndex o = mesh.opposite(h);
        if (mesh.is_border(o)) continue;
        const FaceIndex g = mesh.face(o);
        const double b = angle[g.idx()];
        if (std::isnan(b)) continue;
        const int t = edge_to_transport[mesh.edge(h).idx()];
        CHECK_GE(t, 0);
        const double in_f = b + TransportAngle(transports[t], g, f);
        mean += Eigen::Vector2d(std::cos(2 * in_f), std::sin(2 * in_f));
        ++count;
      }
      if (count == 0) continue;
      next[f.idx()] = LineAngle(Eigen::Vector2d(std::cos(0.5 * std::atan2(mean.y(), mean.x())),
                                                std::sin(0.5 * std::atan2(mean.y(), mean.x()))));
      changed = true;
    }
    angle.swap(next);
  }
  return angle;
}

}  // namespace

std::vector<ConjugatePair> TcdPairs(const std::vector<FaceCurvature>& curvature,
                                    const std::vector<Eigen::Vector2d>& z_n) {
  CHECK_EQ(curvature.size(), z_n.size());
  std::vector<ConjugatePair> pairs(z_n.size());
  for (size_t f = 0; f < z_n.size(); ++f) pairs[f] = ConjugatePairOf(curvature[f].M, z_n[f]);
  return pairs;
}

TcdFieldStats FieldStats(const std::vector<FaceCurvature>& curvature,
                         const std::vector<ConjugatePair>& pairs) {
  CHECK_EQ(curvature.size(), pairs.size());
  TcdFieldStats s;
  for (size_t f = 0; f < pairs.size(); ++f) {
    if (!pairs[f].valid) {
      ++s.invalid_faces;
      continue;
    }
    ++s.valid_faces;
    s.max_conjugacy_error =
        std::max(s.max_conjugacy_error, ConjugacyError(curvature[f].M, pairs[f].v, pairs[f].w));
    const double c = std::min(1.0, std::abs(pairs[f].v.dot(pairs[f].w)));
    s.min_angle_deg = std::min(s.min_angle_deg, std::acos(c) * 180.0 / M_PI);
  }
  return s;
}

std::vector<double> BisectorAngles(const std::vector<ConjugatePair>& pairs) {
  std::vector<double> out(pairs.size(), std::numeric_limits<double>::quiet_NaN());
  for (size_t f = 0; f < pairs.size(); ++f) {
    if (pairs[f].valid) out[f] = BisectorAngle(pairs[f].v, pairs[f].w);
  }
  return out;
}

std::vector<double> VertexIndices(const Mesh& mesh, const std::vector<EdgeTransport>& transports,
                                  const std::vector<int>& edge_to_transport,
                                  const std::vector<double>& line_angle) {
  CHECK(!mesh.has_garbage());
  CHECK_EQ(line_angle.size(), mesh.number_of_faces());
  CHECK_EQ(edge_to_transport.size(), mesh.number_of_edges());
  const std::vector<double> angle = FillUndefined(mesh, transports, edge_to_transport, line_angle);
  std::vector<double> index(mesh.number_of_vertices(), 0.0);
  for (VertexIndex v : mesh.vertices()) {
    if (mesh.is_isolated(v) || mesh.is_border(v, /*check_all_incident_halfedges=*/true)) continue;
    // CGAL visits the halfedges into v clockwise (seen from the normal): the
    // face after face(h) is across edge(next(h)). Collect them, then walk the
    // loop counter-clockwise (reversed).
    std::vector<HalfedgeIndex> cw;
    double angle_sum = 0.0;
    for (HalfedgeIndex h : mesh.halfedges_around_target(mesh.halfedge(v))) {
      cw.push_back(h);
      angle_sum += CornerAngle(mesh, h);
    }
    const size_t k = cw.size();
    // Counter-clockwise faces G_j = face(cw[(k − j) mod k]) and the transport
    // tau[j] = τ_{G_j G_{j+1}} (the angle of G_{j+1}'s frame in G_j's frame);
    // G_j and G_{j+1} = face(cw[i − 1]) share edge(next(cw[i − 1])).
    std::vector<FaceIndex> ccw(k);
    std::vector<double> tau(k);
    for (size_t j = 0; j < k; ++j) {
      const size_t i = (k - j) % k, i_next = (k - j - 1 + k) % k;
      ccw[j] = mesh.face(cw[i]);
      const int t = edge_to_transport[mesh.edge(mesh.next(cw[i_next])).idx()];
      CHECK_GE(t, 0);
      tau[j] = TransportAngle(transports[t], mesh.face(cw[i_next]), ccw[j]);
    }
    size_t j0 = 0;
    while (j0 < k && std::isnan(angle[ccw[j0].idx()])) ++j0;
    if (j0 == k) continue;  // the field is undefined all around v
    double rotation = 0.0;  // Σ Δ_i
    double carried = 0.0;   // transport since the last defined face
    double last = angle[ccw[j0].idx()];
    for (size_t s = 1; s <= k; ++s) {
      const size_t j = (j0 + s) % k;
      carried += tau[(j + k - 1) % k];
      const double beta = angle[ccw[j].idx()];
      if (std::isnan(beta)) continue;
      rotation += WrapLineAngle(beta + carried - last);
      carried = 0.0;
      last = beta;
    }
    const double defect = 2.0 * M_PI - angle_sum;
    const double value = (rotation + defect) / (2.0 * M_PI);
    const double half = std::round(2.0 * value) / 2.0;
    CHECK_LT(std::abs(value - half), 1e-6)
        << "vertex " << v.idx() << ": index " << value << " is not a multiple of 1/2";
    index[v.idx()] = half;
  }
  return index;
}

std::vector<Singularity> Singularities(const Mesh& mesh, const std::vector<double>& vertex_index) {
  CHECK_EQ(vertex_index.size(), mesh.number_of_vertices());
  std::vector<Singularity> out;
  for (VertexIndex v : mesh.vertices()) {
    const double ind = vertex_index[v.idx()];
    if (ind == 0.0) continue;
    out.push_back({v, ind, EigenPoint(mesh, v)});
  }
  return out;
}

double SigmaBlend(double t, double r1, double r2) {
  CHECK(r1 >= 0.0 && r2 > r1) << "SigmaBlend: need 0 <= r1 < r2";
  if (t <= r1) return 1.0;
  if (t >= r2) return 0.0;
  return 0.5 + 0.5 * std::cos(M_PI * (t - r1) / (r2 - r1));
}

SingularityMove MoveSingularity(const Mesh& mesh, const FaceFrames& frames,
                                const std::vector<EdgeTransport>& transports,
                                const std::vector<FaceCurvature>& curvature,
                                const std::vector<Eigen::Vector2d>& z_n, FaceIndex from,
                                FaceIndex to, double r1, double r2) {
  const size_t n = mesh.number_of_faces();
  CHECK(from.idx() < n && to.idx() < n) << "MoveSingularity: face out of range";
  CHECK_EQ(curvature.size(), n);
  CHECK_EQ(z_n.size(), n);
  CHECK(r1 >= 0.0 && r2 > r1) << "MoveSingularity: need 0 <= r1 < r2";
  if (!curvature[to.idx()].z_m_finite) {
    SingularityMove out;
    out.z_n = z_n;
    out.beta.assign(n, 0.0);
    out.error = "face " + std::to_string(to.idx()) +
                " has z_M at infinity (zero mean curvature or flat): no singularity can be placed there";
    return out;
  }
  std::vector<double> dist0, unused, dist1, angle1;
  DualDijkstra(mesh, frames, transports, from, &dist0, &unused);
  DualDijkstra(mesh, frames, transports, to, &dist1, &angle1);
  const Eigen::Vector2d correction = z_n[to.idx()] - curvature[to.idx()].z_m;
  SingularityMove out;
  out.z_n = z_n;
  out.beta.assign(n, 0.0);
  for (size_t f = 0; f < n; ++f) {
    const double beta = std::isfinite(dist0[f]) ? SigmaBlend(dist0[f], r1, r2) : 0.0;
    out.beta[f] = beta;
    if (beta == 0.0) continue;
    // Faces with β > 0 but unreachable from f1 (another component) keep z_N.
    if (!std::isfinite(dist1[f])) continue;
    out.z_n[f] -= beta * Rotation(2.0 * angle1[f]) * correction;
  }
  out.reached = out.beta[to.idx()] == 1.0;
  return out;
}

}  // namespace archgeo
