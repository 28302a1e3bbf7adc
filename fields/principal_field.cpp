// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fields/principal_field.h"

#include <algorithm>
#include <cmath>

#include <glog/logging.h>

#include "fields/spin2_extension.h"

namespace archgeo {

PrincipalReliability Reliability(const std::vector<FaceCurvature>& curvature, double anisotropy,
                                 double flat) {
  PrincipalReliability r;
  const size_t n = curvature.size();
  r.weight.assign(n, 0.0);
  r.reliable.assign(n, 0);
  std::vector<double> size(n);
  for (size_t f = 0; f < n; ++f) size[f] = 0.5 * (std::abs(curvature[f].k1) + std::abs(curvature[f].k2));
  std::vector<double> sorted = size;
  double median = 0;
  if (n > 0) {
    std::nth_element(sorted.begin(), sorted.begin() + long(n / 2), sorted.end());
    median = sorted[n / 2];
  }
  for (size_t f = 0; f < n; ++f) {
    const FaceCurvature& k = curvature[f];
    const double sum = std::abs(k.k1) + std::abs(k.k2);
    const double a = sum > 0 ? (k.k1 - k.k2) / sum : 0.0;
    if (k.flat || (k.gaussian_sign > 0 && !(a >= anisotropy))) {
      ++r.umbilic;
    } else if (k.gaussian_sign > 0 && size[f] < flat * median) {
      ++r.flat;
    } else {
      r.reliable[f] = 1;
      r.weight[f] = a;
    }
  }
  return r;
}

double PrincipalAngle(const FaceCurvature& k) { return std::atan2(k.d1.y(), k.d1.x()); }

namespace {

// Per face: the index of its connected set of unreliable faces (joined
// across interior edges) when no reliable face is adjacent to that set, else
// −1.
std::vector<int> UnanchoredSets(const Mesh& mesh, const std::vector<EdgeTransport>& transports,
                                const PrincipalReliability& reliability, const std::vector<int>& unknown) {
  const size_t n = unknown.size();
  std::vector<std::vector<int>> next(n);
  for (const EdgeTransport& t : transports) {
    next[t.f.idx()].push_back(int(t.g.idx()));
    next[t.g.idx()].push_back(int(t.f.idx()));
  }
  std::vector<int> set(n, -1), component(n, -1);
  int sets = 0, components = 0;
  for (size_t start = 0; start < n; ++start) {
    if (unknown[start] < 0 || component[start] >= 0) continue;
    std::vector<int> members{int(start)};
    component[start] = components;
    bool anchored = false;
    for (size_t k = 0; k < members.size(); ++k) {
      for (int g : next[size_t(members[k])]) {
        if (reliability.reliable[size_t(g)]) {
          anchored = true;
        } else if (component[size_t(g)] < 0) {
          component[size_t(g)] = components;
          members.push_back(g);
        }
      }
    }
    ++components;
    if (anchored) continue;
    for (int f : members) set[size_t(f)] = sets;
    ++sets;
  }
  if (sets == 0) set.clear();
  return set;
}

}  // namespace

std::vector<double> PropagatedAngles(const Mesh& mesh, const std::vector<EdgeTransport>& transports,
                                     const std::vector<FaceCurvature>& curvature,
                                     const PrincipalReliability& reliability) {
  const size_t n = curvature.size();
  CHECK_EQ(n, mesh.number_of_faces());
  CHECK_EQ(reliability.reliable.size(), n);
  std::vector<bool> free(n);
  std::vector<int> unknown(n, -1);
  int m = 0;
  std::vector<Eigen::Vector2d> u(n, Eigen::Vector2d::Zero());
  for (size_t f = 0; f < n; ++f) {
    free[f] = !reliability.reliable[f];
    if (free[f]) {
      unknown[f] = m++;
    } else {
      const double theta = PrincipalAngle(curvature[f]);
      u[f] = Eigen::Vector2d(std::cos(2 * theta), std::sin(2 * theta));
    }
  }
  std::vector<double> theta(n, 0.0);
  for (size_t f = 0; f < n; ++f) {
    if (!free[f]) theta[f] = PrincipalAngle(curvature[f]);
  }
  if (m == 0) return theta;
  // A tiny |u|² keeps a free set without reliable faces solvable.
  double mean_weight = 0;
  for (const EdgeTransport& t : transports) mean_weight += t.weight;
  mean_weight /= std::max<size_t>(1, transports.size());
  const Spin2Extension extension(transports, free, 1e-9 * mean_weight);
  CHECK(extension.Extend(&u)) << "PropagatedAngles: the extension's matrix is singular";
  // A connected set of unreliable faces no reliable face touches (a whole
  // sphere, a near-umbilic dome): the smoothest line field there, the
  // eigenvector of the smallest eigenvalue of the same (block-diagonal)
  // matrix, by inverse iteration from the frames' e1, per set.
  const std::vector<int> set = UnanchoredSets(mesh, transports, reliability, unknown);
  const int sets = set.empty() ? 0 : 1 + *std::max_element(set.begin(), set.end());
  if (sets > 0) {
    std::vector<Eigen::Vector2d> y(n, Eigen::Vector2d::Zero());
    for (size_t f = 0; f < n; ++f) {
      if (set[f] >= 0) y[f] = Eigen::Vector2d(1, 0);
    }
    for (int it = 0; it < 50; ++it) {
      CHECK(extension.InverseStep(&y)) << "PropagatedAngles: the inverse iteration failed";
      std::vector<double> norm(size_t(sets), 0.0);
      for (size_t f = 0; f < n; ++f) {
        if (set[f] >= 0) norm[size_t(set[f])] += y[f].squaredNorm();
      }
      for (size_t f = 0; f < n; ++f) {
        if (set[f] >= 0) y[f] /= std::sqrt(norm[size_t(set[f])]);
      }
    }
    for (size_t f = 0; f < n; ++f) {
      if (set[f] >= 0) u[f] = y[f];
    }
  }
  for (size_t f = 0; f < n; ++f) {
    if (free[f]) theta[f] = (u[f].x() == 0 && u[f].y() == 0) ? 0.0 : 0.5 * std::atan2(u[f].y(), u[f].x());
  }
  return theta;
}

FaceCurvature TurnedCurvature(const FaceCurvature& k, double theta, double sign_tolerance) {
  const Eigen::Vector2d d1(std::cos(theta), std::sin(theta)), d2(-d1.y(), d1.x());
  const Eigen::Matrix2d M = k.k1 * d1 * d1.transpose() + k.k2 * d2 * d2.transpose();
  // Same eigenvalues: flat exactly when the measured face is.
  return CurvatureOfMatrix(M, k.flat ? INFINITY : 0.0, sign_tolerance);
}

}  // namespace archgeo
