// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "geometry/patchwork_io.h"

#include <glog/logging.h>

#include <cstdint>
#include <cstring>

#include "core/input_error.h"
#include "io/output_stream.h"

namespace archgeo {
namespace {

template <typename T>
void Put(std::ostream& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));  // little-endian hosts only (x86-64, arm64)
  out.write(bytes, sizeof(T));
}

}  // namespace

void WritePatchworkPly(const std::string& path, const SampledPatchwork& patchwork,
                       const std::vector<std::array<unsigned char, 3>>& colors, bool ascii) {
  const size_t n = patchwork.positions.size();
  CHECK_EQ(patchwork.normals.size(), n);
  CHECK(colors.empty() || colors.size() == n);
  std::vector<int> index(n, -1);
  int used = 0;
  for (const auto& t : patchwork.triangles) {
    for (int v : t) {
      CHECK(v >= 0 && size_t(v) < n);
      if (index[v] < 0) index[v] = used++;
    }
  }
  std::vector<int> order(used);
  for (size_t v = 0; v < n; ++v) {
    if (index[v] >= 0) order[index[v]] = int(v);
  }

  NoFollowOfstream out(path);
  if (!out) throw InputError(path, 0, "", "cannot write the patchwork");
  out << "ply\nformat " << (ascii ? "ascii" : "binary_little_endian") << " 1.0\n"
      << "comment archgeo H-net patchwork (rational bilinear patches, Shi 2014)\n"
      << "element vertex " << used << "\n"
      << "property double x\nproperty double y\nproperty double z\n"
      << "property float nx\nproperty float ny\nproperty float nz\n";
  if (!colors.empty()) {
    out << "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  }
  out << "element face " << patchwork.triangles.size() << "\n"
      << "property list uchar int vertex_indices\nend_header\n";
  out.precision(17);
  for (int v : order) {
    const Vec3& p = patchwork.positions[v];
    const Vec3& nv = patchwork.normals[v];
    if (ascii) {
      out << p[0] << " " << p[1] << " " << p[2] << " " << float(nv[0]) << " " << float(nv[1])
          << " " << float(nv[2]);
      if (!colors.empty()) {
        out << " " << int(colors[v][0]) << " " << int(colors[v][1]) << " " << int(colors[v][2]);
      }
      out << "\n";
    } else {
      for (double c : p) Put(out, c);
      for (double c : nv) Put(out, float(c));
      if (!colors.empty()) {
        for (unsigned char c : colors[v]) Put(out, c);
      }
    }
  }
  for (const auto& t : patchwork.triangles) {
    if (ascii) {
      out << "3 " << index[t[0]] << " " << index[t[1]] << " " << index[t[2]] << "\n";
    } else {
      Put(out, static_cast<unsigned char>(3));
      for (int v : t) Put(out, static_cast<std::int32_t>(index[v]));
    }
  }
  out.close();
  if (out.fail()) throw InputError(path, 0, "", "cannot write the patchwork");
}

}  // namespace archgeo
