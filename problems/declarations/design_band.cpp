// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/declarations/design_band.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "core/magnitude.h"
#include "geometry/reference.h"
#include "mesh/similarity.h"
#include "problems/declarations/registry.h"
#include "problems/runtime/model.h"
#include "problems/runtime/solve.h"

namespace archgeo {
namespace {

// "At the band": beyond this fraction of it (the manifold holds 0.95 of it
// from the tangent plane, which the surface may curve towards).
constexpr double kAtBand = 0.8;

// The input's bounding-box diagonal (principal axes) in canonical lengths.
double CanonicalDiagonal(const HookContext& c) {
  return PrincipalBoxDiagonal(*c.input) / c.frame.scale;
}

// The band in canonical lengths (input mean edge lengths); 0 = none.
double CanonicalBand(const HookContext& c) {
  const Settings& s = *c.settings;
  const double absolute = s.Number("tolerance.surface_distance");
  if (absolute > 0) return absolute / c.frame.scale;
  return s.Number("tolerance.surface_distance_max") * CanonicalDiagonal(c);
}

// The bound as the loop tests it: in file units when given so, else relative.
Tolerance BandTolerance(const Settings& s) {
  Tolerance t;
  const bool absolute = s.Number("tolerance.surface_distance") > 0;
  t.measure = absolute ? "surface_distance" : "surface_distance_relative";
  t.key = absolute ? "tolerance.surface_distance" : "tolerance.surface_distance_max";
  t.per_iteration = true;
  t.stops = false;
  t.bound = true;
  return t;
}

std::string Percent(double fraction) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g%%", 100 * fraction);
  return text;
}

// After a round: a vertex the tangent-plane model let past `band` (the
// surface curves away under it) is put back on the band's edge, towards its
// closest reference point; returns how many. The overshoot is a fraction of
// the band (the manifold holds 0.95 b in the model), so the panels it
// touches stay as planar as the next round needs.
int ClampToBand(HookContext& c, double band) {
  if (!(band > 0)) return 0;
  Mesh& mesh = c.store->mesh();
  int clamped = 0;
  for (VertexIndex v : mesh.vertices()) {
    if (c.fixed[v.idx()]) continue;
    const Vec3 x = ToVec3(mesh.point(v));
    const Vec3 p = c.reference->Closest(x).point;
    const double d = std::hypot(x[0] - p[0], x[1] - p[1], x[2] - p[2]);
    if (d <= band) continue;
    const double t = (1 - 1e-9) * band / d;
    mesh.point(v) = Point(p[0] + t * (x[0] - p[0]), p[1] + t * (x[1] - p[1]), p[2] + t * (x[2] - p[2]));
    ++clamped;
  }
  return clamped;
}

// Band tightening (planar_quads): when the rounds at the band pressed
// against it (a round at kAtBand of it or more) and ended short of the
// goals, on a net the problem's BandTighteningIf accepts, a stage that
// first solves with the band open, until the goals hold, and then closes it
// towards the band: after each round that meets the goals, the next
// round's band is kTightenStep of the smaller of the current band and the
// deviation reached, down to the band asked for. A round that misses the
// goals keeps its band (and grows the weights); after kStepRounds such
// rounds in a row at a band wider than the one asked for (the band open
// included), the stage ends. The rounds before the last band are beyond
// it, so never the output; the stage's output is its flattest round within
// the band, or the rounds before it when none is flatter. The goals and the
// band, reached from a planar state, hold in places a solve pressing a
// non-planar net against the band stalls (docs/methods/design_band.md has
// the figures).
// Its state, in details.band_tightening: whether a round pressed against
// the band, the band of the last and the next round (canonical lengths,
// 0 = open), the rounds in a row that missed the goals, one entry per round.
constexpr double kTightenStep = 0.8;
constexpr int kStepRounds = 4;
// The continued weights restart at this scale: where the first rounds of
// the shared nets are nearly planar (the rounds before end far stiffer).
constexpr double kTightenScale = 1e3;

// After a round of the stages at the band: whether it pressed against it.
void RecordPressed(HookContext& c) {
  const double band = CanonicalBand(c);
  if (c.Measure("surface_distance_relative") * CanonicalDiagonal(c) >= kAtBand * band) {
    c.details["band_tightening"]["pressed"] = true;
  }
}

// Whether `goals` hold on the current state.
bool GoalsMet(HookContext& c, const std::vector<Tolerance>& goals) {
  bool met = true;
  for (const Tolerance& g : goals) {
    const double bound = c.settings->Number(g.key);
    met = met && (!(bound > 0) || c.Measure(g.measure) <= bound);
  }
  return met;
}

Stage TighteningStage(const Stage& base, const BandTighteningIf& tighten_if) {
  Stage t = base;  // its terms, tolerances (the band's included), logged measures, keep_best
  t.name = "band";
  t.rounds_key = "stall.band_tightening";
  t.skip_if_met = false;  // runs decides, leaving the stop of the rounds before
  t.start_scale = kTightenScale;
  t.restart_on_goals = true;
  // The stall rule of the rounds before, counting only rounds within the
  // band (the rounds that close it are beyond it by design).
  t.patience_counts_valid = true;
  std::vector<Tolerance> goals;
  for (const Tolerance& tol : base.tolerances) {
    if (!tol.bound) goals.push_back(tol);
  }
  t.runs = [goals, tighten_if](HookContext& c) {
    return c.details.contains("band_tightening") &&
           c.details["band_tightening"].value("pressed", false) && !GoalsMet(c, goals) &&
           tighten_if(c);
  };
  t.ends = [](HookContext& c) {
    const nlohmann::json& state = c.details["band_tightening"];
    const double last = state["last_band"].get<double>();
    if (state["misses"].get<int>() < kStepRounds || last == CanonicalBand(c)) return std::string();
    return "band tightening: the goals missed in " + std::to_string(kStepRounds) + " rounds " +
           (last > 0 ? "at a band of " + Percent(last / CanonicalDiagonal(c)) + " of the diagonal"
                     : std::string("with the band open"));
  };
  const Hook before = base.before_round, after = base.after_round;
  t.before_round = [before](HookContext& c) {
    if (before) before(c);
    nlohmann::json& state = c.details["band_tightening"];
    if (!state.contains("rounds")) {
      state["band"] = 0.0;
      state["misses"] = 0;
      state["rounds"] = nlohmann::json::array();
    }
    const double band = state["band"].get<double>();  // 0: no band at the vertex
    for (VertexIndex v : c.store->mesh().vertices()) {
      c.store->At("surface_band", int(v.idx()))[0] = band;
    }
  };
  t.after_round = [after, goals](HookContext& c) {
    if (after) after(c);
    nlohmann::json& state = c.details["band_tightening"];
    const double band = state["band"].get<double>(), target = CanonicalBand(c);
    ClampToBand(c, band);
    const bool met = GoalsMet(c, goals);
    const double diagonal = CanonicalDiagonal(c);
    const double deviation = c.Measure("surface_distance_relative") * diagonal;
    state["rounds"].push_back({{"band_relative", band / diagonal},
                               {"goals_met", met},
                               {"deviation_relative", deviation / diagonal}});
    state["last_band"] = band;
    state["misses"] = met ? 0 : state["misses"].get<int>() + 1;
    if (met) {
      const double reached = band > 0 ? std::min(band, deviation) : deviation;
      state["band"] = std::max(target, kTightenStep * reached);
      // The next band starts from this planar state: anchor and fairness
      // keep it rather than the net before the band opened.
      c.model->Rebase();
    }
  };
  return t;
}

// What the goals need when the band binds and no round met them: the same
// problem solved again on the same net without a band (every other key as
// given); its output's largest vertex distance from the reference, relative
// to the diagonal, and whether that run met the goals.
struct BandNeed {
  double deviation_relative = 0;
  bool goals_met = false;
};

BandNeed UnboundedNeed(HookContext& c, const std::string& problem) {
  ProblemSpec spec;
  spec.spec_path = c.settings->spec_file();
  spec.declaration = std::shared_ptr<const ProblemDecl>(FindProblem(problem), [](auto*) {});
  spec.settings = *c.settings;
  const Origin origin{c.settings->spec_file(), 0};
  spec.settings.Set("tolerance.surface_distance_max", 0.0, origin);
  spec.settings.Set("tolerance.surface_distance", 0.0, origin);
  ProgressSink progress;
  if (c.progress) {
    progress = [sink = c.progress](const ProgressEvent& event) {
      ProgressEvent prefixed = event;
      prefixed.line = "without the band: " + event.line;
      sink(prefixed);
    };
  }
  const std::unique_ptr<Solution> run = Solve(spec, *c.input, nullptr, progress);
  BandNeed need;
  need.goals_met = run->loop.usable;
  for (const auto& [key, met] : run->loop.tolerances) need.goals_met = need.goals_met && met;
  double largest = 0;  // canonical lengths, against this run's reference
  for (VertexIndex v : run->output.vertices()) {
    const Vec3 x = c.frame.ToCanonical(ToVec3(run->output.point(v)));
    const Vec3 p = c.reference->Closest(x).point;
    largest = std::max(largest, std::hypot(x[0] - p[0], x[1] - p[1], x[2] - p[2]));
  }
  need.deviation_relative = largest * c.frame.scale / PrincipalBoxDiagonal(*c.input);
  return need;
}

// details.surface_band and, when it binds, a headline line. `problem`
// (non-empty): the problem to solve again without the band when it binds
// and no round met the goals (UnboundedNeed).
void Report(HookContext& c, const std::string& problem) {
  const double band = CanonicalBand(c);
  if (!(band > 0) || c.loop == nullptr) return;
  const double diagonal = CanonicalDiagonal(c);
  const Mesh& mesh = c.store->mesh();
  int at_band = 0;
  for (VertexIndex v : mesh.vertices()) {
    const Vec3 x = ToVec3(mesh.point(v));
    const Vec3 p = c.reference->Closest(x).point;
    if (std::hypot(x[0] - p[0], x[1] - p[1], x[2] - p[2]) >= kAtBand * band) ++at_band;
  }
  const double deviation = c.Measure("surface_distance_relative");
  const Tolerance t = BandTolerance(*c.settings);
  bool goals_met = true;
  for (const auto& [key, met] : c.loop->tolerances) goals_met = goals_met && (met || key == t.key);
  // The output is the best valid round, which need not be the one that
  // pressed against the band: the largest deviation any round reached.
  const auto relative = [&](double value) {
    return t.measure == "surface_distance" ? value / c.frame.scale / diagonal : value;
  };
  double reached = deviation;
  for (const RoundLog& row : c.loop->log) {
    if (row.stage == "band") continue;  // band tightening: its own bands (below)
    const auto it = row.measures.find(t.measure);
    if (it != row.measures.end()) reached = std::max(reached, relative(it->second));
  }
  const bool binds = !goals_met && (at_band > 0 || reached >= kAtBand * band / diagonal);
  nlohmann::json j = {{"band_relative", band / diagonal},
                      {"band", band * c.frame.scale},
                      {"deviation_relative", deviation},
                      {"deviation", c.Measure("surface_distance")},
                      {"deviation_reached_relative", reached},
                      {"vertices_at_band", at_band},
                      {"binds", binds}};
  if (c.details.contains("band_tightening")) {
    if (c.details["band_tightening"].contains("rounds")) {
      j["tightening"] = c.details["band_tightening"]["rounds"];
    }
    c.details.erase("band_tightening");
  }
  const auto need = c.loop->bound_needs.find(t.key);
  if (need != c.loop->bound_needs.end()) {
    j["goals_needed_relative"] = relative(need->second);
  }
  if (binds && !j.contains("goals_needed_relative") && !problem.empty()) {
    const BandNeed unbounded = UnboundedNeed(c, problem);
    j["unbounded"] = {{"deviation_relative", unbounded.deviation_relative},
                      {"goals_met", unbounded.goals_met}};
  }
  c.details["surface_band"] = j;
  if (!binds) return;
  std::string line = "BAND BINDS: the goals were missed at the deviation band (" +
                     Percent(band / diagonal) + " of the diagonal; rounds reached " +
                     Percent(reached) + ", the output " + Percent(deviation) + " with " +
                     std::to_string(at_band) + " vertices within 20% of the band)";
  if (j.contains("goals_needed_relative")) {
    line += "; a round met them at a deviation of " +
            Percent(j["goals_needed_relative"].get<double>());
  } else if (j.contains("unbounded")) {
    line += std::string("; without the band the same run ") +
            (j["unbounded"]["goals_met"].get<bool>() ? "met them" : "missed them too") +
            " at a deviation of " + Percent(j["unbounded"]["deviation_relative"].get<double>());
  }
  c.headline += line + ". Raise tolerance.surface_distance_max to trade deviation for them.\n";
}

}  // namespace

