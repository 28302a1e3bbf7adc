// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — files of the field pipeline: the field as a viewable PLY of line
// segments, and libigl's dense-matrix (DMAT) files of per-face constraints.
//
// Include only where CGAL is acceptable (pulls in mesh/surface_mesh.h).
#pragma once

#include <string>

#include <Eigen/Core>

#include "fields/streamlines.h"
#include "fields/tcd_field.h"
#include "mesh/similarity.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

// The field as an ASCII PLY that mesh viewers (MeshLab, CloudCompare) show:
// per valid face two line segments through its centroid (`element edge`),
// v red and w blue, each 0.7·sqrt(2·area) long; then one vertex per
// singularity (not on an edge: shown as a point), yellow for index > 0 and
// magenta for index < 0, its index in a `comment` line. `mesh`, `geometry`
// and `field` in the canonical frame; written in file units (`frame`).
// Throws InputError(path, 0, key, ...) when the file cannot be written.
void WriteFieldPly(const std::string& path, const Mesh& mesh, const FieldGeometry& geometry,
                   const TcdField& field, const Similarity& frame, const std::string& key);

// The arrays fields/streamlines.h traces on: `mesh`'s vertices and faces (by
// index; no garbage), v and w of every face as 3-D vectors, the singularities.
StreamlineInput StreamlineInputOf(const Mesh& mesh, const FieldGeometry& geometry,
                                  const TcdField& field);

// The lines as an OBJ of polylines (`v` and `l` records; a closed line repeats
// its first vertex): the groups `g v` and `g w` (the streamlines of each
// family) and `g separatrices`, in file units (`frame`). Throws
// InputError(path, 0, key, ...) when the file cannot be written.
void WriteStreamlinesObj(const std::string& path, const std::vector<Streamline>& lines,
                         const Similarity& frame, const std::string& key);

// Directional's raw field (directional::read_raw_field / write_raw_field,
// the tutorial's *.rawfield files): a first line "N F", then one line per
// face of 3N numbers, its N vectors (x y z each, extrinsic, file units).
struct RawField {
  int n = 0;                // directions per face
  Eigen::MatrixXd vectors;  // F × 3N
};
// Throws InputError(path, line, key, ...) for a file that cannot be read, a
// bad header, a line without 3N numbers or with a non-finite one, or fewer
// lines than F.
RawField ReadRawField(const std::string& path, const std::string& key);

// The field as a raw field of degree 4 (v, w, −v, −w per face, unit vectors in
// file units; zeros for a face without a valid pair), which
// ReadRawField / `field.file` read back and Directional's viewers show.
void WriteFieldRaw(const std::string& path, const Mesh& mesh, const FieldGeometry& geometry,
                   const TcdField& field, const Similarity& frame, const std::string& key);

// WriteFieldRaw if `name` (the path the user gave) ends in .rawfield, else
// WriteFieldPly; written to `path`.
void WriteField(const std::string& path, const std::string& name, const Mesh& mesh,
                const FieldGeometry& geometry, const TcdField& field, const Similarity& frame,
                const std::string& key);

// A libigl DMAT file (igl::readDMAT, ASCII): a first line "cols rows", then
// cols·rows numbers in column-major order (all of column 0 first). Throws
// InputError(path, line, key, ...) for a file that cannot be read or does not
// follow the format (the binary variant, "0 0" followed by a binary header,
// is refused with a message).
Eigen::MatrixXd ReadDmat(const std::string& path, const std::string& key);

}  // namespace archgeo
