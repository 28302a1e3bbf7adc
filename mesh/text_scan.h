// archgeo — plain-text pre-scan of ASCII OBJ/OFF/PLY mesh files (no CGAL).
//
// Step 1 of ReadMesh (mesh/io.cpp). CGAL's soup readers answer only
// true/false, and std::istream cannot parse "nan" or "inf". The scan records
// the line of every vertex and face record, rejects garbage and non-finite
// numbers with their line, and joins OFF face lists wrapped over several lines
// (CGAL's OFF reader reads one face per line; libigl's *_quads_*.off files
// wrap them). Binary files are left to CGAL.
// Messages number vertices and faces from 0, in file order; lines from 1.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace archgeo {

// 1-based lines of the vertex and face records of an ASCII file (empty for
// binary files); used only to point messages at the file.
struct LineMap {
  std::vector<int> vertex, face;
  int Vertex(std::size_t i) const { return i < vertex.size() ? vertex[i] : 0; }
  int Face(std::size_t i) const { return i < face.size() ? face[i] : 0; }
};

// Throws InputError for `path` at 1-based `line` (0 = unknown), no key.
[[noreturn]] void FailInput(const std::string& path, int line, const std::string& message);

// `token` in single quotes, for messages.
std::string QuoteToken(std::string_view token);

// "empty mesh" message for a file with `vertices` vertices and no faces.
std::string NoFacesMessage(std::size_t vertices);

// Message for face `face` (0-based) referring to a vertex index outside a
// file with `vertices` vertices.
std::string OutOfRangeMessage(std::size_t face, std::size_t vertices);

// The whole content of the file at `path` (read as binary). Throws
// InputError if it is a directory or cannot be opened or read.
std::string ReadFile(const std::string& path);

// OBJ: `v` and `f` records. `text` is the file's content; tabs become spaces
// in it: CGAL's OBJ reader skips from one face index to the next by looking
// for a space. Throws InputError (naming `path`) for a malformed vertex, an
// unparsable or zero face index, or no faces.
LineMap ScanObj(const std::string& path, std::string* text);

// OFF: the header, then one vertex per line, then faces "n i1 ... in [colour]"
// whose indices may wrap onto following lines. ASCII `text` is rewritten with
// one record per line and no comments; binary OFF is left to CGAL (empty
// LineMap, `text` unchanged). Throws InputError (naming `path`) for a bad
// header, missing records, a malformed vertex, or a bad face index.
LineMap ScanOff(const std::string& path, std::string* text);

// PLY: a header up to "end_header"; in ASCII PLY each element is one line, in
// the header's element order. Binary PLY is left to CGAL (empty LineMap).
// Throws InputError (naming `path`) for a bad header, missing elements, or a
// malformed vertex.
LineMap ScanPly(const std::string& path, const std::string& text);

}  // namespace archgeo
