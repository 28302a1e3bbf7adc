#include "problems/spec.h"

#include <yaml-cpp/yaml.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

#include "mesh/input_error.h"

namespace archgeo {
namespace {

namespace fs = std::filesystem;

// Walks the YAML tree, turning every problem into an InputError that names
// the file and line, or "--set" for values that came from the command line.
class Reader {
 public:
  Reader(std::string file, std::set<std::string> overridden)
      : file_(std::move(file)), overridden_(std::move(overridden)) {}

  [[noreturn]] void Fail(const YAML::Node& node, const std::string& key,
                         const std::string& message) const {
    for (const std::string& o : overridden_) {
      if (key == o || key.rfind(o + ".", 0) == 0) throw InputError("--set", 0, key, message);
    }
    const int line = node.IsDefined() && node.Mark().line >= 0 ? node.Mark().line + 1 : 0;
    throw InputError(file_, line, key, message);
  }

  void CheckKeys(const YAML::Node& map, const std::string& path,
                 const std::set<std::string>& allowed) const {
    if (!map.IsMap()) Fail(map, path, "expected a mapping of keys");
    for (const auto& entry : map) {
      const std::string key = entry.first.as<std::string>();
      if (!allowed.count(key)) {
        std::string list;
        for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
        Fail(entry.first, Join(path, key), "unknown key (allowed: " + list + ")");
      }
    }
  }

  double Number(const YAML::Node& node, const std::string& key, double lo, double hi) const {
    double value = 0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value) || !(value == value)) {
      Fail(node, key, "expected a number, got " + Describe(node));
    }
    if (value < lo || value > hi) {
      std::ostringstream range;
      range << "must be in [" << lo << ", " << hi << "], got " << value;
      Fail(node, key, range.str());
    }
    return value;
  }

  int Integer(const YAML::Node& node, const std::string& key, int lo, int hi) const {
    int value = 0;
    if (!node.IsScalar() || !YAML::convert<int>::decode(node, value)) {
      Fail(node, key, "expected an integer, got " + Describe(node));
    }
    if (value < lo || value > hi) {
      Fail(node, key, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                          std::to_string(value));
    }
    return value;
  }

  bool Bool(const YAML::Node& node, const std::string& key) const {
    bool value = false;
    if (!node.IsScalar() || !YAML::convert<bool>::decode(node, value)) {
      Fail(node, key, "expected true or false, got " + Describe(node));
    }
    return value;
  }

  std::string String(const YAML::Node& node, const std::string& key,
                     const std::set<std::string>& choices = {}) const {
    if (!node.IsScalar()) Fail(node, key, "expected a string, got " + Describe(node));
    std::string value = node.Scalar();
    if (!choices.empty() && !choices.count(value)) {
      std::string list;
      for (const std::string& c : choices) list += (list.empty() ? "" : ", ") + c;
      Fail(node, key, "'" + value + "' is not one of: " + list);
    }
    return value;
  }

  // Paths in the file are relative to its folder; --set paths to the cwd.
  std::string Path(const YAML::Node& node, const std::string& key) const {
    const std::string value = String(node, key);
    if (value.empty()) Fail(node, key, "empty path");
    fs::path p(value);
    if (p.is_absolute()) return p.lexically_normal().string();
    if (overridden_.count(key)) return fs::absolute(p).lexically_normal().string();
    return (fs::path(file_).parent_path() / p).lexically_normal().string();
  }

  static std::string Join(const std::string& path, const std::string& key) {
    return path.empty() ? key : path + "." + key;
  }

 private:
  static std::string Describe(const YAML::Node& node) {
    if (node.IsScalar()) return "'" + node.Scalar() + "'";
    if (node.IsSequence()) return "a list";
    if (node.IsMap()) return "a mapping";
    return "nothing";
  }
  std::string file_;
  std::set<std::string> overridden_;
};

// Applies "dotted.key=value" to `root`, returning the dotted key.
std::string ApplyOverride(YAML::Node& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError("--set", 0, assignment, "expected KEY=VALUE (e.g. solver.threads=1)");
  }
  const std::string key = assignment.substr(0, eq);
  YAML::Node value;
  try {
    value = YAML::Load(assignment.substr(eq + 1));
  } catch (const YAML::Exception& e) {
    throw InputError("--set", 0, key, "value is not valid YAML: " + e.msg);
  }
  std::vector<std::string> parts;
  std::stringstream ss(key);
  for (std::string part; std::getline(ss, part, '.');) {
    if (part.empty()) throw InputError("--set", 0, key, "empty component in dotted key");
    parts.push_back(part);
  }
  YAML::Node node;
  node.reset(root);
  for (size_t i = 0; i + 1 < parts.size(); ++i) {
    YAML::Node child = node[parts[i]];
    if (!child.IsMap()) {
      if (child.IsDefined() && !child.IsNull()) {
        throw InputError("--set", 0, key, "'" + parts[i] + "' is not a mapping in the spec");
      }
      node[parts[i]] = YAML::Node(YAML::NodeType::Map);
      child = node[parts[i]];
    }
    node.reset(child);
  }
  node[parts.back()] = value;
  return key;
}

