#include "problems/custom.h"

#include <algorithm>

#include "energies/registry.h"
#include "mesh/elements.h"
#include "mesh/input_error.h"
#include "problems/model.h"

namespace archgeo {

ProblemDecl CustomProblem(const YAML::Node& root, const std::string& path,
                          const std::set<std::string>& overridden) {
  ProblemDecl d;
  d.name = "custom";
  d.summary = "the spec's own composition of registered terms";
  d.paper = "(see each term's paper)";
  const YAML::Node terms = root["terms"];
  const int line = terms && terms.Mark().line >= 0 ? terms.Mark().line + 1 : 0;
  const std::string file = overridden.count("terms") ? "--set" : path;
  if (!terms || !terms.IsMap() || terms.size() == 0) {
    throw InputError(file, line, "terms",
                     "problem: custom needs a mapping `terms:` of registered terms and weights");
  }
  std::vector<std::string> known;
  for (const TermSpec* t : RegisteredTerms()) known.push_back(t->name);
  std::vector<std::string> driven;
  for (const auto& entry : terms) {
    const std::string name = entry.first.IsScalar() ? entry.first.Scalar() : "";
    const int at = entry.first.Mark().line >= 0 ? entry.first.Mark().line + 1 : line;
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
  d.keys.push_back(NumberKey("continuation.band", 0, 0, 1,
                             "a pq_diagonal/face_planarity residual within band × tolerance "
                             "costs nothing"));
  bool smooth = false;
  for (const TermUse& u : d.terms) {
    smooth = smooth || u.term == "dihedral_energy" || u.term == "total_absolute_curvature";
  }
  d.analyses = {"planarity"};
  if (smooth) d.analyses.insert("smoothness");
  d.stages = [driven, smooth, d](const Settings&) {
    Stage s;
    s.name = "custom";
    s.rounds_key = "schedule.outer_iterations";
    for (const std::string& m : driven) {
      s.tolerances.push_back({m, "tolerance." + m, m == "pq_normalized_max"});
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
  return d;
}

}  // namespace archgeo
