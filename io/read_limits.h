// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — size limits for reading a mesh file (no CGAL; the spec reader
// includes this to fill them from its `limits:` section).
#pragma once

#include <cstddef>
#include <cstdint>

namespace archgeo {

// Bounds checked by ReadMesh (io/io.h) BEFORE anything of that size is
// allocated: declared counts (OFF/PLY headers) are checked first against what
// the file's size can hold, then against these limits; OBJ counts as it reads.
// A file beyond a limit is refused with an InputError that names the spec key
// (given below) so the user can raise it. The defaults hold a 1M-quad mesh
// 50 times over; at the defaults a mesh at the limit needs several GB of
// memory (about 150 bytes per face and 60 per vertex while reading).
struct ReadLimits {
  // Vertices in the file (isolated ones included).       spec: limits.max_vertices
  std::size_t max_vertices = 50'000'000;
  // Faces in the file.                                     spec: limits.max_faces
  std::size_t max_faces = 50'000'000;
  // Vertices of one face (PLY can store at most 255 with
  // the usual uchar count; OFF and OBJ have no bound).     spec: limits.max_face_degree
  std::size_t max_face_degree = 1000;
  // Size of the file in bytes (it is read whole): 8 GiB,
  // enough for the vertex and face limits above in OBJ.    spec: limits.max_file_bytes
  std::uint64_t max_file_bytes = std::uint64_t{8} << 30;
  // Vertices closer than this × the mean edge length are
  // welded into one (io/weld.h); 0: never.                 spec: limits.weld_distance
  double weld_distance = 1e-6;
};

}  // namespace archgeo
