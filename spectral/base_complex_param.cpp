// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A chart over its primitive domain (spectral/base_complex_charts.h, step 2).
#include <cmath>
#include <limits>

#include <Eigen/Geometry>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include "spectral/base_complex_charts.h"

namespace archgeo {
namespace {

using ChartTriplet = Eigen::Triplet<double>;

// Boundary vertices by arc length between the corners of the domain.
void PlaceChartBoundary(const std::vector<Eigen::Vector3d>& points, const Chart& chart,
                        const std::vector<Eigen::Vector2d>& corners, ChartMap& map) {
  const int sides = int(corners.size());
  const int loop = int(chart.boundary.size());
  for (int k = 0; k < sides; ++k) {
    const int begin = chart.corner_at[k];
    const int end = k + 1 < sides ? chart.corner_at[k + 1] : loop;
    std::vector<double> at{0};
    for (int i = begin; i < end; ++i) {
      const int u = chart.vertices[chart.boundary[i]];
      const int v = chart.vertices[chart.boundary[(i + 1) % loop]];
      at.push_back(at.back() + (points[u] - points[v]).norm());
    }
    const Eigen::Vector2d& a = corners[k];
    const Eigen::Vector2d& b = corners[(k + 1) % sides];
    for (int i = begin; i < end; ++i) {
      const double t = at[i - begin] / at.back();
      map.uv[chart.boundary[i]] = (1 - t) * a + t * b;
    }
  }
}

// w[i][j] of the harmonic map for one triangle, added to `out` as (i, j, w).
void ChartTriangleWeights(const Eigen::Vector3d (&p)[3], const int (&id)[3], ChartWeights kind,
                          std::vector<ChartTriplet>& out) {
  for (int k = 0; k < 3; ++k) {
    const int i = k, j = (k + 1) % 3, o = (k + 2) % 3;
    if (kind == ChartWeights::kCotangent) {
      // Edge ij, angle at o: ½ cot, both directions.
      const Eigen::Vector3d a = p[i] - p[o], b = p[j] - p[o];
      const double cot = a.dot(b) / std::max(a.cross(b).norm(), 1e-300);
      out.push_back({id[i], id[j], 0.5 * cot});
      out.push_back({id[j], id[i], 0.5 * cot});
    } else {
      // At vertex i, angle γ between its two edges: tan(γ/2)/‖e‖ on each.
      const Eigen::Vector3d a = p[j] - p[i], b = p[o] - p[i];
      const double gamma = std::atan2(a.cross(b).norm(), a.dot(b));
      const double t = std::tan(0.5 * gamma);
      out.push_back({id[i], id[j], t / std::max(a.norm(), 1e-300)});
      out.push_back({id[i], id[o], t / std::max(b.norm(), 1e-300)});
    }
  }
}

}  // namespace

std::vector<Eigen::Vector2d> ChartDomain(int sides) {
  if (sides == 3) return {{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}};
  return {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
}

ChartMap ParameteriseChart(const std::vector<Eigen::Vector3d>& points,
                           const std::vector<std::array<int, 3>>& triangles,
                           const ChartLayout& layout, int c, ChartWeights weights) {
  const Chart& chart = layout.charts[c];
  const std::vector<Eigen::Vector2d> corners = ChartDomain(int(layout.sides[c].size()));
  ChartMap map;
  const int count = int(chart.vertices.size());
  const int fixed = int(chart.boundary.size());
  map.uv.assign(count, Eigen::Vector2d::Zero());
  PlaceChartBoundary(points, chart, corners, map);
  std::vector<int> local(points.size(), -1);  // surface id -> chart index
  for (int i = 0; i < count; ++i) local[chart.vertices[i]] = i;

  const int free = count - fixed;  // interior vertices: chart indices fixed … count − 1
  if (free > 0) {
    std::vector<ChartTriplet> w;
    for (int t : chart.triangles) {
      Eigen::Vector3d p[3];
      int id[3];
      for (int k = 0; k < 3; ++k) {
        p[k] = points[triangles[t][k]];
        id[k] = local[triangles[t][k]];
      }
      ChartTriangleWeights(p, id, weights, w);
    }
    std::vector<ChartTriplet> a;
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(free, 2);
    for (const ChartTriplet& e : w) {
      const int i = e.row(), j = e.col();
      if (i < fixed) continue;
      a.push_back({i - fixed, i - fixed, e.value()});
      if (j >= fixed) {
        a.push_back({i - fixed, j - fixed, -e.value()});
      } else {
        rhs.row(i - fixed) += e.value() * map.uv[j].transpose();
      }
    }
    Eigen::SparseMatrix<double> A(free, free);
    A.setFromTriplets(a.begin(), a.end());
    Eigen::MatrixXd x;
    if (weights == ChartWeights::kCotangent) {
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(A);
      x = solver.solve(rhs);
    } else {
      Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
      solver.analyzePattern(A);
      solver.factorize(A);
      x = solver.solve(rhs);
    }
    for (int i = 0; i < free; ++i) map.uv[fixed + i] = x.row(i).transpose();
  }

  const double domain = corners.size() == 3 ? std::sqrt(3.0) / 4 : 1.0;
  map.min_area = std::numeric_limits<double>::infinity();
  for (int t : chart.triangles) {
    const Eigen::Vector2d& a = map.uv[local[triangles[t][0]]];
    const Eigen::Vector2d& b = map.uv[local[triangles[t][1]]];
    const Eigen::Vector2d& d = map.uv[local[triangles[t][2]]];
    const double area = 0.5 * ((b - a).x() * (d - a).y() - (b - a).y() * (d - a).x());
    if (!(area > 0)) ++map.flipped;
    map.min_area = std::min(map.min_area, area / domain);
  }
  return map;
}

}  // namespace archgeo
