// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — analytic asymptotic quad nets [Shi, Wang, Pottmann 2014, §3.3].
#include "generators/asymptotic_nets.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glog/logging.h>

#include "core/input_error.h"

namespace archgeo {
namespace {

constexpr Complex kI(0.0, 1.0);
// Reference surfaces: the net's region grown by this fraction of its extent
// on every side, sampled with this many cells per net quad (times resolution).
constexpr double kReferenceMargin = 0.1;
constexpr int kReferenceCellsPerQuad = 4;

[[noreturn]] void Fail(const std::string& key, const std::string& message) {
  throw InputError("", 0, key, message);
}

void RequireAtLeast(const std::string& key, int value, int minimum) {
  if (value < minimum) {
    Fail(key, "must be >= " + std::to_string(minimum) + ", got " + std::to_string(value));
  }
}

// Integration state: w, Φ = ∫ φ(w) dw, and the current branch of sqrt(f g').
struct State {
  Complex w;
  Complex phi[3];
  Complex root;
};

// The root of f(w) g'(w) nearest to `reference` (continuous branch).
Complex RootNear(const WeierstrassData& data, Complex w, Complex reference) {
  const Complex r = std::sqrt(data.f(w) * data.dg(w));
  return std::abs(r + reference) < std::abs(r - reference) ? -r : r;
}

// d(state)/dτ along ζ(τ) = ζ_start + τ Δ (Δ = `delta`), branch near y.root.
State Derivative(const WeierstrassData& data, const State& y, Complex delta) {
  const Complex f = data.f(y.w), g = data.g(y.w);
  const Complex dw = delta / RootNear(data, y.w, y.root);
  State d;
  d.w = dw;
  d.phi[0] = f * (1.0 - g * g) * dw;
  d.phi[1] = kI * f * (1.0 + g * g) * dw;
  d.phi[2] = 2.0 * f * g * dw;
  d.root = 0.0;
  return d;
}

State Add(const State& y, const State& k, double scale) {
  State r = y;
  r.w += scale * k.w;
  for (int c = 0; c < 3; ++c) r.phi[c] += scale * k.phi[c];
  return r;
}

// Classical RK4 over the straight segment ζ → ζ + delta, |step| <= kWeierstrassStep.
State March(const WeierstrassData& data, State y, Complex delta) {
  const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(delta) / kWeierstrassStep)));
  const Complex h = delta / static_cast<double>(steps);
  for (int n = 0; n < steps; ++n) {
    const State k1 = Derivative(data, y, h);
    const State k2 = Derivative(data, Add(y, k1, 0.5), h);
    const State k3 = Derivative(data, Add(y, k2, 0.5), h);
    const State k4 = Derivative(data, Add(y, k3, 1.0), h);
    State next = y;
    next.w += (k1.w + 2.0 * k2.w + 2.0 * k3.w + k4.w) / 6.0;
    for (int c = 0; c < 3; ++c) {
      next.phi[c] += (k1.phi[c] + 2.0 * k2.phi[c] + 2.0 * k3.phi[c] + k4.phi[c]) / 6.0;
    }
    next.root = RootNear(data, next.w, y.root);
    y = next;
  }
  return y;
}

State BaseState(const WeierstrassData& data) {
  CHECK(data.f && data.g && data.dg) << "WeierstrassData: f, g and dg must be set";
  State y;
  y.w = data.w0;
  for (Complex& p : y.phi) p = 0.0;
  y.root = std::sqrt(data.f(data.w0) * data.dg(data.w0));
  if (!(std::abs(y.root) > 0.0) || !std::isfinite(std::abs(y.root))) {
    Fail("weierstrass", "f g' vanishes or is singular at the base point w0");
  }
  return y;
}

Vec3 Position(const WeierstrassData& data, const State& y) {
  const Vec3 x = {data.x0[0] + y.phi[0].real(), data.x0[1] + y.phi[1].real(),
                  data.x0[2] + y.phi[2].real()};
  if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]) ||
      !std::isfinite(std::abs(y.w))) {
    Fail("weierstrass", "integration diverged: f g' has a zero or pole on the sampling path");
  }
  return x;
}

