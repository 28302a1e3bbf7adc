// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Tests for surfaces/: the parametric surfaces and their factory.
//  (a) analytic first derivatives of every named surface against central
//      differences, and Jets through Point equal to Tangents;
//  (b) periodicity (with the Klein bottle's reflection) and regularity
//      (|x_u × x_v| > 0: every surface is an immersion);
//  (c) closest parameter: recovers (u, v) of surface points from a nearby
//      start and from no start, and the foot point of a point off the surface;
//  (d) analytic facts: the torus and the unsheared Dupin cyclide are
//      parametrised by curvature lines (x_u · x_v = 0), the tower's radius is
//      a at the waist and a√2 at |v − z_w| = c, the function graph is ±s at
//      the corners, the placement is x → Q x + t;
//  (e) the factory and grid requests: unknown names and parameters, non-finite
//      and out-of-range values, closures on non-periodic directions and sizes
//      below 2 throw InputError naming the key.
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "surfaces/grid.h"
#include "surfaces/surface.h"
#include "surfaces/surface_factory.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

// Central differences of a smooth map: error O(h²) ≈ 1e-10 relative at h = 1e-5.
constexpr double kDifferenceStep = 1e-5;
constexpr double kDifferenceTolerance = 1e-7;
// Agreement of quantities equal in exact arithmetic (relative to the size).
constexpr double kTolerance = 1e-12;
constexpr int kSamples = 9;

double Size(const Surface& s) {
  // A length scale: the largest distance from x(u0, v0) over a coarse sample.
  const ParameterDomain d = s.Domain();
  double size = 0.0;
  const Eigen::Vector3d origin = s.Point(Eigen::Vector2d(d.u0, d.v0));
  for (int i = 0; i <= 4; ++i) {
    for (int j = 0; j <= 4; ++j) {
      const Eigen::Vector2d uv(d.u0 + d.PeriodU() * i / 4, d.v0 + d.PeriodV() * j / 4);
      size = std::max(size, (s.Point(uv) - origin).norm());
    }
  }
  return size;
}

// Sample parameters strictly inside the domain (and a little beyond for open
// directions: the formulas hold there too).
std::vector<Eigen::Vector2d> Samples(const Surface& s) {
  const ParameterDomain d = s.Domain();
  std::vector<Eigen::Vector2d> uv;
  for (int i = 0; i < kSamples; ++i) {
    for (int j = 0; j < kSamples; ++j) {
      uv.emplace_back(d.u0 + d.PeriodU() * (i + 0.37) / kSamples,
                      d.v0 + d.PeriodV() * (j + 0.61) / kSamples);
    }
  }
  return uv;
}

TEST(Surfaces, EveryNameIsBuiltWithItsDocumentedParameters) {
  const std::vector<std::string> names = SurfaceNames();
  ASSERT_EQ(names.size(), 10u);
  for (const std::string& name : names) {
    const Surface s = MakeSurface(name);
    const ParameterValues values = SurfaceParameterValues(s);
    const std::vector<SurfaceParameter> documented = SurfaceParameters(name);
    ASSERT_EQ(values.size(), documented.size()) << name;
    for (const SurfaceParameter& p : documented) {
      EXPECT_FALSE(p.doc.empty()) << name << "." << p.name;
      EXPECT_EQ(values.at(p.name), p.default_value) << name << "." << p.name;
    }
    const ParameterDomain d = s.Domain();
    EXPECT_LT(d.u0, d.u1) << name;
    EXPECT_LT(d.v0, d.v1) << name;
  }
}

TEST(Surfaces, TangentsMatchCentralDifferences) {
  for (const std::string& name : SurfaceNames()) {
    const Surface s = MakeSurface(name);
    const ParameterDomain d = s.Domain();
    const double hu = kDifferenceStep * d.PeriodU(), hv = kDifferenceStep * d.PeriodV();
    for (const Eigen::Vector2d& uv : Samples(s)) {
      Eigen::Vector3d xu, xv;
      s.Tangents(uv[0], uv[1], &xu, &xv);
      const Eigen::Vector3d du =
          (s.Point(uv[0] + hu, uv[1]) - s.Point(uv[0] - hu, uv[1])) / (2.0 * hu);
      const Eigen::Vector3d dv =
          (s.Point(uv[0], uv[1] + hv) - s.Point(uv[0], uv[1] - hv)) / (2.0 * hv);
      EXPECT_LT((xu - du).norm(), kDifferenceTolerance * (1.0 + xu.norm())) << name;
      EXPECT_LT((xv - dv).norm(), kDifferenceTolerance * (1.0 + xv.norm())) << name;
    }
  }
}

