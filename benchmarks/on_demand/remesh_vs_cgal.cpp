// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo benchmark — isotropic remeshing (problem `remesh`,
// geometry/isotropic_remesh.h; Gebreiter 2012, §3.1.2) beside CGAL 5.5's
// Polygon_mesh_processing::isotropic_remeshing at the same target edge length
// (the input's mean edge × --edge-length), the same iterations (10), the same
// feature edges (dihedral angle > 30°) and corners (boundary turning > 30°,
// feature ends) as constraints CGAL may split and collapse, and relax along
// (relax_constraints true) or not (false, CGAL's default), and
// every figure measured the same way on both outputs: the share of triangles
// whose every angle is ≥ 30°, the smallest angle, the edge-length coefficient
// of variation, the largest distance of an output boundary vertex from the
// input's boundary polylines, the Hausdorff distance to the input (CGAL's
// approximate symmetric Hausdorff distance, grid sampling), and the median
// wall time of three runs.
//
// Built on demand (CGAL's remeshing and distance headers cost more compile
// time than the rest of the benchmarks): 
//   ninja -C build remesh_vs_cgal
//   build/benchmarks/remesh_vs_cgal [--edge-length 1] MESH...
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <CGAL/Polygon_mesh_processing/distance.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>

#include "geometry/isotropic_remesh.h"
#include "geometry/reference.h"
#include "io/io.h"

