#include "problems/spec.h"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <limits>
#include <set>

#include "mesh/input_error.h"
#include "problems/builders.h"
#include "problems/spec_reader.h"

namespace archgeo {
namespace {

void ReadSolver(const SpecReader& r, const YAML::Node& s, SolverSettings& out) {
  r.CheckKeys(s, "solver",
              {"linear_solver", "sparse_library", "trust_region", "preconditioner",
               "max_iterations", "outer_iterations", "function_tolerance", "gradient_tolerance",
               "parameter_tolerance", "threads"});
  for (auto [key, field] : {std::pair{"linear_solver", &out.linear_solver},
                             std::pair{"sparse_library", &out.sparse_library},
                             std::pair{"trust_region", &out.trust_region},
                             std::pair{"preconditioner", &out.preconditioner}}) {
    if (s[key]) {
      const std::vector<std::string> choices = SolverChoices(key);
      *field = r.String(s[key], std::string("solver.") + key, {choices.begin(), choices.end()});
    }
  }
  if (s["max_iterations"]) {
    out.max_iterations = r.Integer(s["max_iterations"], "solver.max_iterations", 1, 100000);
  }
  if (s["outer_iterations"]) {
    out.outer_iterations = r.Integer(s["outer_iterations"], "solver.outer_iterations", 1, 1000);
  }
  if (s["function_tolerance"]) {
    out.function_tolerance = r.Number(s["function_tolerance"], "solver.function_tolerance", 0, 1);
  }
  if (s["gradient_tolerance"]) {
    out.gradient_tolerance = r.Number(s["gradient_tolerance"], "solver.gradient_tolerance", 0, 1);
  }
  if (s["parameter_tolerance"]) {
    out.parameter_tolerance =
        r.Number(s["parameter_tolerance"], "solver.parameter_tolerance", 0, 1);
  }
  if (s["threads"]) out.threads = r.Integer(s["threads"], "solver.threads", 1, 256);
}

void ReadFixed(const SpecReader& r, const YAML::Node& f, ProblemSpec& spec, bool overridden) {
  spec.fixed_file = overridden ? "--set" : spec.spec_path;
  spec.fixed_line = overridden || f.Mark().line < 0 ? 0 : f.Mark().line + 1;
  if (f.IsSequence()) {
    spec.fixed = "ids";
    for (size_t i = 0; i < f.size(); ++i) {
      spec.fixed_ids.push_back(
          r.Integer(f[i], "fixed[" + std::to_string(i) + "]", 0, std::numeric_limits<int>::max()));
    }
  } else {
    spec.fixed = r.String(f, "fixed", {"none", "corners", "boundary"});
  }
}

void ReadOutput(const SpecReader& r, const YAML::Node& o, const Builder& builder,
                ProblemSpec& spec) {
  std::set<std::string> keys = {"mesh", "report", "color_max", "ascii_ply"};
  for (const std::string& k : builder.OutputKeys()) keys.insert(k);
  r.CheckKeys(o, "output", keys);
  // An empty value (`mesh:` or --set output.mesh=) writes no file.
  auto path = [&](const std::string& key) {
    const YAML::Node n = o[key];
    return n && !n.IsNull() ? r.Path(n, "output." + key) : std::string();
  };
  spec.output_mesh = path("mesh");
  spec.output_report = path("report");
  for (const std::string& k : builder.OutputKeys()) {
    const std::string p = path(k);
    if (!p.empty()) spec.extra_outputs[k] = p;
  }
  if (o["color_max"]) spec.color_max = r.Number(o["color_max"], "output.color_max", 1e-12, 1e12);
  if (o["ascii_ply"]) spec.ascii_ply = r.Bool(o["ascii_ply"], "output.ascii_ply");
}

}  // namespace

ProblemSpec ReadSpec(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "", "cannot open the problem spec");
  YAML::Node root;
  try {
    root = YAML::Load(in);
  } catch (const YAML::ParserException& e) {
    throw InputError(path, e.mark.line >= 0 ? e.mark.line + 1 : 0, "", "malformed YAML: " + e.msg);
  }
  if (root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
  std::set<std::string> overridden;
  const bool file_lists_terms = root.IsMap() && root["terms"].IsDefined();
  for (const std::string& o : overrides) {
    if (!root.IsMap()) break;  // reported below
    const std::string key = ApplyOverride(root, o);
    // Listing `terms` turns the unlisted terms off: a --set that creates the
    // section would silently switch off every default term.
    if (!file_lists_terms && key.rfind("terms.", 0) == 0) {
      throw InputError("--set", 0, key,
                       "the spec has no 'terms:' section, so this would turn every other term "
                       "off; list the terms you want in the spec (its builder's header shows "
                       "the defaults) and override them there");
    }
    overridden.insert(key);
  }
  const SpecReader r(path, overridden);
  if (!root.IsMap()) r.Fail(root, "", "expected a mapping of keys");

  ProblemSpec spec;
  spec.spec_path = path;
  if (root["problem"]) {
    const std::vector<std::string> names = BuilderNames();
    spec.problem = r.String(root["problem"], "problem", {names.begin(), names.end()});
  }
  std::unique_ptr<Builder> builder = MakeBuilder(spec.problem);
  std::set<std::string> keys = {"mesh",   "reference", "problem", "fixed",
                                "solver", "output",    "multiresolution"};
  for (const std::string& k : builder->Keys()) keys.insert(k);
  r.CheckKeys(root, "", keys);

  if (!root["mesh"]) r.Fail(root, "mesh", "missing: the input mesh file (OBJ, OFF or PLY)");
  spec.mesh = r.Path(root["mesh"], "mesh");
  if (root["reference"]) spec.reference = r.Path(root["reference"], "reference");
  builder->Read(r, root);
  if (root["fixed"]) ReadFixed(r, root["fixed"], spec, overridden.count("fixed") > 0);
  if (root["solver"]) ReadSolver(r, root["solver"], spec.solver);
  if (const YAML::Node m = root["multiresolution"]) {
    r.CheckKeys(m, "multiresolution", {"levels", "scheme"});
    if (m["levels"]) {
      spec.multiresolution_levels = r.Integer(m["levels"], "multiresolution.levels", 0, 6);
    }
    if (m["scheme"]) {
      spec.multiresolution_scheme = r.String(m["scheme"], "multiresolution.scheme",
                                             {"loop", "sqrt3", "catmull_clark", "doo_sabin"});
    }
  }
  if (root["output"]) ReadOutput(r, root["output"], *builder, spec);
  spec.builder = std::move(builder);
  return spec;
}

}  // namespace archgeo
