// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — every registered term (core/term.h), by name. A term is the
// energy of the same name in energies/<name>.h; its declaration (TermSpec)
// sits at the end of energies/<name>.cpp and is listed once in registry.cpp.
#pragma once

#include <string>
#include <vector>

#include "core/term.h"

namespace archgeo {

// In registry order (alphabetical).
const std::vector<const TermSpec*>& RegisteredTerms();

// The term named `name`, or null.
const TermSpec* FindTerm(const std::string& name);

// Mutation testing (tools/mutation_check.sh): the term named by the
// environment variable ARCHGEO_ZERO_TERM (read once; "" when unset)
// contributes nothing: its residuals and Jacobians are zero and its
// manifolds are not set, so a test that needs the term fails. A run with it
// set says so in its summary.
const std::string& ZeroedTerm();

}  // namespace archgeo
