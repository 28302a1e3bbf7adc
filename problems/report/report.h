// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — human-readable tables of metrics, for `solve` and `measure`.
#pragma once

#include <cstddef>
#include <string>

#include "analysis/metrics.h"

namespace archgeo {

// A table with one row per metric: the value in file units and relative to
// `scale` (the input's bounding-box diagonal); with `after`, before and
// after side by side. Rows not computed (-1) are left out.
std::string FormatMetrics(const Metrics& before, const Metrics* after, double scale);

// The change from `before` to `after` for a summary line: "+12%" or "-3%"
// (rounded to whole percents); the absolute change ("+0.0123", "-4.5e-05")
// where a percentage means nothing (from or to zero); "x15.2" (the factor)
// beyond +1000%. Empty when nothing changed.
std::string ChangeText(double before, double after);

// `text` padded with spaces to `width` columns (a UTF-8 character is one).
std::string PadColumns(const std::string& text, size_t width);

}  // namespace archgeo