TEST(Surfaces, JetsPassThroughPointAndTangents) {
  using Jet = ceres::Jet<double, 2>;
  for (const std::string& name : SurfaceNames()) {
    const Surface s = MakeSurface(name);
    for (const Eigen::Vector2d& uv : Samples(s)) {
      const Vec3T<Jet> p = s.Point(Jet(uv[0], 0), Jet(uv[1], 1));
      Eigen::Vector3d xu, xv;
      s.Tangents(uv[0], uv[1], &xu, &xv);
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(p[k].a, s.Point(uv)[k], kTolerance * (1.0 + std::abs(p[k].a))) << name;
        EXPECT_NEAR(p[k].v[0], xu[k], kTolerance * (1.0 + xu.norm())) << name;
        EXPECT_NEAR(p[k].v[1], xv[k], kTolerance * (1.0 + xv.norm())) << name;
      }
      // Tangents<Jet>: the mixed second derivatives agree (x_uv = x_vu).
      Vec3T<Jet> ju, jv;
      s.Tangents(Jet(uv[0], 0), Jet(uv[1], 1), &ju, &jv);
      for (int k = 0; k < 3; ++k) {
        EXPECT_NEAR(ju[k].v[1], jv[k].v[0], 1e-9 * (1.0 + std::abs(ju[k].v[1]))) << name;
      }
    }
  }
}

TEST(Surfaces, PeriodicityAsDeclared) {
  struct Expected {
    const char* name;
    bool periodic_u, periodic_v, flip;
  };
  const Expected expected[] = {
      {"klein_bottle", true, true, true}, {"tower", true, false, false},
      {"tower_rings", false, false, false}, {"dupin_bridge", false, false, false},
      {"function_graph", false, false, false}, {"plane", false, false, false},
      {"cylinder", true, false, false}, {"torus", true, true, false},
      {"catenoid", true, false, false}, {"helicoid", false, false, false}};
  for (const Expected& e : expected) {
    const Surface s = MakeSurface(e.name);
    const ParameterDomain d = s.Domain();
    EXPECT_EQ(d.periodic_u, e.periodic_u) << e.name;
    EXPECT_EQ(d.periodic_v, e.periodic_v) << e.name;
    EXPECT_EQ(d.u_seam_flips_v, e.flip) << e.name;
    const double size = Size(s);
    for (const Eigen::Vector2d& uv : Samples(s)) {
      Eigen::Vector3d xu, xv, yu, yv;
      s.Tangents(uv[0], uv[1], &xu, &xv);
      if (d.periodic_u) {
        // x(u + P, v) = x(u, v) or, across a flipping seam, x(u, v0 + v1 − v);
        // then x_u keeps its sign and x_v flips.
        const Eigen::Vector2d there(uv[0] + d.PeriodU(), uv[1]);
        const Eigen::Vector2d mirror(uv[0], d.u_seam_flips_v ? d.v0 + d.v1 - uv[1] : uv[1]);
        EXPECT_LT((s.Point(there) - s.Point(mirror)).norm(), kTolerance * size) << e.name;
        s.Tangents(there[0], there[1], &yu, &yv);
        Eigen::Vector3d mu, mv;
        s.Tangents(mirror[0], mirror[1], &mu, &mv);
        EXPECT_LT((yu - mu).norm(), 1e-10 * (1.0 + mu.norm())) << e.name;
        EXPECT_LT((yv - (d.u_seam_flips_v ? -mv : mv)).norm(), 1e-10 * (1.0 + mv.norm())) << e.name;
        // Without the reflection the flipping surface is not u-periodic.
        if (d.u_seam_flips_v) {
          EXPECT_GT((s.Point(there) - s.Point(uv)).norm(), 1e-3 * size);
        }
      } else {
        // An open direction does not close up: the two ends differ.
        EXPECT_GT((s.Point(Eigen::Vector2d(d.u0, uv[1])) - s.Point(Eigen::Vector2d(d.u1, uv[1]))).norm(),
                  1e-3 * size)
            << e.name;
      }
      if (d.periodic_v) {
        EXPECT_LT((s.Point(Eigen::Vector2d(uv[0], uv[1] + d.PeriodV())) - s.Point(uv)).norm(),
                  kTolerance * size)
            << e.name;
      } else {
        EXPECT_GT((s.Point(Eigen::Vector2d(uv[0], d.v0)) - s.Point(Eigen::Vector2d(uv[0], d.v1))).norm(),
                  1e-3 * size)
            << e.name;
      }
    }
  }
}