ProblemDecl WithDesignBand(ProblemDecl d, double relative, bool measure_need,
                           BandTighteningIf tighten) {
  // Beside the problem's other tolerance keys (a template writes each
  // section once).
  auto at = d.keys.begin();
  for (auto k = d.keys.begin(); k != d.keys.end(); ++k) {
    if (k->name.rfind("tolerance.", 0) == 0) at = k + 1;
  }
  std::vector<Key> band;
  band.push_back(NumberKey(
      "tolerance.surface_distance_max", relative, 0, 1,
      "deviation band: every vertex (and face centroid, when `reference` is a surface of "
      "its own) stays within this fraction of the input's bounding-box diagonal from the "
      "reference surface (each vertex on a bounded manifold while solving; a round beyond "
      "it is never the output; docs/methods/design_band.md); 0 = none"));
  band.push_back(NumberKey("tolerance.surface_distance", 0, 0, kMaxCoordinate,
                           "the deviation band in file units; > 0 replaces "
                           "tolerance.surface_distance_max"));
  d.keys.insert(at, band.begin(), band.end());
  if (tighten) {
    // Beside the stall keys: what follows a run that stalls at the band.
    auto stall = d.keys.end();
    for (auto k = d.keys.begin(); k != d.keys.end(); ++k) {
      if (k->name.rfind("stall.", 0) == 0) stall = k + 1;
    }
    d.keys.insert(stall, IntegerKey(
        "stall.band_tightening", 16, 0, 100000,
        "rounds at most of band tightening after rounds that pressed against the deviation "
        "band (a round at 80% of it or more) and missed the goals, on a net near conjugate "
        "(the suitability check does not warn): the band opened until they "
        "hold, then closed towards it, to 0.8 of the deviation reached after each round that "
        "meets them; it ends after 4 rounds in a row short of them at a wider band "
        "(docs/methods/design_band.md); 0 = off"));
  }
  d.blocks.push_back({"surface_band", Site::kVertex, 1, FrameMap::kLength, false,
                      Carry::kReinitialise, false, true,
                      "the deviation band at the vertex (surface_band term)"});
  bool listed = false;  // a custom problem may list the term itself
  for (const TermUse& use : d.terms) listed = listed || use.term == "surface_band";
  if (!listed) d.terms.push_back({"surface_band", 1000, {}, "", true});
  Hook init = d.init;
  d.init = [init](HookContext& c) {
    const double band = CanonicalBand(c);
    for (VertexIndex v : c.store->mesh().vertices()) {
      c.store->At("surface_band", int(v.idx()))[0] = band;
    }
    if (init) init(c);
  };
  auto stages = d.stages;
  d.stages = [stages, tighten](const Settings& s) {
    std::vector<Stage> all = stages(s);
    const Tolerance t = BandTolerance(s);
    if (!(s.Number(t.key) > 0)) return all;
    for (Stage& stage : all) {
      stage.tolerances.push_back(t);
      if (!stage.terms.empty()) stage.terms.push_back("surface_band");
      stage.logged.push_back(t.measure);
    }
    const bool tightening =
        bool(tighten) && !all.empty() && s.Integer("stall.band_tightening") > 0;
    const Stage first = tightening ? all.front() : Stage();
    for (Stage& stage : all) {
      Hook after = stage.after_round;
      stage.after_round = [after, tightening](HookContext& c) {
        if (after) after(c);
        ClampToBand(c, CanonicalBand(c));
        if (tightening) RecordPressed(c);
      };
    }
    if (tightening) all.push_back(TighteningStage(first, tighten));
    return all;
  };
  Hook finish = d.finish;
  const std::string problem = measure_need ? d.name : std::string();
  d.finish = [finish, problem](HookContext& c) {
    if (finish) finish(c);
    Report(c, problem);
  };
  return d;
}

}  // namespace archgeo
