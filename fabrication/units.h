// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the length units a spec can name for its mesh (`units`).
#pragma once

#include <string>
#include <vector>

namespace archgeo {

// "none" (not said) and the units a mesh can be in: mm, cm, m, in, ft.
const std::vector<std::string>& LengthUnitNames();

// Millimetres in one `unit` (mm 1, cm 10, m 1000, in 25.4, ft 304.8); 0 for
// "none" or a name LengthUnitNames() does not list.
double MillimetresPerUnit(const std::string& unit);

}  // namespace archgeo
