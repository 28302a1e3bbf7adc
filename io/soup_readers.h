// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — OBJ, OFF and PLY files held in memory, parsed into a polygon soup
// (no CGAL). Step 1 of ReadMesh (io/io.cpp), which then checks and orients
// the soup with CGAL and builds the Surface_mesh.
//
// Why not CGAL's soup readers (CGAL 5.5): they read OBJ indices as int (an
// index >= 2^31 ends the face: a quad becomes a triangle), trust declared
// counts (OFF resizes to the header's vertex count, PLY to each list count:
// minutes and GBs for a 59-byte file, std::length_error for a negative
// count), stop silently after the declared faces, read binary OFF face
// colour counts as faces, give coordinates missing from a PLY header the
// value 0, and answer only true/false. These parsers share one lexical layer
// (io/text_scan.h) and guarantee, for any input:
//  - work and memory proportional to the data: every declared count is
//    checked against what the remaining bytes can hold, then against
//    `limits`, before anything is reserved;
//  - every point finite, every index in range, every face at most
//    limits.max_face_degree long;
//  - the file holds exactly what its header declares: missing records are
//    refused as a truncated file, extra records as "more than its header
//    declares";
//  - an InputError naming `name` (and the line, for ASCII files) otherwise.
// Faces with fewer than 3 vertices, repeated vertices or zero area are left
// to ReadMesh's checks, which name them with their lines.
//
// Formats read:
//  - OBJ: `v x y z [...]`, `f i[/t][/n] ...` with 1-based or negative
//    (relative: -1 is the last vertex read so far) indices; `vt`, `vn`, `vp`,
//    `o`, `g`, `s`, `usemtl`, `mtllib` and render attributes are ignored;
//    other statements (`l`, `p`, curves, surfaces) are refused.
//  - OFF: ASCII with the [ST][C][N][4]OFF keywords (4: homogeneous x y z w),
//    counts on the keyword line or the next, '#' comments, face index lists
//    wrapped over lines, colours after the indices; binary "OFF BINARY"
//    (big-endian int32 counts and indices, float32 coordinates, a colour
//    count and colours after each face).
//  - PLY: ascii, binary_little_endian, binary_big_endian; any elements and
//    scalar or list properties of the standard types; the vertex element
//    ("vertex"/"vertices") needs x, y, z, the face element ("face"/"faces")
//    an integer list vertex_indices (or vertex_index). ASCII PLY: one item
//    per line.
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "io/read_limits.h"
#include "io/text_scan.h"

namespace archgeo {

struct PolygonSoup {
  std::vector<std::array<double, 3>> points;        // file order
  std::vector<std::vector<std::size_t>> polygons;   // 0-based indices into points
  LineMap lines;                                    // ASCII files: the record lines
};

// Each parses `data`, the content of the file `name` (used in messages only).
PolygonSoup ParseObj(const std::string& name, std::string_view data, const ReadLimits& limits);
PolygonSoup ParseOff(const std::string& name, std::string_view data, const ReadLimits& limits);
PolygonSoup ParsePly(const std::string& name, std::string_view data, const ReadLimits& limits);

}  // namespace archgeo
