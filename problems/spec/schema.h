// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the settings schema of a problem: the common keys (mesh,
// reference, fixed, schedule, multiresolution, limits, output), the solver
// keys (core/solver_options.h), the keys of every term of the problem
// (terms.<t>.weight, .on, .select, .loss, .loss_scale and the term's own
// options) and the problem's own keys. Everything that reads, checks,
// reports or documents a setting goes through this one declaration.
#pragma once

#include <string>

#include "core/problem.h"
#include "core/settings.h"

namespace archgeo {

// The full schema of `declaration`, its defaults applied.
Schema ProblemSchema(const ProblemDecl& declaration);

// `archgeo spec PROBLEM`: every key with its default and doc, as a YAML file
// a user can start from (it reads back with ReadSpec once `mesh` is set).
std::string SpecTemplate(const ProblemDecl& declaration);

// The key table of a problem (docs/keys.md) (Markdown: key | default | meaning),
// without the common and solver keys unless `common`.
std::string KeyTable(const ProblemDecl& declaration, bool common);

}  // namespace archgeo
