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

// The measure s² curl(F/s): for Y with η = 1 the area-weighted RMS of 1/r,
// √(ln 2 / 1.5); 0 for X with μ = 1 or μ = r and for Y with η = r, up to the
// discretisation (the circulation's trapezoidal rule on each edge errs by
// O(h³), the curl by O(h): a few hundredths here).
TEST(SizeCurl, DiscreteCurlOfThePolarFrame) {
  const PolarAnnulus a = MakePolarAnnulus();
  const std::vector<double> one(a.mesh.number_of_vertices(), 1.0), r = Radii(a.mesh);
  const WaveSizeCurl constant = MeasureWaveSizeCurl(a.mesh, a.frames, one, one);
  const WaveSizeCurl radial = MeasureWaveSizeCurl(a.mesh, a.frames, r, r);
  std::printf("polar annulus: curl x %.3g y %.4g (exact %.4g) with η = 1; y %.3g with η = r\n",
              constant.x, constant.y, std::sqrt(std::log(2.0) / 1.5), radial.y);
  EXPECT_NEAR(constant.y, std::sqrt(std::log(2.0) / 1.5), 0.005);
  EXPECT_LT(constant.x, 0.05 * constant.y);
  EXPECT_LT(radial.x, 0.1 * constant.y);
  EXPECT_LT(radial.y, 0.05 * constant.y);
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
  EXPECT_LT(rms(1), 0.05 * rms(0));
  EXPECT_GT(rms(-1), 1.5 * rms(0));
}

// wave_quads on the torus R = 3, r = 1 with a constant designated η: the
// curl-free η along the parallels (Y) is proportional to ρ, the distance to
// the axis, and μ along the meridians constant (up to the discrete curl's
// O(h) error on this coarse torus). Only the sizes are asked, so the
// waves are long (one round the tube, two round the axis): the Morse–Smale
// complex of a wave with many defects (the wrong sizes of a test whose term
// is zeroed) takes minutes to embed.
std::unique_ptr<Solution> SizeTorus(const std::string& extra = "", int n_u = 60, int n_v = 30) {
  const std::string yaml =
      "problem: wave_quads\n"
      "wave: {wavelength: 6.283185307179586, wavelength_y: 9.42477796076938,\n"
      "       curl_correction: on, restarts: 1}\n" + extra;
  return Solve(ParseSpec(yaml, "/in-memory/wave.yaml"), TorusPrincipalQuads(3, 1, n_u, n_v),
               nullptr, {});
}

// A `terms:` section lists every term (one not listed is off): the
// defaults but `changed`.
std::string SizeTerms(const std::string& changed) {
  return "terms: {wave_transfer: 1, wave_norm: 0.15, wave_product: 0.15, wave_feature: 1e8,\n"
         "        size_curl: 1, " + changed + "}\n";
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
  EXPECT_LT(mu_spread, 0.2);
}

// A heavy target weight holds the sizes at the designated ones (constant
// here), against the curl term's η ∝ ρ. A 40 × 20 torus: the Morse–Smale
// complex of the wave with the designated sizes' defects takes minutes to
// embed on the 60 × 30 one.
TEST(SizeTarget, HoldsTheSizesToTheDesignatedOnes) {
  const auto s = SizeTorus(SizeTerms("size_target: 1e4, size_smoothing: 0.01"), 40, 20);
  const auto& c = s->details.at("wave").at("curl");
  std::printf("size_target at 1e4: μ/μ_t %.3g–%.3g, η/η_t %.3g–%.3g\n",
              c.at("mu_ratio_min").get<double>(), c.at("mu_ratio_max").get<double>(),
              c.at("eta_ratio_min").get<double>(), c.at("eta_ratio_max").get<double>());
  EXPECT_GT(c.at("eta_ratio_min").get<double>(), 0.95);
  EXPECT_LT(c.at("eta_ratio_max").get<double>(), 1.05);
}

// A heavy smoothing weight flattens the sizes (to their target's level).
TEST(SizeSmoothing, FlattensTheSizes) {
  const auto s = SizeTorus(SizeTerms("size_target: 0.001, size_smoothing: 1e4"), 40, 20);
  const auto& c = s->details.at("wave").at("curl");
  const double range = c.at("eta_ratio_max").get<double>() / c.at("eta_ratio_min").get<double>();
  std::printf("size_smoothing at 1e4: η/η_t %.3g–%.3g\n", c.at("eta_ratio_min").get<double>(),
              c.at("eta_ratio_max").get<double>());
  EXPECT_LT(range, 1.2);
}

}  // namespace ARCHGEO_UNITY_ID
}  // namespace archgeo
