// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/declarations/flatness.h"

#include <string>
#include <utility>
#include <vector>

#include "core/settings.h"

namespace archgeo {

ProblemDecl WithFlatness(ProblemDecl d) {
  // Beside the problem's other tolerance keys.
  auto at = d.keys.begin();
  for (auto k = d.keys.begin(); k != d.keys.end(); ++k) {
    if (k->name.rfind("tolerance.", 0) == 0) at = k + 1;
  }
  d.keys.insert(at, NumberKey("tolerance.flatness_mm", 0, 0, 1e12,
                              "stop as soon as no panel corner is farther than this many "
                              "millimetres from the panel's best-fit plane (needs `units`; "
                              "docs/fabrication.md); beside tolerance.pq_normalized_max, both "
                              "must hold; 0 = off"));
  auto stages = d.stages;
  d.stages = [stages](const Settings& s) {
    std::vector<Stage> all = stages(s);
    if (!(s.Number("tolerance.flatness_mm") > 0)) return all;
    for (Stage& stage : all) {
      bool planarity = false;
      for (const Tolerance& t : stage.tolerances)
        planarity = planarity || t.measure == "pq_normalized_max";
      if (!planarity) continue;
      stage.tolerances.push_back({"flatness_mm", "tolerance.flatness_mm", /*per_iteration=*/true});
      stage.logged.push_back("flatness_mm");
    }
    return all;
  };
  return d;
}

}  // namespace archgeo