// Quad mesh on a (n_a + 1) x (n_b + 1) point grid, entry b (n_a + 1) + a.
Mesh QuadMeshFromGrid(const std::vector<Vec3>& points, int n_a, int n_b) {
  CHECK_EQ(points.size(), static_cast<size_t>(n_a + 1) * (n_b + 1));
  Mesh mesh;
  std::vector<VertexIndex> v;
  v.reserve(points.size());
  for (const Vec3& p : points) v.push_back(mesh.add_vertex(ToPoint(p)));
  const auto at = [&](int a, int b) { return v[static_cast<size_t>(b) * (n_a + 1) + a]; };
  for (int b = 0; b < n_b; ++b) {
    for (int a = 0; a < n_a; ++a) {
      const FaceIndex f = mesh.add_face(at(a, b), at(a + 1, b), at(a + 1, b + 1), at(a, b + 1));
      CHECK(f != Mesh::null_face()) << "QuadMeshFromGrid: add_face failed at " << a << ", " << b;
    }
  }
  return mesh;
}

// Triangle mesh on the same kind of grid; with periodic_b the column b = n_b
// is identified with b = 0 (and not added).
Mesh TriangleMeshFromGrid(const std::vector<Vec3>& points, int n_a, int n_b, bool periodic_b) {
  CHECK_EQ(points.size(), static_cast<size_t>(n_a + 1) * (n_b + 1));
  Mesh mesh;
  const int columns = periodic_b ? n_b : n_b + 1;
  std::vector<VertexIndex> v;
  for (int b = 0; b < columns; ++b) {
    for (int a = 0; a <= n_a; ++a) {
      v.push_back(mesh.add_vertex(ToPoint(points[static_cast<size_t>(b) * (n_a + 1) + a])));
    }
  }
  const auto at = [&](int a, int b) {
    return v[static_cast<size_t>(b % columns) * (n_a + 1) + a];
  };
  for (int b = 0; b < n_b; ++b) {
    for (int a = 0; a < n_a; ++a) {
      const FaceIndex f1 = mesh.add_face(at(a, b), at(a + 1, b), at(a + 1, b + 1));
      const FaceIndex f2 = mesh.add_face(at(a, b), at(a + 1, b + 1), at(a, b + 1));
      CHECK(f1 != Mesh::null_face() && f2 != Mesh::null_face())
          << "TriangleMeshFromGrid: add_face failed at " << a << ", " << b;
    }
  }
  return mesh;
}

// An (s, t) rectangle of a Weierstrass test net.
struct MinimalPreset {
  WeierstrassData data;
  double s_min, s_max, t_min, t_max;
  int n_s, n_t;
};

MinimalPreset Preset(AsymptoticTestNet which) {
  switch (which) {
    case AsymptoticTestNet::kEnneperLarge:
      return {EnneperData(), -1.2, 1.2, -1.2, 1.2, 12, 12};
    case AsymptoticTestNet::kEnneperSmall:
      return {EnneperData(), 0.0, 1.4, -1.2, 1.2, 7, 12};
    case AsymptoticTestNet::kScherk:
      return {ScherkData(), -1.8, 1.8, -1.8, 1.8, 24, 24};
    default:
      LOG(FATAL) << "Preset: not a Weierstrass test net";
  }
  return {};
}

constexpr int kHyparQuads = 12;
constexpr double kHyparSize = 1.0;

}  // namespace

ZetaGrid AsymptoticGrid(double s_min, double s_max, int n_s, double t_min, double t_max,
                        int n_t) {
  RequireAtLeast("n_s", n_s, 1);
  RequireAtLeast("n_t", n_t, 1);
  if (!(std::isfinite(s_min) && std::isfinite(s_max) && s_max > s_min)) {
    Fail("s", "need finite s_min < s_max");
  }
  if (!(std::isfinite(t_min) && std::isfinite(t_max) && t_max > t_min)) {
    Fail("t", "need finite t_min < t_max");
  }
  const double hs = (s_max - s_min) / n_s, ht = (t_max - t_min) / n_t;
  ZetaGrid grid;
  grid.origin = Complex(0.5 * (s_min + t_min), 0.5 * (s_min - t_min));
  grid.step_a = Complex(0.5 * hs, 0.5 * hs);    // ds: ζ += (1 + i) ds / 2
  grid.step_b = Complex(0.5 * ht, -0.5 * ht);   // dt: ζ += (1 − i) dt / 2
  grid.n_a = n_s;
  grid.n_b = n_t;
  return grid;
}

