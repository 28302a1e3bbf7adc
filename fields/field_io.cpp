// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fields/field_io.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/input_error.h"
#include "io/output_files.h"

namespace archgeo {
namespace {

std::string Xyz(const Eigen::Vector3d& x) {
  char s[96];
  std::snprintf(s, sizeof s, "%.9g %.9g %.9g", x.x(), x.y(), x.z());
  return s;
}

Eigen::Vector3d InFile(const Similarity& frame, const Eigen::Vector3d& x) {
  const Vec3 y = frame.FromCanonical(Vec3{x.x(), x.y(), x.z()});
  return Eigen::Vector3d(y[0], y[1], y[2]);
}

}  // namespace

void WriteFieldPly(const std::string& path, const Mesh& mesh, const FieldGeometry& geometry,
                   const TcdField& field, const Similarity& frame, const std::string& key) {
  std::vector<std::string> vertices, edges;
  for (FaceIndex f : mesh.faces()) {
    const ConjugatePair& pair = field.pairs[f.idx()];
    if (!pair.valid) continue;
    const double length = 0.7 * std::sqrt(2.0 * geometry.frames.area[f.idx()]);
    const Eigen::Vector3d c = geometry.frames.centroid[f.idx()];
    for (int k = 0; k < 2; ++k) {
      const Eigen::Vector3d d = FromFrame(geometry.frames, f, k == 0 ? pair.v : pair.w);
      const char* rgb = k == 0 ? "220 50 40" : "40 90 220";
      const size_t first = vertices.size();
      vertices.push_back(Xyz(InFile(frame, c - 0.5 * length * d)) + " " + rgb);
      vertices.push_back(Xyz(InFile(frame, c + 0.5 * length * d)) + " " + rgb);
      edges.push_back(std::to_string(first) + " " + std::to_string(first + 1) + " " + rgb);
    }
  }
  std::string comments;
  for (const Singularity& s : field.singularities) {
    const Eigen::Vector3d p = InFile(frame, s.position);
    char line[160];
    std::snprintf(line, sizeof line, "comment singularity index %+g at %s (vertex %d)\n", s.index,
                  Xyz(p).c_str(), static_cast<int>(s.vertex.idx()));
    comments += line;
    vertices.push_back(Xyz(p) + (s.index > 0 ? " 250 220 0" : " 230 0 230"));
  }
  std::ostringstream out;
  out << "ply\nformat ascii 1.0\n"
      << "comment archgeo TCD field [Zadravec 2010]: per face the conjugate directions v (red) "
         "and w (blue) through the face centroid; singularities as points (yellow +, magenta -)\n"
      << comments << "element vertex " << vertices.size()
      << "\nproperty float x\nproperty float y\nproperty float z\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\n"
      << "element edge " << edges.size()
      << "\nproperty int vertex1\nproperty int vertex2\n"
         "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  for (const std::string& v : vertices) out << v << "\n";
  for (const std::string& e : edges) out << e << "\n";
  WriteTextFile(path, out.str(), key);
}

namespace {

bool EndsWithRawfield(const std::string& name) {
  const std::string suffix = ".rawfield";
  if (name.size() < suffix.size()) return false;
  std::string end = name.substr(name.size() - suffix.size());
  for (char& ch : end) ch = char(std::tolower(static_cast<unsigned char>(ch)));
  return end == suffix;
}

}  // namespace

void WriteFieldRaw(const std::string& path, const Mesh& mesh, const FieldGeometry& geometry,
                   const TcdField& field, const Similarity& frame, const std::string& key) {
  std::ostringstream out;
  out.precision(17);
  out << 4 << " " << mesh.number_of_faces() << "\n";
  for (FaceIndex f : mesh.faces()) {
    const ConjugatePair& pair = field.pairs[f.idx()];
    Eigen::Vector3d d[2] = {Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    if (pair.valid) {
      for (int k = 0; k < 2; ++k) {
        // A direction: the frame's rotation only (InFile of two points).
        const Eigen::Vector3d c = geometry.frames.centroid[f.idx()];
        d[k] = (InFile(frame, c + FromFrame(geometry.frames, f, k == 0 ? pair.v : pair.w)) - InFile(frame, c))
                   .normalized();
      }
    }
    for (const Eigen::Vector3d& x : {d[0], d[1], Eigen::Vector3d(-d[0]), Eigen::Vector3d(-d[1])}) {
      out << x.x() << " " << x.y() << " " << x.z() << " ";
    }
    out << "\n";
  }
  WriteTextFile(path, out.str(), key);
}

void WriteField(const std::string& path, const std::string& name, const Mesh& mesh,
                const FieldGeometry& geometry, const TcdField& field, const Similarity& frame,
                const std::string& key) {
  if (EndsWithRawfield(name)) {
    WriteFieldRaw(path, mesh, geometry, field, frame, key);
  } else {
    WriteFieldPly(path, mesh, geometry, field, frame, key);
  }
}

RawField ReadRawField(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, key, "cannot open the raw field file");
  std::string text;
  std::getline(in, text);
  std::istringstream h(text);
  long long n = -1, faces = -1;
  if (!(h >> n >> faces) || n < 1 || n > 64 || faces < 0) {
    throw InputError(path, 1, key, "expected a raw field header \"N F\" (N directions per face, 1–64; F faces)");
  }
  std::error_code error;
  const auto bytes = static_cast<long long>(std::filesystem::file_size(path, error));
  if (!error && faces > bytes / (6 * n)) {
    throw InputError(path, 1, key, "the header promises " + std::to_string(faces) + " faces, more than a file of " +
                                       std::to_string(bytes) + " bytes can hold");
  }
  RawField r;
  r.n = int(n);
  r.vectors.resize(faces, 3 * n);
  for (long long f = 0; f < faces; ++f) {
    const int line = int(f) + 2;
    if (!std::getline(in, text)) {
      throw InputError(path, line, key, "the header promises " + std::to_string(faces) +
                                            " faces; the file ends after " + std::to_string(f));
    }
    std::istringstream row(text);
    for (long long k = 0; k < 3 * n; ++k) {
      std::string token;
      if (!(row >> token)) {
        throw InputError(path, line, key, "expected " + std::to_string(3 * n) + " numbers (" + std::to_string(n) +
                                              " vectors) for face " + std::to_string(f) + ", found " +
                                              std::to_string(k));
      }
      char* end = nullptr;
      const double x = std::strtod(token.c_str(), &end);
      if (end == token.c_str() || *end != '\0' || !std::isfinite(x)) {
        throw InputError(path, line, key, "'" + token + "' is not a finite number");
      }
      r.vectors(f, k) = x;
    }
  }
  return r;
}

StreamlineInput StreamlineInputOf(const Mesh& mesh, const FieldGeometry& geometry,
                                  const TcdField& field) {
  StreamlineInput in;
  for (VertexIndex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    in.points.emplace_back(p.x(), p.y(), p.z());
  }
  for (FaceIndex f : mesh.faces()) {
    std::array<int, 3> t{};
    int k = 0;
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) {
      if (k < 3) t[size_t(k)] = int(v.idx());
      ++k;
    }
    in.triangles.push_back(t);
    const ConjugatePair& pair = field.pairs[f.idx()];
    in.directions.push_back({FromFrame(geometry.frames, f, pair.v).normalized(),
                             FromFrame(geometry.frames, f, pair.w).normalized()});
    in.valid.push_back(pair.valid && k == 3);
  }
  for (const Singularity& s : field.singularities) {
    in.singularities.push_back({int(s.vertex.idx()), s.index});
  }
  return in;
}

