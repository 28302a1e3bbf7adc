// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/commands/spectral.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "core/input_error.h"
#include "geometry/reference.h"
#include "io/io.h"
#include "mesh/eigen_point.h"
#include "spectral/eigenpairs.h"

namespace archgeo {

SpectralMesh SpectralArrays(const Mesh& mesh) {
  SpectralMesh out;
  for (VertexIndex v : mesh.vertices()) out.points.push_back(EigenPoint(mesh, v));
  for (FaceIndex f : mesh.faces()) {
    std::array<int, 3> t{};
    int c = 0;
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) t[size_t(c++)] = int(v.idx());
    out.triangles.push_back(t);
    out.area += 0.5 * (out.points[t[1]] - out.points[t[0]])
                          .cross(out.points[t[2]] - out.points[t[0]])
                          .norm();
  }
  out.rings.resize(mesh.number_of_vertices());
  out.closed.resize(mesh.number_of_vertices());
  for (VertexIndex v : mesh.vertices()) {
    out.closed[v.idx()] = !mesh.is_border(v);
    out.has_boundary = out.has_boundary || mesh.is_border(v);
    if (mesh.is_isolated(v)) continue;
    // A boundary vertex's ring runs over its faces from one boundary
    // neighbour to the other: after the border halfedge into v, whose
    // source and the next one's span the gap.
    HalfedgeIndex start = mesh.halfedge(v);
    for (HalfedgeIndex h : mesh.halfedges_around_target(mesh.halfedge(v))) {
      if (mesh.is_border(h)) start = mesh.opposite(mesh.next(h));
    }
    for (VertexIndex u : mesh.vertices_around_target(start)) {
      out.rings[v.idx()].push_back(int(u.idx()));
    }
  }
  out.euler = int(mesh.number_of_vertices()) - int(mesh.number_of_edges()) +
              int(mesh.number_of_faces());
  return out;
}

namespace {

std::string Row(int k, double lambda, const CriticalPoints& c) {
  char line[160];
  std::snprintf(line, sizeof line, "%4d  %10.4e  %5d %5d  %7d (%d)  %3d %3d %3d  %g", k, lambda,
                c.maxima, c.minima, c.saddles, c.multi_saddles, c.boundary_maxima,
                c.boundary_minima, c.boundary_saddles, c.EulerSum());
  return line;
}

}  // namespace

std::vector<SpectralCandidate> SpectralCandidatesOf(const SpectralMesh& m,
                                                    const Eigenpairs& pairs) {
  std::vector<SpectralCandidate> out;
  for (int k = 1; k < int(pairs.values.size()); ++k) {
    out.push_back({k, pairs.values[k], FindCriticalPoints(m.rings, m.closed, pairs.vectors.col(k))});
  }
  return out;
}

std::vector<SpectralCandidate> SpectralCandidates(const Mesh& triangles, int count,
                                                  LaplacianKind kind) {
  const SpectralMesh m = SpectralArrays(triangles);
  const Laplacian laplacian = BuildLaplacian(m.points, m.triangles, kind);
  return SpectralCandidatesOf(m, LowestEigenpairs(laplacian.stiffness, laplacian.mass, count));
}

int SpectralCharts(const CriticalPoints& c) { return c.saddles + c.boundary_saddles / 2; }

int SpectralTarget(double area, int charts, double edge_length) {
  if (charts > 0) return charts;
  return edge_length > 0 ? int(std::lround(area / (edge_length * edge_length))) : 0;
}

std::vector<int> SpectralByTarget(const std::vector<SpectralCandidate>& candidates, int target) {
  std::vector<int> order(candidates.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = int(i);
  auto gap = [&](int i) { return std::abs(SpectralCharts(candidates[size_t(i)].critical) - target); };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    return gap(a) != gap(b) ? gap(a) < gap(b) : candidates[size_t(a)].k < candidates[size_t(b)].k;
  });
  return order;
}

std::string SpectralList(const SpectralRequest& q) {
  if (q.laplacian != "cotangent" && q.laplacian != "normalised") {
    throw InputError("", 0, "--laplacian", "must be cotangent or normalised");
  }
  if (q.charts < 0 || q.edge_length < 0 || !std::isfinite(q.edge_length)) {
    throw InputError("", 0, q.charts < 0 ? "--charts" : "--edge-length", "must be positive");
  }
  const Mesh mesh = TriangulatedCopy(ReadMesh(q.mesh));
  const SpectralMesh m = SpectralArrays(mesh);
  if (q.count < 2 || q.count >= int(m.points.size())) {
    throw InputError(q.mesh, 0, "--count",
                     "must be at least 2 and below the mesh's " + std::to_string(m.points.size()) +
                         " vertices");
  }
  std::vector<SpectralCandidate> candidates;
  try {
    candidates = SpectralCandidates(mesh, q.count,
                                    q.laplacian == "cotangent" ? LaplacianKind::kCotangent
                                                               : LaplacianKind::kNormalised);
  } catch (const std::invalid_argument& e) {
    throw InputError(q.mesh, 0, "--laplacian", e.what());
  } catch (const std::runtime_error& e) {
    throw InputError(q.mesh, 0, "--count", e.what());
  }
  const int target = SpectralTarget(m.area, q.charts, q.edge_length);
  std::string text = "spectral: " + q.laplacian + " Laplacian of " + q.mesh + " (" +
                     std::to_string(m.points.size()) + " vertices, " +
                     std::to_string(m.triangles.size()) + " triangles, Euler characteristic " +
                     std::to_string(m.euler) + (m.has_boundary ? ", with boundary" : ", closed") +
                     ")\n";
  text += "   k  eigenvalue    max   min  saddles (multi)  boundary max min saddles  "
          "euler\n";
  for (const SpectralCandidate& c : candidates) text += Row(c.k, c.eigenvalue, c.critical) + "\n";
  const int best =
      candidates.empty() ? -1 : candidates[size_t(SpectralByTarget(candidates, target)[0])].k;
  text += "charts: one per saddle, half per boundary saddle (the Morse-Smale complex of "
          "eigenfunction k); euler: max + "
          "min - saddles, boundary points counted half, = " + std::to_string(m.euler) +
          " (the Euler characteristic) for every k\n";
  if (target > 0) {
    text += "closest to " + std::to_string(target) + " charts: k = " + std::to_string(best) + "\n";
  }
  return text;
}

}  // namespace archgeo