TEST(Surfaces, EverySurfaceIsAnImmersion) {
  // |x_u × x_v| bounded away from 0 on a fine sample of the whole domain.
  constexpr int kFine = 81;
  for (const std::string& name : SurfaceNames()) {
    const Surface s = MakeSurface(name);
    const ParameterDomain d = s.Domain();
    double smallest = INFINITY, largest = 0.0;
    for (int i = 0; i <= kFine; ++i) {
      for (int j = 0; j <= kFine; ++j) {
        Eigen::Vector3d xu, xv;
        s.Tangents(d.u0 + d.PeriodU() * i / kFine, d.v0 + d.PeriodV() * j / kFine, &xu, &xv);
        const double area = xu.cross(xv).norm();
        smallest = std::min(smallest, area);
        largest = std::max(largest, area);
      }
    }
    EXPECT_GT(smallest, 1e-3 * largest) << name;
  }
}

TEST(Surfaces, CanonicalAndWrappedKeepThePoint) {
  for (const char* name : {"klein_bottle", "torus", "tower", "cylinder"}) {
    const Surface s = MakeSurface(name);
    const ParameterDomain d = s.Domain();
    const double size = Size(s);
    for (const Eigen::Vector2d& uv : Samples(s)) {
      for (int turns : {-3, -1, 1, 2, 5}) {
        const Eigen::Vector2d far(uv[0] + turns * d.PeriodU(),
                                  uv[1] + (d.periodic_v ? 2 * turns * d.PeriodV() : 0.0));
        const Eigen::Vector2d c = s.Canonical(far);
        EXPECT_GE(c[0], d.u0);
        EXPECT_LT(c[0], d.u1);
        EXPECT_GE(c[1], d.v0);
        EXPECT_LE(c[1], d.v1);
        EXPECT_LT((s.Point(c) - s.Point(far)).norm(), 1e-11 * size) << name;
      }
    }
  }
  // Open directions: Canonical clamps, Wrapped does not.
  const Surface plane = MakeSurface("plane");
  EXPECT_EQ(plane.Canonical(Eigen::Vector2d(-1, 12)), Eigen::Vector2d(0, 10));
  EXPECT_EQ(plane.Wrapped(Eigen::Vector2d(-1, 12)), Eigen::Vector2d(-1, 12));
}

TEST(Surfaces, ClosestParameterRecoversSurfacePoints) {
  for (const std::string& name : SurfaceNames()) {
    const Surface s = MakeSurface(name);
    const ParameterDomain d = s.Domain();
    const double size = Size(s);
    for (const Eigen::Vector2d& uv : Samples(s)) {
      const Eigen::Vector3d x = s.Point(uv);
      // From a start a 1% of the domain away (inside the basin: the Klein
      // bottle's figure-8 lobes are narrower than 5% of its domain).
      const Eigen::Vector2d start = uv + Eigen::Vector2d(0.01 * d.PeriodU(), -0.008 * d.PeriodV());
      const Eigen::Vector2d found = s.ClosestParameter(x, start);
      EXPECT_LT((s.Point(found) - x).norm(), kTolerance * size) << name;
      EXPECT_LT((found - s.Canonical(uv)).norm(), 1e-9 * (1.0 + uv.norm())) << name;
    }
  }
}

TEST(Surfaces, ClosestParameterFindsTheFootOfAnOffsetPoint) {
  // x + δ n has foot point x for δ below the smaller radius of curvature.
  for (const char* name : {"torus", "tower", "catenoid", "dupin_bridge", "function_graph"}) {
    const Surface s = MakeSurface(name);
    const double size = Size(s);
    for (const Eigen::Vector2d& uv : Samples(s)) {
      const Eigen::Vector3d x = s.Point(uv);
      const Eigen::Vector3d off = x + 1e-3 * size * s.Normal(uv);
      const Eigen::Vector2d found = s.ClosestParameter(off);  // global start
      EXPECT_LT((s.Point(found) - x).norm(), 1e-9 * size) << name;
    }
  }
}

