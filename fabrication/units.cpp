// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fabrication/units.h"

#include <utility>

namespace archgeo {
namespace {

const std::vector<std::pair<std::string, double>>& UnitTable() {
  static const std::vector<std::pair<std::string, double>> table = {
      {"none", 0.0}, {"mm", 1.0}, {"cm", 10.0}, {"m", 1000.0}, {"in", 25.4}, {"ft", 304.8}};
  return table;
}

}  // namespace

const std::vector<std::string>& LengthUnitNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const auto& entry : UnitTable()) n.push_back(entry.first);
    return n;
  }();
  return names;
}

double MillimetresPerUnit(const std::string& unit) {
  for (const auto& [name, mm] : UnitTable()) {
    if (name == unit) return mm;
  }
  return 0.0;
}

}  // namespace archgeo
