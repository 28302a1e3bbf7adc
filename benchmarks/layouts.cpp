// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Our layouts beside the published ones of the same surfaces (issue 42):
// examples/conjugate_layout.yaml on a design surface, at the face count of
// the published layout, against that layout made planar by
// examples/planar_quads.yaml. Published layouts in ../shared/data: libigl's
// conjugate-field and smooth-field layouts of its inspired mesh, and two DOS
// nets (the botanic-garden bubble and the pillow), whose design surface is
// the net itself (conjugate_layout triangulates it).
//
//   cmake --build <build> --target archgeo_benchmarks
//   <build>/benchmarks/layouts [--set KEY=VALUE ...]
//
// Every figure is measured here: the shapes on the layouts (ours written to
// a scratch folder), the rest from the runs' reports: irregular vertices (interior, valence ≠ 4),
// non-quad faces, quads, the share of boundary faces (faces with a vertex on
// the boundary) that are quads with a whole edge on it, face areas over the
// median (5th and 95th percentile, and the share within 0.25–4×), δ_PQ,n
// before the PQ step (the layout as made or published) and after it, exit
// code and wall time (ours: field, level sets and PQ step; published: the PQ
// step). Informational: no acceptance is checked.
#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "benchmarks/bench_util.h"
#include "benchmarks/program.h"
#include "io/io.h"

namespace ARCHGEO_UNITY_ID {

using archgeo::FaceIndex;
using archgeo::Mesh;
using archgeo::VertexIndex;
using bench::Fmt;
using bench::Get;

struct Shape {
  int faces = 0, quads = 0, non_quads = 0, irregular = 0;
  double boundary_quads = 0;                   // share of boundary faces
  double area_p5 = 0, area_p95 = 0, area_in = 0;  // over the median; share in 0.25–4×
};

double Area(const Mesh& m, FaceIndex f) {
  Eigen::Vector3d n = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> p;
  for (VertexIndex v : m.vertices_around_face(m.halfedge(f))) {
    const auto& q = m.point(v);
    p.emplace_back(q.x(), q.y(), q.z());
  }
  for (size_t i = 0; i < p.size(); ++i) n += p[i].cross(p[(i + 1) % p.size()]);
  return 0.5 * n.norm();
}

Shape Measure(const Mesh& m) {
  Shape s;
  std::vector<double> area;
  int boundary_faces = 0, boundary_quads = 0;
  for (FaceIndex f : m.faces()) {
    ++s.faces;
    const bool quad = m.degree(f) == 4;
    quad ? ++s.quads : ++s.non_quads;
    area.push_back(Area(m, f));
    bool touches = false, edge_on = false;
    for (auto h : m.halfedges_around_face(m.halfedge(f))) {
      touches = touches || m.is_border(m.target(h), false);
      edge_on = edge_on || m.is_border(m.opposite(h));
    }
    if (!touches) continue;
    ++boundary_faces;
    if (quad && edge_on) ++boundary_quads;
  }
  for (VertexIndex v : m.vertices()) {
    if (!m.is_border(v, false) && m.degree(v) != 4) ++s.irregular;
  }
  s.boundary_quads = boundary_faces > 0 ? double(boundary_quads) / boundary_faces : 0.0;
  std::vector<double> sorted = area;
  std::sort(sorted.begin(), sorted.end());
  const auto at = [&](double q) { return sorted[size_t(q * double(sorted.size() - 1))]; };
  const double median = at(0.5);
  s.area_p5 = at(0.05) / median;
  s.area_p95 = at(0.95) / median;
  int in = 0;
  for (double a : area) in += a >= 0.25 * median && a <= 4 * median;
  s.area_in = double(in) / double(area.size());
  return s;
}

struct Row {
  const char* surface;  // the design surface (data file)
  const char* published;  // the published layout of it (data file)
  const char* who;
};

void Add(bench::Table& t, const std::string& label, const Shape& s, const std::string& singular,
         const bench::Json& r) {
  t.Add({label, Fmt("%d", s.faces), Fmt("%.1f%%", 100.0 * s.quads / s.faces),
         Fmt("%d / %d", s.irregular, s.non_quads), singular, Fmt("%.1f%%", 100 * s.boundary_quads),
         Fmt("%.2f–%.2f", s.area_p5, s.area_p95), Fmt("%.1f%%", 100 * s.area_in),
         Fmt("%.2e", Get(r, "/before/pq_normalized_max")), Fmt("%.2e", Get(r, "/after/pq_normalized_max")),
         Fmt("%d", r.value("exit_code", -1)), Fmt("%.1f", r.value("wall_seconds", 0.0))});
}

int Main(int argc, char** argv) {
  bench::Init(argc, argv);
  const Row rows[] = {
      {"libigl_inspired_mesh.obj", "libigl_inspired_mesh_quads_Conjugate.off", "libigl conjugate"},
      {"libigl_inspired_mesh.obj", "libigl_inspired_mesh_quads_Smooth.off", "libigl smooth"},
      {"dos_botanic-garden-bubble-0.obj", "dos_botanic-garden-bubble-0.obj", "DOS"},
      {"dos_pillow_1.obj", "dos_pillow_1.obj", "DOS"}};
  std::cout << "Our layouts (examples/conjugate_layout.yaml at the published face count) beside\n"
               "the published layouts of the same surfaces (examples/planar_quads.yaml); every\n"
               "figure measured here, on the written meshes\n\n";
  bench::Table t({"layout", "faces", "quads", "irregular v. / non-quads", "field sing.",
                  "boundary quads", "area p5–p95", "area 0.25–4×", "δ_PQ,n before", "δ_PQ,n after",
                  "exit", "sec"});
  int k = 0;
  for (const Row& row : rows) {
    const std::string tag = Fmt("layouts_%d", k++);
    const Mesh published = archgeo::ReadMesh(bench::Data(row.published));
    const bench::Json pq =
        bench::Solve(bench::Source("examples/planar_quads.yaml"), {"mesh=" + bench::Data(row.published)});
    Add(t, std::string(row.who) + ": " + row.published, Measure(published), "–", pq);
    const std::string layout = (bench::Scratch() / (tag + "_layout.obj")).string();
    const bench::Json ours =
        bench::Solve(bench::Source("examples/conjugate_layout.yaml"),
                     {"mesh=" + bench::Data(row.surface), "output.field=",
                      Fmt("level_sets.target_faces=%d", int(published.number_of_faces()))},
                     {}, {"output.layout=" + layout});
    const std::string singular =
        Fmt("%d", int(ours.at("details").at("net").at("field").at("singularities").size()));
    Add(t, std::string("ours: ") + row.surface, Measure(archgeo::ReadMesh(layout)), singular, ours);
  }
  t.Print();
  std::cout << "\nirregular v.: interior vertices of valence ≠ 4. field sing.: singularities of\n"
               "our field. boundary quads: the share of the faces with a vertex on the boundary\n"
               "that are quads with a whole edge on it. area: face areas over the median face's.\n"
               "The shapes are the layout's (ours: as made; published: as published); δ_PQ,n\n"
               "before the PQ step and after it (the final mesh); sec: wall time of the run\n"
               "(ours: field, level sets and PQ step; published: the PQ step).\n";
  return 0;
}

}  // namespace ARCHGEO_UNITY_ID

ARCHGEO_BENCHMARK_PROGRAM(layouts, ARCHGEO_UNITY_ID::Main);
