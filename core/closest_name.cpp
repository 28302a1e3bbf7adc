// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/closest_name.h"

#include <algorithm>

namespace archgeo {

std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string ClosestName(const std::string& name, const std::vector<std::string>& candidates,
                        std::size_t max_edits) {
  std::string best;
  std::size_t best_distance = std::min(max_edits + 1, name.size());
  for (const std::string& candidate : candidates) {
    std::size_t d = EditDistance(name, candidate);
    for (std::size_t cut = candidate.find('_'); cut != std::string::npos;
         cut = candidate.find('_', cut + 1)) {
      d = std::min(d, EditDistance(name, candidate.substr(cut + 1)));
    }
    if (d < best_distance) {
      best_distance = d;
      best = candidate;
    }
  }
  return best;
}

}  // namespace archgeo
