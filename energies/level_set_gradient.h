// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The gradient of a piecewise-linear function on one triangle, in the
// triangle's 2-D frame: shared by the level-set functors (level_set_*.h).
//
//   ∇g = Σ_k g_k ∇φ_k,   ∇φ_k = J (p_{k+2} − p_{k+1}) / (2A)
//
// p_0, p_1, p_2 are the corners (counter-clockwise, 2A = (p1 − p0) × (p2 − p0)
// > 0), J the rotation by +90°, φ_k the linear hat function of corner k
// (indices mod 3). Not a cost functor.
#ifndef ARCHGEO_ENERGIES_LEVEL_SET_GRADIENT_H_
#define ARCHGEO_ENERGIES_LEVEL_SET_GRADIENT_H_

#include <Eigen/Core>

namespace archgeo {

struct TriangleGradient {
  // corners: 6 doubles, (x0, y0, x1, y1, x2, y2) in the face frame.
  explicit TriangleGradient(const double corners[6]) {
    const Eigen::Vector2d p[3] = {{corners[0], corners[1]},
                                  {corners[2], corners[3]},
                                  {corners[4], corners[5]}};
    const Eigen::Vector2d a = p[1] - p[0], b = p[2] - p[0];
    area = 0.5 * (a.x() * b.y() - a.y() * b.x());
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d e = p[(k + 2) % 3] - p[(k + 1) % 3];
      G.col(k) = Eigen::Vector2d(-e.y(), e.x()) / (2.0 * area);
    }
  }

  // ∇g from the corner values g0, g1, g2.
  template <typename T>
  Eigen::Matrix<T, 2, 1> operator()(const T& g0, const T& g1, const T& g2) const {
    return Eigen::Matrix<T, 2, 1>(T(G(0, 0)) * g0 + T(G(0, 1)) * g1 + T(G(0, 2)) * g2,
                                  T(G(1, 0)) * g0 + T(G(1, 1)) * g1 + T(G(1, 2)) * g2);
  }

  Eigen::Matrix<double, 2, 3> G;  // columns ∇φ_k
  double area = 0.0;              // signed; > 0 for counter-clockwise corners
};

}  // namespace archgeo

#endif  // ARCHGEO_ENERGIES_LEVEL_SET_GRADIENT_H_
