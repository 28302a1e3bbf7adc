// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/mean_curvature_flow.h"

#include <algorithm>
#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"
#include "energies/laplacian.h"

namespace archgeo {
namespace {

// Lower bound of the sine in CotangentWeights.
constexpr double kMinSine = 1e-6;

int MinValence(bool closed) { return closed ? 3 : 2; }

// Cotangent of the angle at p in the triangle (p, q, s).
double Cotangent(const Eigen::Vector3d& p, const Eigen::Vector3d& q,
                 const Eigen::Vector3d& s) {
  const Eigen::Vector3d a = q - p, b = s - p;
  const double norms = a.norm() * b.norm();
  if (!(norms > 0.0)) return 0.0;
  const double sine = a.cross(b).norm() / norms;
  return a.dot(b) / norms / std::max(sine, kMinSine);
}

}  // namespace

MeanCurvatureFlow CheckedMeanCurvatureFlow(int valence, bool closed, double inv_length) {
  CHECK_GE(valence, MinValence(closed))
      << "MeanCurvatureFlow: valence too small (closed = " << closed << ")";
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "MeanCurvatureFlow: inv_length must be finite and > 0, got "
      << inv_length;
  return MeanCurvatureFlow(valence, closed, inv_length);
}

std::vector<double> CotangentWeights(const double* v,
                                     const std::vector<const double*>& ring,
                                     bool closed) {
  CHECK(v != nullptr);
  const int n = static_cast<int>(ring.size());
  CHECK_GE(n, MinValence(closed))
      << "CotangentWeights: one-ring too small (closed = " << closed << ")";
  const Eigen::Vector3d p(v[0], v[1], v[2]);
  std::vector<Eigen::Vector3d> w;
  for (const double* x : ring) {
    CHECK(x != nullptr);
    w.emplace_back(x[0], x[1], x[2]);
  }
  std::vector<double> weights(n, 0.0);
  const int triangles = closed ? n : n - 1;
  for (int k = 0; k < triangles; ++k) {
    // Triangle (v, w_k, w_{k+1}): the angle at w_{k+1} is opposite the edge
    // v w_k, the angle at w_k opposite the edge v w_{k+1}.
    const int next = (k + 1) % n;
    weights[k] += 0.5 * Cotangent(w[next], p, w[k]);
    weights[next] += 0.5 * Cotangent(w[k], p, w[next]);
  }
  double sum = 0.0;
  for (double c : weights) sum += c;
  if (!(sum > 0.0) || !std::isfinite(sum)) weights.assign(n, 1.0);
  return weights;
}

}  // namespace archgeo

// --- term `mean_curvature_flow` ------------------------------------------------

namespace archgeo::terms {
namespace {

// Fan (v; w_1 … w_n), closed unless kOpen; free v only. frozen: the
// Laplacian with the cotangent weights at the start of the round; live:
// −∇_v(fan area)/L with the weights recomputed inside the functor.
void AddMeanCurvatureFlow(TermContext& c, size_t i) {
  const int* s = c.elements->Vertices(i);
  const int n = c.elements->Count(i) - 1;
  const bool closed = !c.elements->Has(i, kOpen);
  // A support's area gradient is a reaction, not a condition (at a fixed
  // boundary vertex it never vanishes).
  if (n < (closed ? 3 : 2) || c.Fixed(s[0])) return;
  std::vector<double*> blocks;
  for (int j = 0; j <= n; ++j) blocks.push_back(c.Position(s[j]));
  if (c.String("form") == "live") {
    c.Add(MakeStarAutoDiff(CheckedMeanCurvatureFlow(n, closed, 1.0)), blocks);
    return;
  }
  std::vector<const double*> ring;
  for (int j = 1; j <= n; ++j) ring.push_back(c.Previous(s[j]));
  c.Add(MakeStarAutoDiff(CheckedLaplacian(CotangentWeights(c.Previous(s[0]), ring, closed), 1.0)),
        blocks);
}

}  // namespace

const TermSpec& mean_curvature_flow() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "mean_curvature_flow";
    t.summary = "mean-curvature flow (area gradient) of triangle fans: towards a minimal "
                "surface with the boundary held";
    t.paper = "[Gebreiter 2012, §10.1 curvature operators; Pinkall & Polthier 1993; Desbrun "
              "et al. 1999, eq. 7]";
    t.elements = "triangle_fans";
    t.options = {ChoiceKey("form", "frozen", {"frozen", "live"},
                           "frozen: cotangent weights of the round's start (one linear step per "
                           "round, robust); live: the area gradient with its weights "
                           "differentiated (combine with `step`: alone it can stall)")};
    t.add = &AddMeanCurvatureFlow;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_STAR_AUTODIFF(archgeo::MeanCurvatureFlow)
