// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// core/newell.h against analytic values: a planar polygon's N is twice its
// vector area along its normal, whatever corner it starts at; a skew quad's
// N is the sum of its two triangles' (any diagonal); a polygon without area
// has N = 0 and the zero unit normal.
#include <gtest/gtest.h>

#include <array>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/newell.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

using V = Eigen::Vector3d;

TEST(Newell, PlanarPolygonGivesTwiceItsAreaAlongItsNormal) {
  // A 2 x 3 rectangle in the plane through (1, 2, 3) with normal (0, 0.6, 0.8).
  const V n(0, 0.6, 0.8), a(1, 0, 0), b = n.cross(a), o(1, 2, 3);
  const std::vector<V> p = {o, o + 2 * a, o + 2 * a + 3 * b, o + 3 * b};
  for (int start = 0; start < 4; ++start) {
    const auto corner = [&](int k) { return p[size_t((k + start) % 4)]; };
    EXPECT_LT((NewellVector(4, corner) - 12.0 * n).norm(), 1e-12);
    EXPECT_LT((NewellNormal(4, corner) - n).norm(), 1e-15);
  }
  // Any corner type indexed [0..2]: a raw double array.
  const double raw[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_EQ(NewellVector(3, [&](int k) { return raw[k]; }), V(0, 0, 1));
}

TEST(Newell, SkewQuadIsTheSumOfItsTriangles) {
  const std::array<V, 4> p = {V(0, 0, 0), V(1, 0, 0.3), V(1.2, 1, -0.2), V(0, 0.9, 0.1)};
  const V triangles = (p[1] - p[0]).cross(p[2] - p[0]) + (p[2] - p[0]).cross(p[3] - p[0]);
  EXPECT_LT((NewellVector(4, [&](int k) { return p[size_t(k)]; }) - triangles).norm(), 1e-14);
}

// A unit square 1e8 away from the origin: twice its area along z, to the
// digits its coordinates keep (Σ p_k × p_{k+1} of absolute positions would
// lose them all: its terms are 1e16 for a sum of 2).
TEST(Newell, FarFromTheOriginKeepsItsDigits) {
  const double far = 1e8;
  const std::vector<Eigen::Vector3d> square = {{far, far, far},
                                               {far + 1, far, far},
                                               {far + 1, far + 1, far},
                                               {far, far + 1, far}};
  const Eigen::Vector3d n = NewellVector(4, [&](int k) { return square[size_t(k)]; });
  EXPECT_NEAR(n.z(), 2.0, 1e-12);
  EXPECT_NEAR(n.x(), 0.0, 1e-12);
  EXPECT_NEAR(n.y(), 0.0, 1e-12);
}

TEST(Newell, PolygonWithoutAreaHasTheZeroNormal) {
  const std::array<V, 3> line = {V(0, 0, 0), V(1, 1, 1), V(2, 2, 2)};
  const auto corner = [&](int k) { return line[size_t(k)]; };
  EXPECT_EQ(NewellVector(3, corner), V::Zero());
  EXPECT_EQ(NewellNormal(3, corner), V::Zero());
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
