// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — human-readable tables of metrics, for `solve` and `measure`.
#pragma once

#include <string>

#include "analysis/metrics.h"

namespace archgeo {

// A table with one row per metric: the value in file units and relative to
// `scale` (the input's bounding-box diagonal); with `after`, before and
// after side by side. Rows not computed (-1) are left out.
std::string FormatMetrics(const Metrics& before, const Metrics* after, double scale);

}  // namespace archgeo
