// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — one number as printf formats it, e.g. FormatNumber("%.3e", x).
#pragma once

#include <cstdio>
#include <string>

namespace archgeo {

inline std::string FormatNumber(const char* format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

}  // namespace archgeo
