// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — every problem declaration (core/problem.h) by name: one file
// problems/declarations/<name>.cpp each, listed once in registry.cpp, plus `custom`, which
// composes any registered terms named in the spec (problems/declarations/custom.h).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/problem.h"

namespace archgeo {

std::vector<std::string> ProblemNames();  // registry order, then "custom"

// The declaration named `name` (not "custom"), or null.
const ProblemDecl* FindProblem(const std::string& name);

}  // namespace archgeo
