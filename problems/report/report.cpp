// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/report/report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace archgeo {
namespace {

struct Row {
  const char* name;
  double Metrics::*field;
  bool length;  // a length in file units (else a ratio)
};

const std::vector<Row>& Rows() {
  static const std::vector<Row> rows = {
      {"δ_PQ max (diagonal distance)", &Metrics::pq_max, true},
      {"δ_PQ mean", &Metrics::pq_mean, true},
      {"δ_PQ,n max (/ mean diagonal)", &Metrics::pq_normalized_max, false},
      {"δ_PQ,n mean", &Metrics::pq_normalized_mean, false},
      {"warp max (/ shortest edge)", &Metrics::warp_max, false},
      {"warp mean", &Metrics::warp_mean, false},
      {"δ_prox (to tangent plane)", &Metrics::prox_max, true},
      {"δ∂_prox (to boundary tangent)", &Metrics::boundary_prox_max, true},
      {"distance to reference max", &Metrics::surface_distance_max, true},
      {"distance to reference mean", &Metrics::surface_distance_mean, true},
      {"Hausdorff to reference", &Metrics::hausdorff, true},
      {"displacement max", &Metrics::displacement_max, true},
      {"displacement mean", &Metrics::displacement_mean, true},
  };
  return rows;
}

// Pads to `width` characters as displayed (UTF-8 code points, not bytes).
std::string Cell(double value, bool length, double scale) {
  char buf[64];
  if (value < 0) return "-";
  if (length) {
    std::snprintf(buf, sizeof buf, "%.4e (%.3e)", value, value / scale);
  } else {
    std::snprintf(buf, sizeof buf, "%.4e", value);
  }
  return buf;
}

}  // namespace

std::string FormatMetrics(const Metrics& before, const Metrics* after, double scale) {
  std::string out;
  char line[512];
  std::snprintf(line, sizeof line,
                "mesh: %d vertices, %d faces (%d quads, %d triangles, %d polygons > 4 sides)\n"
                "bounding-box diagonal %.6g (principal axes; axis-aligned %.6g), mean edge "
                "length %.6g (file units)\n"
                "lengths: file units (relative to the bounding-box diagonal %.6g)\n",
                before.vertices, before.faces, before.quads, before.triangles, before.polygons,
                before.bbox_diagonal, before.aabb_diagonal, before.mean_edge_length, scale);
  out += line;
  if (after && (after->vertices != before.vertices || after->faces != before.faces)) {
    std::snprintf(line, sizeof line,
                  "after (subdivided): %d vertices, %d faces (%d quads, %d triangles, %d polygons "
                  "> 4 sides)\n",
                  after->vertices, after->faces, after->quads, after->triangles, after->polygons);
    out += line;
  }
  out += PadColumns("metric", 32) + PadColumns(after ? "before" : "value", 26) + (after ? "after" : "") + "\n";
  for (const Row& row : Rows()) {
    const double b = before.*row.field;
    const double a = after ? (*after).*row.field : -1;
    if (b < 0 && a < 0) continue;
    out += PadColumns(row.name, 32) + PadColumns(Cell(b, row.length, scale), 26) +
           (after ? Cell(a, row.length, scale) : "") + "\n";
  }
  return out;
}

std::string ChangeText(double before, double after) {
  if (before == after) return "";
  char text[64];
  // A value at rounding level of the other (e.g. 4e-18 of a distance that
  // is exactly 0 in exact arithmetic) counts as zero: an absolute change.
  const double scale = 1e-12 * std::max(std::abs(before), std::abs(after));
  if (std::abs(before) <= scale || std::abs(after) <= scale || !std::isfinite(before) ||
      !std::isfinite(after)) {
    std::snprintf(text, sizeof text, "%+.3g", after - before);
  } else if ((after - before) / std::abs(before) > 10) {
    std::snprintf(text, sizeof text, "x%.3g", after / before);
  } else {
    std::snprintf(text, sizeof text, "%+ld%%", std::lround(100.0 * (after - before) / std::abs(before)));
  }
  return text;
}

std::string PadColumns(const std::string& text, size_t width) {
  size_t shown = 0;
  for (unsigned char c : text) shown += (c & 0xC0) != 0x80;
  return text + std::string(width > shown ? width - shown : 0, ' ');
}

}  // namespace archgeo
