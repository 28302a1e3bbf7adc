// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/convexity.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <glog/logging.h>

#include "core/term.h"
#include "core/newell.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

double CornerTurnSine(const double a[3], const double b[3], const double c[3],
                      const double normal[3]) {
  const Eigen::Vector3d u = Eigen::Vector3d(b[0], b[1], b[2]) - Eigen::Vector3d(a[0], a[1], a[2]);
  const Eigen::Vector3d v = Eigen::Vector3d(c[0], c[1], c[2]) - Eigen::Vector3d(b[0], b[1], b[2]);
  return u.cross(v).dot(Eigen::Vector3d(normal[0], normal[1], normal[2])) /
         (std::sqrt(u.squaredNorm() + 1e-18) * std::sqrt(v.squaredNorm() + 1e-18));
}

namespace {


Convexity CheckedConvexity(const double normal[3], double threshold) {
  CHECK(normal != nullptr);
  const double n2 = normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2];
  CHECK(std::isfinite(n2) && std::abs(n2 - 1.0) < 2e-6) << "Convexity: normal not unit";
  CHECK(std::isfinite(threshold) && threshold >= -1.0 && threshold <= 1.0)
      << "Convexity: threshold must be in [-1, 1], got " << threshold;
  return Convexity(normal, threshold);
}

}  // namespace

}  // namespace archgeo

// --- term `convexity` ------------------------------------------------------------

namespace archgeo::terms {
namespace {

constexpr double kDegrees = 3.14159265358979323846 / 180.0;

// Newell's normal of the polygon vs[0..k) at `position(v)`, unit (0 if degenerate).
template <typename Positions>
Eigen::Vector3d Newell(const int* vs, int k, Positions position) {
  return NewellNormal(k, [&](int j) { return position(vs[j]); });  // core/newell.h
}

void AddConvexity(TermContext& c, size_t i) {
  const int* vs = c.elements->Vertices(i);
  const int k = c.elements->Count(i);
  const Eigen::Vector3d now = Newell(vs, k, [&](int v) { return c.Previous(v); });
  const Eigen::Vector3d start = Newell(vs, k, [&](int v) { return c.Original(v); });
  if (now.squaredNorm() == 0 || start.squaredNorm() == 0) return;  // a degenerate face
  const double margin = std::sin(c.Number("margin_degrees") * kDegrees);
  for (int j = 0; j < k; ++j) {
    const int a = vs[(j + k - 1) % k], b = vs[j], d = vs[(j + 1) % k];
    const double input = CornerTurnSine(c.Original(a), c.Original(b), c.Original(d), start.data());
    // A corner the input already has outside the margin (e.g. a straight
    // corner where two quads were joined) may get worse by the margin, no more.
    const double threshold = input >= margin ? margin : std::max(-1.0, input - margin);
    AddAutoDiff(c, CheckedConvexity(now.data(), threshold),
                                 {c.Position(a), c.Position(b), c.Position(d)});
  }
}

}  // namespace

const TermSpec& convexity() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "convexity";
    t.summary = "barrier: every corner of a panel stays convex (or at most the margin worse than the input)";
    t.paper = "[panel validity; Zadravec 2010, §6, Fig. 13]";
    t.elements = "non_triangles";
    t.element_choices = {"faces", "quads", "polygons"};
    t.options = {NumberKey("margin_degrees", 1.0, 0.0, 45.0,
                           "corners are kept at least this far from straight and from a spike "
                           "(interior angle in [m, 180° − m]); corners the input already has "
                           "outside it may get worse by about m, no more")};
    t.barrier = true;
    t.add = &AddConvexity;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::Convexity)
