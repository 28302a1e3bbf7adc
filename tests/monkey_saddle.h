// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Test surface: the monkey saddle z = x³ − 3xy² over [−1, 1]², a jittered
// 30 × 30 triangle grid; its principal field has one −1/2 singularity, at
// the origin.
#pragma once

#include "fields/triangle_surfaces.h"

namespace archgeo {

inline Mesh JitteredMonkeySaddle() {
  TriangleGridOptions opt;
  opt.jitter = 0.2;
  return TriangulatedGrid(30, 30, [](double u, double v) -> Vec3 {
    const double x = 2 * u - 1, y = 2 * v - 1;
    return {x, y, x * x * x - 3 * x * y * y};
  }, opt);
}

}  // namespace archgeo
