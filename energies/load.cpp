// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "energies/load.h"

#include <array>
#include <cmath>

#include <glog/logging.h>

#include "core/term.h"
#include "core/newell.h"
#include "energies/autodiff_impl.h"

namespace archgeo {
namespace {


}  // namespace

LoadEquilibrium CheckedLoadEquilibrium(const double force[3], const std::vector<double>& stiffness,
                                       const std::vector<double>& rest_length, double inv_force) {
  CHECK(force != nullptr);
  CHECK(std::isfinite(force[0]) && std::isfinite(force[1]) &&
        std::isfinite(force[2]))
      << "LoadEquilibrium: non-finite force";
  CHECK_GE(stiffness.size(), 1u) << "LoadEquilibrium: no spring";
  CHECK_EQ(stiffness.size(), rest_length.size())
      << "LoadEquilibrium: one rest length per spring";
  for (size_t j = 0; j < stiffness.size(); ++j) {
    CHECK(std::isfinite(stiffness[j]) && stiffness[j] > 0.0)
        << "LoadEquilibrium: stiffness must be finite and > 0, got "
        << stiffness[j];
    CHECK(std::isfinite(rest_length[j]) && rest_length[j] >= 0.0)
        << "LoadEquilibrium: rest length must be finite and >= 0, got "
        << rest_length[j];
  }
  CHECK(std::isfinite(inv_force) && inv_force > 0.0)
      << "LoadEquilibrium: inv_force must be finite and > 0, got "
      << inv_force;
  return LoadEquilibrium(force, stiffness, rest_length, inv_force);
}

}  // namespace archgeo

// --- term `load` ---------------------------------------------------------------

namespace archgeo::terms {
namespace {

using Vec = std::array<double, 3>;

Vec Minus(const double* a, const double* b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
double Length(const Vec& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// The load's unit direction (file axes → canonical) and magnitude in the
// canonical frame, where forces are file forces / s (s = the input's mean
// edge length; springs k d_file = s k d_canonical): a load per area q gives
// q s per canonical area, a force F per vertex F / s.
Vec Direction(TermContext& c) {
  const std::vector<double> d = c.settings().Numbers("terms." + c.term_name() + ".direction");
  Vec u{d[0], d[1], d[2]};
  const double n = Length(u);
  if (!(n > 0)) {
    throw c.settings().Error("terms." + c.term_name() + ".direction", "the zero vector has no "
                                                                      "direction");
  }
  for (double& x : u) x /= n;
  c.FromFile(FrameMap::kDirection, u.data(), 3);
  return u;
}

double Magnitude(TermContext& c) {
  double q = c.Number("load");
  c.FromFile(c.String("per") == "area" ? FrameMap::kInverseLength : FrameMap::kLength, &q, 1);
  return q;
}

// Vertex loads (block load_force, canonical): per area, q × the vertex's
// tributary area at the start of the solve (Σ over its faces of the
// face's Newell area / its number of vertices); per vertex, F.
void InitLoad(TermContext& c) {
  const Vec u = Direction(c);
  const double q = Magnitude(c);
  std::vector<double> weight(size_t(c.NumVertices()), 0.0);
  if (c.String("per") == "area") {
    const ElementSet& faces = c.Elements("faces");
    for (size_t f = 0; f < faces.size(); ++f) {
      const int* vs = faces.Vertices(f);
      const int k = faces.Count(f);
      const double area = 0.5 * NewellVector(k, [&](int j) { return c.Original(vs[j]); }).norm();
      for (int j = 0; j < k; ++j) weight[size_t(vs[j])] += area / k;
    }
  } else {
    weight.assign(weight.size(), 1.0);
  }
  for (int v = 0; v < c.NumVertices(); ++v) {
    double* f = c.Block("load_force", v);
    for (int a = 0; a < 3; ++a) f[a] = q * weight[size_t(v)] * u[a];
  }
  // The springs' rest lengths per edge, for the force-balance measure.
  const ElementSet& edges = c.Elements("edges");
  const double fraction = c.Number("rest_fraction");
  for (size_t e = 0; e < edges.size(); ++e) {
    const int* ab = edges.Vertices(e);
    c.Block("load_rest_length", edges.edge[e])[0] =
        fraction * Length(Minus(c.Original(ab[1]), c.Original(ab[0])));
  }
}

// At a free vertex v with neighbours w_j: r = (f_v + Σ_j k (1 − L0_j/‖d_j‖) d_j)/F,
// L0_j = rest_fraction × the edge's length at the start of the solve, F =
// the load per canonical area or per vertex (the stiffness if that is 0).
void AddLoad(TermContext& c, size_t i) {
  const int* s = c.elements->Vertices(i);
  const int n = c.elements->Count(i) - 1;
  if (n < 1 || c.Fixed(s[0])) return;
  const double k = c.Number("stiffness");
  const double fraction = c.Number("rest_fraction");
  std::vector<double> stiffness(size_t(n), k), rest(size_t(n), 0.0);
  std::vector<double*> blocks = {c.Position(s[0])};
  for (int j = 1; j <= n; ++j) {
    rest[size_t(j - 1)] = fraction * Length(Minus(c.Original(s[j]), c.Original(s[0])));
    blocks.push_back(c.Position(s[j]));
  }
  const double scale = std::abs(Magnitude(c));
  c.Add(MakeStarAutoDiff(CheckedLoadEquilibrium(c.Block("load_force", s[0]), stiffness, rest,
                                                1.0 / (scale > 0 ? scale : k))),
        blocks);
}

}  // namespace

const TermSpec& load() {
  static const TermSpec spec = [] {
    TermSpec t;
    t.name = "load";
    t.summary = "hanging net: force balance of a constant load (per area or per vertex) and "
                "the springs of every edge at each free vertex (carries the net's springs: "
                "no `spring` on the same edges)";
    t.paper = "[Gebreiter 2012, §11.2.2, §10.1 dynamic relaxation; Barnes 1977]";
    t.elements = "one_rings";
    t.declares = {{"load_force", Site::kVertex, 3, FrameMap::kVector, false,
                   Carry::kReinitialise, true, true,
                   "the load on each vertex (load; force units of the spec)"},
                  {"load_rest_length", Site::kEdge, 1, FrameMap::kLength, false,
                   Carry::kReinitialise, false, true,
                   "rest length of each edge's spring in the load term"}};
    t.options = {
        ChoiceKey("per", "area", {"area", "vertex"},
                  "area: `load` per unit area, times each vertex's tributary area at the start "
                  "(gravity, snow); vertex: `load` on every vertex"),
        NumberKey("load", 1, 0, 1e30, "load per area or per vertex (force units of the spec, "
                                      "lengths in file units)"),
        [] {
          Key k;
          k.name = "direction";
          k.type = Type::kNumbers;
          k.size = 3;
          k.fallback = std::vector<double>{0, 0, 1};
          k.doc = "direction of the load in the file's axes ([0, 0, 1]: reversed gravity, a "
                  "vault; [0, 0, -1]: gravity, a hanging net)";
          return k;
        }(),
        NumberKey("stiffness", 1, 1e-30, 1e30,
                  "spring stiffness of every edge (force per file length unit)"),
        NumberKey("rest_fraction", 0, 0, 1e6,
                  "spring rest length = this × the edge's length at the start (0: zero-length "
                  "springs, the thesis' hanging net)")};
    t.drives = "force_balance_max";
    t.init = &InitLoad;
    t.add = &AddLoad;
    return t;
  }();
  return spec;
}

}  // namespace archgeo::terms

ARCHGEO_STAR_AUTODIFF(archgeo::LoadEquilibrium)
