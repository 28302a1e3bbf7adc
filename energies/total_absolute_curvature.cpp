// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/total_absolute_curvature.h"

#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {
namespace {

int MinValence(bool closed) { return closed ? 3 : 2; }

}  // namespace

double TotalAbsoluteCurvatureIrlsWeight(double lambda, double inv_length,
                                        double epsilon) {
  CHECK(std::isfinite(lambda))
      << "TotalAbsoluteCurvatureIrlsWeight: non-finite lambda";
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "TotalAbsoluteCurvatureIrlsWeight: inv_length must be finite and > 0,"
         " got "
      << inv_length;
  CHECK(std::isfinite(epsilon) && epsilon > 0.0)
      << "TotalAbsoluteCurvatureIrlsWeight: epsilon must be finite and > 0, got "
      << epsilon;
  return std::abs(lambda) * inv_length + epsilon;
}

TotalAbsoluteCurvature CheckedTotalAbsoluteCurvature(int valence, bool closed, double inv_length,
                                                     double omega1, double omega2) {
  CHECK_GE(valence, MinValence(closed))
      << "TotalAbsoluteCurvature: valence too small (closed = " << closed
      << ")";
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "TotalAbsoluteCurvature: inv_length must be finite and > 0, got "
      << inv_length;
  CHECK(std::isfinite(omega1) && omega1 > 0.0 && std::isfinite(omega2) &&
        omega2 > 0.0)
      << "TotalAbsoluteCurvature: omegas must be finite and > 0, got "
      << omega1 << ", " << omega2;
  return TotalAbsoluteCurvature(valence, closed, inv_length, omega1, omega2);
}

VertexShapeOperator EvaluateVertexShapeOperator(
    const double* v, const std::vector<const double*>& ring, bool closed) {
  CHECK(v != nullptr);
  const int k = static_cast<int>(ring.size());
  CHECK_GE(k, MinValence(closed))
      << "EvaluateVertexShapeOperator: one-ring too small (closed = " << closed
      << ")";
  double mean = 0.0;
  for (const double* w : ring) {
    CHECK(w != nullptr);
    mean += std::sqrt((w[0] - v[0]) * (w[0] - v[0]) +
                      (w[1] - v[1]) * (w[1] - v[1]) +
                      (w[2] - v[2]) * (w[2] - v[2]));
  }
  mean /= k;
  const double length = mean > 0.0 && std::isfinite(mean) ? mean : 1.0;
  VertexShapeOperator result;
  TangentialShapeOperator<double>(v, ring.data(), k, closed, 1.0 / length,
                                  /*gap_epsilon=*/0.0, &result.shape,
                                  &result.normal, &result.lambda1,
                                  &result.lambda2);
  result.shape *= length;
  result.lambda1 *= length;
  result.lambda2 *= length;
  return result;
}

}  // namespace archgeo

// --- term `total_absolute_curvature` -------------------------------------------

namespace archgeo::terms {
namespace {

// Element: (v, w_1 … w_n), the counter-clockwise fan of v (open: from one
// boundary neighbour to the other). The IRLS weights 1/(|λ| + ε) come from
// the tangential eigenvalues at the start of the round.
void AddTotalAbsoluteCurvature(TermContext& c, size_t i) {
  const int* s = c.elements->Vertices(i);
  const int count = c.elements->Count(i);
  const bool closed = !c.elements->Has(i, kOpen);
  std::vector<const double*> ring;
  std::vector<double*> blocks{c.Position(s[0])};
  for (int k = 1; k < count; ++k) {
    ring.push_back(c.Position(s[k]));
    blocks.push_back(c.Position(s[k]));
  }
  const VertexShapeOperator op = EvaluateVertexShapeOperator(c.Position(s[0]), ring, closed);
  const double epsilon = c.Number("epsilon");
  const double omega1 = TotalAbsoluteCurvatureIrlsWeight(op.lambda1, 1.0, epsilon);
  const double omega2 = TotalAbsoluteCurvatureIrlsWeight(op.lambda2, 1.0, epsilon);
  c.Add(MakeStarAutoDiff(CheckedTotalAbsoluteCurvature(count - 1, closed, 1.0, omega1, omega2)),
        blocks);
}

}  // namespace

const TermSpec& total_absolute_curvature() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "total_absolute_curvature";
    t.summary =
        "total absolute curvature Σ |λ1| + |λ2| of the vertex shape operators W′ (IRLS)";
    t.paper = "[Pellis 2019, §5.3]";
    t.elements = "fans";
    t.options = {NumberKey("epsilon", 1e-3, 1e-12, 1e3,
                           "ε of the IRLS weights 1/(|λ_prev|/L + ε) (unit-free)")};
    t.add = &AddTotalAbsoluteCurvature;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_STAR_AUTODIFF(archgeo::TotalAbsoluteCurvature)
