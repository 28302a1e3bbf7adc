// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// "Did you mean": the name a mistyped one most likely meant.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace archgeo {

// Edits (insertions, deletions, substitutions) that turn `a` into `b`.
std::size_t EditDistance(const std::string& a, const std::string& b);

// The candidate nearest to `name`, compared whole and by its tails after
// each '_' (so "treads" finds "num_threads"), if within `max_edits` edits
// and fewer edits than `name` has characters; empty otherwise. Ties go to
// the earlier candidate.
std::string ClosestName(const std::string& name, const std::vector<std::string>& candidates,
                        std::size_t max_edits = 2);

}  // namespace archgeo
