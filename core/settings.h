// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — settings declared once: every key of a problem spec is a Key
// (name, type, default, range or choices, one-line doc) in a Schema. Reading
// and validation (problems/spec/spec.h), the report's settings, `archgeo
// spec PROBLEM` and the key tables (docs/keys.md) all come from these declarations.
//
// No CGAL and no YAML here: a Settings object holds plain values, and where
// each came from (file and line, or "--set"), so any later check can name
// the place (Settings::Error).
#pragma once

#include <limits>
#include <map>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/custom_value.h"
#include "core/input_error.h"

namespace archgeo {

// The value of one key.
using Value = std::variant<std::monostate, bool, long long, double, std::string,
                           std::vector<double>, std::vector<long long>>;

enum class Type {
  kBool,
  kInteger,
  kNumber,
  kChoice,      // a string out of Key::choices
  kString,
  kInputPath,   // a file archgeo reads (never overwritten by an output)
  kOutputPath,  // a file archgeo writes; empty: not written
  kNumbers,     // a list of numbers (Key::size entries, or any number if 0)
  kIntegers,    // a list of integers
  kChoiceOrIntegers,  // a choice, or a list of integers (e.g. `fixed`)
  kCustom,      // a structured value read by the problem (Settings::Custom)
};

struct Key {
  std::string name;      // dotted path, e.g. "tolerance.pq_normalized_max"
  Type type = Type::kNumber;
  Value fallback;        // the default; std::monostate = none
  std::string doc;       // one line
  double lo = -std::numeric_limits<double>::infinity();  // numbers, integers, list entries
  double hi = std::numeric_limits<double>::infinity();
  std::vector<std::string> choices;  // kChoice, kChoiceOrIntegers
  int size = 0;          // kNumbers / kIntegers: exact length (0 = any)
  std::string example;   // a YAML example for `archgeo spec` (a comment unless `required`)
  bool required = false; // no default: the spec must give it (`archgeo spec` shows the example)
};

// Helpers to declare keys tersely.
Key NumberKey(std::string name, double fallback, double lo, double hi, std::string doc);
Key IntegerKey(std::string name, long long fallback, long long lo, long long hi, std::string doc);
Key BoolKey(std::string name, bool fallback, std::string doc);
Key ChoiceKey(std::string name, std::string fallback, std::vector<std::string> choices,
              std::string doc);
// A file name (type kInputPath or kOutputPath) without a default.
Key PathKey(std::string name, Type type, std::string doc);
// A structured value the problem parses itself (type kCustom), shown by
// `archgeo spec` with `example`.
Key CustomKey(std::string name, std::string example, std::string doc);

// An ordered set of keys (the order of `archgeo spec` and docs/keys.md).
class Schema {
 public:
  void Add(Key key);  // CHECKs that the name is new
  void Add(const std::vector<Key>& keys);
  const Key* Find(const std::string& name) const;
  // Whether `prefix` is a section: some key starts with "prefix.".
  bool IsSection(const std::string& prefix) const;
  // The names directly under `prefix` ("" = top level), for messages.
  std::vector<std::string> Children(const std::string& prefix) const;
  const std::vector<Key>& keys() const { return keys_; }

 private:
  std::vector<Key> keys_;
  std::map<std::string, size_t> index_;
};

// Where a value came from.
struct Origin {
  std::string file;  // the spec file, or "--set"; empty: the default
  int line = 0;
};

class Settings {
 public:
  explicit Settings(Schema schema = {});

  const Schema& schema() const { return schema_; }

  // Sets a value (type-checked by the caller, e.g. the YAML reader).
  void Set(const std::string& name, Value value, Origin origin);
  void SetCustom(const std::string& name, CustomValue value, Origin origin);

  // Whether the user gave `name` (not only its default).
  bool Given(const std::string& name) const;
  Origin Where(const std::string& name) const;

  // Typed access (CHECKs the key exists and has that type).
  const Value& Get(const std::string& name) const;
  double Number(const std::string& name) const;
  long long Integer(const std::string& name) const;
  bool Bool(const std::string& name) const;
  const std::string& String(const std::string& name) const;  // choices, strings, paths
  std::vector<double> Numbers(const std::string& name) const;
  std::vector<long long> Integers(const std::string& name) const;
  // A structured (kCustom) value as given; null if it was not.
  const CustomValue* Custom(const std::string& name) const;

  // An InputError about `name` at the place it was given (or the spec file
  // and line 0 when it was a default, `spec_file` then).
  InputError Error(const std::string& name, const std::string& message) const;
  // An InputError about `node`, a part of the structured setting `name`,
  // under `key` (e.g. "handles[2].position"): at the node's line, or the
  // setting's when the node's is unknown; line 0 when given by --set.
  InputError ErrorAt(const std::string& name, const CustomValue& node, const std::string& key,
                     const std::string& message) const;
  void set_spec_file(std::string file) { spec_file_ = std::move(file); }
  const std::string& spec_file() const { return spec_file_; }

  // Every key with its value, as a nested JSON object (custom keys as given).
  nlohmann::json ToJson() const;
  // The values under "prefix." as a nested object.
  nlohmann::json SectionJson(const std::string& prefix) const;

 private:
  Schema schema_;
  std::map<std::string, Value> values_;
  std::map<std::string, CustomValue> custom_;
  std::map<std::string, Origin> origin_;
  std::string spec_file_;
};

// A value as text (for messages, `archgeo spec` and docs/keys.md).
std::string ToText(const Value& value);
nlohmann::json ToJson(const Value& value);

}  // namespace archgeo