TEST(Surfaces, CurvatureLineParametrisationsAreOrthogonal) {
  // The torus and the Dupin cyclide (shear 0) are parametrised by their lines
  // of curvature; the sheared cyclide is not.
  const Surface torus = MakeSurface("torus");
  const Surface cyclide = MakeSurface("dupin_bridge", {{"shear", 0.0}});
  const Surface sheared = MakeSurface("dupin_bridge");
  double sheared_max = 0.0;
  for (const Eigen::Vector2d& uv : Samples(cyclide)) {
    Eigen::Vector3d xu, xv;
    cyclide.Tangents(uv[0], uv[1], &xu, &xv);
    EXPECT_LT(std::abs(xu.dot(xv)), 1e-12 * xu.norm() * xv.norm());
    sheared.Tangents(uv[0], uv[1], &xu, &xv);
    sheared_max = std::max(sheared_max, std::abs(xu.dot(xv)) / (xu.norm() * xv.norm()));
  }
  EXPECT_GT(sheared_max, std::sin(20.0 * M_PI / 180.0));
  for (const Eigen::Vector2d& uv : Samples(torus)) {
    Eigen::Vector3d xu, xv;
    torus.Tangents(uv[0], uv[1], &xu, &xv);
    EXPECT_LT(std::abs(xu.dot(xv)), 1e-12 * xu.norm() * xv.norm());
  }
}

TEST(Surfaces, AnalyticValues) {
  // Tower: radius a at the waist, a√2 at |v − z_w| = c; twist turns the v-line.
  const Surface tower = MakeSurface("tower", {{"a", 5}, {"c", 10}, {"z_w", 20}, {"H", 40},
                                              {"twist", 1.0}});
  const Eigen::Vector3d waist = tower.Point(Eigen::Vector2d(0.0, 20.0));
  EXPECT_NEAR(waist.head<2>().norm(), 5.0, kTolerance);
  EXPECT_NEAR(std::atan2(waist[1], waist[0]), 0.5, kTolerance);  // τ v = 1/40 · 20
  EXPECT_NEAR(tower.Point(Eigen::Vector2d(0.3, 30.0)).head<2>().norm(), 5.0 * std::sqrt(2.0), kTolerance);
  // Function graph: f = ±s at the corners, s + h... at the centre h − 0 (saddle 0).
  const Surface graph = MakeSurface("function_graph", {{"h", 2}, {"s", 3}});
  EXPECT_NEAR(graph.Point(Eigen::Vector2d(0, 0))[2], 3.0, kTolerance);
  EXPECT_NEAR(graph.Point(Eigen::Vector2d(10, 0))[2], -3.0, kTolerance);
  EXPECT_NEAR(graph.Point(Eigen::Vector2d(5, 5))[2], 2.0, kTolerance);
  // Cylinder: |x_u| = R, |x_v| = 1.
  const Surface cylinder = MakeSurface("cylinder", {{"R", 2.5}});
  Eigen::Vector3d xu, xv;
  cylinder.Tangents(0.7, 0.3, &xu, &xv);
  EXPECT_NEAR(xu.norm(), 2.5, kTolerance);
  EXPECT_NEAR(xv.norm(), 1.0, kTolerance);
  // Klein bottle: on the central circle (v = 0) ρ = R, z = 0.
  const Surface klein = MakeSurface("klein_bottle", {{"R", 4}, {"a", 1.5}});
  const Eigen::Vector3d k = klein.Point(Eigen::Vector2d(1.1, 0.0));
  EXPECT_NEAR(k.head<2>().norm(), 4.0, kTolerance);
  EXPECT_NEAR(k[2], 0.0, kTolerance);
}

TEST(Surfaces, PlacementIsARigidMotion) {
  const Surface torus = MakeSurface("torus");
  const Eigen::Matrix3d q = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d t(4, -5, 6);
  const Surface moved = torus.Placed(q, t);
  for (const Eigen::Vector2d& uv : Samples(torus)) {
    EXPECT_LT((moved.Point(uv) - (q * torus.Point(uv) + t)).norm(), kTolerance * 10);
    Eigen::Vector3d xu, xv, mu, mv;
    torus.Tangents(uv[0], uv[1], &xu, &xv);
    moved.Tangents(uv[0], uv[1], &mu, &mv);
    EXPECT_LT((mu - q * xu).norm(), kTolerance * 10);
    EXPECT_LT((mv - q * xv).norm(), kTolerance * 10);
    // The closest parameter is found in the moved frame too.
    EXPECT_LT((moved.ClosestParameter(moved.Point(uv), uv + Eigen::Vector2d(0.1, 0.1)) - uv).norm(), 1e-9);
  }
}

// The InputError thrown by `f`, or a failure.
template <typename F>
InputError Thrown(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "no InputError";
  return InputError("", 0, "", "");
}

