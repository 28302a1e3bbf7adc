// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/declarations/custom.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "energies/registry.h"
#include "geometry/curves.h"
#include "mesh/elements.h"
#include "core/input_error.h"
#include "geometry/reference.h"
#include "mesh/similarity.h"
#include "problems/declarations/design_band.h"
#include "problems/declarations/flatness.h"
#include "problems/runtime/model.h"
#include "problems/spec/selection.h"

namespace archgeo {
namespace {

bool On(const Settings& s, const std::string& term) {
  const std::string key = "terms." + term + ".weight";
  return s.schema().Find(key) && s.Number(key) > 0;
}

// Hanging net (load term): span and rise in file units along the load
// direction d: rise = max_v d·x_v − max_supports d·x_s (how far the net goes
// beyond its highest support along the load: the rise of a vault, the sag
// of a hanging net), span = the largest distance between two supports
// across d (the diameter of the supports' plan); and the force balance.
void FormDetails(HookContext& c) {
  const Settings& s = *c.settings;
  const std::vector<double> d = s.Numbers("terms.load.direction");
  Eigen::Vector3d u(d[0], d[1], d[2]);
  u = (1.0 / u.norm()) * u;
  const Mesh& mesh = c.store->mesh();
  std::vector<Eigen::Vector3d> supports;
  double top = -std::numeric_limits<double>::infinity();
  double support_top = top;
  for (VertexIndex v : mesh.vertices()) {
    const Vec3 p = c.frame.FromCanonical(ToVec3(mesh.point(v)));
    const Eigen::Vector3d x(p[0], p[1], p[2]);
    top = std::max(top, u.dot(x));
    if (!c.fixed[v.idx()]) continue;
    support_top = std::max(support_top, u.dot(x));
    supports.push_back(x - u.dot(x) * u);
  }
  const double balance = c.Measure("force_balance_max");
  nlohmann::json form = {{"force_balance_max", balance},
                         {"supports", supports.size()},
                         {"direction", {u[0], u[1], u[2]}}};
  char line[256];
  std::snprintf(line, sizeof line, "load: force balance %.3e of the load", balance);
  std::string text = line;
  if (!supports.empty()) {
    double span = 0;
    for (size_t i = 0; i < supports.size(); ++i) {
      for (size_t j = i + 1; j < supports.size(); ++j) {
        span = std::max(span, (supports[i] - supports[j]).norm());
      }
    }
    const double rise = top - support_top;
    form["span"] = span;
    form["rise"] = rise;
    form["span_over_rise"] = rise > 0 ? nlohmann::json(span / rise) : nlohmann::json(nullptr);
    std::snprintf(line, sizeof line, "; span %.6g, rise %.6g (span/rise %.4g; file units)", span,
                  rise, rise > 0 ? span / rise : 0.0);
    text += line;
  }
  c.details["load"] = form;
  c.headline += text + "\n";
}

// on_curve: how far its vertices are from their curves (they slide on them).
void CurveDetails(HookContext& c) {
  const Settings& s = *c.settings;
  const Mesh& mesh = c.store->mesh();
  const std::vector<Polyline> curves =
      TermCurves(s, "terms.on_curve.curve", c.frame, c.reference->Triangles());
  std::vector<PolylineLocator> locators;
  for (const Polyline& p : curves) locators.emplace_back(p);
  const ElementSet& bound = c.model->Selected(*FindTerm("on_curve"));
  double worst = 0;
  int count = 0;
  for (size_t i = 0; i < bound.size(); ++i) {
    const int v = bound.Vertices(i)[0];
    if (c.fixed[size_t(v)]) continue;
    double distance = std::numeric_limits<double>::infinity();
    for (const PolylineLocator& l : locators) {
      distance = std::min(distance, l.Closest(ToVec3(mesh.point(VertexIndex(v)))).distance);
    }
    worst = std::max(worst, distance);
    ++count;
  }
  const double diagonal = PrincipalBoxDiagonal(mesh);
  c.details["on_curve"] = {{"vertices", count},
                           {"curves", curves.size()},
                           {"max_distance_relative", worst / diagonal}};
  char line[200];
  std::snprintf(line, sizeof line,
                "on_curve: %d vertices, max distance to their curves %.3e of the diagonal\n",
                count, worst / diagonal);
  c.headline += line;
}

// The per-face quantity the composition lowers (problems/report/colors.h):
// planarity with a planarity term, else E or C with a smoothness term, else
// none (spreads, loads and curves have no per-face picture).
std::string ColorsOf(const std::vector<TermUse>& terms) {
  auto has = [&](std::initializer_list<const char*> names) {
    for (const TermUse& u : terms) {
      for (const char* n : names) {
        if (u.term == n) return true;
      }
    }
    return false;
  };
  if (has({"pq_diagonal", "face_planarity", "conical"})) return "planarity";
  if (has({"dihedral_energy", "smoothed_dihedral_energy"})) return "energy";
  if (has({"total_absolute_curvature"})) return "curvature";
  return "none";
}

void FinishCustom(HookContext& c) {
  if (On(*c.settings, "load")) FormDetails(c);
  if (On(*c.settings, "on_curve")) CurveDetails(c);
}

}  // namespace

ProblemDecl CustomProblem(const CustomValue* terms, const std::string& file) {
  ProblemDecl d;
  d.name = "custom";
  d.summary = "the spec's own composition of registered terms";
  d.paper = "(see each term's paper)";
  const int line = terms ? terms->line : 0;
  if (!terms || !terms->IsMap() || terms->entries.empty()) {
    throw InputError(file, line, "terms",
                     "problem: custom needs a mapping `terms:` of registered terms and weights");
  }
  std::vector<std::string> known;
  for (const TermSpec* t : RegisteredTerms()) known.push_back(t->name);
  std::vector<std::string> driven;
  for (const CustomValue::Entry& entry : terms->entries) {
    const std::string& name = entry.key.text;
    const int at = entry.key.line > 0 ? entry.key.line : line;
    const TermSpec* spec = FindTerm(name);
    if (!spec) {
      std::string list;
      for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
      throw InputError(file, at, "terms." + name, "not a registered term (" + list + ")");
    }
    const std::vector<std::string>& built_in = ElementSetNames();
    if (std::find(built_in.begin(), built_in.end(), spec->elements) == built_in.end()) {
      throw InputError(file, at, "terms." + name,
                       std::string("acts on '") + spec->elements +
                           "', elements only its own problem provides; it cannot be composed");
    }
    TermUse use;
    use.term = name;
    use.weight = 1.0;
    d.terms.push_back(use);
    if (spec->drives[0] != '\0' &&
        std::find(driven.begin(), driven.end(), spec->drives) == driven.end()) {
      driven.push_back(spec->drives);
    }
  }
  for (const std::string& m : driven) {
    d.keys.push_back(NumberKey("tolerance." + m, 0, 0, 1,
                               "stop when " + m + " is at most this; 0 = off"));
  }
  d.keys.push_back(NumberKey("continuation.factor", 10, 1, 1e6,
                             "weight growth of the terms driving a tolerance, per round short "
                             "of it"));
  d.keys.push_back(NumberKey("continuation.start", 1, 1, 1e30,
                             "scale of the continued weights (planarity, barriers) in the first round; it grows by "
                             "continuation.factor per round short of the tolerance. A session's re-solve "
                             "(archgeo::Session) starts at the scale its last solve ended with"));
  d.keys.push_back(NumberKey("continuation.band", 0, 0, 1,
                             "a pq_diagonal/face_planarity residual within band × tolerance "
                             "costs nothing"));
  bool smooth = false;
  for (const TermUse& u : d.terms) {
    smooth = smooth || u.term == "dihedral_energy" || u.term == "smoothed_dihedral_energy" ||
                      u.term == "total_absolute_curvature";
  }
  bool conical = false;
  for (const TermUse& u : d.terms) conical = conical || u.term == "conical";
  d.analyses = {"planarity", "spreads"};
  if (smooth) d.analyses.insert("smoothness");
  d.colors = ColorsOf(d.terms);
  if (conical) d.analyses.insert("conical");
  d.stages = [driven, smooth, d](const Settings&) {
    Stage s;
    s.name = "custom";
    s.rounds_key = "schedule.outer_iterations";
    for (const std::string& m : driven) {
      s.tolerances.push_back({m, "tolerance." + m, /*per_iteration=*/true});
      s.logged.push_back(m);
    }
    for (const TermUse& u : d.terms) {
      const TermSpec* spec = FindTerm(u.term);
      if (spec->drives[0] != '\0' || (spec->barrier && !driven.empty())) {
        s.continued.push_back(u.term);
      }
    }
    s.factor_key = "continuation.factor";
    s.band_key = "continuation.band";
    s.rest_move = 1e-6;
    if (smooth) s.logged.push_back("E");
    return std::vector<Stage>{s};
  };
  d.finish = &FinishCustom;
  // A listed term with nothing to act on is an input error naming it.
  d.init = [](HookContext& c) {
    for (const Key& k : c.settings->schema().keys()) {
      const std::string suffix = ".weight";
      if (k.name.rfind("terms.", 0) != 0 || k.name.size() < suffix.size() ||
          k.name.compare(k.name.size() - suffix.size(), suffix.size(), suffix) != 0) {
        continue;
      }
      if (c.settings->Number(k.name) <= 0) continue;
      const std::string term = k.name.substr(6, k.name.size() - 6 - suffix.size());
      const std::string on = c.settings->String("terms." + term + ".on");
      if (c.model->Elements(on).size() == 0) {
        throw c.settings->Error("terms." + term, term + " acts on " + on +
                                                    ", and the mesh has none");
      }
    }
  };
  // The deviation band, off unless the spec sets it (design_band.h).
  // Flatness in millimetres where a term drives δ_PQ,n (flatness.h).
  if (std::find(driven.begin(), driven.end(), "pq_normalized_max") != driven.end()) {
    d = WithFlatness(std::move(d));
  }
  return WithDesignBand(std::move(d), 0);
}

ProblemDecl CustomExample() {
  // The composition of examples/planar_smooth.yaml: planar quads that stay
  // smooth, close to the input and valid.
  const std::vector<std::pair<std::string, double>> weights = {
      {"pq_diagonal", 10},      {"face_planarity", 10},     {"fairness", 10},
      {"dihedral_energy", 0.3}, {"proximity", 2},           {"boundary_proximity", 10},
      {"anchor", 1},            {"convexity", 1000},        {"min_edge_length", 1000}};
  CustomValue terms;
  terms.kind = CustomValue::Kind::kMap;
  for (const auto& [name, weight] : weights) {
    CustomValue::Entry entry;
    entry.key.kind = CustomValue::Kind::kScalar;
    entry.key.text = name;
    terms.entries.push_back(entry);
  }
  ProblemDecl d = CustomProblem(&terms, "");
  for (TermUse& use : d.terms) {
    for (const auto& [name, weight] : weights) {
      if (use.term == name) use.weight = weight;
    }
    if (use.term == "face_planarity") use.elements = "non_triangles";
    if (use.term == "proximity") use.options["point_weight"] = 0.01;
  }
  return d;
}

}  // namespace archgeo