void WriteStreamlinesObj(const std::string& path, const std::vector<Streamline>& lines,
                         const Similarity& frame, const std::string& key) {
  std::ostringstream out;
  out << "# archgeo streamlines of a TCD field [Gebreiter 2012, §8.2]: groups v, w (the two "
         "families) and separatrices\n";
  size_t next = 1;
  for (const char* group : {"v", "w", "separatrices"}) {
    out << "g " << group << "\n";
    for (const Streamline& l : lines) {
      const bool in_group =
          std::string(group) == "separatrices" ? l.separatrix
                                               : !l.separatrix && l.family == (group[0] == 'w');
      if (!in_group || l.points.size() < 2) continue;
      for (const Eigen::Vector3d& p : l.points) out << "v " << Xyz(InFile(frame, p)) << "\n";
      out << "l";
      for (size_t i = 0; i < l.points.size(); ++i) out << " " << next + i;
      if (l.closed) out << " " << next;
      out << "\n";
      next += l.points.size();
    }
  }
  WriteTextFile(path, out.str(), key);
}

Eigen::MatrixXd ReadDmat(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, key, "cannot open the DMAT file");
  std::string header;
  std::getline(in, header);
  std::istringstream h(header);
  long long cols = -1, rows = -1;
  if (!(h >> cols >> rows) || cols < 0 || rows < 0) {
    throw InputError(path, 1, key, "expected a DMAT header \"cols rows\"");
  }
  if (cols == 0 && rows == 0) {
    throw InputError(path, 1, key, "binary DMAT files are not supported; write it as ASCII");
  }
  // Every number takes at least two bytes (a digit and a separator): a
  // header promising more than the file can hold is refused before the
  // matrix is allocated.
  std::error_code error;
  const auto bytes = static_cast<long long>(std::filesystem::file_size(path, error));
  const long long room = error ? 0 : bytes / 2;
  if (cols > 0 && rows > room / cols) {
    throw InputError(path, 1, key,
                     "the header promises " + std::to_string(rows) + " x " + std::to_string(cols) +
                         " numbers, more than a file of " + std::to_string(bytes) +
                         " bytes can hold");
  }
  Eigen::MatrixXd m(rows, cols);
  int line = 2;  // the first number follows the header line
  for (long long c = 0; c < cols; ++c) {
    for (long long r = 0; r < rows; ++r) {
      std::string token;
      // One or more numbers per line; count lines for messages.
      while (true) {
        const int next = in.peek();
        if (next == '\n') ++line;
        if (next == EOF || !std::isspace(next)) break;
        in.get();
      }
      if (!(in >> token)) {
        throw InputError(path, line, key,
                         "the header promises " + std::to_string(rows) + " x " +
                             std::to_string(cols) + " numbers; the file ends after " +
                             std::to_string(c * rows + r));
      }
      char* end = nullptr;
      const double x = std::strtod(token.c_str(), &end);
      if (end == token.c_str() || *end != '\0' || !std::isfinite(x)) {
        throw InputError(path, line, key, "'" + token + "' is not a finite number");
      }
      m(r, c) = x;
    }
  }
  return m;
}

}  // namespace archgeo
