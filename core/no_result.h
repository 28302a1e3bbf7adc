// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — no result for a valid input.
//
// A step that cannot make what the problem needs from an input that is
// itself fine (the level sets of a conjugate layout that give no layout)
// throws NoResult; `archgeo solve` ends with exit 3 ("no valid result",
// nothing written) and its message, where an InputError would blame the
// user's input (exit 2).
#pragma once

#include <stdexcept>
#include <string>

namespace archgeo {

class NoResult : public std::runtime_error {
 public:
  explicit NoResult(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace archgeo