std::vector<Vec3> SampleMinimalSurface(const WeierstrassData& data, const ZetaGrid& grid) {
  RequireAtLeast("n_a", grid.n_a, 1);
  RequireAtLeast("n_b", grid.n_b, 1);
  const State corner = March(data, BaseState(data), grid.origin - data.zeta0);
  // March along the first row (b = 0), then up every column.
  std::vector<State> row(grid.n_a + 1);
  row[0] = corner;
  for (int a = 1; a <= grid.n_a; ++a) row[a] = March(data, row[a - 1], grid.step_a);
  std::vector<Vec3> points(static_cast<size_t>(grid.n_a + 1) * (grid.n_b + 1));
  for (int a = 0; a <= grid.n_a; ++a) {
    State y = row[a];
    for (int b = 0; b <= grid.n_b; ++b) {
      if (b > 0) y = March(data, y, grid.step_b);
      points[static_cast<size_t>(b) * (grid.n_a + 1) + a] = Position(data, y);
    }
  }
  return points;
}

Vec3 MinimalSurfacePoint(const WeierstrassData& data, Complex zeta) {
  return Position(data, March(data, BaseState(data), zeta - data.zeta0));
}

Mesh MinimalSurfaceNet(const WeierstrassData& data, const ZetaGrid& grid) {
  return QuadMeshFromGrid(SampleMinimalSurface(data, grid), grid.n_a, grid.n_b);
}

Vec3 EnneperPoint(double u, double v) {
  return {u - u * u * u / 3.0 + u * v * v, -v + v * v * v / 3.0 - u * u * v, u * u - v * v};
}

WeierstrassData EnneperData() {
  WeierstrassData data;
  data.f = [](Complex) { return Complex(1.0, 0.0); };
  data.g = [](Complex w) { return w; };
  data.dg = [](Complex) { return Complex(1.0, 0.0); };
  return data;
}

WeierstrassData CatenoidData() {
  WeierstrassData data;
  data.f = [](Complex w) { return 0.5 * std::exp(-w); };
  data.g = [](Complex w) { return std::exp(w); };
  data.dg = [](Complex w) { return std::exp(w); };
  data.x0 = {-1.0, 0.0, 0.0};
  return data;
}

WeierstrassData ScherkData() {
  WeierstrassData data;
  data.f = [](Complex w) { return 4.0 / (1.0 - w * w * w * w); };
  data.g = [](Complex w) { return w; };
  data.dg = [](Complex) { return Complex(1.0, 0.0); };
  return data;
}

Mesh HyperbolicParaboloidNet(int n_u, int n_v, double h) {
  RequireAtLeast("n_u", n_u, 1);
  RequireAtLeast("n_v", n_v, 1);
  if (!(std::isfinite(h) && h > 0.0)) Fail("h", "must be finite and > 0");
  std::vector<Vec3> points;
  points.reserve(static_cast<size_t>(n_u + 1) * (n_v + 1));
  for (int j = 0; j <= n_v; ++j) {
    for (int i = 0; i <= n_u; ++i) {
      const double x = (i - 0.5 * n_u) * h, y = (j - 0.5 * n_v) * h;
      points.push_back({x, y, x * y});
    }
  }
  return QuadMeshFromGrid(points, n_u, n_v);
}

Mesh CatenoidBandNet(int m, int rows) {
  RequireAtLeast("m", m, 4);
  if (m % 2 != 0) Fail("m", "the number of quads around must be even, got " + std::to_string(m));
  RequireAtLeast("rows", rows, 5);
  const double h = std::sqrt(2.0) * M_PI / m;
  // Lattice (p, q), p = 0 … m − 1, q = −(m − 1) … rows − 1 covers every vertex.
  const int q_min = -(m - 1);
  const ZetaGrid grid = AsymptoticGrid(0.0, (m - 1) * h, m - 1, q_min * h - 0.5 * (rows - 1) * h,
                                       (rows - 1) * h - 0.5 * (rows - 1) * h, rows - 1 - q_min);
  const std::vector<Vec3> lattice = SampleMinimalSurface(CatenoidData(), grid);
  Mesh mesh;
  std::vector<VertexIndex> v;
  v.reserve(static_cast<size_t>(m) * rows);
  for (int k = 0; k < rows; ++k) {
    for (int i = 0; i < m; ++i) {
      const int a = i, b = k - i - q_min;
      v.push_back(mesh.add_vertex(ToPoint(lattice[static_cast<size_t>(b) * m + a])));
    }
  }
  const auto at = [&](int k, int i) { return v[static_cast<size_t>(k) * m + (i % m)]; };
  for (int k = 0; k + 2 < rows; ++k) {
    for (int i = 0; i < m; ++i) {
      const FaceIndex f = mesh.add_face(at(k, i), at(k + 1, i + 1), at(k + 2, i + 1), at(k + 1, i));
      CHECK(f != Mesh::null_face()) << "CatenoidBandNet: add_face failed at " << k << ", " << i;
    }
  }
  return mesh;
}

