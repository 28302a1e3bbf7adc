// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/settings.h"

#include <glog/logging.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <sstream>

namespace archgeo {

Key NumberKey(std::string name, double fallback, double lo, double hi, std::string doc) {
  Key k;
  k.name = std::move(name);
  k.type = Type::kNumber;
  k.fallback = fallback;
  k.lo = lo;
  k.hi = hi;
  k.doc = std::move(doc);
  return k;
}

Key IntegerKey(std::string name, long long fallback, long long lo, long long hi,
               std::string doc) {
  Key k;
  k.name = std::move(name);
  k.type = Type::kInteger;
  k.fallback = fallback;
  k.lo = double(lo);
  k.hi = double(hi);
  k.doc = std::move(doc);
  return k;
}

Key BoolKey(std::string name, bool fallback, std::string doc) {
  Key k;
  k.name = std::move(name);
  k.type = Type::kBool;
  k.fallback = fallback;
  k.doc = std::move(doc);
  return k;
}

Key ChoiceKey(std::string name, std::string fallback, std::vector<std::string> choices,
              std::string doc) {
  Key k;
  k.name = std::move(name);
  k.type = Type::kChoice;
  k.fallback = std::move(fallback);
  k.choices = std::move(choices);
  k.doc = std::move(doc);
  return k;
}

Key PathKey(std::string name, Type type, std::string doc) {
  Key k;
  k.name = std::move(name);
  k.type = type;
  k.doc = std::move(doc);
  return k;
}

Key CustomKey(std::string name, std::string example, std::string doc) {
  Key k = PathKey(std::move(name), Type::kCustom, std::move(doc));
  k.example = std::move(example);
  return k;
}

void Schema::Add(Key key) {
  CHECK(!index_.count(key.name)) << "setting '" << key.name << "' declared twice";
  index_[key.name] = keys_.size();
  keys_.push_back(std::move(key));
}

void Schema::Add(const std::vector<Key>& keys) {
  for (const Key& k : keys) Add(k);
}

const Key* Schema::Find(const std::string& name) const {
  const auto it = index_.find(name);
  return it == index_.end() ? nullptr : &keys_[it->second];
}

bool Schema::IsSection(const std::string& prefix) const {
  const std::string p = prefix + ".";
  const auto it = index_.lower_bound(p);
  return it != index_.end() && it->first.compare(0, p.size(), p) == 0;
}

std::vector<std::string> Schema::Children(const std::string& prefix) const {
  std::vector<std::string> out;
  const std::string p = prefix.empty() ? "" : prefix + ".";
  for (const Key& k : keys_) {
    if (k.name.compare(0, p.size(), p) != 0) continue;
    const std::string rest = k.name.substr(p.size());
    const std::string child = rest.substr(0, rest.find('.'));
    bool seen = false;
    for (const std::string& c : out) seen = seen || c == child;
    if (!seen) out.push_back(child);
  }
  return out;
}

Settings::Settings(Schema schema) : schema_(std::move(schema)) {
  for (const Key& k : schema_.keys()) values_[k.name] = k.fallback;
}

void Settings::Set(const std::string& name, Value value, Origin origin) {
  CHECK(schema_.Find(name)) << "no setting '" << name << "'";
  values_[name] = std::move(value);
  origin_[name] = std::move(origin);
}

void Settings::SetCustom(const std::string& name, CustomValue value, Origin origin) {
  const Key* key = schema_.Find(name);
  CHECK(key && key->type == Type::kCustom) << "no custom setting '" << name << "'";
  custom_[name] = std::move(value);
  origin_[name] = std::move(origin);
}

bool Settings::Given(const std::string& name) const { return origin_.count(name) > 0; }

Origin Settings::Where(const std::string& name) const {
  const auto it = origin_.find(name);
  return it == origin_.end() ? Origin{} : it->second;
}

const Value& Settings::Get(const std::string& name) const {
  const auto it = values_.find(name);
  CHECK(it != values_.end()) << "no setting '" << name << "'";
  return it->second;
}

double Settings::Number(const std::string& name) const {
  const Value& v = Get(name);
  if (const auto* i = std::get_if<long long>(&v)) return double(*i);
  CHECK(std::holds_alternative<double>(v)) << "setting '" << name << "' is not a number";
  return std::get<double>(v);
}

long long Settings::Integer(const std::string& name) const {
  const Value& v = Get(name);
  CHECK(std::holds_alternative<long long>(v)) << "setting '" << name << "' is not an integer";
  return std::get<long long>(v);
}

bool Settings::Bool(const std::string& name) const {
  const Value& v = Get(name);
  CHECK(std::holds_alternative<bool>(v)) << "setting '" << name << "' is not a boolean";
  return std::get<bool>(v);
}

const std::string& Settings::String(const std::string& name) const {
  const Value& v = Get(name);
  static const std::string kEmpty;
  if (std::holds_alternative<std::monostate>(v)) return kEmpty;
  CHECK(std::holds_alternative<std::string>(v)) << "setting '" << name << "' is not a string";
  return std::get<std::string>(v);
}

std::vector<double> Settings::Numbers(const std::string& name) const {
  const Value& v = Get(name);
  if (std::holds_alternative<std::monostate>(v)) return {};
  CHECK(std::holds_alternative<std::vector<double>>(v)) << "setting '" << name << "' is no list";
  return std::get<std::vector<double>>(v);
}

std::vector<long long> Settings::Integers(const std::string& name) const {
  const Value& v = Get(name);
  if (!std::holds_alternative<std::vector<long long>>(v)) return {};
  return std::get<std::vector<long long>>(v);
}

const CustomValue* Settings::Custom(const std::string& name) const {
  const auto it = custom_.find(name);
  return it == custom_.end() ? nullptr : &it->second;
}

InputError Settings::Error(const std::string& name, const std::string& message) const {
  const Origin o = Where(name);
  return InputError(o.file.empty() ? spec_file_ : o.file, o.line, name, message);
}

InputError Settings::ErrorAt(const std::string& name, const CustomValue& node,
                             const std::string& key, const std::string& message) const {
  const Origin o = Where(name);
  const int line = o.file == "--set" ? 0 : node.line > 0 ? node.line : o.line;
  return InputError(o.file.empty() ? spec_file_ : o.file, line, key, message);
}

std::string ToText(const Value& value) {
  struct Visitor {
    std::string operator()(std::monostate) const { return ""; }
    std::string operator()(bool b) const { return b ? "true" : "false"; }
    std::string operator()(long long i) const { return std::to_string(i); }
    std::string operator()(double d) const {
      std::ostringstream s;
      s.precision(12);
      s << d;
      return s.str();
    }
    std::string operator()(const std::string& s) const { return s; }
    std::string operator()(const std::vector<double>& v) const {
      std::string s = "[";
      for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + (*this)(v[i]);
      return s + "]";
    }
    std::string operator()(const std::vector<long long>& v) const {
      std::string s = "[";
      for (size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + std::to_string(v[i]);
      return s + "]";
    }
  };
  return std::visit(Visitor{}, value);
}

nlohmann::json ToJson(const Value& value) {
  struct Visitor {
    nlohmann::json operator()(std::monostate) const { return nullptr; }
    nlohmann::json operator()(bool b) const { return b; }
    nlohmann::json operator()(long long i) const { return i; }
    nlohmann::json operator()(double d) const { return d; }
    nlohmann::json operator()(const std::string& s) const { return s; }
    nlohmann::json operator()(const std::vector<double>& v) const { return v; }
    nlohmann::json operator()(const std::vector<long long>& v) const { return v; }
  };
  return std::visit(Visitor{}, value);
}

namespace {

void Place(nlohmann::json& root, const std::string& dotted, nlohmann::json value) {
  nlohmann::json* node = &root;
  std::stringstream parts(dotted);
  std::string part, next;
  std::getline(parts, part, '.');
  while (std::getline(parts, next, '.')) {
    node = &(*node)[part];
    part = next;
  }
  (*node)[part] = std::move(value);
}

}  // namespace

nlohmann::json Settings::ToJson() const { return SectionJson(""); }

nlohmann::json Settings::SectionJson(const std::string& prefix) const {
  nlohmann::json out = nlohmann::json::object();
  const std::string p = prefix.empty() ? "" : prefix + ".";
  for (const Key& k : schema_.keys()) {
    if (k.name.compare(0, p.size(), p) != 0) continue;
    const std::string rest = k.name.substr(p.size());
    if (k.type == Type::kCustom) {
      if (Given(k.name)) Place(out, rest, "(given)");
      continue;
    }
    Place(out, rest, archgeo::ToJson(Get(k.name)));
  }
  return out;
}

}  // namespace archgeo
