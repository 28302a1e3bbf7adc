// The planar_quads builder's spec keys and its adapter to the generic run
// (problems/builder.h); the optimisation is SolvePlanarQuads
// (problems/planar_quads.h, which documents the keys).
#include <cstdio>

#include "mesh/input_error.h"
#include "mesh/metrics.h"
#include "problems/builders.h"
#include "problems/planar_quads.h"

namespace archgeo {
namespace {

class PlanarQuadsBuilder : public Builder {
 public:
  std::set<std::string> Keys() const override { return {"tolerance", "terms", "continuation"}; }

  void Read(const SpecReader& r, const YAML::Node& root) override {
    if (const YAML::Node t = root["tolerance"]) {
      r.CheckKeys(t, "tolerance", {"pq_normalized_max"});
      if (t["pq_normalized_max"]) {
        s_.tolerance = r.Number(t["pq_normalized_max"], "tolerance.pq_normalized_max", 0, 1);
      }
    }
    if (root["terms"]) ReadTerms(r, root["terms"]);
    if (const YAML::Node c = root["continuation"]) {
      r.CheckKeys(c, "continuation", {"band", "factor"});
      if (c["band"]) s_.continuation_band = r.Number(c["band"], "continuation.band", 0, 1);
      if (c["factor"]) {
        s_.continuation_factor = r.Number(c["factor"], "continuation.factor", 1, 1e6);
      }
    }
  }

  nlohmann::json SettingsJson() const override {
    const TermWeights& w = s_.terms;
    return {{"terms",
             {{"pq_diagonal", w.pq_diagonal},
              {"face_planarity", w.face_planarity},
              {"fairness", {{"weight", w.fairness}, {"relative_to_original", w.fairness_relative}}},
              {"proximity", {{"weight", w.proximity}, {"point_weight", w.proximity_point}}},
              {"boundary_proximity", w.boundary_proximity},
              {"anchor", w.anchor}}},
            {"tolerance", {{"pq_normalized_max", s_.tolerance}}},
            {"continuation", {{"band", s_.continuation_band}, {"factor", s_.continuation_factor}}}};
  }

  void CheckInput(const Mesh& input, const std::string& path) const override {
    for (FaceIndex f : input.faces()) {
      if (input.degree(f) >= 4) return;
    }
    throw InputError(path, 0, "mesh",
                     "planar_quads needs quads (or larger polygons); this mesh has only "
                     "triangles");
  }

  SolveOutcome Solve(Mesh& mesh, const SolveContext& context) const override {
    PlanarQuadsSettings settings = s_;
    settings.fixed = context.fixed;
    settings.solver = context.solver;
    const PlanarQuadsResult r =
        SolvePlanarQuads(mesh, *context.reference, settings, context.progress);
    SolveOutcome out = r;
    out.details["tolerance"] = {{"pq_normalized_max", s_.tolerance}, {"met", r.tolerance_met}};
    nlohmann::json log = nlohmann::json::array();
    for (const OuterIterationLog& l : r.log) {
      log.push_back({{"outer", l.outer}, {"iterations", l.inner_iterations}, {"cost", l.cost},
                     {"pq_normalized_max", l.pq_normalized_max},
                     {"faces_above_tolerance", l.faces_above_tolerance},
                     {"weight_max", l.weight_max}, {"max_move_mean_edges", l.max_move},
                     {"seconds", l.seconds}});
    }
    out.details["outer_log"] = log;
    char line[256];
    std::snprintf(line, sizeof line, "tolerance δ_PQ,n max <= %g: %s\n", s_.tolerance,
                  s_.tolerance <= 0 ? "off"
                  : r.tolerance_met ? "met"
                                    : "NOT met within solver.outer_iterations rounds (weaker "
                                      "anchor/proximity pulls let it move more)");
    out.headline = line;
    return out;
  }

 private:
  void ReadTerms(const SpecReader& r, const YAML::Node& terms) {
    r.CheckKeys(terms, "terms",
                {"pq_diagonal", "face_planarity", "fairness", "proximity", "boundary_proximity",
                 "anchor"});
    // Listing `terms` turns every unlisted term off.
    TermWeights& w = s_.terms;
    w = TermWeights{0, 0, 0, true, 0, 0, 0, 0};
    auto weight = [&](const char* name, double& out) {
      if (terms[name]) r.Weight(terms[name], std::string("terms.") + name, &out);
    };
    weight("pq_diagonal", w.pq_diagonal);
    weight("face_planarity", w.face_planarity);
    weight("boundary_proximity", w.boundary_proximity);
    weight("anchor", w.anchor);
    if (const YAML::Node fair = terms["fairness"]) {
      r.FairnessTerm(fair, &w.fairness, &w.fairness_relative);
    }
    if (const YAML::Node prox = terms["proximity"]) {
      w.proximity_point = TermWeights{}.proximity_point;
      r.ProximityTerm(prox, &w.proximity, &w.proximity_point);
    }
  }

  PlanarQuadsSettings s_;
};

}  // namespace

std::unique_ptr<Builder> MakePlanarQuadsBuilder() { return std::make_unique<PlanarQuadsBuilder>(); }

}  // namespace archgeo
