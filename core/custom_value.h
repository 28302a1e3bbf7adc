// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the value of a structured setting (Type::kCustom, e.g. `handles`,
// `surface`, `terms.<t>.select`) in plain C++: the spec reader
// (problems/spec/spec.cpp) turns what the user wrote into a tree of scalars, lists
// and mappings, each node with its line, and each scalar with its readings as
// a number, an integer and a boolean under YAML's rules. Problems read their
// own forms from it and name the place of an error (Settings::ErrorAt)
// without knowing YAML.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace archgeo {

struct CustomValue {
  enum class Kind { kNull, kScalar, kList, kMap };
  struct Entry;

  Kind kind = Kind::kNull;
  int line = 0;                      // 1-based line in the file it came from; 0: unknown
  std::string text;                  // kScalar: as written ("" for other kinds)
  std::optional<double> number;      // kScalar: the text read as a number, if it is one
  std::optional<long long> integer;  // kScalar: the text read as an integer, if it is one
  std::optional<bool> boolean;       // kScalar: the text read as true or false, if it is one
  std::vector<CustomValue> items;    // kList
  std::vector<Entry> entries;        // kMap, in the order written (repeated keys kept)

  bool IsScalar() const { return kind == Kind::kScalar; }
  bool IsList() const { return kind == Kind::kList; }
  bool IsMap() const { return kind == Kind::kMap; }
  // The value of the first entry whose key is the scalar `key`; null if
  // there is none (or this is not a mapping).
  const CustomValue* Find(const std::string& key) const;
  // "'text'", "a list", "a mapping" or "nothing" (for messages).
  std::string Describe() const;
};

struct CustomValue::Entry {
  CustomValue key;
  CustomValue value;
};

}  // namespace archgeo
