// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The curl correction of the wave's size fields [Gebreiter 2012, §8.1.4;
// Zhang et al. 2010]: the discrete curl on a planar annulus with the polar
// frame (known in closed form), and `wave_quads` with wave.curl_correction
// on the torus, whose curl-free sizes are known: one test per term, each
// named after it and failing when its residuals are zeroed
// (tools/mutation_check.sh).
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "energies/size_elements.h"
#include "fields/triangle_surfaces.h"
#include "generators/smoothness_surfaces.h"
#include "mesh/eigen_point.h"
#include "problems/declarations/wave_size_curl.h"
#include "problems/runtime/solve.h"
#include "problems/spec/spec.h"

namespace archgeo {
namespace ARCHGEO_UNITY_ID {

namespace sd = size_data;

// The annulus 1 ≤ r ≤ 2 in the plane z = 0 with X = e_r, Y = n × e_r (±e_θ
// by the mesh's orientation): curl X = 0, curl Y = 1/r, and Y/η is curl-free
// (the gradient of ±θ) for η = r.
struct PolarAnnulus {
  Mesh mesh;
  WaveFrames frames;
};

PolarAnnulus MakePolarAnnulus() {
  TriangleGridOptions o;
  o.closed_u = true;
  PolarAnnulus a;
  a.mesh = TriangulatedGrid(96, 24, [](double u, double v) -> Vec3 {
    return {(1 + v) * std::cos(2 * M_PI * u), (1 + v) * std::sin(2 * M_PI * u), 0};
  }, o);
  const HalfedgeIndex h = a.mesh.halfedge(*a.mesh.faces().begin());
  const Eigen::Vector3d p0 = EigenPoint(a.mesh, a.mesh.source(h)),
                        p1 = EigenPoint(a.mesh, a.mesh.target(h)),
                        p2 = EigenPoint(a.mesh, a.mesh.target(a.mesh.next(h)));
  const Eigen::Vector3d n = (p1 - p0).cross(p2 - p0).normalized();
  for (VertexIndex v : a.mesh.vertices()) {
    const Eigen::Vector3d p = EigenPoint(a.mesh, v);
    const Eigen::Vector3d er = Eigen::Vector3d(p.x(), p.y(), 0).normalized();
    a.frames.normal.push_back(n);
    a.frames.x.push_back(er);
    a.frames.y.push_back(n.cross(er));
  }
  return a;
}

std::vector<double> Radii(const Mesh& mesh) {
  std::vector<double> r;
  for (VertexIndex v : mesh.vertices()) {
    const Eigen::Vector3d p = EigenPoint(mesh, v);
    r.push_back(std::hypot(p.x(), p.y()));
  }
  return r;
}

// The measure s² curl(F/s): 0 for X with any radial μ; for Y with η = 1 the
// area-weighted RMS of 1/r, √(ln 2 / 1.5); with η = r, 0 up to the
// discretisation.
TEST(SizeCurl, DiscreteCurlOfThePolarFrame) {
  const PolarAnnulus a = MakePolarAnnulus();
  const std::vector<double> one(a.mesh.number_of_vertices(), 1.0), r = Radii(a.mesh);
  const WaveSizeCurl constant = MeasureWaveSizeCurl(a.mesh, a.frames, one, one);
  const WaveSizeCurl radial = MeasureWaveSizeCurl(a.mesh, a.frames, r, r);
  std::printf("polar annulus: curl x %.3g y %.4g (exact %.4g) with η = 1; y %.3g with η = r\n",
              constant.x, constant.y, std::sqrt(std::log(2.0) / 1.5), radial.y);
  EXPECT_LT(constant.x, 1e-3);
  EXPECT_NEAR(constant.y, std::sqrt(std::log(2.0) / 1.5), 0.01);
  EXPECT_LT(radial.x, 1e-3);
  EXPECT_LT(radial.y, 0.01);
}

// The size_curl elements: residual a + Σ g_k s̃_k vanishes (up to the
// discretisation) at η̃ = log r, not at η̃ = −log r (the sign of the
// condition: the wave integrates Y/η, not ηY), nor at a constant.
TEST(SizeCurl, ElementsVanishAtTheCurlFreeLogSizes) {
  const PolarAnnulus a = MakePolarAnnulus();
  const std::vector<double> r = Radii(a.mesh), one(r.size(), 1.0);
  const WaveSizeSets sets = WaveSizeCurlSets(a.mesh, a.frames, one, one);
  auto rms = [&](double power) {
    double sum = 0;
    for (size_t e = 0; e < sets.triangles.size(); ++e) {
      const double* d = sets.triangles.Data(e);
      const int* v = sets.triangles.Vertices(e);
      double res = d[sd::kConstant];
      for (int k = 0; k < 3; ++k) {
        const double log_r = power * std::log(r[size_t(v[k])]);
        res += d[sd::kGradient + k] * (d[sd::kSource + k] == 1 ? log_r : 0.0);
      }
      sum += res * res;
    }
    return std::sqrt(sum / double(sets.triangles.size()));
  };
  std::printf("size_curl residual rms: η̃ = log r %.3g, 0 %.3g, −log r %.3g\n", rms(1), rms(0),
              rms(-1));
  EXPECT_LT(rms(1), 0.02 * rms(0));
  EXPECT_GT(rms(-1), 1.5 * rms(0));
}

// wave_quads on the torus R = 3, r = 1 with a constant designated η: the
// curl-free η along the parallels (Y) is proportional to ρ, the distance to
// the axis, and μ along the meridians constant.
std::unique_ptr<Solution> SizeTorus(const std::string& extra = "") {
  const std::string yaml =
      "problem: wave_quads\n"
      "wave: {wavelength: 2.0943951023931953, wavelength_y: 3.141592653589793,\n"
      "       curl_correction: on, restarts: 1}\n" + extra;
  return Solve(ParseSpec(yaml, "/in-memory/wave.yaml"), TorusPrincipalQuads(3, 1, 60, 30),
               nullptr, {});
}

// The spread (max − min) of log η − log ρ and of log μ over the vertices.
std::pair<double, double> SizeSpreads(const Solution& s) {
  double lo_eta = 1e300, hi_eta = -1e300, lo_mu = 1e300, hi_mu = -1e300;
  const std::vector<double> rho = Radii(s.input);
  for (size_t v = 0; v < rho.size(); ++v) {
    const double* size = s.store->At("wave_size", int(v));
    lo_eta = std::min(lo_eta, size[1] - std::log(rho[v]));
    hi_eta = std::max(hi_eta, size[1] - std::log(rho[v]));
    lo_mu = std::min(lo_mu, size[0]);
    hi_mu = std::max(hi_mu, size[0]);
  }
  return {hi_eta - lo_eta, hi_mu - lo_mu};
}

TEST(SizeCurl, TorusSizesBecomeProportionalToTheAxisDistance) {
  const auto s = SizeTorus();
  ASSERT_TRUE(s->loop.usable) << s->loop.message;
  const auto& c = s->details.at("wave").at("curl");
  const auto [eta_spread, mu_spread] = SizeSpreads(*s);
  std::printf("torus: curl y %.3g -> %.3g, x %.3g -> %.3g; spread of log(η/ρ) %.3g (log 2 = "
              "%.3g for a constant η), of log μ %.3g\n",
              c.at("curl_y_target").get<double>(), c.at("curl_y").get<double>(),
              c.at("curl_x_target").get<double>(), c.at("curl_x").get<double>(), eta_spread,
              std::log(2.0), mu_spread);
  EXPECT_TRUE(c.at("correction").get<bool>());
  EXPECT_LT(c.at("curl_y").get<double>(), 0.1 * c.at("curl_y_target").get<double>());
  EXPECT_LT(eta_spread, 0.1 * std::log(2.0));
  EXPECT_LT(mu_spread, 0.05);
}

// The target fixes the sizes' level (the curl term leaves a constant free):
// η/η_t brackets 1 (ρ/ρ_mean from 2/3 to 4/3 here), μ/μ_t ≈ 1.
TEST(SizeTarget, HoldsTheSizesToTheDesignatedOnes) {
  const auto s = SizeTorus();
  const auto& c = s->details.at("wave").at("curl");
  std::printf("size_target: μ/μ_t %.3g–%.3g, η/η_t %.3g–%.3g\n",
              c.at("mu_ratio_min").get<double>(), c.at("mu_ratio_max").get<double>(),
              c.at("eta_ratio_min").get<double>(), c.at("eta_ratio_max").get<double>());
  EXPECT_GT(c.at("mu_ratio_min").get<double>(), 0.97);
  EXPECT_LT(c.at("mu_ratio_max").get<double>(), 1.03);
  EXPECT_GT(c.at("eta_ratio_min").get<double>(), 0.55);
  EXPECT_LT(c.at("eta_ratio_min").get<double>(), 0.85);
  EXPECT_GT(c.at("eta_ratio_max").get<double>(), 1.15);
  EXPECT_LT(c.at("eta_ratio_max").get<double>(), 1.6);
}

// A heavy smoothing weight flattens the sizes towards the designated one.
TEST(SizeSmoothing, FlattensTheSizes) {
  const auto s = SizeTorus("terms: {size_smoothing: {weight: 100}}\n");
  const auto& c = s->details.at("wave").at("curl");
  const double range = c.at("eta_ratio_max").get<double>() / c.at("eta_ratio_min").get<double>();
  std::printf("size_smoothing at 100: η/η_t %.3g–%.3g\n", c.at("eta_ratio_min").get<double>(),
              c.at("eta_ratio_max").get<double>());
  EXPECT_LT(range, 1.2);
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
