// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — where a run's progress lines go (one per solver iteration, round
// or stage; the CLI prints them to stderr, the API may collect them).
#pragma once

#include <functional>
#include <string>

namespace archgeo {

// Receives one progress line (no trailing newline); empty: no progress.
using ProgressSink = std::function<void(const std::string& line)>;

}  // namespace archgeo
