// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/spec/spec.h"

#include <sys/stat.h>
#include <yaml-cpp/yaml.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "core/closest_name.h"
#include "core/solver_options.h"
#include "energies/registry.h"
#include "core/input_error.h"
#include "io/input_file.h"
#include "problems/declarations/custom.h"
#include "problems/declarations/registry.h"
#include "problems/spec/schema.h"

namespace archgeo {
namespace {

namespace fs = std::filesystem;

// Keys of earlier archgeo versions, for a helpful message.
const std::map<std::string, std::string>& Renamed() {
  static const std::map<std::string, std::string> renamed = {
      {"solver.linear_solver", "solver.linear_solver_type"},
      {"solver.sparse_library", "solver.sparse_linear_algebra_library_type"},
      {"solver.trust_region", "solver.trust_region_strategy_type"},
      {"solver.preconditioner", "solver.preconditioner_type"},
      {"solver.max_iterations", "solver.max_num_iterations"},
      {"solver.threads", "solver.num_threads"},
      {"solver.outer_iterations", "schedule.outer_iterations"},
      {"terms.target", "terms.total_absolute_curvature"},
      {"terms.regularizer", "terms.step"},
      {"terms.strip", "terms.principal_strip"},
      {"terms.saddle", "terms.saddle_sign"},
      {"irls.epsilon", "terms.total_absolute_curvature.epsilon"},
      {"boundary.weight", "terms.tangent_plane.weight"},
      {"terms.fairness.order", "terms.fairness.on (polyline_quadruples for third differences)"},
  };
  return renamed;
}

std::string Describe(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

// Structured values are read this many levels below their key (the deepest
// form, handles, reads three): a list or mapping deeper than that keeps its
// kind and line, not its contents (an alias can make the YAML graph cyclic,
// and each level read multiplies what a list of aliases repeats).
constexpr int kCustomDepth = 4;
// At most this many nodes per structured value: more than a 1 MiB spec holds
// without aliases, which can repeat a subtree exponentially often.
constexpr size_t kCustomNodes = size_t{1} << 20;

void ReadScalar(const YAML::Node& node, CustomValue& out) {
  out.kind = CustomValue::Kind::kScalar;
  out.text = node.Scalar();
  double number = 0;
  if (YAML::convert<double>::decode(node, number)) out.number = number;
  long long integer = 0;
  if (YAML::convert<long long>::decode(node, integer)) out.integer = integer;
  bool boolean = false;
  if (YAML::convert<bool>::decode(node, boolean)) out.boolean = boolean;
}

// Reads `node` at `depth` into `out`, taking one from `budget` per node;
// false when the budget is spent.
bool ReadCustomNode(const YAML::Node& node, int depth, size_t& budget, CustomValue& out) {
  if (budget == 0) return false;
  --budget;
  out.line = node.Mark().line >= 0 ? node.Mark().line + 1 : 0;
  if (node.IsScalar()) {
    ReadScalar(node, out);
  } else if (node.IsSequence()) {
    out.kind = CustomValue::Kind::kList;
    for (const YAML::Node& item : node) {
      if (depth >= kCustomDepth) break;
      if (!ReadCustomNode(item, depth + 1, budget, out.items.emplace_back())) return false;
    }
  } else if (node.IsMap()) {
    out.kind = CustomValue::Kind::kMap;
    for (const auto& entry : node) {
      if (depth >= kCustomDepth) break;
      CustomValue::Entry& e = out.entries.emplace_back();
      if (!ReadCustomNode(entry.first, depth + 1, budget, e.key) ||
          !ReadCustomNode(entry.second, depth + 1, budget, e.value)) {
        return false;
      }
    }
  }
  return true;
}

// The structured value `node` of `key`, given at `where`.
CustomValue ReadCustom(const YAML::Node& node, const Origin& where, const std::string& key) {
  CustomValue value;
  size_t budget = kCustomNodes;
  if (!ReadCustomNode(node, 0, budget, value)) {
    throw InputError(where.file, where.line, key,
                     "more than " + std::to_string(kCustomNodes) +
                         " values once its aliases are expanded: too large");
  }
  return value;
}

std::string List(const std::vector<std::string>& items) {
  std::string list;
  for (const std::string& a : items) list += (list.empty() ? "" : ", ") + a;
  return list;
}

class Reader {
 public:
  Reader(std::string file, std::set<std::string> overridden, const Schema& schema)
      : file_(std::move(file)), overridden_(std::move(overridden)), schema_(schema) {}

  bool Overridden(const std::string& key) const {
    for (const std::string& o : overridden_) {
      if (key == o || key.rfind(o + ".", 0) == 0 || o.rfind(key + ".", 0) == 0) return true;
    }
    return false;
  }

  Origin Where(const YAML::Node& node, const std::string& key) const {
    if (Overridden(key)) return {"--set", 0};
    return {file_, node.IsDefined() && node.Mark().line >= 0 ? node.Mark().line + 1 : 0};
  }

  [[noreturn]] void Fail(const YAML::Node& node, const std::string& key,
                         const std::string& message) const {
    const Origin o = Where(node, key);
    throw InputError(o.file, o.line, key, message);
  }

  // Walks a mapping: every key must be declared (or a section of declared
  // keys); duplicate and non-scalar keys are errors.
  void Walk(const YAML::Node& map, const std::string& prefix, Settings& out) const {
    if (!map.IsMap()) Fail(map, prefix, "expected a mapping of keys, got " + Describe(map));
    std::set<std::string> seen;
    for (const auto& entry : map) {
      if (!entry.first.IsScalar()) {
        Fail(entry.first, prefix, "a key must be a plain name, got " + Describe(entry.first));
      }
      const std::string name = entry.first.Scalar();
      const std::string key = prefix.empty() ? name : prefix + "." + name;
      if (!seen.insert(name).second) Fail(entry.first, key, "duplicate key");
      const YAML::Node& value = entry.second;
      if (const Key* k = schema_.Find(key)) {
        Set(*k, value, out);
      } else if (schema_.IsSection(key) && value.IsMap()) {
        Walk(value, key, out);
      } else if (prefix == "terms" && schema_.Find(key + ".weight") && !value.IsMap()) {
        // `terms.<t>: w` is the weight; messages name `terms.<t>`.
        Key weight = *schema_.Find(key + ".weight");
        weight.name = key;
        out.Set(key + ".weight", Parse(weight, value), Where(value, key));
      } else if (schema_.IsSection(key) && value.IsNull() && prefix.empty()) {
        // An empty section (e.g. `output:`) sets nothing.
      } else {
        const auto renamed = Renamed().find(key);
        std::string message = "unknown key";
        if (renamed != Renamed().end()) {
          message += " (renamed: use " + renamed->second + ")";
        } else if (schema_.IsSection(key)) {
          message = "expected a mapping of keys (" + List(schema_.Children(key)) + "), got " +
                    Describe(value);
        } else {
          const std::vector<std::string> allowed = schema_.Children(prefix);
          const std::string meant = ClosestName(name, allowed);
          if (!meant.empty()) message += "; did you mean '" + meant + "'?";
          message += " (allowed here: " + List(allowed) + ")";
        }
        Fail(entry.first, key, message);
      }
    }
  }

  void Set(const Key& k, const YAML::Node& node, Settings& out) const {
    out.Set(k.name, Parse(k, node), Where(node, k.name));
    if (k.type == Type::kCustom) {
      out.SetCustom(k.name, ReadCustom(node, Where(node, k.name), k.name), Where(node, k.name));
    }
  }

 private:
  double Number(const Key& k, const YAML::Node& node) const {
    double value = 0;
    if (!node.IsScalar() || !YAML::convert<double>::decode(node, value)) {
      Fail(node, k.name, "expected a number, got " + Describe(node));
    }
    if (!std::isfinite(value)) Fail(node, k.name, "expected a finite number, got " + Describe(node));
    // A value written non-zero that reads as 0 (1e-400) would turn a bound
    // "off" without a word.
    const std::string text = node.Scalar();
    const std::string mantissa = text.substr(0, text.find_first_of("eE"));
    if (value == 0 && mantissa.find_first_of("123456789") != std::string::npos) {
      Fail(node, k.name, "'" + text + "' underflows to 0 in double precision (the smallest is "
                         "about 2.2e-308)");
    }
    if (value < k.lo || value > k.hi) {
      std::ostringstream range;
      range << "must be in [" << k.lo << ", " << k.hi << "], got " << value;
      Fail(node, k.name, range.str());
    }
    return value;
  }

  long long Integer(const Key& k, const YAML::Node& node) const {
    long long value = 0;
    if (!node.IsScalar() || !YAML::convert<long long>::decode(node, value)) {
      Fail(node, k.name, "expected an integer, got " + Describe(node));
    }
    if (double(value) < k.lo || double(value) > k.hi) {
      std::ostringstream range;
      range.precision(15);
      range << "must be in [" << k.lo << ", " << k.hi << "], got " << value;
      Fail(node, k.name, range.str());
    }
    return value;
  }

  std::string Choice(const Key& k, const YAML::Node& node) const {
    if (!node.IsScalar()) Fail(node, k.name, "expected one of: " + List(k.choices));
    const std::string value = node.Scalar();
    for (const std::string& c : k.choices) {
      if (c == value) return value;
    }
    const std::string meant = ClosestName(value, k.choices);
    Fail(node, k.name, "'" + value + "' is not one of: " + List(k.choices) +
                           (meant.empty() ? "" : "; did you mean '" + meant + "'?"));
  }

  std::string Path(const Key& k, const YAML::Node& node) const {
    // `mesh:` writes nothing; an optional input file left empty (`--set
    // field.constraints=`, dropping one an example gives) is not read.
    if (node.IsNull() && (k.type == Type::kOutputPath || (k.name != "mesh" && !k.required))) {
      return "";
    }
    if (!node.IsScalar()) Fail(node, k.name, "expected a file path, got " + Describe(node));
    const std::string value = node.Scalar();
    if (value.empty()) {
      if (k.name != "mesh") return "";  // an optional file not given
      Fail(node, k.name, "empty path");
    }
    fs::path p(value);
    if (p.is_absolute()) return p.lexically_normal().string();
    if (Overridden(k.name)) return fs::absolute(p).lexically_normal().string();
    return (fs::path(file_).parent_path() / p).lexically_normal().string();
  }

  Value Parse(const Key& k, const YAML::Node& node) const {
    switch (k.type) {
      case Type::kBool: {
        bool value = false;
        if (!node.IsScalar() || !YAML::convert<bool>::decode(node, value)) {
          Fail(node, k.name, "expected true or false, got " + Describe(node));
        }
        return value;
      }
      case Type::kInteger:
        return Integer(k, node);
      case Type::kNumber:
        return Number(k, node);
      case Type::kChoice:
        return Choice(k, node);
      case Type::kString:
        if (!node.IsScalar()) Fail(node, k.name, "expected a string, got " + Describe(node));
        return node.Scalar();
      case Type::kInputPath:
      case Type::kOutputPath:
        return Path(k, node);
      case Type::kNumbers:
      case Type::kIntegers: {
        if (!node.IsSequence()) Fail(node, k.name, "expected a list, got " + Describe(node));
        if (k.size > 0 && int(node.size()) != k.size) {
          Fail(node, k.name, "expected a list of " + std::to_string(k.size) + " values");
        }
        if (k.type == Type::kNumbers) {
          std::vector<double> values;
          for (const YAML::Node& n : node) values.push_back(Number(k, n));
          return values;
        }
        std::vector<long long> values;
        for (const YAML::Node& n : node) values.push_back(Integer(k, n));
        return values;
      }
      case Type::kChoiceOrIntegers: {
        if (node.IsSequence()) {
          std::vector<long long> values;
          for (const YAML::Node& n : node) values.push_back(Integer(k, n));
          return values;
        }
        if (!node.IsScalar()) {
          Fail(node, k.name, "expected one of " + List(k.choices) + " or a list of indices");
        }
        return Choice(k, node);
      }
      case Type::kCustom:
        return std::string("(given)");
    }
    return std::monostate{};
  }

  std::string file_;
  std::set<std::string> overridden_;
  const Schema& schema_;
};

// Applies "dotted.key=value" (value parsed as YAML) to `root`; returns the
// dotted key.
std::string ApplyOverride(YAML::Node& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InputError("--set", 0, assignment,
                     "expected KEY=VALUE (e.g. solver.num_threads=1)");
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
    if (i == 1 && parts[0] == "terms" && child.IsScalar()) {
      // `terms.X: w` is short for `terms.X: {weight: w}`: an option of X
      // set from the command line keeps the spec's weight.
      YAML::Node expanded(YAML::NodeType::Map);
      expanded["weight"] = YAML::Clone(child);
      node[parts[i]] = expanded;
      child = node[parts[i]];
    }
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

YAML::Node ParseYaml(const std::string& text, const std::string& path) {
  try {
    YAML::Node root = YAML::Load(text);
    if (root.IsNull()) root = YAML::Node(YAML::NodeType::Map);
    return root;
  } catch (const YAML::ParserException& e) {
    throw InputError(path, e.mark.line >= 0 ? e.mark.line + 1 : 0, "", "malformed YAML: " + e.msg);
  } catch (const YAML::Exception& e) {
    throw InputError(path, 0, "", "malformed YAML: " + e.msg);
  }
}

YAML::Node Load(const std::string& path) {
  // Regular files only (a FIFO or device would block or never end), at most 1 MiB.
  return ParseYaml(ReadInputFile(path, "", std::uint64_t{1} << 20, ""), path);
}

}  // namespace

std::vector<std::string> ProblemSpec::InputFiles() const {
  std::vector<std::string> files;
  for (const Key& k : settings.schema().keys()) {
    if (k.type == Type::kInputPath && !settings.String(k.name).empty()) {
      files.push_back(settings.String(k.name));
    }
  }
  return files;
}

namespace {

// The custom problem of the spec `root`, from its `terms:` section.
ProblemDecl CustomOf(const YAML::Node& root, const std::string& path,
                     const std::set<std::string>& overridden) {
  const std::string file = overridden.count("terms") ? "--set" : path;
  const YAML::Node terms = root["terms"];
  if (!terms) return CustomProblem(nullptr, file);
  const CustomValue value =
      ReadCustom(terms, {file, terms.Mark().line >= 0 ? terms.Mark().line + 1 : 0}, "terms");
  return CustomProblem(&value, file);
}

ProblemSpec Parse(YAML::Node root, const std::string& path,
                  const std::vector<std::string>& overrides, bool require_mesh) {
  if (!root.IsMap()) throw InputError(path, 1, "", "expected a mapping of keys");
  std::set<std::string> overridden;
  const bool file_lists_terms = root["terms"].IsDefined();
  for (const std::string& o : overrides) {
    const std::string key = ApplyOverride(root, o);
    // Listing `terms` turns the unlisted terms off: a --set that creates the
    // section would silently switch off every default term.
    if (!file_lists_terms && key.rfind("terms.", 0) == 0) {
      throw InputError("--set", 0, key,
                       "the spec has no 'terms:' section, so this would turn every other term "
                       "off; list the terms you want in the spec (`archgeo spec PROBLEM` shows "
                       "them with their defaults) and override them there");
    }
    overridden.insert(key);
  }

  // The problem decides the schema.
  std::string problem = "planar_quads";
  if (const YAML::Node p = root["problem"]) {
    const std::vector<std::string> names = ProblemNames();
    const Origin where = overridden.count("problem") ? Origin{"--set", 0}
                                                     : Origin{path, p.Mark().line + 1};
    if (!p.IsScalar() || std::find(names.begin(), names.end(), p.Scalar()) == names.end()) {
      throw InputError(where.file, where.line, "problem",
                       Describe(p) + " is not one of: " + List(names));
    }
    problem = p.Scalar();
  }
  ProblemSpec spec;
  spec.spec_path = path;
  if (problem == "custom") {
    spec.declaration = std::make_shared<const ProblemDecl>(CustomOf(root, path, overridden));
  } else {
    spec.declaration = std::shared_ptr<const ProblemDecl>(FindProblem(problem), [](auto*) {});
  }
  const Schema schema = ProblemSchema(*spec.declaration);
  spec.settings = Settings(schema);
  spec.settings.set_spec_file(path);
  const Reader reader(path, overridden, schema);
  reader.Walk(root, "", spec.settings);

  if (require_mesh && !spec.declaration->makes_input && !spec.settings.Given("mesh")) {
    throw InputError(path, 0, "mesh", "missing: the input mesh file (OBJ, OFF or PLY)");
  }
  // Listing `terms` turns every unlisted term of the problem off.
  if (file_lists_terms && problem != "custom") {
    const YAML::Node terms = root["terms"];
    const Origin where{path, terms.Mark().line + 1};
    for (const TermUse& use : spec.declaration->terms) {
      if (!use.implicit && (!terms.IsMap() || !terms[use.term])) {
        spec.settings.Set("terms." + use.term + ".weight", 0.0, where);
      }
    }
  }
  // The problem's checks across keys (e.g. which of two alternatives is given),
  // and a solver combination Ceres would reject only at run time.
  if (spec.declaration->check) spec.declaration->check(spec.settings);
  SolverOptions(spec.settings);
  return spec;
}

}  // namespace

namespace {

// yaml-cpp throws its own exceptions for structures the reader does not
// expect (e.g. a lookup in a mapping whose keys are not scalars): those are
// input errors too.
ProblemSpec Guarded(const std::function<ProblemSpec()>& read, const std::string& path) {
  try {
    return read();
  } catch (const YAML::Exception& e) {
    throw InputError(path, e.mark.line >= 0 ? e.mark.line + 1 : 0, "",
                     "unexpected YAML structure: " + e.msg);
  }
}

}  // namespace

ProblemSpec ReadSpec(const std::string& path, const std::vector<std::string>& overrides) {
  return Guarded([&] { return Parse(Load(path), path, overrides, true); }, path);
}

ProblemSpec ParseSpec(const std::string& yaml, const std::string& path,
                      const std::vector<std::string>& overrides) {
  return Guarded([&] { return Parse(ParseYaml(yaml, path), path, overrides, false); }, path);
}

}  // namespace archgeo
