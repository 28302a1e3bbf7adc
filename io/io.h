// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — mesh files: OBJ, OFF, PLY (ASCII and binary), polygonal faces.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "io/read_limits.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

// What ReadMesh had to repair, for the run report.
struct ReadInfo {
  std::string format;        // "obj", "off" or "ply"
  int reoriented_faces = 0;  // faces flipped to make the orientation consistent
  int welded_vertices = 0;   // coincident vertices welded away (io/weld.h)
};

// Reads a polygon mesh (format from the extension, case-insensitive; the
// formats and syntax accepted are listed in io/soup_readers.h).
// The result keeps the file's vertex order and count: vertex i is the i-th
// vertex of the file (isolated vertices included).
// Repairs: inconsistently oriented faces are re-oriented (counted in `info`).
// Throws InputError naming the file (and the line where it can be known) for:
// a missing path or one that is not a regular file (a FIFO, a device, a
// socket, a directory: refused without opening it for reading, see
// io/input_file.h), an unreadable file, an unknown extension, a parse
// error, non-finite coordinates, a coordinate of magnitude 1e150 or more or
// a mesh less than 1e-150 across (core/magnitude.h), a face index out of range (OBJ: 1-based, or
// negative = relative to the vertices read so far), a face with fewer than 3
// distinct vertices, a degenerate face (zero area), an empty mesh (no faces),
// a non-manifold or non-orientable mesh (one that cannot be a Surface_mesh
// without duplicating vertices), a file that holds fewer or more records than
// its header declares (OFF, PLY), and a file beyond `limits` (the message
// names the spec key that raises the limit). Declared counts are checked
// against the file size and `limits` before anything is allocated, so the
// work and memory are proportional to the file's size.
Mesh ReadMesh(const std::string& path, ReadInfo* info = nullptr,
              const ReadLimits& limits = ReadLimits());

// ReadMesh on a file's content already in memory: `name` gives the format
// (its extension) and names the file in messages; nothing is opened. Same
// checks and results as ReadMesh (which reads the file and calls this), so
// the fuzzers (fuzz/) exercise exactly the readers' code path.
Mesh ReadMeshFromMemory(const std::string& name, std::string_view data, ReadInfo* info = nullptr,
                        const ReadLimits& limits = ReadLimits());

// Throws InputError unless `path` ends in a supported mesh extension
// (.obj, .off, .ply, any case): lets a run reject a bad output name before
// doing any work.
void CheckMeshExtension(const std::string& path);

using Rgb = std::array<unsigned char, 3>;

// A named scalar per face or per vertex, written as a PLY property
// `float <name>` of the face or vertex element.
struct PlyValues {
  std::string name;            // a PLY property name: letters, digits, '_'
  std::vector<double> values;  // one per face (vertex), indexed by face (vertex) index
};

// Writes `mesh` to `path` (format from the extension: .obj, .off, .ply),
// full double precision. PLY is binary little-endian unless `ascii_ply`;
// `face_colors` (one per face, indexed by face index) is written as PLY
// face properties uchar red/green/blue, `face_values` as float face
// properties after them and `vertex_values` as float vertex properties
// after x y z; all three are ignored for OBJ/OFF. PLY layout: vertex x y z
// (double) [values], face vertex_indices (uchar count, int indices) [red
// green blue] [values]. Writes exactly `path` (use StagedOutputs for atomic
// outputs). Throws InputError (naming `path`) if the file cannot be written,
// the extension is unknown, a PLY face has more than 255 vertices, or a
// vertex has a non-finite coordinate (the message names the first such
// vertex, numbered as in the file; nothing is written), since no reader
// could read such a file back.
void WriteMesh(const std::string& path, const Mesh& mesh,
               const std::vector<Rgb>* face_colors = nullptr, bool ascii_ply = false,
               const std::vector<PlyValues>* face_values = nullptr,
               const std::vector<PlyValues>* vertex_values = nullptr);

}  // namespace archgeo
