// archgeo — mesh files: OBJ, OFF, PLY (ASCII and binary), polygonal faces.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "mesh/surface_mesh.h"

namespace archgeo {

// What ReadMesh had to repair, for the run report.
struct ReadInfo {
  std::string format;        // "obj", "off" or "ply"
  int reoriented_faces = 0;  // faces flipped to make the orientation consistent
};

// Reads a polygon mesh (format from the extension, case-insensitive).
// The result keeps the file's vertex order and count: vertex i is the i-th
// vertex of the file (isolated vertices included).
// Repairs: inconsistently oriented faces are re-oriented (counted in `info`).
// Throws InputError naming the file (and the line where it can be known) for:
// a missing or unreadable file, an unknown extension, a parse error,
// non-finite coordinates, a face index out of range, a face with fewer than
// 3 distinct vertices, a degenerate face (zero area), an empty mesh (no
// faces), and a non-manifold or non-orientable mesh (one that cannot be a
// Surface_mesh without duplicating vertices).
Mesh ReadMesh(const std::string& path, ReadInfo* info = nullptr);

// Throws InputError unless `path` ends in a supported mesh extension
// (.obj, .off, .ply, any case): lets a run reject a bad output name before
// doing any work.
void CheckMeshExtension(const std::string& path);

using Rgb = std::array<unsigned char, 3>;

// Writes `mesh` to `path` (format from the extension: .obj, .off, .ply),
// full double precision. PLY is binary little-endian unless `ascii_ply`;
// `face_colors` (one per face, indexed by face index) is written as PLY
// face properties red/green/blue and ignored for OBJ/OFF. Writes exactly
// `path` (use StagedOutputs for atomic outputs). Throws InputError if the
// file cannot be written or the extension is unknown.
void WriteMesh(const std::string& path, const Mesh& mesh,
               const std::vector<Rgb>* face_colors = nullptr, bool ascii_ply = false);

}  // namespace archgeo
