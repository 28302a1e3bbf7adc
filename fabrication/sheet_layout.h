// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — flat panel outlines laid out on rectangular sheets for cutting,
// without overlap: each outline turned to its smallest bounding rectangle
// (lying flat: width ≥ height), then the rectangles placed by shelf packing
// (tallest first, left to right along a shelf, shelves bottom to top, a new
// sheet when the next shelf does not fit), `gap` apart and from the sheet's
// edges. Rectangles do not overlap, so neither do the outlines in them.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace archgeo {

struct PlacedOutline {
  int panel = 0;                         // index into the outlines given
  int sheet = 0;                         // 0-based
  std::vector<Eigen::Vector2d> corners;  // in the sheet's frame (origin: its lower-left corner)
  Eigen::Vector2d low = Eigen::Vector2d::Zero(), high = Eigen::Vector2d::Zero();  // its rectangle
};

struct SheetLayout {
  // Per sheet: its size (`sheet`, or larger for a panel that does not fit
  // one: such a panel gets a sheet of its own, listed in `oversize`).
  std::vector<Eigen::Vector2d> sheets;
  std::vector<PlacedOutline> outlines;  // in the order given
  std::vector<int> oversize;            // panels larger than a sheet
};

// `outlines`: closed polygons (any position and turn); `sheet`: width and
// height (> 0); `gap` ≥ 0: between rectangles and from the sheet's edges.
SheetLayout LayOutOnSheets(const std::vector<std::vector<Eigen::Vector2d>>& outlines,
                           const Eigen::Vector2d& sheet, double gap);

}  // namespace archgeo