TEST(SurfaceFactory, BadInputNamesTheKey) {
  InputContext where;
  where.file = "grid.yaml";
  where.line = 7;
  where.name_key = "surface.type";
  where.parameter_key_prefix = "surface.parameters";
  InputError e = Thrown([&] { MakeSurface("moebius", {}, where); });
  EXPECT_EQ(e.key(), "surface.type");
  EXPECT_EQ(e.file(), "grid.yaml");
  EXPECT_EQ(e.line(), 7);
  EXPECT_NE(e.message().find("klein_bottle"), std::string::npos);  // lists the known names
  e = Thrown([&] { MakeSurface("torus", {{"radius", 2}}, where); });
  EXPECT_EQ(e.key(), "surface.parameters.radius");
  e = Thrown([&] { MakeSurface("torus", {{"R", NAN}}, where); });
  EXPECT_EQ(e.key(), "surface.parameters.R");
  e = Thrown([&] { MakeSurface("torus", {{"R", INFINITY}}, where); });
  EXPECT_EQ(e.key(), "surface.parameters.R");
  e = Thrown([&] { MakeSurface("torus", {{"r", 0.0}}, where); });
  EXPECT_EQ(e.key(), "surface.parameters.r");
  e = Thrown([&] { MakeSurface("torus", {{"R", 1.0}, {"r", 1.0}}, where); });
  EXPECT_EQ(e.key(), "surface.parameters.r");
  e = Thrown([&] { MakeSurface("tower", {{"sector", 7.0}}, where); });
  EXPECT_EQ(e.key(), "surface.parameters.sector");
  e = Thrown([&] { MakeSurface("dupin_bridge", {{"mu", 200.0}}, where); });
  EXPECT_EQ(e.key(), "surface.parameters.mu");
  e = Thrown([&] { MakeSurface("dupin_bridge", {{"u_hi", 0.0}}, where); });
  EXPECT_EQ(e.key(), "surface.parameters.u_hi");
  e = Thrown([&] { MakeSurface("klein_bottle", {{"R", 1.0}}, where); });
  EXPECT_EQ(e.key(), "surface.parameters.R");
  e = Thrown([&] { SurfaceParameters("sphere", where); });
  EXPECT_EQ(e.key(), "surface.type");
  // A tower sector within 1e-6 of 2π is the closed tower.
  EXPECT_TRUE(MakeSurface("tower", {{"sector", 6.2831853}}).Domain().periodic_u);
  EXPECT_FALSE(MakeSurface("tower", {{"sector", 6.28}}).Domain().periodic_u);
}

TEST(GridRequest, BadSizesAndClosuresNameTheKey) {
  InputContext where;
  where.file = "g.yaml";
  const Surface plane = MakeSurface("plane");
  const Surface cylinder = MakeSurface("cylinder");
  const Surface torus = MakeSurface("torus");
  EXPECT_NO_THROW(CheckGridRequest(plane, 2, 2, GridType::kOpen, where));
  EXPECT_NO_THROW(CheckGridRequest(torus, 3, 3, GridType::kClosedBoth, where));
  EXPECT_EQ(Thrown([&] { CheckGridRequest(plane, 1, 5, GridType::kOpen, where); }).key(), "grid.nu");
  EXPECT_EQ(Thrown([&] { CheckGridRequest(plane, 5, 0, GridType::kOpen, where); }).key(), "grid.nv");
  EXPECT_EQ(Thrown([&] { CheckGridRequest(cylinder, 2, 5, GridType::kClosedU, where); }).key(),
            "grid.nu");
  EXPECT_EQ(Thrown([&] { CheckGridRequest(plane, 5, 5, GridType::kClosedU, where); }).key(),
            "grid.type");
  EXPECT_EQ(Thrown([&] { CheckGridRequest(cylinder, 5, 5, GridType::kClosedV, where); }).key(),
            "grid.type");
  EXPECT_EQ(Thrown([&] { CheckGridRequest(cylinder, 5, 5, GridType::kClosedBoth, where); }).key(),
            "grid.type");
  GridKeys keys;
  keys.type = "grid.closure";
  EXPECT_EQ(Thrown([&] { CheckGridRequest(plane, 5, 5, GridType::kClosedV, where, keys); }).key(),
            "grid.closure");
  EXPECT_EQ(Thrown([&] { ParseGridType("closed", where, "grid.type"); }).key(), "grid.type");
  EXPECT_EQ(ParseGridType("closed_both", where, "grid.type"), GridType::kClosedBoth);
}

}  // namespace
}  // namespace archgeo
