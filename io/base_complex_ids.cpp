// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "io/base_complex_ids.h"

#include <sstream>

#include "core/input_error.h"
#include "io/input_file.h"

namespace archgeo {

BaseComplexIds ReadBaseComplexIds(const std::string& path, const std::string& key) {
  std::istringstream text(ReadInputFile(path, key));
  BaseComplexIds out;
  std::vector<int> face_lines;
  std::string line;
  for (int number = 1; std::getline(text, line); ++number) {
    const size_t hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::istringstream in(line);
    std::string tag;
    if (!(in >> tag)) continue;
    std::vector<long long> values;
    std::string token;
    while (in >> token) {
      size_t used = 0;
      long long value = 0;
      try {
        value = std::stoll(token, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used != token.size()) {
        throw InputError(path, number, key, "'" + token + "' is not an integer");
      }
      values.push_back(value);
    }
    if (tag == "v") {
      if (values.size() != 1 || values[0] < 0 || values[0] > 2147483647LL) {
        throw InputError(path, number, key, "a vertex line is 'v ID' with one surface vertex id ≥ 0");
      }
      out.nodes.push_back(int(values[0]));
    } else if (tag == "f") {
      if (values.size() != 3 && values.size() != 4) {
        throw InputError(path, number, key, "a face line is 'f I J K' or 'f I J K L' (triangles and quads)");
      }
      std::vector<int> face;
      for (long long v : values) face.push_back(v >= 1 && v <= 2147483647LL ? int(v - 1) : -1);
      out.faces.push_back(face);
      face_lines.push_back(number);
    } else {
      throw InputError(path, number, key, "unknown line '" + tag + "' (v ID or f I J K [L])");
    }
  }
  for (size_t f = 0; f < out.faces.size(); ++f) {
    for (int v : out.faces[f]) {
      if (v < 0 || v >= int(out.nodes.size())) {
        throw InputError(path, face_lines[f], key,
                         "base face " + std::to_string(f) + " names a base vertex that is not among the " +
                             std::to_string(out.nodes.size()) + " 'v' lines (1-based)");
      }
    }
  }
  if (out.faces.empty()) throw InputError(path, 0, key, "has no 'f' line");
  return out;
}

}  // namespace archgeo
