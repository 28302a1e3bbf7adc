#include "problems/spec_reader.h"

#include <filesystem>
#include <sstream>

#include "mesh/input_error.h"

namespace archgeo {
namespace {

namespace fs = std::filesystem;

std::string Describe(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

std::string List(const std::set<std::string>& items) {
  std::string list;
  for (const std::string& a : items) list += (list.empty() ? "" : ", ") + a;
  return list;
}

}  // namespace

SpecReader::SpecReader(std::string file, std::set<std::string> overridden)
    : file_(std::move(file)), overridden_(std::move(overridden)) {}

void SpecReader::Fail(const YAML::Node& node, const std::string& key,
                      const std::string& message) const {
  for (const std::string& o : overridden_) {
    if (key == o || key.rfind(o + ".", 0) == 0) throw InputError("--set", 0, key, message);
  }
  const int line = node.IsDefined() && node.Mark().line >= 0 ? node.Mark().line + 1 : 0;
  throw InputError(file_, line, key, message);
}

void SpecReader::CheckKeys(const YAML::Node& map, const std::string& path,
                           const std::set<std::string>& allowed) const {
  if (!map.IsMap()) Fail(map, path, "expected a mapping of keys");
  for (const auto& entry : map) {
    const std::string key = entry.first.as<std::string>();
    if (!allowed.count(key)) {
      Fail(entry.first, Join(path, key), "unknown key (allowed: " + List(allowed) + ")");
    }
  }
}

double SpecReader::Number(const YAML::Node& node, const std::string& key, double lo,
                          double hi) const {
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

int SpecReader::Integer(const YAML::Node& node, const std::string& key, int lo, int hi) const {
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

bool SpecReader::Bool(const YAML::Node& node, const std::string& key) const {
  bool value = false;
  if (!node.IsScalar() || !YAML::convert<bool>::decode(node, value)) {
    Fail(node, key, "expected true or false, got " + Describe(node));
  }
  return value;
}

std::string SpecReader::String(const YAML::Node& node, const std::string& key,
                               const std::set<std::string>& choices) const {
  if (!node.IsScalar()) Fail(node, key, "expected a string, got " + Describe(node));
  std::string value = node.Scalar();
  if (!choices.empty() && !choices.count(value)) {
    Fail(node, key, "'" + value + "' is not one of: " + List(choices));
  }
  return value;
}

std::string SpecReader::Path(const YAML::Node& node, const std::string& key) const {
  const std::string value = String(node, key);
  if (value.empty()) Fail(node, key, "empty path");
  fs::path p(value);
  if (p.is_absolute()) return p.lexically_normal().string();
  if (overridden_.count(key)) return fs::absolute(p).lexically_normal().string();
  return (fs::path(file_).parent_path() / p).lexically_normal().string();
}

YAML::Node SpecReader::Weight(const YAML::Node& node, const std::string& key, double* weight,
                              const std::set<std::string>& extra) const {
  constexpr double kMaxWeight = 1e12;
  if (!node.IsMap()) {
    *weight = Number(node, key, 0, kMaxWeight);
    return YAML::Node(YAML::NodeType::Undefined);
  }
  std::set<std::string> allowed = extra;
  allowed.insert("weight");
  CheckKeys(node, key, allowed);
  if (node["weight"]) *weight = Number(node["weight"], key + ".weight", 0, kMaxWeight);
  return node;
}

void SpecReader::ProximityTerm(const YAML::Node& node, double* weight,
                               double* point_weight) const {
  const YAML::Node extra = Weight(node, "terms.proximity", weight, {"point_weight"});
  if (extra && extra["point_weight"]) {
    *point_weight = Number(extra["point_weight"], "terms.proximity.point_weight", 0, 1e12);
  }
}

YAML::Node SpecReader::FairnessTerm(const YAML::Node& node, double* weight, bool* relative,
                                    const std::set<std::string>& extra) const {
  std::set<std::string> keys = extra;
  keys.insert("relative_to_original");
  const YAML::Node map = Weight(node, "terms.fairness", weight, keys);
  if (map && map["relative_to_original"]) {
    *relative = Bool(map["relative_to_original"], "terms.fairness.relative_to_original");
  }
  return map;
}

std::string SpecReader::Join(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

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

}  // namespace archgeo
