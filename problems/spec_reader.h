// archgeo — reading YAML problem specs with errors that name file, line and key.
//
// Every builder reads its own keys through a SpecReader, so every problem
// reports bad input the same way: "spec.yaml:7: key 'terms.fairness':
// expected a number, got 'high'" (or "--set" for a value that came from the
// command line).
#pragma once

#include <set>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace archgeo {

class SpecReader {
 public:
  // `file`: the spec's path (for messages and relative paths); `overridden`:
  // the dotted keys that came from --set.
  SpecReader(std::string file, std::set<std::string> overridden);

  // Throws InputError(file, line of `node`, key, message), or ("--set", 0, ...)
  // when `key` (or a parent of it) was overridden.
  [[noreturn]] void Fail(const YAML::Node& node, const std::string& key,
                         const std::string& message) const;

  // `map` must be a mapping whose keys are all in `allowed`.
  void CheckKeys(const YAML::Node& map, const std::string& path,
                 const std::set<std::string>& allowed) const;

  double Number(const YAML::Node& node, const std::string& key, double lo, double hi) const;
  int Integer(const YAML::Node& node, const std::string& key, int lo, int hi) const;
  bool Bool(const YAML::Node& node, const std::string& key) const;
  // With `choices`, the value must be one of them.
  std::string String(const YAML::Node& node, const std::string& key,
                     const std::set<std::string>& choices = {}) const;
  // A non-empty path; relative paths are resolved against the spec's folder,
  // or the current folder for --set values.
  std::string Path(const YAML::Node& node, const std::string& key) const;

  // A weight given either as a number or as a mapping {weight: w, <extra>...}:
  // reads `weight` into *weight (range [0, 1e12]) and checks the mapping's
  // keys against {"weight"} ∪ `extra`. Returns the node for the extra keys
  // (undefined when the weight was a plain number).
  YAML::Node Weight(const YAML::Node& node, const std::string& key, double* weight,
                    const std::set<std::string>& extra = {}) const;

  // The shared term forms. `terms.proximity`: a weight, or {weight,
  // point_weight} (*point_weight keeps its value unless given).
  void ProximityTerm(const YAML::Node& node, double* weight, double* point_weight) const;
  // `terms.fairness`: a weight, or {weight, relative_to_original, <extra>...}
  // (*relative keeps its value unless given). Returns the mapping for the
  // extra keys (undefined for a plain number).
  YAML::Node FairnessTerm(const YAML::Node& node, double* weight, bool* relative,
                          const std::set<std::string>& extra = {}) const;

  const std::string& file() const { return file_; }
  bool Overridden(const std::string& key) const { return overridden_.count(key) > 0; }

  static std::string Join(const std::string& path, const std::string& key);

 private:
  std::string file_;
  std::set<std::string> overridden_;
};

// Applies "dotted.key=value" (value parsed as YAML) to `root`; returns the
// dotted key. Throws InputError("--set", ...) for a malformed assignment.
std::string ApplyOverride(YAML::Node& root, const std::string& assignment);

}  // namespace archgeo
