// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the one colour scale of face colours and pictures: green at 0,
// yellow at red_at / 2, red at red_at and above (Zadravec 2010, Fig. 1).
// Header-only, no dependencies.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace archgeo {

// The colour of `value` on a scale red at `red_at` (> 0). Non-finite values
// and red_at ≤ 0 give green.
inline std::array<unsigned char, 3> ScaleColor(double value, double red_at) {
  const double t =
      red_at > 0 && std::isfinite(value) ? std::clamp(value / red_at, 0.0, 1.0) : 0.0;
  const auto channel = [](double x) {
    return static_cast<unsigned char>(std::lround(255 * std::clamp(x, 0.0, 1.0)));
  };
  return {channel(2 * t), channel(2 * (1 - t)), 0};
}

}  // namespace archgeo
