// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — input suitability warnings: before solving, whether the net can
// become what the problem makes, from how its edges lie against the jet-fitted
// curvature directions of the surface (fields/net_curvature.h). A net far from
// them gets a WARNING line with the figures (on the terminal at once, or for
// planar_quads, measured on a second thread, at the start of the first round
// after the measure ends; and in the summary) and every figure goes to the report's details.suitability; the
// run goes on (the validity checks and tolerances decide its exit code).
//
//   hnet                 A-nets discretise asymptotic nets [Shi 2014, §2.2]:
//                        warns when the mean angle between the net's edge
//                        directions and the nearest asymptotic direction
//                        exceeds kAsymptoticDegrees, or when more than
//                        kPositiveCurvature of its quads lie where K ≥ 0
//                        (no asymptotic directions there). The negshell's
//                        A-nets: 2.8° and 3.1°, no K ≥ 0; its own quad mesh
//                        (not an A-net): 48°.
//   planar_quads         planar quads discretise conjugate nets [Zadravec
//                        2010, §1]: warns when the mean conjugacy
//                        |II(u, v)| / (κ |u||v|) exceeds kConjugacy,
//                        calibrated on eleven public nets (docs/methods/
//                        metrics.md): planar_quads reaches δ_PQ,n ≤ 1e-3 with
//                        convex quads on negshell 0.02, bubble 0.06, libigl
//                        Conjugate 0.17 and Smooth 0.29, and cannot on horse
//                        0.26, gnet1 0.27, flower 0.33, heart 0.33, pillow
//                        0.40, M2 0.47, wein99 0.53: 0.25 warns before every
//                        failure, and on Smooth, which succeeds.
//   principal_symmetric  labelled principal edges [Pellis 2019, §5]: warns
//                        when their mean angle from the nearest principal
//                        direction exceeds kPrincipalDegrees (umbilic and flat
//                        places not measured).
#pragma once

#include <utility>
#include <vector>

#include "mesh/surface_mesh.h"
#include "problems/runtime/model.h"

namespace archgeo {

constexpr double kAsymptoticDegrees = 10;
constexpr double kPositiveCurvature = 0.05;
constexpr double kConjugacy = 0.25;
constexpr double kPrincipalDegrees = 10;

void CheckAsymptoticNet(HookContext& c, const Mesh& net);
// On a thread of its own (recorded by HookContext::RecordChecks).
void CheckConjugateNet(HookContext& c, const Mesh& net);
// The same check at once, recorded before it returns; whether the net is
// suitable (planar_quads' relayout: auto decides on it).
bool CheckConjugateNetNow(HookContext& c, const Mesh& net);
void CheckPrincipalLabels(HookContext& c, const Mesh& mesh,
                          const std::vector<std::pair<int, int>>& labels);

}  // namespace archgeo
