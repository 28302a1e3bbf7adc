// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — a base complex given as surface vertex ids and faces (the
// `base_complex.ids` file of problem base_complex_quads):
//
//   # comments and blank lines are skipped
//   v 17          # base vertex 0 is surface vertex 17 (0-based, as the mesh file orders them)
//   v 203         # base vertex 1
//   f 1 2 3       # a base face: its base vertices, 1-based and counter-clockwise as in OBJ
//   f 1 3 4 5     # triangles and quads
#pragma once

#include <string>
#include <vector>

namespace archgeo {

struct BaseComplexIds {
  std::vector<int> nodes;               // surface vertex id per base vertex
  std::vector<std::vector<int>> faces;  // base vertex indices (0-based)
};

// Throws InputError(path, line, key, ...) for a line that is not `v ID` or
// `f I J K [L]`, an index out of range, or a file without faces.
BaseComplexIds ReadBaseComplexIds(const std::string& path, const std::string& key);

}  // namespace archgeo