std::string AsymptoticTestNetName(AsymptoticTestNet which) {
  switch (which) {
    case AsymptoticTestNet::kHyperbolicParaboloid: return "hyperbolic_paraboloid";
    case AsymptoticTestNet::kEnneperLarge: return "enneper_large";
    case AsymptoticTestNet::kEnneperSmall: return "enneper_small";
    case AsymptoticTestNet::kCatenoidBand: return "catenoid_band";
    case AsymptoticTestNet::kScherk: return "scherk";
  }
  return "";
}

std::string AsymptoticTestNetPaperRow(AsymptoticTestNet which) {
  switch (which) {
    case AsymptoticTestNet::kHyperbolicParaboloid: return "mass spring surface";
    case AsymptoticTestNet::kEnneperLarge: return "minimal surface 1";
    case AsymptoticTestNet::kEnneperSmall: return "minimal surface 2";
    case AsymptoticTestNet::kCatenoidBand: return "catenoid";
    case AsymptoticTestNet::kScherk: return "Schwarz surface";
  }
  return "";
}

Mesh MakeAsymptoticTestNet(AsymptoticTestNet which, int refinement) {
  RequireAtLeast("refinement", refinement, 1);
  switch (which) {
    case AsymptoticTestNet::kHyperbolicParaboloid: {
      const int n = kHyparQuads * refinement;
      return HyperbolicParaboloidNet(n, n, kHyparSize / n);
    }
    case AsymptoticTestNet::kCatenoidBand:
      return CatenoidBandNet(44 * refinement, 31 * refinement + 1);
    default: {
      const MinimalPreset p = Preset(which);
      return MinimalSurfaceNet(p.data, AsymptoticGrid(p.s_min, p.s_max, p.n_s * refinement,
                                                      p.t_min, p.t_max, p.n_t * refinement));
    }
  }
}

Mesh MakeAsymptoticTestReference(AsymptoticTestNet which, int resolution) {
  RequireAtLeast("resolution", resolution, 1);
  const int per_quad = kReferenceCellsPerQuad * resolution;
  // Cells over the enlarged extent: n quads grown by 2 × 10%.
  const auto cells = [&](int n) {
    return static_cast<int>(std::ceil(n * per_quad * (1.0 + 2.0 * kReferenceMargin)));
  };
  switch (which) {
    case AsymptoticTestNet::kHyperbolicParaboloid: {
      const double half = 0.5 * kHyparSize * (1.0 + 2.0 * kReferenceMargin);
      const int n = cells(kHyparQuads);
      std::vector<Vec3> points;
      for (int b = 0; b <= n; ++b) {
        for (int a = 0; a <= n; ++a) {
          const double x = -half + 2.0 * half * a / n, y = -half + 2.0 * half * b / n;
          points.push_back({x, y, x * y});
        }
      }
      return TriangleMeshFromGrid(points, n, n, false);
    }
    case AsymptoticTestNet::kCatenoidBand: {
      constexpr int kM = 44, kRows = 32;
      const double z_half = 0.5 * (kRows - 1) * M_PI / kM * (1.0 + 2.0 * kReferenceMargin);
      const int around = kM * per_quad;
      const int along = static_cast<int>(std::ceil(2.0 * z_half / (2.0 * M_PI / around)));
      // Curvature-line grid w = u + i v, ζ = w / √2.
      ZetaGrid grid;
      grid.origin = Complex(-z_half / std::sqrt(2.0), 0.0);
      grid.step_a = Complex(2.0 * z_half / along / std::sqrt(2.0), 0.0);
      grid.step_b = Complex(0.0, 2.0 * M_PI / around / std::sqrt(2.0));
      grid.n_a = along;
      grid.n_b = around;
      return TriangleMeshFromGrid(SampleMinimalSurface(CatenoidData(), grid), along, around, true);
    }
    default: {
      const MinimalPreset p = Preset(which);
      const double ds = kReferenceMargin * (p.s_max - p.s_min);
      const double dt = kReferenceMargin * (p.t_max - p.t_min);
      const int n_s = cells(p.n_s), n_t = cells(p.n_t);
      return TriangleMeshFromGrid(
          SampleMinimalSurface(p.data, AsymptoticGrid(p.s_min - ds, p.s_max + ds, n_s,
                                                      p.t_min - dt, p.t_max + dt, n_t)),
          n_s, n_t, false);
    }
  }
}

}  // namespace archgeo
