// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — input suitability warnings (see suitability.h).
#include "problems/declarations/suitability.h"

#include <omp.h>

#include <cstdio>
#include <functional>
#include <future>
#include <string>
#include <utility>

#include "fields/net_curvature.h"

namespace archgeo {
namespace {

// Records the figures and, if `warning` is not empty, prints and keeps it.
void Report(HookContext& c, nlohmann::json figures, const std::string& warning) {
  figures["suitable"] = warning.empty();
  if (!warning.empty()) figures["warning"] = warning;
  c.details["suitability"] = figures;
  if (warning.empty()) return;
  const std::string line = "WARNING (input suitability): " + warning;
  c.headline += line + "\n";
  if (c.progress) c.progress(line);
}

}  // namespace

void CheckAsymptoticNet(HookContext& c, const Mesh& net) {
  const NetCurvatureFigures f = MeasureNetCurvature(net);
  nlohmann::json figures = {{"check", "edges along asymptotic directions (A-net)"},
                            {"quads", f.quads},
                            {"quads_sampled", f.sampled},
                            {"quads_measured", f.measured},
                            {"asymptotic_angle_mean_degrees", f.asymptotic_angle_mean},
                            {"asymptotic_angle_max_degrees", f.asymptotic_angle_max},
                            {"positive_curvature_fraction", f.positive_curvature_fraction},
                            {"bound_angle_mean_degrees", kAsymptoticDegrees},
                            {"bound_positive_curvature_fraction", kPositiveCurvature}};
  std::string warning;
  char text[512];
  if (f.measured > 0 && (f.asymptotic_angle_mean > kAsymptoticDegrees ||
                         f.positive_curvature_fraction > kPositiveCurvature)) {
    std::snprintf(text, sizeof text,
                  "the net is not along asymptotic directions: its edges are %.1f° from them "
                  "on average (max %.1f°; an A-net: a few degrees, bound %.0f°) and %.0f%% of "
                  "its quads lie where the Gaussian curvature is not negative (bound %.0f%%). "
                  "Flattening its vertex stars will move it far or fold it.",
                  f.asymptotic_angle_mean, f.asymptotic_angle_max, kAsymptoticDegrees,
                  100 * f.positive_curvature_fraction, 100 * kPositiveCurvature);
    warning = text;
  }
  Report(c, figures, warning);
}

namespace {

// The conjugate-net check's figures and warning ("" if suitable).
std::pair<nlohmann::json, std::string> ConjugateNetFigures(const Mesh& net) {
  const NetCurvatureFigures f = MeasureNetCurvature(net);
  nlohmann::json figures = {{"check", "quad edges along conjugate directions (PQ net)"},
                            {"quads", f.quads},
                            {"quads_sampled", f.sampled},
                            {"quads_measured", f.measured},
                            {"conjugacy_mean", f.conjugacy_mean},
                            {"conjugacy_max", f.conjugacy_max},
                            {"bound_conjugacy_mean", kConjugacy}};
  std::string warning;
  if (f.measured > 0 && f.conjugacy_mean > kConjugacy) {
    char text[512];
    std::snprintf(text, sizeof text,
                  "the quads are far from a conjugate net: mean |II(u,v)|/(κ|u||v|) %.2f (max "
                  "%.2f; bound %.2f; 0 for a conjugate net). Planar quads may then only come "
                  "with folds or reflex corners, which the validity checks refuse: expect a "
                  "missed tolerance.",
                  f.conjugacy_mean, f.conjugacy_max, kConjugacy);
    warning = text;
  }
  return {figures, warning};
}

}  // namespace

// On a thread of its own (one core), recorded at the start of the first
// round after it ends (HookContext::RecordChecks): the solve's first round
// begins with serial work (the reference's tree, the residuals and their
// pattern) that leaves the other core idle; its figures and warning are
// those of a serial check.
void CheckConjugateNet(HookContext& c, const Mesh& net) {
  c.checks.push_back(std::async(std::launch::async, [&net] {
    omp_set_num_threads(1);  // this thread's parallel regions (the jet fits)
    const auto [figures, warning] = ConjugateNetFigures(net);
    return std::function<void(HookContext&)>(
        [figures = figures, warning = warning](HookContext& c) { Report(c, figures, warning); });
  }));
}

bool CheckConjugateNetNow(HookContext& c, const Mesh& net) {
  const auto [figures, warning] = ConjugateNetFigures(net);
  Report(c, figures, warning);
  return warning.empty();
}

void CheckPrincipalLabels(HookContext& c, const Mesh& mesh,
                          const std::vector<std::pair<int, int>>& labels) {
  const PrincipalLabelFigures f = MeasurePrincipalLabels(mesh, labels);
  nlohmann::json figures = {{"check", "principal edges along principal directions"},
                            {"edges", f.edges},
                            {"edges_measured", f.measured},
                            {"principal_angle_mean_degrees", f.angle_mean},
                            {"principal_angle_max_degrees", f.angle_max},
                            {"bound_angle_mean_degrees", kPrincipalDegrees}};
  std::string warning;
  if (f.measured > 0 && f.angle_mean > kPrincipalDegrees) {
    char text[512];
    std::snprintf(text, sizeof text,
                  "the principal-edge labels do not follow the principal directions: %.1f° "
                  "from them on average over %d edges (max %.1f°; bound %.0f°). The conditions "
                  "can then only be met by moving the mesh far.",
                  f.angle_mean, f.measured, f.angle_max, kPrincipalDegrees);
    warning = text;
  }
  Report(c, figures, warning);
}

}  // namespace archgeo
