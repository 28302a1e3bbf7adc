// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — analytic test meshes for the visual-smoothness analysis [Pellis 2019].
#include "generators/smoothness_surfaces.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glog/logging.h>

#include "core/input_error.h"
#include "analysis/smoothness_metrics.h"

namespace archgeo {
namespace {

[[noreturn]] void FailKey(const std::string& key, const std::string& message) {
  throw InputError("", 0, key, message);
}

void RequireFinite(const std::string& key, double x) {
  if (!std::isfinite(x)) FailKey(key, "must be finite, got " + std::to_string(x));
}
void RequirePositive(const std::string& key, double x) {
  if (!(x > 0) || !std::isfinite(x)) FailKey(key, "must be finite and > 0, got " + std::to_string(x));
}
void RequireCount(const std::string& key, int n, int minimum) {
  if (n < minimum) {
    FailKey(key, "must be at least " + std::to_string(minimum) + ", got " + std::to_string(n));
  }
}

void CheckTorus(double R, double r) {
  RequirePositive("R", R);
  RequirePositive("r", r);
  if (!(r < R)) FailKey("r", "must be smaller than R (a ring torus), got r = " +
                              std::to_string(r) + ", R = " + std::to_string(R));
}

FaceIndex AddFace(Mesh& mesh, std::initializer_list<VertexIndex> vertices) {
  const FaceIndex f = mesh.add_face(std::vector<VertexIndex>(vertices));
  CHECK(f != Mesh::null_face()) << "smoothness_surfaces: add_face failed";
  return f;
}

}  // namespace

Mesh TorusPrincipalQuads(double R, double r, int n_u, int n_v) {
  CheckTorus(R, r);
  RequireCount("n_u", n_u, 3);
  RequireCount("n_v", n_v, 3);
  Mesh mesh;
  for (int j = 0; j < n_v; ++j) {
    const double v = 2 * M_PI * j / n_v;
    for (int i = 0; i < n_u; ++i) {
      const double u = 2 * M_PI * i / n_u;
      const double rho = R + r * std::cos(v);
      mesh.add_vertex(Point(rho * std::cos(u), rho * std::sin(u), r * std::sin(v)));
    }
  }
  const auto at = [&](int i, int j) { return VertexIndex((j % n_v) * n_u + (i % n_u)); };
  for (int j = 0; j < n_v; ++j) {
    for (int i = 0; i < n_u; ++i) {
      AddFace(mesh, {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});  // along x_u × x_v
    }
  }
  return mesh;
}

double TorusTotalAbsoluteCurvature(double R, double r) {
  CheckTorus(R, r);
  return 4 * M_PI * M_PI * R + 8 * M_PI * r;
}

double RevolutionProfile::Radius(double z) const {
  return r0 + (r1 - r0) * z / height + bulge * std::sin(M_PI * z / height);
}

Mesh RevolutionTriangles(const RevolutionProfile& profile, int n_around, int n_rings) {
  RequirePositive("r0", profile.r0);
  RequirePositive("r1", profile.r1);
  RequirePositive("height", profile.height);
  RequireFinite("bulge", profile.bulge);
  RequireCount("n_around", n_around, 3);
  RequireCount("n_rings", n_rings, 1);
  Mesh mesh;
  for (int j = 0; j <= n_rings; ++j) {
    const double z = profile.height * j / n_rings;
    const double rho = profile.Radius(z);
    if (!(rho > 0)) {
      FailKey("bulge", "the profile radius must stay > 0, got " + std::to_string(rho) + " at z = " +
                        std::to_string(z));
    }
    for (int i = 0; i < n_around; ++i) {
      const double angle = 2 * M_PI * (i + 0.5 * j) / n_around;
      mesh.add_vertex(Point(rho * std::cos(angle), rho * std::sin(angle), z));
    }
  }
  const auto at = [&](int i, int j) { return VertexIndex(j * n_around + (i % n_around)); };
  for (int j = 0; j < n_rings; ++j) {
    for (int i = 0; i < n_around; ++i) {
      // Ring j + 1 vertex i sits between ring j vertices i and i + 1.
      AddFace(mesh, {at(i, j), at(i + 1, j), at(i, j + 1)});
      AddFace(mesh, {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return mesh;
}

double ConeDeviation(const Mesh& mesh, double r0, double r1, double height) {
  RequireFinite("r0", r0);
  RequireFinite("r1", r1);
  RequirePositive("height", height);
  double deviation = 0;
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    const double rho = std::hypot(p.x(), p.y());
    const double cone = r0 + (r1 - r0) * p.z() / height;
    deviation = std::max(deviation, std::abs(rho - cone) / height);
  }
  return deviation;
}

double LatticeEnergyPerArea(double alpha, double beta, const std::array<double, 2>& a,
                            const std::array<double, 2>& b, LatticeFaces faces) {
  RequireFinite("alpha", alpha);
  RequireFinite("beta", beta);
  for (double x : {a[0], a[1]}) RequireFinite("a", x);
  for (double x : {b[0], b[1]}) RequireFinite("b", x);
  const double cell_area = std::abs(a[0] * b[1] - a[1] * b[0]);
  if (!(cell_area > 0)) FailKey("b", "a and b must span a lattice (|a x b| > 0)");

  if (faces == LatticeFaces::kTrianglesAveraged) {
    return 0.5 * (LatticeEnergyPerArea(alpha, beta, a, b, LatticeFaces::kTrianglesDiagonalAPlusB) +
                  LatticeEnergyPerArea(alpha, beta, a, b, LatticeFaces::kTrianglesDiagonalAMinusB));
  }
  // 3 x 3 vertices i, j ∈ {−1, 0, 1}; vertex (i, j) has index 3(j + 1) + (i + 1).
  Mesh mesh;
  for (int j = -1; j <= 1; ++j) {
    for (int i = -1; i <= 1; ++i) {
      const double x = i * a[0] + j * b[0], y = i * a[1] + j * b[1];
      mesh.add_vertex(Point(x, y, alpha * x * x + beta * y * y));
    }
  }
  const auto at = [](int i, int j) { return VertexIndex(3 * (j + 1) + (i + 1)); };
  for (int j = -1; j < 1; ++j) {
    for (int i = -1; i < 1; ++i) {
      const VertexIndex q0 = at(i, j), q1 = at(i + 1, j), q2 = at(i + 1, j + 1), q3 = at(i, j + 1);
      switch (faces) {
        case LatticeFaces::kQuads:
          AddFace(mesh, {q0, q1, q2, q3});
          break;
        case LatticeFaces::kTrianglesDiagonalAPlusB:
          AddFace(mesh, {q0, q1, q2});
          AddFace(mesh, {q0, q2, q3});
          break;
        case LatticeFaces::kTrianglesDiagonalAMinusB:
          AddFace(mesh, {q0, q1, q3});
          AddFace(mesh, {q1, q2, q3});
          break;
        case LatticeFaces::kTrianglesAveraged:
          LOG(FATAL) << "handled above";
      }
    }
  }
  // a × b < 0 gives clockwise faces: the energy does not depend on orientation.
  const EdgeSmoothness edges = MeasureEdgeSmoothness(mesh, FaceNormals(mesh));
  const VertexIndex origin = at(0, 0);
  double energy = 0;
  for (HalfedgeIndex h : mesh.halfedges_around_target(mesh.halfedge(origin))) {
    const size_t e = mesh.edge(h).idx();
    CHECK(edges.measured[e]) << "LatticeEnergyPerArea: a star edge is not interior";
    energy += 0.5 * edges.length[e] * edges.dual_length[e];
  }
  return energy / cell_area;
}

double LatticeEnergyPerArea(double alpha, double beta, double theta, LatticeFaces faces) {
  RequireFinite("theta", theta);
  RequireFinite("alpha", alpha);
  RequireFinite("beta", beta);
  const double curvature = std::max(std::abs(alpha), std::abs(beta));
  const double h = curvature > 0 ? kLatticeStep / curvature : kLatticeStep;
  const double c = std::cos(theta), s = std::sin(theta);
  return LatticeEnergyPerArea(alpha, beta, {h * c, h * s}, {-h * s, h * c}, faces);
}

}  // namespace archgeo
