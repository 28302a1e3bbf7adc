// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// `archgeo spectral MESH --complex OUT.obj --eigenfunction K`: the
// Morse–Smale complex of eigenfunction K (spectral/morse_smale.h), of the
// mesh doubled across its boundary when it has one
// (problems/declarations/surface_complex.h).
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <unordered_map>

#include "core/input_error.h"
#include "geometry/reference.h"
#include "io/io.h"
#include "io/output_files.h"
#include "problems/commands/spectral.h"
#include "problems/declarations/surface_complex.h"
#include "spectral/eigenpairs.h"
#include "spectral/morse_smale.h"

namespace archgeo {
namespace {

std::string ComplexPoint(const Eigen::Vector3d& p) {
  char line[96];
  std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p.x(), p.y(), p.z());
  return line;
}

void ComplexCheckRequest(const SpectralRequest& q, int vertices) {
  if (q.eigenfunction < 1 || q.eigenfunction >= vertices) {
    throw InputError(q.mesh, 0, "--eigenfunction",
                     "must be at least 1 and below the mesh's " + std::to_string(vertices) +
                         " vertices");
  }
  if (q.cancel_to < 0) throw InputError("", 0, "--cancel-to", "must be 0 or positive");
  if (q.laplacian != "cotangent" && q.laplacian != "normalised") {
    throw InputError("", 0, "--laplacian", "must be cotangent or normalised");
  }
}

}  // namespace

// The arcs as polylines over the vertices they use.
std::string MorseSmaleArcsObj(const MorseSmaleComplex& c, const std::string& header) {
  std::string vertices, lines;
  std::unordered_map<int, int> index;
  for (const MorseSmaleArc& a : c.arcs) {
    lines += "l";
    for (int v : a.path) {
      auto [it, fresh] = index.try_emplace(v, int(index.size()) + 1);
      if (fresh) vertices += ComplexPoint(c.points[size_t(v)]);
      lines += " " + std::to_string(it->second);
    }
    lines += "\n";
  }
  return "# " + header + "\n" + vertices + lines;
}

std::string QuasiDualObj(const QuadBaseComplex& q, const std::string& header) {
  std::string text = "# " + header + "\n";
  for (const Eigen::Vector3d& p : q.points) text += ComplexPoint(p);
  for (const std::array<int, 4>& f : q.quads) {
    text += "f " + std::to_string(f[0] + 1) + " " + std::to_string(f[1] + 1) + " " +
            std::to_string(f[2] + 1) + " " + std::to_string(f[3] + 1) + "\n";
  }
  return text;
}

SpectralComplexResult SpectralComplex(const SpectralRequest& q) {
  if (q.persistence < 0 || !std::isfinite(q.persistence)) {
    throw InputError("", 0, "--persistence", "must be 0 or positive");
  }
  const Mesh mesh = TriangulatedCopy(ReadMesh(q.mesh));
  const SpectralMesh m = SpectralArrays(mesh);
  ComplexCheckRequest(q, int(m.points.size()));
  Eigenpairs pairs;
  try {
    const Laplacian l = BuildLaplacian(m.points, m.triangles,
                                       q.laplacian == "cotangent" ? LaplacianKind::kCotangent
                                                                  : LaplacianKind::kNormalised);
    pairs = LowestEigenpairs(l.stiffness, l.mass, q.eigenfunction + 1);
  } catch (const std::invalid_argument& e) {
    throw InputError(q.mesh, 0, "--laplacian", e.what());
  } catch (const std::runtime_error& e) {
    throw InputError(q.mesh, 0, "--eigenfunction", e.what());
  }
  Eigen::VectorXd f = pairs.vectors.col(q.eigenfunction);
  f /= std::max(f.cwiseAbs().maxCoeff(), 1e-300);  // max |φ_k| = 1
  MorseSmaleOptions options;
  options.persistence = q.persistence;
  options.target_extrema = q.cancel_to;
  const SurfaceComplex s = BuildSurfaceComplex(mesh, f, options);
  if (!s.built) throw InputError(q.mesh, 0, "--complex", s.error);
  const MorseSmaleComplex& c = s.complex;
  const QuadBaseComplex& dual = s.quasi_dual;
  const std::string function = "eigenfunction " + std::to_string(q.eigenfunction);
  StagedOutputs staged({q.mesh});
  if (!q.complex_out.empty()) {
    staged.Write(q.complex_out, "--complex", [&](const std::string& path) {
      WriteTextFile(path, SurfaceComplexArcsObj(s, function), "--complex");
    });
  }
  if (!q.quasi_dual_out.empty()) {
    staged.Write(q.quasi_dual_out, "--quasi-dual", [&](const std::string& path) {
      WriteTextFile(path, SurfaceQuasiDualObj(s), "--quasi-dual");
    });
  }
  staged.Commit();
  char text[640];
  std::snprintf(text, sizeof text,
                "spectral complex: eigenfunction %d (eigenvalue %.6g) of %s\n"
                "max %d  min %d  saddles %d  (max + min - saddles = %d)\n"
                "cancelled pairs %d  arcs %zu  rerouted %d  unresolved %d  shared vertices %d\n"
                "cells %zu  invalid cells %d  valid %s\n"
                "quasi-dual: %zu vertices  %zu quads  degenerate %d  irregular vertices %d  "
                "V - E + F = %d\n",
                q.eigenfunction, pairs.values[q.eigenfunction], q.mesh.c_str(), c.maxima,
                c.minima, c.saddles, c.maxima + c.minima - c.saddles, c.cancelled, c.arcs.size(),
                c.rerouted, c.unresolved, c.shared_vertices, c.cells.size(), c.invalid_cells,
                c.valid ? "yes" : "no", dual.points.size(), dual.quads.size(),
                dual.degenerate_quads, dual.irregular_vertices, dual.euler);
  SpectralComplexResult out;
  out.text = text;
  if (s.doubled) {
    out.text += "the counts are those of the mesh doubled across its boundary (V - E + F = " +
                std::to_string(2 * m.euler) +
                "): nodes, arcs and quads on the boundary once, the others twice\n";
    if (c.valid) {
      // The base complex spectral_quads charts on the surface itself.
      try {
        const BaseComplex half = HalfBaseComplex(s);
        size_t quads = 0;
        for (const auto& face : half.faces) quads += face.size() == 4;
        out.text += "on the surface: " + std::to_string(half.nodes.size()) + " nodes, " +
                    std::to_string(quads) + " quads, " + std::to_string(half.faces.size() - quads) +
                    " triangles along the boundary (the half of the quasi-dual)\n";
      } catch (const BaseComplexError& e) {
        out.text += std::string("on the surface: no base complex: ") + e.what() + "\n";
      }
    }
  }
  if (s.refinements > 0) {
    out.text += "the arcs lie on the mesh refined " + std::to_string(s.refinements) +
                " times (the same critical points)\n";
  }
  out.valid = c.valid;
  if (!c.valid) {
    out.why = "the complex of eigenfunction " + std::to_string(q.eigenfunction) +
              " is not a valid quad complex (" + std::to_string(c.invalid_cells) +
              " invalid cells, " + std::to_string(c.unresolved) + " arcs not placed)";
  }
  return out;
}

}  // namespace archgeo
