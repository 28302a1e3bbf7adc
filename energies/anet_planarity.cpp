// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/anet_planarity.h"

#include <cmath>

#include <Eigen/Eigenvalues>
#include <glog/logging.h>

#include "core/term.h"
#include "energies/autodiff_impl.h"

namespace archgeo {

std::vector<std::array<int, 3>> AnetStarQuadNeighbours(int valence) {
  CHECK_GE(valence, 3) << "AnetStarQuadNeighbours: a star needs >= 3 neighbours";
  std::vector<std::array<int, 3>> quads;
  quads.reserve(valence - 2);
  for (int i = 0; i + 2 < valence; ++i) quads.push_back({i, i + 1, i + 2});
  return quads;
}

AnetVertexNormal CheckedAnetVertexNormal(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "AnetVertexNormal: inv_length must be finite and > 0, got "
      << inv_length;
  return AnetVertexNormal(inv_length);
}

AnetStarQuad CheckedAnetStarQuad(double inv_length) {
  CHECK(std::isfinite(inv_length) && inv_length > 0.0)
      << "AnetStarQuad: inv_length must be finite and > 0, got "
      << inv_length;
  return AnetStarQuad(inv_length);
}

}  // namespace archgeo

// --- term `anet_planarity` -----------------------------------------------------

namespace archgeo::terms {
namespace {

using V = Eigen::Map<const Eigen::Vector3d>;

// 1 / the star's mean edge length at the start of the solve.
double InvLength(TermContext& c, const int* s, int count) {
  double length = 0;
  for (int k = 1; k < count; ++k) length += (V(c.Original(s[k])) - V(c.Original(s[0]))).norm();
  length /= double(std::max(1, count - 1));
  return length > 0 ? 1.0 / length : 1.0;
}

// The unit normal of the least-squares plane of each star (variant normals).
void InitNormals(TermContext& c) {
  if (c.String("variant") != "normals") return;
  for (size_t i = 0; i < c.elements->size(); ++i) {
    const int* s = c.elements->Vertices(i);
    const int count = c.elements->Count(i);
    Eigen::Vector3d center = V(c.Position(s[0]));
    for (int k = 1; k < count; ++k) center += V(c.Position(s[k]));
    center /= double(count);
    Eigen::Matrix3d cov = (V(c.Position(s[0])) - center) * (V(c.Position(s[0])) - center).transpose();
    for (int k = 1; k < count; ++k) {
      cov += (V(c.Position(s[k])) - center) * (V(c.Position(s[k])) - center).transpose();
    }
    const Eigen::Vector3d n =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov).eigenvectors().col(0);
    double* block = c.Block("anet_normal", s[0]);
    for (int a = 0; a < 3; ++a) block[a] = n[a];
  }
}

// Element: (v, w_1 … w_n), a star in order.
void AddAnet(TermContext& c, size_t i) {
  const int* s = c.elements->Vertices(i);
  const int count = c.elements->Count(i);
  const double inv_length = InvLength(c, s, count);
  if (c.String("variant") == "normals") {
    double* n = c.Block("anet_normal", s[0]);
    for (int k = 1; k < count; ++k) {
      AddAutoDiff(c, CheckedAnetVertexNormal(inv_length), {n, c.Position(s[0]), c.Position(s[k])});
    }
    c.SetUnit(n);
  } else {
    for (const auto& t : AnetStarQuadNeighbours(count - 1)) {
      AddAutoDiff(c, CheckedAnetStarQuad(inv_length), {c.Position(s[0]), c.Position(s[1 + t[0]]),
                                           c.Position(s[1 + t[1]]), c.Position(s[1 + t[2]])});
    }
  }
}

}  // namespace

const TermSpec& anet_planarity() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "anet_planarity";
    t.summary = "vertex-star planarity (A-nets): a unit normal per vertex, or n − 2 star quads";
    t.paper = "[Shi 2014, §3.2 step 1, eq. 10, F_p (i) and (ii)]";
    t.elements = "stars";
    t.declares = {{"anet_normal", Site::kVertex, 3, FrameMap::kDirection, true,
                   Carry::kReinitialise, false, false,
                   "unit normal of a vertex star's plane (anet_planarity, variant normals)"}};
    t.options = {ChoiceKey("variant", "normals", {"normals", "quads"},
                           "normals: a unit vertex normal and the neighbours' distances "
                           "from its plane (i); quads: the n − 2 star quads (ii)")};
    t.init = &InitNormals;
    t.drives = "star_planarity_max";
    t.add = &AddAnet;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_AUTODIFF(archgeo::AnetVertexNormal)
ARCHGEO_AUTODIFF(archgeo::AnetStarQuad)
