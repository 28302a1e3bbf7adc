// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/declarations/wave_size_curl.h"

#include <array>
#include <cmath>

#include <Eigen/Geometry>

#include "energies/size_elements.h"
#include "mesh/eigen_point.h"

namespace archgeo {
namespace {

namespace sd = size_data;
using SizeV3 = Eigen::Vector3d;

// A triangle of the fans and the guidance field matched to its first corner:
// per corner the field's X and Y (signed, the ones of ±X_k, ±Y_k nearest
// X_0 and Y_0) and which of the corner's sizes goes with the matched X
// (0: μ, 1: η).
struct SizeTriangle {
  int face = -1;
  std::array<int, 3> v{};
  std::array<SizeV3, 3> p, x, y;
  std::array<int, 3> source_x{};
  SizeV3 n;
  double area = 0;
};

// Which of j's X, Y (0, 1) with which sign is i's X, and i's Y likewise.
void MatchCorner(const WaveFrames& f, int i, int j, int* source, SizeV3* x, SizeV3* y) {
  const SizeV3 cand[2] = {f.x[size_t(j)], f.y[size_t(j)]};
  double best = -2;
  for (int k = 0; k < 2; ++k) {
    for (double s : {1.0, -1.0}) {
      const double d = s * cand[k].dot(f.x[size_t(i)]);
      if (d > best) best = d, *source = k, *x = s * cand[k];
    }
  }
  const SizeV3& other = cand[1 - *source];
  *y = other.dot(f.y[size_t(i)]) >= 0 ? other : SizeV3(-other);
}

// The fan triangles of every face, with their matched fields.
std::vector<SizeTriangle> SizeTriangles(const Mesh& mesh, const WaveFrames& f) {
  std::vector<SizeTriangle> out;
  for (FaceIndex face : mesh.faces()) {
    std::vector<int> vs;
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(face))) vs.push_back(int(v.idx()));
    for (size_t k = 1; k + 1 < vs.size(); ++k) {
      SizeTriangle t;
      t.face = int(face.idx());
      t.v = {vs[0], vs[k], vs[k + 1]};
      for (int c = 0; c < 3; ++c) {
        t.p[size_t(c)] = EigenPoint(mesh, VertexIndex(t.v[size_t(c)]));
        MatchCorner(f, t.v[0], t.v[size_t(c)], &t.source_x[size_t(c)], &t.x[size_t(c)],
                    &t.y[size_t(c)]);
      }
      const SizeV3 cross = (t.p[1] - t.p[0]).cross(t.p[2] - t.p[0]);
      t.area = 0.5 * cross.norm();
      if (!(t.area > 1e-14)) continue;
      t.n = cross.normalized();
      out.push_back(t);
    }
  }
  return out;
}

// ∮ F·dl over the triangle's edges, F at each edge's midpoint the mean of
// its ends' values (projected into the triangle's plane).
double Circulation(const SizeTriangle& t, const std::array<SizeV3, 3>& field) {
  double sum = 0;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    SizeV3 mid = 0.5 * (field[size_t(i)] + field[size_t(j)]);
    mid -= mid.dot(t.n) * t.n;
    sum += mid.dot(t.p[size_t(j)] - t.p[size_t(i)]);
  }
  return sum;
}

// The size_curl element of the family `field` (X or Y of t) with the
// corners' sources.
void AddCurlElement(const SizeTriangle& t, const std::array<SizeV3, 3>& field,
                    const std::array<int, 3>& source, ElementSet* set) {
  const double root = std::sqrt(t.area);
  SizeV3 mean = SizeV3::Zero();
  for (const SizeV3& x : field) mean += x - x.dot(t.n) * t.n;
  if (mean.norm() < 1e-12) return;
  const SizeV3 across = t.n.cross(mean.normalized());
  std::vector<double> data(sd::kTriangleWidth);
  data[sd::kConstant] = root * Circulation(t, field) / t.area;
  for (int k = 0; k < 3; ++k) {
    const SizeV3 grad_b = t.n.cross(t.p[size_t((k + 2) % 3)] - t.p[size_t((k + 1) % 3)]) /
                          (2 * t.area);
    data[size_t(sd::kGradient + k)] = root * across.dot(grad_b);
    data[size_t(sd::kSource + k)] = source[size_t(k)];
  }
  set->Add({t.v[0], t.v[1], t.v[2]}, t.face, t.face, -1, 0, data);
}

}  // namespace

WaveSizeSets WaveSizeCurlSets(const Mesh& mesh, const WaveFrames& frames,
                              const std::vector<double>& mu, const std::vector<double>& eta) {
  WaveSizeSets out;
  out.triangles.site = Site::kFace;
  out.triangles.data_width = sd::kTriangleWidth;
  std::vector<double> area(mesh.number_of_vertices(), 0.0);
  for (const SizeTriangle& t : SizeTriangles(mesh, frames)) {
    std::array<int, 3> source_y{};
    for (int k = 0; k < 3; ++k) source_y[size_t(k)] = 1 - t.source_x[size_t(k)];
    AddCurlElement(t, t.x, t.source_x, &out.triangles);
    AddCurlElement(t, t.y, source_y, &out.triangles);
    for (int v : t.v) area[size_t(v)] += t.area / 3;
  }
  out.vertices.site = Site::kVertex;
  out.vertices.data_width = sd::kVertexWidth;
  for (VertexIndex v : mesh.vertices()) {
    const size_t i = v.idx();
    const double root = std::sqrt(area[i]);
    out.vertices.Add({int(i)}, int(i), -1, -1, 0,
                     {std::log(mu[i]), std::log(eta[i]), root / mu[i], root / eta[i]});
  }
  out.edges.site = Site::kEdge;
  out.edges.data_width = sd::kEdgeWidth;
  for (EdgeIndex e : mesh.edges()) {
    const HalfedgeIndex h = mesh.halfedge(e);
    const int i = int(mesh.source(h).idx()), j = int(mesh.target(h).idx());
    int source = 0;
    SizeV3 x, y;
    MatchCorner(frames, i, j, &source, &x, &y);
    out.edges.Add({i, j}, int(e.idx()), -1, int(e.idx()), 0, {double(source)});
  }
  return out;
}

WaveSizeCurl MeasureWaveSizeCurl(const Mesh& mesh, const WaveFrames& frames,
                                 const std::vector<double>& mu, const std::vector<double>& eta) {
  double sum_x = 0, sum_y = 0, sum_area = 0;
  for (const SizeTriangle& t : SizeTriangles(mesh, frames)) {
    std::array<SizeV3, 3> x, y;
    double size_x = 0, size_y = 0;
    for (int k = 0; k < 3; ++k) {
      const size_t v = size_t(t.v[size_t(k)]);
      const bool same = t.source_x[size_t(k)] == 0;
      const double sx = same ? mu[v] : eta[v], sy = same ? eta[v] : mu[v];
      x[size_t(k)] = t.x[size_t(k)] / sx;
      y[size_t(k)] = t.y[size_t(k)] / sy;
      size_x += sx / 3;
      size_y += sy / 3;
    }
    const double cx = size_x * size_x * Circulation(t, x) / t.area;
    const double cy = size_y * size_y * Circulation(t, y) / t.area;
    sum_x += t.area * cx * cx;
    sum_y += t.area * cy * cy;
    sum_area += t.area;
  }
  if (sum_area <= 0) return {};
  return {std::sqrt(sum_x / sum_area), std::sqrt(sum_y / sum_area)};
}

}  // namespace archgeo
