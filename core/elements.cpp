// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/elements.h"

#include <glog/logging.h>

namespace archgeo {

void ElementSet::Add(const std::vector<int>& vs, int site_index, int face_index, int edge_index,
                     std::uint8_t element_flags, const std::vector<double>& element_data,
                     int other_face_index) {
  CHECK_EQ(int(element_data.size()), data_width) << "element set " << name;
  vertices.insert(vertices.end(), vs.begin(), vs.end());
  offsets.push_back(int(vertices.size()));
  sites.push_back(site_index);
  face.push_back(face_index);
  edge.push_back(edge_index);
  other_face.push_back(other_face_index);
  flags.push_back(element_flags);
  data.insert(data.end(), element_data.begin(), element_data.end());
}

ElementSet ElementSet::Subset(const std::vector<size_t>& keep) const {
  ElementSet out;
  out.name = name;
  out.site = site;
  out.data_width = data_width;
  for (size_t i : keep) {
    CHECK_LT(i, size());
    out.Add(std::vector<int>(Vertices(i), Vertices(i) + Count(i)), sites[i], face[i], edge[i],
            flags[i], std::vector<double>(Data(i), Data(i) + data_width), other_face[i]);
  }
  return out;
}

}  // namespace archgeo