namespace {

using namespace archgeo;
namespace PMP = CGAL::Polygon_mesh_processing;
using Clock = std::chrono::steady_clock;

double MeanEdge(const Mesh& m) {
  double sum = 0;
  for (EdgeIndex e : m.edges()) {
    sum += std::sqrt(CGAL::squared_distance(m.point(m.source(m.halfedge(e))), m.point(m.target(m.halfedge(e)))));
  }
  return sum / double(m.number_of_edges());
}

double Diagonal(const Mesh& m) {
  const CGAL::Bbox_3 b = PMP::bbox(m);
  return std::sqrt(std::pow(b.xmax() - b.xmin(), 2) + std::pow(b.ymax() - b.ymin(), 2) +
                   std::pow(b.zmax() - b.zmin(), 2));
}

Vector FaceNormal(const Mesh& m, HalfedgeIndex h) {
  const Point& a = m.point(m.source(h));
  return CGAL::cross_product(m.point(m.target(h)) - a, m.point(m.target(m.next(h))) - a);
}

// The constraints IsotropicRemesh derives, as CGAL's maps: feature edges
// (dihedral > 30°) and corners (boundary turning > 30°; feature vertices with
// other than two feature edges or on the boundary).
void MarkConstraints(Mesh& m, Mesh::Property_map<EdgeIndex, bool> edges,
                     Mesh::Property_map<VertexIndex, bool> corners) {
  const double limit = std::cos(30 * M_PI / 180);
  std::vector<int> count(m.number_of_vertices(), 0);
  for (EdgeIndex e : m.edges()) {
    if (m.is_border(e)) continue;
    const HalfedgeIndex h = m.halfedge(e);
    Vector n1 = FaceNormal(m, h), n2 = FaceNormal(m, m.opposite(h));
    if (n1 * n2 >= limit * std::sqrt(n1.squared_length() * n2.squared_length())) continue;
    edges[e] = true;
    ++count[m.source(h).idx()];
    ++count[m.target(h).idx()];
  }
  for (HalfedgeIndex h : m.halfedges()) {
    if (!m.is_border(h)) continue;
    const VertexIndex v = m.target(h);
    Vector in = m.point(v) - m.point(m.source(h)), out = m.point(m.target(m.next(h))) - m.point(v);
    if (in * out < limit * std::sqrt(in.squared_length() * out.squared_length())) corners[v] = true;
    if (count[v.idx()] > 0) corners[v] = true;
  }
  for (VertexIndex v : m.vertices()) {
    if (count[v.idx()] > 0 && count[v.idx()] != 2) corners[v] = true;
  }
}

Mesh CgalRemesh(const Mesh& input, double target, bool relax) {
  Mesh m = TriangulatedCopy(input);
  auto edges = m.add_property_map<EdgeIndex, bool>("e:constrained", false).first;
  auto corners = m.add_property_map<VertexIndex, bool>("v:constrained", false).first;
  MarkConstraints(m, edges, corners);
  PMP::isotropic_remeshing(faces(m), target, m,
                           CGAL::parameters::number_of_iterations(10)
                               .edge_is_constrained_map(edges)
                               .vertex_is_constrained_map(corners)
                               .protect_constraints(false)
                               .relax_constraints(relax));
  m.collect_garbage();
  return m;
}

struct Row {
  TriangleQuality q;
  double boundary = 0, hausdorff = 0, seconds = 0;
  size_t faces = 0;
};

Row Measure(const Mesh& input, const ReferenceSurface& surface, const Mesh& out, double seconds) {
  Row r;
  r.q = MeasureTriangles(out);
  r.faces = out.number_of_faces();
  r.seconds = seconds;
  for (VertexIndex v : out.vertices()) {
    if (!out.is_border(v)) continue;
    const Point& p = out.point(v);
    const auto c = surface.ClosestOnBoundary({p.x(), p.y(), p.z()});
    if (c) {
      r.boundary = std::max(r.boundary, std::sqrt(CGAL::squared_distance(p, Point(c->point[0], c->point[1], c->point[2]))));
    }
  }
  const Mesh tri = TriangulatedCopy(input);
  const double spacing = 0.25 * MeanEdge(tri);
  r.hausdorff = PMP::approximate_symmetric_Hausdorff_distance<CGAL::Sequential_tag>(
      tri, out, CGAL::parameters::use_grid_sampling(true).grid_spacing(spacing),
      CGAL::parameters::use_grid_sampling(true).grid_spacing(spacing));
  return r;
}

template <class F>
std::pair<Mesh, double> Timed(F remesh) {
  std::vector<double> times;
  Mesh out;
  for (int k = 0; k < 3; ++k) {
    const auto t0 = Clock::now();
    out = remesh();
    times.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  std::sort(times.begin(), times.end());
  return {std::move(out), times[1]};
}

void Print(const char* who, const Row& r, double diagonal) {
  std::printf("| %s | %zu | %.2f%% | %.1f° | %.3f | %.1e | %.3f%% | %.2f s |\n", who, r.faces,
              100 * r.q.min_angle_30_fraction, r.q.min_angle_degrees, r.q.edge_cv, r.boundary / diagonal,
              100 * r.hausdorff / diagonal, r.seconds);
}

}  // namespace

int main(int argc, char** argv) {
  double relative = 1;
  std::vector<std::string> meshes;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--edge-length" && i + 1 < argc) {
      relative = std::atof(argv[++i]);
    } else if (a.rfind("--", 0) == 0) {
      std::fprintf(stderr, "usage: remesh_vs_cgal [--edge-length R] MESH...\n");
      return 2;
    } else {
      meshes.push_back(a);
    }
  }
  if (meshes.empty() || !(relative > 0)) {
    std::fprintf(stderr, "usage: remesh_vs_cgal [--edge-length R] MESH...\n");
    return 2;
  }
  for (const std::string& path : meshes) {
    Mesh input;
    try {
      input = ReadMesh(path);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s: %s\n", path.c_str(), e.what());
      return 2;
    }
    const double target = relative * MeanEdge(input), diagonal = Diagonal(input);
    const ReferenceSurface surface(input);
    std::printf("\n%s: %zu faces, target edge %.4g (%.3g × the mean edge), diagonal %.4g\n\n", path.c_str(),
                size_t(input.number_of_faces()), target, relative, diagonal);
    std::printf("| remesher | triangles | angles ≥ 30° | smallest angle | edge CV | boundary off (÷ diagonal) | "
                "Hausdorff (÷ diagonal) | time (median of 3) |\n|---|---|---|---|---|---|---|---|\n");
    RemeshOptions o;
    o.target_edge_length = target;
    o.feature_angle_degrees = 30;
    auto [ours, ours_s] = Timed([&] { return IsotropicRemesh(input, o).mesh; });
    Print("archgeo remesh", Measure(input, surface, ours, ours_s), diagonal);
    auto [cgal, cgal_s] = Timed([&] { return CgalRemesh(input, target, true); });
    Print("CGAL, constraints relaxed", Measure(input, surface, cgal, cgal_s), diagonal);
    auto [fixed, fixed_s] = Timed([&] { return CgalRemesh(input, target, false); });
    Print("CGAL, constraints not relaxed", Measure(input, surface, fixed, fixed_s), diagonal);
  }
  return 0;
}