void ReadTerms(const Reader& r, const YAML::Node& terms, TermWeights& w) {
  r.CheckKeys(terms, "terms",
              {"pq_diagonal", "face_planarity", "fairness", "proximity", "boundary_proximity",
               "anchor"});
  const double kMax = 1e12;
  // Listing `terms` turns every unlisted term off.
  w = TermWeights{0, 0, 0, true, 0, 0, 0, 0};
  auto weight = [&](const char* name, double& out) {
    if (terms[name]) out = r.Number(terms[name], std::string("terms.") + name, 0, kMax);
  };
  weight("pq_diagonal", w.pq_diagonal);
  weight("face_planarity", w.face_planarity);
  weight("boundary_proximity", w.boundary_proximity);
  weight("anchor", w.anchor);
  if (const YAML::Node fair = terms["fairness"]) {
    if (fair.IsMap()) {
      r.CheckKeys(fair, "terms.fairness", {"weight", "relative_to_original"});
      if (fair["weight"]) w.fairness = r.Number(fair["weight"], "terms.fairness.weight", 0, kMax);
      if (fair["relative_to_original"]) {
        w.fairness_relative =
            r.Bool(fair["relative_to_original"], "terms.fairness.relative_to_original");
      }
    } else {
      w.fairness = r.Number(fair, "terms.fairness", 0, kMax);
    }
  }
  if (const YAML::Node prox = terms["proximity"]) {
    w.proximity_point = TermWeights{}.proximity_point;
    if (prox.IsMap()) {
      r.CheckKeys(prox, "terms.proximity", {"weight", "point_weight"});
      if (prox["weight"]) w.proximity = r.Number(prox["weight"], "terms.proximity.weight", 0, kMax);
      if (prox["point_weight"]) {
        w.proximity_point = r.Number(prox["point_weight"], "terms.proximity.point_weight", 0, kMax);
      }
    } else {
      w.proximity = r.Number(prox, "terms.proximity", 0, kMax);
    }
  }
}

void ReadSolver(const Reader& r, const YAML::Node& s, SolverSettings& out) {
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

void ReadFixed(const Reader& r, const YAML::Node& f, ProblemSpec& spec, bool overridden) {
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
  for (const std::string& o : overrides) {
    if (!root.IsMap()) break;  // reported below
    overridden.insert(ApplyOverride(root, o));
  }
  const Reader r(path, overridden);
  r.CheckKeys(root, "",
              {"mesh", "reference", "problem", "tolerance", "terms", "continuation", "fixed",
               "solver", "output"});

  ProblemSpec spec;
  spec.spec_path = path;
  if (!root["mesh"]) r.Fail(root, "mesh", "missing: the input mesh file (OBJ, OFF or PLY)");
  spec.mesh = r.Path(root["mesh"], "mesh");
  if (root["reference"]) spec.reference = r.Path(root["reference"], "reference");
  if (root["problem"]) spec.problem = r.String(root["problem"], "problem", {"planar_quads"});
  if (const YAML::Node t = root["tolerance"]) {
    r.CheckKeys(t, "tolerance", {"pq_normalized_max"});
    if (t["pq_normalized_max"]) {
      spec.pq_normalized_max =
          r.Number(t["pq_normalized_max"], "tolerance.pq_normalized_max", 0, 1);
    }
  }
  if (root["terms"]) ReadTerms(r, root["terms"], spec.terms);
  if (const YAML::Node c = root["continuation"]) {
    r.CheckKeys(c, "continuation", {"band", "factor"});
    if (c["band"]) spec.continuation_band = r.Number(c["band"], "continuation.band", 0, 1);
    if (c["factor"]) {
      spec.continuation_factor = r.Number(c["factor"], "continuation.factor", 1, 1e6);
    }
  }
  if (root["fixed"]) ReadFixed(r, root["fixed"], spec, overridden.count("fixed") > 0);
  if (root["solver"]) ReadSolver(r, root["solver"], spec.solver);
  if (const YAML::Node o = root["output"]) {
    r.CheckKeys(o, "output", {"mesh", "report", "color_max", "ascii_ply"});
    // An empty value (`mesh:` or --set output.mesh=) writes no file.
    if (o["mesh"] && !o["mesh"].IsNull()) spec.output_mesh = r.Path(o["mesh"], "output.mesh");
    if (o["report"] && !o["report"].IsNull()) {
      spec.output_report = r.Path(o["report"], "output.report");
    }
    if (o["color_max"]) spec.color_max = r.Number(o["color_max"], "output.color_max", 1e-12, 1);
    if (o["ascii_ply"]) spec.ascii_ply = r.Bool(o["ascii_ply"], "output.ascii_ply");
  }
  return spec;
}

}  // namespace archgeo
