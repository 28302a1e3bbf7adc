// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the YAML problem spec: parse, validate against the problem's
// schema (problems/spec/schema.h), apply --set overrides.
//
// Every key is declared once (name, type, range, default, doc); `archgeo
// spec PROBLEM` prints them all. An unknown key, a duplicate key, a wrong type
// or an out-of-range value is an InputError naming the file, the line and the
// dotted key ("--set" for a value from the command line). Relative paths in
// the file are relative to its folder; paths given with --set to the current
// folder.
//
// `terms`: each entry is a number (the weight) or a mapping {weight, on,
// select, loss, loss_scale, <the term's options>}. If a spec lists `terms`,
// every term of the problem it does not list is off (weight 0); `--set
// terms.X=...` on a spec without a `terms` section is refused, since it would
// switch the other terms off.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/problem.h"
#include "core/settings.h"

namespace archgeo {

struct ProblemSpec {
  std::string spec_path;  // the YAML file as given
  std::shared_ptr<const ProblemDecl> declaration;
  Settings settings;      // every key of the problem, with where it came from

  const std::string& problem() const { return declaration->name; }
  const std::string& mesh() const { return settings.String("mesh"); }
  const std::string& reference() const { return settings.String("reference"); }
  // The files the run reads besides the spec: mesh, reference and every
  // input path of the problem (no output may name them).
  std::vector<std::string> InputFiles() const;
};

// Reads and validates `path` after applying `overrides` ("dotted.key=value",
// the value parsed as YAML). Throws InputError.
ProblemSpec ReadSpec(const std::string& path, const std::vector<std::string>& overrides = {});

// A spec given as YAML text (for meshes in memory: `mesh` may be missing);
// `path` names it in messages and anchors relative paths.
ProblemSpec ParseSpec(const std::string& yaml, const std::string& path = "<spec>",
                      const std::vector<std::string>& overrides = {});

}  // namespace archgeo
