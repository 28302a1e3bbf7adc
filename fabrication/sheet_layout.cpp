// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fabrication/sheet_layout.h"

#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include <Eigen/Geometry>

namespace archgeo {
namespace {

// Directions tried for the smallest bounding rectangle: every pair of
// corners (which includes every edge of the convex hull, where the smallest
// rectangle has a side) up to this many corners, the edges beyond.
constexpr size_t kAllPairsUpTo = 24;

struct Turned {
  std::vector<Eigen::Vector2d> corners;  // bounding rectangle [0, size]
  Eigen::Vector2d size = Eigen::Vector2d::Zero();
};

// `corners` turned by `angle` and moved so that their rectangle starts at 0.
Turned TurnAndRest(const std::vector<Eigen::Vector2d>& corners, double angle) {
  const Eigen::Matrix2d rotation = Eigen::Rotation2Dd(angle).toRotationMatrix();
  Turned t;
  Eigen::Vector2d low = Eigen::Vector2d::Constant(INFINITY), high = -low;
  for (const Eigen::Vector2d& c : corners) {
    t.corners.push_back(rotation * c);
    low = low.cwiseMin(t.corners.back());
    high = high.cwiseMax(t.corners.back());
  }
  for (Eigen::Vector2d& c : t.corners) c -= low;
  t.size = high - low;
  return t;
}

// The outline turned to its smallest bounding rectangle, lying flat.
Turned SmallestRectangle(const std::vector<Eigen::Vector2d>& corners) {
  const size_t n = corners.size();
  Turned best = TurnAndRest(corners, 0.0);
  const auto consider = [&](size_t i, size_t j) {
    const Eigen::Vector2d d = corners[j] - corners[i];
    if (!(d.norm() > 0)) return;
    const Turned t = TurnAndRest(corners, -std::atan2(d.y(), d.x()));
    if (t.size.prod() < best.size.prod()) best = t;
  };
  for (size_t i = 0; i < n; ++i) {
    if (n <= kAllPairsUpTo) {
      for (size_t j = i + 1; j < n; ++j) consider(i, j);
    } else {
      consider(i, (i + 1) % n);
    }
  }
  if (best.size.y() > best.size.x()) best = TurnAndRest(best.corners, M_PI / 2);
  return best;
}

bool FitsSheet(const Eigen::Vector2d& size, const Eigen::Vector2d& sheet, double gap) {
  return size.x() + 2 * gap <= sheet.x() && size.y() + 2 * gap <= sheet.y();
}

}  // namespace

SheetLayout LayOutOnSheets(const std::vector<std::vector<Eigen::Vector2d>>& outlines,
                           const Eigen::Vector2d& sheet, double gap) {
  CHECK(sheet.x() > 0 && sheet.y() > 0 && gap >= 0)
      << "LayOutOnSheets: sheet " << sheet.transpose() << ", gap " << gap;
  const size_t count = outlines.size();
  std::vector<Turned> turned;
  for (const auto& outline : outlines) turned.push_back(SmallestRectangle(outline));
  std::vector<size_t> order(count);
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return turned[a].size.y() > turned[b].size.y(); });

  SheetLayout layout;
  layout.outlines.resize(count);
  std::vector<size_t> oversize;
  int open_sheet = -1;
  double x = 0, y = 0, shelf = 0;
  for (const size_t i : order) {
    Turned& t = turned[i];
    if (!FitsSheet(t.size, sheet, gap)) {
      const Turned upright = TurnAndRest(t.corners, M_PI / 2);
      if (!FitsSheet(upright.size, sheet, gap)) {
        oversize.push_back(i);
        continue;
      }
      t = upright;
    }
    if (open_sheet < 0 || x + t.size.x() + gap > sheet.x()) {  // a new shelf
      y += open_sheet < 0 ? 0.0 : shelf + gap;
      x = gap;
      shelf = 0;
    }
    if (open_sheet < 0 || y + t.size.y() + gap > sheet.y()) {  // a new sheet
      ++open_sheet;
      layout.sheets.push_back(sheet);
      x = gap, y = gap, shelf = 0;
    }
    PlacedOutline& placed = layout.outlines[i];
    placed.panel = int(i);
    placed.sheet = open_sheet;
    placed.low = {x, y};
    placed.high = placed.low + t.size;
    for (const Eigen::Vector2d& c : t.corners) placed.corners.push_back(c + placed.low);
    x += t.size.x() + gap;
    shelf = std::max(shelf, t.size.y());
  }
  std::sort(oversize.begin(), oversize.end());
  for (const size_t i : oversize) {
    const Turned& t = turned[i];
    layout.sheets.push_back(sheet.cwiseMax(t.size + Eigen::Vector2d::Constant(2 * gap)));
    PlacedOutline& placed = layout.outlines[i];
    placed.panel = int(i);
    placed.sheet = int(layout.sheets.size()) - 1;
    placed.low = Eigen::Vector2d::Constant(gap);
    placed.high = placed.low + t.size;
    for (const Eigen::Vector2d& c : t.corners) placed.corners.push_back(c + placed.low);
    layout.oversize.push_back(int(i));
  }
  return layout;
}

}  // namespace archgeo
