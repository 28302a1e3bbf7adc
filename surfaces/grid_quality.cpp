// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "surfaces/grid_quality.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include <Eigen/Geometry>
#include <glog/logging.h>

#include "surfaces/cubic_spline.h"

namespace archgeo {
namespace {

constexpr double kDegrees = 180.0 / M_PI;

// |90° − θ| for two tangents, in degrees: the angle of a·b off zero.
double DeviationOfTangents(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(std::abs(a.dot(b)), a.cross(b).norm()) * kDegrees;
}

double AngleDegrees(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * kDegrees;
}

struct Accumulator {
  double max = 0.0, sum = 0.0;
  int count = 0;
  void Add(double x) {
    max = std::max(max, x);
    sum += x;
    ++count;
  }
  double Max() const { return count > 0 ? max : std::numeric_limits<double>::quiet_NaN(); }
  double Mean() const { return count > 0 ? sum / count : std::numeric_limits<double>::quiet_NaN(); }
};

}  // namespace

GridNetwork NetworkOfGrid(const Grid& grid) {
  GridNetwork net;
  net.num_points = grid.NumVertices();
  const std::vector<GridLine> lines = GridLines(grid);
  // Every vertex's (line, node) on its u-line [0] and its v-line [1]; every
  // segment by its end points.
  std::vector<std::array<std::array<int, 2>, 2>> at(net.num_points, {{{-1, -1}, {-1, -1}}});
  std::map<std::pair<int, int>, std::array<int, 2>> segment_of;
  for (size_t l = 0; l < lines.size(); ++l) {
    const GridLine& line = lines[l];
    net.lines.push_back({line.vertices, line.closed});
    const int n = static_cast<int>(line.vertices.size());
    const int family = l < lines.size() - static_cast<size_t>(grid.nu) ? 0 : 1;
    for (int k = 0; k < n; ++k) at[line.vertices[k]][family] = {int(l), k};
    const int segments = line.closed ? n : n - 1;
    for (int s = 0; s < segments; ++s) {
      const int a = line.vertices[s], b = line.vertices[(s + 1) % n];
      const bool inserted = segment_of.insert({{std::min(a, b), std::max(a, b)}, {int(l), s}}).second;
      CHECK(inserted) << "NetworkOfGrid: two grid edges join vertices " << a << " and " << b;
    }
  }
  for (int v = 0; v < net.num_points; ++v) {
    const GridNeighbours n = Neighbours(grid, v);
    if (n.Count() != 4) continue;
    net.crossings.push_back({v, {n.l0, n.t0, n.l1, n.t1}, at[v][0][0], at[v][0][1], at[v][1][0],
                             at[v][1][1]});
  }
  for (const auto& q : GridQuads(grid)) {
    GridNetwork::Quad quad;
    quad.vertices = q;
    for (int k = 0; k < 4; ++k) {
      const int a = q[k], b = q[(k + 1) % 4];
      quad.sides[k] = segment_of.at({std::min(a, b), std::max(a, b)});
    }
    net.quads.push_back(quad);
  }
  return net;
}

GridQuality MeasureGridNetwork(const GridNetwork& net, const std::vector<Eigen::Vector3d>& points) {
  CHECK_EQ(static_cast<int>(points.size()), net.num_points) << "MeasureGridNetwork: one point per vertex";
  std::vector<CubicSpline3> splines;
  splines.reserve(net.lines.size());
  for (const auto& line : net.lines) {
    std::vector<Eigen::Vector3d> p;
    for (int v : line.vertices) p.push_back(points[v]);
    splines.emplace_back(std::move(p), line.closed);
  }

  GridQuality quality;
  Accumulator spline_o, discrete_o, spline_e, discrete_e;
  for (const auto& c : net.crossings) {
    spline_o.Add(DeviationOfTangents(splines[c.line_a].Derivative(c.node_a),
                                     splines[c.line_b].Derivative(c.node_b)));
    double largest = 0.0;
    for (int k = 0; k < 4; ++k) {
      largest = std::max(largest, AngleDegrees(points[c.ring[k]] - points[c.vertex],
                                               points[c.ring[(k + 1) % 4]] - points[c.vertex]));
    }
    discrete_o.Add(std::abs(90.0 - largest));
  }
  for (const auto& q : net.quads) {
    double chord_max = 0, chord_min = std::numeric_limits<double>::infinity();
    double arc_max = 0, arc_min = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k) {
      const double chord = (points[q.vertices[(k + 1) % 4]] - points[q.vertices[k]]).norm();
      const double arc = splines[q.sides[k][0]].ArcLength(q.sides[k][1]);
      chord_max = std::max(chord_max, chord);
      chord_min = std::min(chord_min, chord);
      arc_max = std::max(arc_max, arc);
      arc_min = std::min(arc_min, arc);
    }
    discrete_e.Add(100.0 * (chord_max / chord_min - 1.0));
    spline_e.Add(100.0 * (arc_max / arc_min - 1.0));
  }
  quality.spline = {spline_o.Max(), spline_o.Mean(), spline_e.Max(), spline_e.Mean()};
  quality.discrete = {discrete_o.Max(), discrete_o.Mean(), discrete_e.Max(), discrete_e.Mean()};
  quality.crossings = static_cast<int>(net.crossings.size());
  quality.quads = static_cast<int>(net.quads.size());
  return quality;
}

GridQuality MeasureGrid(const Grid& grid, const Surface& surface) {
  return MeasureGridNetwork(NetworkOfGrid(grid), GridPoints(grid, surface));
}

}  // namespace archgeo
