// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// A test mesh as OBJ text: an n × n grid of unit quads over z = twist · x · y
// (0: planar quads; a hyperbolic paraboloid's quads are twisted, δ_PQ,n ≈
// twist / √2 for unit quads).
#pragma once

#include <string>

namespace archgeo {

inline std::string GridObj(int n, double twist) {
  std::string obj;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      const double x = i - n / 2.0, y = j - n / 2.0;
      obj += "v " + std::to_string(x) + " " + std::to_string(y) + " " +
             std::to_string(twist * x * y) + "\n";
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int a = j * (n + 1) + i + 1;
      obj += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " +
             std::to_string(a + n + 2) + " " + std::to_string(a + n + 1) + "\n";
    }
  }
  return obj;
}

}  // namespace archgeo
