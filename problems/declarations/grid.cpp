// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `grid`: orthogonal, locally equilateral quad grids on parametric
// surfaces [force-directed grids paper, §3–4, Listing 1, Table 1].
//
// The problem makes its own input (no `mesh` file): the uniform n_u × n_v
// grid of `grid.type` on the surface named by `surface:` (surfaces/
// surface_factory.h), as a quad mesh whose vertex k is grid vertex k
// (j·n_u + i; generators/grid_mesh.h GridToMesh: a grid whose u-seam reflects v,
// the Klein bottle's, is cut open along that seam, as a Surface_mesh must be
// orientable). The variables are the vertices' surface parameters, the
// per-vertex block "uv" (output); positions are derived: after every round
// each vertex is put at x(u, v) (in the canonical frame), so every vertex
// lies on the surface by construction.
//
// Two methods (`method`):
//   least_squares (default): Ceres over the (u, v), autodiff through the
//     surface map; terms (energies/<name>.h, default weights):
//       grid_orthogonality        1     cos of the angle between the two lines
//                                       at each crossing (central differences)
//       grid_quad_equilaterality  1     the four sides of each quad equal
//       grid_equilaterality       0.01  (|e| − L)/L per edge: sets the size
//       grid_boundary             1     eq. 2's signed distance / L at each
//                                       boundary vertex
//       grid_fairness             0.3   second differences / L along the lines
//                                       (suppresses the zigzag that central
//                                       differences do not see)
//     Boundary (grid.boundary, surfaces/grid_cover.h): by default a grid
//     with an open direction holds its boundary rows on the sides of the
//     parameter domain (or of its centred part of area fraction
//     grid.coverage): a vertex on a side keeps that coordinate and slides
//     along the other, within the side's ends (energies/
//     grid_side_manifold.h; ceres::SubsetManifold along a closed direction),
//     a corner is constant. So the grid covers its patch, and the
//     terms make the best grid of that patch (the uniform grid starts on
//     it). With a free boundary an open direction has nothing that holds the
//     grid on its patch (the energy is lowest where the surface is
//     flattest): the centre vertex keeps its (u, v) (grid.anchor), and a
//     grid open in both directions that reaches beyond the domain by more
//     than grid.fit_tolerance of its length gets a smaller L and is solved
//     again (FitLength), until it lies on its patch: it contracts (to a
//     fifth of the Dupin bridge's patch). Ceres parameter bounds on (u, v)
//     would let an open grid that wants to grow pile up against the bound
//     (the Dupin bridge's corner quads collapse).
//   force: the paper's force-directed iterations (surfaces/force_directed.h,
//     Listing 1: eqs. 1–3; corners of open grids excluded; the boundary rows
//     put back on their sides of the domain after every step unless
//     grid.boundary is free), force.iterations per round, until a §4
//     threshold holds (tolerance.*), the disposition stalls or plateaus (the
//     stage ends, see StepResult::stop), or after force.rounds rounds.
// L, the constant ideal edge length [§3], is grid.ideal_length or the mean
// edge length of the initial grid (on a grid closed in one direction: of its
// closed lines, whose edges the closure fixes), in file units; the fitting
// shrinks it.
//
// Measures (logged every round, tolerances `tolerance.mdo|ado|mde|ade`, 0 =
// off): MDO, ADO (degrees; on the interpolating splines, eqs. 4–5) and MDE,
// ADE (percent; on the quad sides, eq. 6) of the whole grid, its seams
// included (surfaces/grid_quality.h Table1()); coverage (grid area / patch
// area) and parameter_coverage (the grid's (u, v) area / the domain's;
// surfaces/grid_cover.h), in `details.coverage_before|after` too. The
// report's before/after objects hold the four Table 1 measures, measured on
// the mesh by the "grid" analysis
// (problems/report/analysis.h; for the Klein bottle that is the grid cut open along
// its seam, as written to the files), and `details` the whole grid's.
//
// Outputs: output.mesh (the generic writer: positions and faces), and
// output.grid (.obj with one `vt u v` per vertex, or .ply with double vertex
// properties u, v; positions exactly x(u, v)).
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include <ceres/manifold.h>

#include "core/problem.h"
#include "core/newell.h"
#include "generators/grid_mesh.h"
#include "analysis/grid_metrics.h"
#include "core/input_error.h"
#include "energies/grid_side_manifold.h"
#include "problems/runtime/model.h"
#include "surfaces/force_directed.h"
#include "surfaces/grid.h"
#include "surfaces/grid_cover.h"
#include "surfaces/grid_quality.h"
#include "surfaces/surface_factory.h"

namespace archgeo::problems {
namespace {

constexpr const char* kMeasures[] = {"mdo", "ado", "mde", "ade"};

// The run's grid (the problem's state). The surface and L, file units, are
// in HookContext::grid, which the terms read; the surface lives here.
struct GridState : ProblemState {
  Grid grid;                 // topology and the initial (u, v)
  std::optional<Surface> surface;
  std::string surface_name;  // as named in the spec
  double initial_length = 0; // L before fitting to the domain
  int fits = 0;              // times L was shrunk to fit the domain
  int anchor = -1;           // the anchored vertex (least squares), or -1
  bool hold = false;         // open boundary rows held on `covered` (grid.boundary)
  ParameterDomain covered;   // the part of the domain they are held on
  double patch_area = 0;     // of the whole domain (file units²)
  long coverage_version = -1;  // of the cached coverage
  GridCoverage coverage;
  int omitted_faces = 0;     // seam quads a Surface_mesh cannot hold
  long version = -1;         // of the cached quality
  GridQuality quality;
  // Force method: iterations over all rounds, the last stop, the history.
  int force_iterations = 0;
  std::string force_stop;
  nlohmann::json force_history = nlohmann::json::array();
};

std::string Join(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

// `surface: {name: NAME, <parameter>: value, ...}`. Throws InputError naming
// the file, the line and the key (surface, surface.name, surface.<parameter>).
Surface ReadSurface(const Settings& s, std::string* name_out = nullptr) {
  const std::string names = Join(SurfaceNames());
  if (!s.Given("surface")) {
    throw s.Error("surface", "the grid problem needs surface: {name: NAME, <parameter>: value, "
                             "...} (names: " + names + ")");
  }
  const CustomValue& node = *s.Custom("surface");
  const Origin at = s.Where("surface");
  const auto line_of = [&](const CustomValue& n) {
    return at.file == "--set" || n.line <= 0 ? at.line : n.line;
  };
  if (!node.IsMap()) {
    throw InputError(at.file, line_of(node), "surface",
                     "expected a mapping {name: NAME, <parameter>: value, ...}, got " +
                         node.Describe() + " (names: " + names + ")");
  }
  std::string name;
  int name_line = at.line;
  ParameterValues values;
  std::map<std::string, int> lines;  // key -> line
  for (const CustomValue::Entry& entry : node.entries) {
    const std::string& key = entry.key.text;
    const std::string dotted = "surface." + key;
    const int line = line_of(entry.key);
    if (key.empty()) throw InputError(at.file, line, "surface", "a key must be a plain name");
    if (key == "name") {
      if (!entry.value.IsScalar()) {
        throw InputError(at.file, line, dotted, "expected a surface name (" + names + ")");
      }
      name = entry.value.text;
      name_line = line;
      continue;
    }
    if (!entry.value.number) {
      throw InputError(at.file, line, dotted, "expected a number, got " + entry.value.Describe());
    }
    values[key] = *entry.value.number;
    lines[dotted] = line;
  }
  if (name.empty()) {
    throw InputError(at.file, at.line, "surface.name",
                     "missing: the surface's name (" + names + ")");
  }
  if (name_out) *name_out = name;
  InputContext where;
  where.file = at.file;
  where.line = name_line;
  where.name_key = "surface.name";
  where.parameter_key_prefix = "surface";
  try {
    return MakeSurface(name, values, where);
  } catch (const InputError& e) {  // the line of the parameter named
    const auto it = lines.find(e.key());
    if (it == lines.end()) throw;
    throw InputError(e.file(), it->second, e.key(), e.message());
  }
}

GridType TypeOf(const Settings& s) {
  return ParseGridType(s.String("grid.type"), InputContext{s.Where("grid.type").file,
                                                           s.Where("grid.type").line},
                       "grid.type");
}

// CheckGridRequest with each key's own place in the spec.
void CheckRequest(const Settings& s, const Surface& surface) {
  try {
    CheckGridRequest(surface, int(s.Integer("grid.nu")), int(s.Integer("grid.nv")), TypeOf(s),
                     InputContext{});
  } catch (const InputError& e) {
    throw s.Error(e.key(), e.message());
  }
}

const Surface& SurfaceOf(HookContext& c) {
  return *c.grid.surface;
}

std::vector<Eigen::Vector2d> CurrentUv(HookContext& c) {
  const int n = c.State<GridState>().grid.NumVertices();
  std::vector<Eigen::Vector2d> uv(n);
  for (int v = 0; v < n; ++v) {
    const double* p = c.store->At("uv", v);
    uv[v] = Eigen::Vector2d(p[0], p[1]);
  }
  return uv;
}

// Every vertex at x(u, v), in the canonical frame.
void UpdatePositions(HookContext& c) {
  const Surface& surface = SurfaceOf(c);
  Mesh& mesh = c.store->mesh();
  for (VertexIndex v : mesh.vertices()) {
    const double* p = c.store->At("uv", int(v.idx()));
    const Eigen::Vector3d x = surface.Point(Eigen::Vector2d(p[0], p[1]));
    mesh.point(v) = ToPoint(c.frame.ToCanonical(Vec3{x[0], x[1], x[2]}));
  }
}

// MDO, ADO, MDE, ADE of the current (u, v): the whole grid, seams included
// (cached per state version).
const GridQuality& Quality(HookContext& c) {
  GridState& g = c.State<GridState>();
  if (g.version != c.version) {
    Grid grid = g.grid;
    grid.uv = CurrentUv(c);
    g.quality = MeasureGrid(grid, SurfaceOf(c));
    g.version = c.version;
  }
  return g.quality;
}

double Table1(HookContext& c, const std::string& measure) {
  const QualityMeasures q = Quality(c).Table1();
  return measure == "mdo" ? q.mdo : measure == "ado" ? q.ado : measure == "mde" ? q.mde : q.ade;
}

// How far the grid reaches beyond the domain in each open direction: the
// largest parameter excursion beyond a bound as a fraction of the domain's
// length ({"u": .., "v": ..}; a closed direction is absent).
nlohmann::json Excursion(const Grid& grid, const std::vector<Eigen::Vector2d>& uv,
                         const Surface& surface) {
  const ParameterDomain d = surface.Domain();
  double u = 0, v = 0;
  for (const Eigen::Vector2d& p : uv) {
    u = std::max({u, d.u0 - p[0], p[0] - d.u1});
    v = std::max({v, d.v0 - p[1], p[1] - d.v1});
  }
  nlohmann::json j = nlohmann::json::object();
  if (!grid.closed_u) j["u"] = u / (d.u1 - d.u0);
  if (!grid.closed_v) j["v"] = v / (d.v1 - d.v0);
  return j;
}

// The measure "outside": the larger excursion of the two (0: inside).
double Outside(HookContext& c) {
  const GridState& g = c.State<GridState>();
  const nlohmann::json excursion = Excursion(g.grid, CurrentUv(c), SurfaceOf(c));
  double outside = 0;
  for (const auto& fraction : excursion) outside = std::max(outside, fraction.get<double>());
  return outside;
}

// Coverage of the current (u, v) (cached per state version).
const GridCoverage& Coverage(HookContext& c) {
  GridState& g = c.State<GridState>();
  if (g.coverage_version != c.version) {
    Grid grid = g.grid;
    grid.uv = CurrentUv(c);
    g.coverage = MeasureCoverage(grid, g.grid, SurfaceOf(c), g.patch_area);
    g.coverage_version = c.version;
  }
  return g.coverage;
}

nlohmann::json CoverageToJson(const GridCoverage& v) {
  return {{"area_fraction", v.area_fraction},         {"parameter_fraction", v.parameter_fraction},
          {"grid_area", v.grid_area},                 {"patch_area", v.patch_area},
          {"parameter_area", v.parameter_area},       {"domain_area", v.domain_area}};
}

// grid.boundary: held (domain) or free; auto holds every grid with an open
// direction (a grid closed in one direction has its edge length set by the
// closed lines: held rows in the other are stretched or squeezed unless the
// vertex count along it suits the patch, as examples/grid_tower.yaml's).
bool HoldsBoundary(const Settings& s) {
  const std::string mode = s.String("grid.boundary");
  if (mode == "domain") return true;
  if (mode == "free") return false;
  return s.String("grid.type") != "closed_both";
}

// Before a least-squares round of a grid open in both directions: if the
// last round left it beyond the domain by the fraction e (> grid.fit_tolerance),
// L shrinks by f = 1/(1 + 2e + grid.fit_tolerance) — an open grid of squares
// grows with L on both sides — the terms see the new L, and the grid is
// scaled by f in parameter space about its anchor (or its parameter centroid)
// to start the round near its new size. (A grid closed in one direction has
// its edge length set by the closed lines: only n_v resp. n_u fit it.)
void FitLength(HookContext& c) {
  const double tolerance = c.settings->Number("grid.fit_tolerance");
  GridState& g = c.State<GridState>();
  if (tolerance <= 0 || g.hold || g.grid.closed_u || g.grid.closed_v) return;
  const double outside = c.Measure("outside");
  if (outside <= tolerance) return;
  const double f = 1 / (1 + 2 * outside + tolerance);
  c.grid.length *= f;
  ++g.fits;
  const std::vector<Eigen::Vector2d> uv = CurrentUv(c);
  Eigen::Vector2d centre = Eigen::Vector2d::Zero();
  if (g.anchor >= 0) {
    centre = uv[g.anchor];
  } else {
    for (const Eigen::Vector2d& p : uv) centre += p / double(uv.size());
  }
  for (int v = 0; v < g.grid.NumVertices(); ++v) {
    if (c.fixed[v]) continue;
    const Eigen::Vector2d p = centre + f * (uv[v] - centre);
    c.store->At("uv", v)[0] = p[0];
    c.store->At("uv", v)[1] = p[1];
  }
  UpdatePositions(c);
  c.model->StateChanged();
}

// The grid's own validity check (ProblemDecl::invalid). The engine's
// flipped-face check compares each face with the uniform grid the problem
// made; a grid slides along its surface (a tower's grid turns around the axis
// to undo the twist), so a face's normal turns with the surface under it
// however sound the grid is. The grid problem compares instead each face's
// Newell normal (positions x(u, v)) with the surface normal at its corners
// (their sum, each in the chart of the first corner, and that one in the
// chart nearest its initial parameter — the charts in which the uniform
// grid's faces are oriented like the surface; the force method wraps (u, v)
// into the domain, and on a non-orientable surface a face wrapped across
// the flipping seam sees reversed normals): more than grid.max_flip_degrees apart, the face is folded
// against the surface. (The problem's default validity.max_flip_degrees is
// 180, i.e. the engine's check is off; a spec may set it.)
std::string Folded(HookContext& c) {
  const Surface& surface = SurfaceOf(c);
  const double limit = c.settings->Number("grid.max_flip_degrees");
  const Mesh& mesh = c.store->mesh();
  const std::vector<Eigen::Vector2d>& initial = c.State<GridState>().grid.uv;
  int count = 0, example = -1;
  double worst = 0;
  for (FaceIndex f : mesh.faces()) {
    Eigen::Vector3d newell = Eigen::Vector3d::Zero(), normal = Eigen::Vector3d::Zero();
    std::vector<Eigen::Vector3d> x;
    Eigen::Vector2d first;
    for (VertexIndex v : mesh.vertices_around_face(mesh.halfedge(f))) {
      const double* p = c.store->At("uv", int(v.idx()));
      const Eigen::Vector2d uv(p[0], p[1]);
      // The first corner in the chart nearest its initial parameter, the
      // others in the chart of the first.
      if (x.empty()) first = surface.NearestChart(uv, initial[v.idx()]);
      x.push_back(surface.Point(uv));
      normal += surface.Normal(surface.NearestChart(uv, first));
    }
    newell = NewellVector(int(x.size()), [&](int k) { return x[size_t(k)]; });
    const double angle =
        std::atan2(newell.cross(normal).norm(), newell.dot(normal)) * 180 / M_PI;
    if (!(angle <= limit)) {  // NaN counts
      ++count;
      if (!(angle <= worst)) {
        worst = angle;
        example = int(f.idx());
      }
    }
  }
  if (count == 0) return "";
  char line[200];
  std::snprintf(line, sizeof line,
                "grid_folded_faces: %d (worst %.1f degrees from the surface normal, limit "
                "grid.max_flip_degrees = %g; e.g. element %d)\n",
                count, worst, limit, example);
  return line;
}

// L by default: the mean edge length of the initial grid [§3]; on a grid
// closed in one direction, the mean length of the closed lines' edges, which
// the closure fixes (the edges across them can follow).
double DefaultLength(const Grid& grid, const Surface& surface) {
  if (grid.closed_u == grid.closed_v) return MeanEdgeLength(grid, surface);
  const std::vector<std::array<int, 2>> edges = GridEdges(grid);
  const size_t u_edges = size_t(CountUEdges(grid));
  double sum = 0;
  int count = 0;
  for (size_t k = 0; k < edges.size(); ++k) {
    if ((k < u_edges) != grid.closed_u) continue;  // the closed direction's edges
    sum += (surface.Point(grid.uv[edges[k][1]]) - surface.Point(grid.uv[edges[k][0]])).norm();
    ++count;
  }
  return sum / count;
}

void Check(const Settings& s) {
  if (!s.String("reference").empty()) {
    throw s.Error("reference", "the grid problem's reference is its surface: no reference file");
  }
  if (s.Integer("multiresolution.levels") > 0) {
    throw s.Error("multiresolution.levels",
                  "a grid cannot be subdivided (its vertices carry surface parameters)");
  }
  // The grid's size before anything is allocated, as limits.max_vertices
  // bounds a mesh read from a file.
  const long long vertices = s.Integer("grid.nu") * s.Integer("grid.nv");
  if (vertices > s.Integer("limits.max_vertices")) {
    throw s.Error(s.Given("grid.nv") ? "grid.nv" : "grid.nu",
                  "grid.nu × grid.nv = " + std::to_string(vertices) +
                      " vertices, more than limits.max_vertices (" +
                      std::to_string(s.Integer("limits.max_vertices")) + "; raise it for a "
                      "bigger grid)");
  }
  if (s.String("method") == "force" && !(s.Get("fixed") == Value(std::string("none")))) {
    throw s.Error("fixed", "the force method moves every vertex (fixed vertices need "
                           "method: least_squares)");
  }
  const std::string grid_file = s.String("output.grid");
  const auto ends = [&](const std::string& ext) {
    return grid_file.size() >= ext.size() &&
           grid_file.compare(grid_file.size() - ext.size(), ext.size(), ext) == 0;
  };
  if (!grid_file.empty() && !ends(".obj") && !ends(".ply")) {
    throw s.Error("output.grid", "'" + grid_file + "': the grid file is .obj (vt u v) or .ply "
                                 "(vertex properties u, v)");
  }
  CheckRequest(s, ReadSurface(s));
  if (s.Number("grid.coverage") < 1) {
    if (s.String("grid.type") == "closed_both") {
      throw s.Error("grid.coverage", "a grid closed in both directions covers its whole surface");
    }
    if (!HoldsBoundary(s)) {
      throw s.Error("grid.coverage", "a fraction of the domain is covered by a held boundary "
                                     "(grid.boundary: domain)");
    }
  }
}

// The net: the uniform grid on the surface, as a quad mesh.
void GridNet(HookContext& c) {
  const Settings& s = *c.settings;
  GridState& g = c.State<GridState>();
  const Surface surface = ReadSurface(s, &g.surface_name);
  CheckRequest(s, surface);
  const GridType type = TypeOf(s);
  g.grid = MakeUniformGrid(surface, int(s.Integer("grid.nu")), int(s.Integer("grid.nv")), type);
  g.hold = HoldsBoundary(s) && type != GridType::kClosedBoth;
  g.covered = CoveredDomain(surface.Domain(), g.grid, s.Number("grid.coverage"));
  if (g.hold) MapOpenDirections(&g.grid, surface.Domain(), g.covered);
  g.patch_area = PatchArea(surface, surface.Domain());
  g.initial_length = s.Number("grid.ideal_length") > 0 ? s.Number("grid.ideal_length")
                                                        : DefaultLength(g.grid, surface);
  g.surface = surface;
  c.grid = {&*g.surface, g.initial_length};
  c.net.derived = true;
  c.net.mesh = GridToMesh(g.grid, surface, &g.omitted_faces);
  c.net.source.resize(size_t(g.grid.NumVertices()));
  for (size_t v = 0; v < c.net.source.size(); ++v) c.net.source[v] = int(v);
  nlohmann::json parameters = nlohmann::json::object();
  for (const auto& [name, value] : SurfaceParameterValues(surface)) parameters[name] = value;
  c.net.details = {{"net", "grid"},
                   {"surface", g.surface_name},
                   {"surface_kind", surface.KindName()},
                   {"parameters", parameters},
                   {"nu", g.grid.nu},
                   {"nv", g.grid.nv},
                   {"type", GridTypeName(type)},
                   {"paper_type", GridTypePaperName(type)},
                   {"ideal_length", c.grid.length},
                   {"boundary", g.hold ? "domain" : "free"},
                   {"coverage_target",
                    g.hold ? nlohmann::json(s.Number("grid.coverage")) : nlohmann::json()},
                   {"omitted_seam_faces", g.omitted_faces}};
  char line[300];
  std::snprintf(line, sizeof line,
                "grid: %s, %d × %d, %s (%s), L = %.6g%s; method %s\n", g.surface_name.c_str(),
                g.grid.nu, g.grid.nv, GridTypeName(type), GridTypePaperName(type), c.grid.length,
                g.omitted_faces > 0 ? " (mesh cut open along the flipping u-seam)" : "",
                s.String("method").c_str());
  c.net.headline = line;
}

// Per solve: the (u, v), the element sets, fixed vertices and domain bounds.
void InitGrid(HookContext& c) {
  const Settings& s = *c.settings;
  GridState& g = c.State<GridState>();
  const Grid& grid = g.grid;
  const int n = grid.NumVertices();
  CHECK_EQ(int(c.store->mesh().number_of_vertices()), n) << "grid: the net is not the grid";
  for (int v = 0; v < n; ++v) {
    double* p = c.store->At("uv", v);
    p[0] = grid.uv[v][0];
    p[1] = grid.uv[v][1];
  }
  ElementSet crossings, edges, stencils, triples, quads;
  crossings.site = stencils.site = triples.site = quads.site = Site::kVertex;
  edges.site = Site::kVertex;  // the edge's first vertex (seam edges have no mesh edge)
  for (int v = 0; v < n; ++v) {
    const VertexRole role = Role(grid, v);
    if (role == VertexRole::kInterior) {
      const GridNeighbours k = Neighbours(grid, v);
      crossings.Add({k.l0, k.l1, k.t0, k.t1}, v);
    } else if (role == VertexRole::kBoundary) {
      const BoundaryStencil b = BoundaryStencilAt(grid, v);
      stencils.Add({b.p0, b.p1, b.p2, b.p3}, v, -1, -1, kBoundary);
    }
  }
  for (const auto& e : GridEdges(grid)) {
    const bool boundary = Role(grid, e[0]) != VertexRole::kInterior &&
                          Role(grid, e[1]) != VertexRole::kInterior;
    edges.Add({e[0], e[1]}, e[0], -1, -1, boundary ? kBoundary : 0);
  }
  for (const GridLine& line : GridLines(grid)) {
    const int m = int(line.vertices.size());
    for (int k = line.closed ? 0 : 1; k < (line.closed ? m : m - 1); ++k) {
      const int b = line.vertices[k];
      triples.Add({line.vertices[(k + m - 1) % m], b, line.vertices[(k + 1) % m]}, b, -1, -1,
                  Role(grid, b) == VertexRole::kInterior ? 0 : kBoundary);
    }
  }
  for (const auto& q : GridQuads(grid)) quads.Add({q[0], q[1], q[2], q[3]}, q[0]);
  c.SetElements("grid_crossings", std::move(crossings));
  c.SetElements("grid_quads", std::move(quads));
  c.SetElements("grid_edges", std::move(edges));
  c.SetElements("grid_boundary_stencils", std::move(stencils));
  c.SetElements("grid_line_triples", std::move(triples));
  // `fixed: corners | boundary` by the grid's roles (the mesh of a Klein
  // bottle grid has a boundary along its seam that the grid has not).
  const Value& fixed = s.Get("fixed");
  if (const auto* mode = std::get_if<std::string>(&fixed); mode && *mode != "none") {
    c.fixed.assign(size_t(n), false);
    for (int v = 0; v < n; ++v) {
      const VertexRole role = Role(grid, v);
      c.fixed[v] = *mode == "corners" ? role == VertexRole::kCorner : role != VertexRole::kInterior;
    }
  }
  for (int v = 0; v < n; ++v) {
    if (c.fixed[v]) {
      c.model->SetConstant("uv", v);
      continue;
    }
    const BoundaryHold hold = g.hold ? HoldOf(grid, v, g.covered) : BoundaryHold{};
    if (hold.u && hold.v) {
      c.model->SetConstant("uv", v);  // a corner
    } else if (hold.Any()) {
      // On a side: slides along it, within its ends (a closed direction has
      // none).
      const int held = hold.u ? 0 : 1;
      const bool ends = hold.u ? !grid.closed_v : !grid.closed_u;
      const double lo = hold.u ? g.covered.v0 : g.covered.u0;
      const double hi = hold.u ? g.covered.v1 : g.covered.u1;
      c.model->SetManifold("uv", v, [=]() -> ceres::Manifold* {
        if (ends) return MakeGridSideManifold(held, lo, hi);
        return new ceres::SubsetManifold(2, {held});
      });
    }
  }
  // The anchor holds a grid whose open direction nothing else holds.
  const std::string anchor = s.String("grid.anchor");
  g.anchor = -1;
  if (anchor == "centre" ||
      (anchor == "auto" && !g.hold && !(grid.closed_u && grid.closed_v))) {
    g.anchor = grid.Index(grid.nu / 2, grid.nv / 2);
    c.model->SetConstant("uv", g.anchor);
  }
  UpdatePositions(c);
  if (c.level == 0) {
    c.details["quality_before"] = GridQualityToJson(Quality(c));
    c.details["coverage_before"] = CoverageToJson(Coverage(c));
  }
}

// One round of the force method: force.iterations iterations of Listing 1
// (or fewer, to its own stop).
StepResult ForceRound(HookContext& c) {
  const Settings& s = *c.settings;
  GridState& g = c.State<GridState>();
  Grid grid = g.grid;
  grid.uv = CurrentUv(c);
  ForceDirectedOptions o;
  o.d_o = s.Number("force.d_o");
  o.d_b = s.Number("force.d_b");
  o.d_l = s.Number("force.d_l");
  o.ideal_length = c.grid.length;
  o.max_iterations = int(s.Integer("force.iterations"));
  o.stop_mdo = s.Number("tolerance.mdo");
  o.stop_ado = s.Number("tolerance.ado");
  o.stop_mde = s.Number("tolerance.mde");
  o.stop_ade = s.Number("tolerance.ade");
  o.stall_tolerance = s.Number("force.stall_tolerance");
  o.plateau_window = int(s.Integer("force.plateau_window"));
  o.plateau_tolerance = s.Number("force.plateau_tolerance");
  o.clamp_to_domain = s.Bool("force.clamp_to_domain");
  o.hold_boundary = g.hold;
  o.covered = g.covered;
  o.history_stride = int(s.Integer("force.measure_every"));
  const ForceDirectedResult r = RunForceDirected(SurfaceOf(c), grid, o);
  for (int v = 0; v < grid.NumVertices(); ++v) {
    double* p = c.store->At("uv", v);
    p[0] = r.grid.uv[v][0];
    p[1] = r.grid.uv[v][1];
  }
  UpdatePositions(c);
  // The round's history, thinned to at most ~20 entries (first and last kept).
  const size_t stride = std::max<size_t>(1, r.history.size() / 20);
  for (size_t k = 0; k < r.history.size(); ++k) {
    if (k % stride != 0 && k + 1 != r.history.size()) continue;
    const ForceHistoryEntry& h = r.history[k];
    if (h.iteration == 0 && g.force_iterations > 0) continue;  // the previous round's last
    const QualityMeasures q = h.quality.Table1();
    g.force_history.push_back({{"iteration", g.force_iterations + h.iteration},
                               {"mdo", q.mdo},
                               {"ado", q.ado},
                               {"mde", q.mde},
                               {"ade", q.ade},
                               {"max_move", h.max_move}});
  }
  g.force_iterations += r.iterations;
  g.force_stop = ForceStopName(r.stop);
  StepResult out;
  out.iterations = r.iterations;
  if (r.stop == ForceStop::kStalled || r.stop == ForceStop::kPlateau) {
    out.stop = std::string("force method ") + ForceStopName(r.stop);
  }
  return out;
}

void FinishGrid(HookContext& c) {
  const Settings& s = *c.settings;
  GridState& g = c.State<GridState>();
  const GridQuality& after = Quality(c);
  c.details["quality_after"] = GridQualityToJson(after);
  c.details["quality_note"] =
      "quality_before/after: the whole grid, seams included (mdo, ado on the interpolating "
      "splines; mde, ade on the quad sides); the report's before/after: the mesh written";
  c.details["method"] = s.String("method");
  c.details["ideal_length"] = c.grid.length;
  c.details["ideal_length_initial"] = g.initial_length;
  c.details["ideal_length_fits"] = g.fits;
  c.details["outside_domain"] = Excursion(g.grid, CurrentUv(c), SurfaceOf(c));
  const GridCoverage& coverage = Coverage(c);
  c.details["coverage_after"] = CoverageToJson(coverage);
  if (s.String("method") == "force") {
    c.details["force"] = {{"iterations", g.force_iterations},
                          {"stop", g.force_stop},
                          {"history", g.force_history}};
  }
  const nlohmann::json& before = c.details["quality_before"];
  const auto value = [](const nlohmann::json& j, const char* k) {
    return j.at(k).is_number() ? j.at(k).get<double>() : std::nan("");
  };
  const nlohmann::json now = GridQualityToJson(after);
  char line[400];
  std::snprintf(line, sizeof line,
                "grid quality (whole grid): MDO %.4g° -> %.4g°, ADO %.4g° -> %.4g°, "
                "MDE %.4g%% -> %.4g%%, ADE %.4g%% -> %.4g%%%s\n",
                value(before, "mdo"), value(now, "mdo"), value(before, "ado"), value(now, "ado"),
                value(before, "mde"), value(now, "mde"), value(before, "ade"), value(now, "ade"),
                s.String("method") == "force"
                    ? (" (force: " + std::to_string(g.force_iterations) + " iterations, " +
                       g.force_stop + ")").c_str()
                    : "");
  c.headline += line;
  const nlohmann::json& first = c.details["coverage_before"];
  std::snprintf(line, sizeof line,
                "grid coverage (%s boundary): grid area %.1f%% -> %.1f%% of the patch, parameter "
                "domain %.1f%% -> %.1f%%\n",
                g.hold ? "held" : "free", 100 * first.at("area_fraction").get<double>(),
                100 * coverage.area_fraction, 100 * first.at("parameter_fraction").get<double>(),
                100 * coverage.parameter_fraction);
  c.headline += line;
}

// output.grid: the grid mesh with each vertex's (u, v), positions x(u, v).
void WriteGrid(HookContext& c) {
  const auto it = c.temporaries.find("grid");
  if (it == c.temporaries.end()) return;
  const Surface& surface = SurfaceOf(c);
  const std::vector<Eigen::Vector2d> uv = CurrentUv(c);
  // Assigned, not copy-constructed: gcc 12 takes a copy-constructed
  // Surface_mesh's flags for uninitialised (-Wmaybe-uninitialized) in some
  // unity batches of this folder.
  Mesh mesh;
  mesh = *c.output;
  for (VertexIndex v : mesh.vertices()) {
    const Eigen::Vector3d x = surface.Point(uv[v.idx()]);
    mesh.point(v) = Point(x[0], x[1], x[2]);
  }
  WriteGridMesh(it->second, mesh, uv, c.settings->Bool("output.ascii_ply"));
}

std::vector<Tolerance> Tolerances(bool per_iteration) {
  std::vector<Tolerance> t;
  for (const char* m : kMeasures) t.push_back({m, std::string("tolerance.") + m, per_iteration});
  return t;
}

}  // namespace

ProblemDecl grid() {
  ProblemDecl d;
  d.name = "grid";
  d.summary = "orthogonal, locally equilateral quad grids on parametric surfaces";
  d.paper = "[force-directed grids paper, §3–4, Listing 1, eqs. 1–6, Table 1]";
  d.input = InputKind::kQuads;
  d.makes_input = true;
  d.terms = {{"grid_orthogonality", 1},
             {"grid_equilaterality", 0.01},
             {"grid_quad_equilaterality", 1},
             {"grid_boundary", 1},
             {"grid_fairness", 0.3}};
  d.blocks = {{"uv", Site::kVertex, 2, FrameMap::kInvariant, false, Carry::kReinitialise, true,
               false, "the vertex's surface parameters (u, v)"}};
  Key surface = CustomKey("surface", "{name: function_graph, a: 10, b: 10, h: 2, s: 3}",
                          "the surface: {name: " + Join(SurfaceNames()) +
                              ", <parameter>: value, ...} (surfaces/surface_factory.h; `archgeo "
                              "spec grid` and docs/keys.md list the parameters)");
  surface.required = true;
  d.keys = {
      surface,
      IntegerKey("grid.nu", 20, 2, 1000000, "vertices along u (≥ 2; ≥ 3 when closed in u)"),
      IntegerKey("grid.nv", 20, 2, 1000000, "vertices along v (≥ 2; ≥ 3 when closed in v)"),
      ChoiceKey("grid.type", "open", {"open", "closed_u", "closed_v", "closed_both"},
                "open (C0), closed in u or v (C1, on a periodic direction), closed_both (C2)"),
      NumberKey("grid.ideal_length", 0, 0, 1e75,
                "the ideal edge length L (file units, below 1e75 as the surface's parameters); "
                "0: the mean edge length of the initial grid [§3] (closed in one direction: of "
                "the closed lines)"),
      ChoiceKey("grid.anchor", "auto", {"auto", "centre", "none"},
                "least squares: centre: the centre vertex keeps its (u, v) (an open direction "
                "with a free boundary has nothing else that holds the grid on its patch); "
                "auto: centre when an open direction's boundary is free"),
      ChoiceKey("grid.boundary", "auto", {"auto", "domain", "free"},
                "domain: the boundary rows of an open direction stay on the sides of the "
                "parameter domain (a boundary vertex slides along its side, corners stay at the "
                "corners), so the grid covers its patch; free: nothing holds them (least "
                "squares: anchor and grid.fit_tolerance; force: the paper's Listing 1 as "
                "written); auto: domain when the grid has an open direction"),
      NumberKey("grid.coverage", 1, 0, 1,
                "with a held boundary: the fraction of the parameter domain's area the grid "
                "covers, a rectangle centred in the domain (each open direction shrunk by "
                "√fraction when both are open)"),
      NumberKey("grid.fit_tolerance", 0.005, 0, 1,
                "least squares, free boundary: while an open grid reaches beyond the domain by "
                "more than this fraction of its length, shrink L and solve again (0 = off)"),
      NumberKey("grid.max_flip_degrees", 90, 0, 180,
                "validity: a face whose normal is more than this from the surface normal at "
                "its corners is folded (the result is not valid; replaces the engine's "
                "comparison with the initial grid, see validity.max_flip_degrees)"),
      ChoiceKey("method", "least_squares", {"least_squares", "force"},
                "least_squares (Ceres over (u, v)) or force (the paper's Listing 1)"),
      NumberKey("tolerance.mdo", 0, 0, 90, "stop when MDO (degrees) is at most this; 0 = off"),
      NumberKey("tolerance.ado", 0, 0, 90, "stop when ADO (degrees) is at most this; 0 = off"),
      NumberKey("tolerance.mde", 0, 0, 1e9, "stop when MDE (percent) is at most this; 0 = off"),
      NumberKey("tolerance.ade", 0, 0, 1e9, "stop when ADE (percent) is at most this; 0 = off"),
      NumberKey("force.d_o", 0.05, 0, 1,
                "eq. 1 factor, a fraction of L (the paper: 1%–5% of the mean edge length)"),
      NumberKey("force.d_b", 0.05, 0, 1, "eq. 2 factor (boundary anti-folding)"),
      NumberKey("force.d_l", 0.05, 0, 1, "Listing 1 step 2 factor (edge length)"),
      IntegerKey("force.iterations", 5000, 1, 100000000, "force iterations per round at most"),
      IntegerKey("force.rounds", 10, 1, 1000000, "force rounds at most"),
      NumberKey("force.stall_tolerance", 1e-11, 0, 1,
                "stop when no vertex's step changes by more than this × L between iterations"),
      IntegerKey("force.plateau_window", 2000, 0, 100000000,
                 "stop when no measure changed by force.plateau_tolerance over this many "
                 "iterations (0 = off)"),
      NumberKey("force.plateau_tolerance", 0.01, 0, 1e9, "degrees resp. percent"),
      BoolKey("force.clamp_to_domain", false,
              "clamp an open direction to the domain (the paper has no such rule; it folds)"),
      IntegerKey("force.measure_every", 10, 1, 100000000,
                 "measure (thresholds, plateau, history) every this many iterations")};
  d.defaults = {{"schedule.outer_iterations", 8LL},
                {"solver.max_num_iterations", 500LL},
                {"validity.max_flip_degrees", 180.0}};  // see Folded
  d.invalid = &Folded;
  d.output_keys = {"grid"};
  d.check = &Check;
  d.net = &GridNet;
  d.init = &InitGrid;
  d.finish = &FinishGrid;
  d.write = &WriteGrid;
  for (const char* m : kMeasures) {
    d.measures[m] = [name = std::string(m)](HookContext& c) { return Table1(c, name); };
  }
  d.measures["outside"] = &Outside;
  d.measures["coverage"] = [](HookContext& c) { return Coverage(c).area_fraction; };
  d.measures["parameter_coverage"] = [](HookContext& c) {
    return Coverage(c).parameter_fraction;
  };
  d.stages = [](const Settings& s) {
    Stage st;
    st.logged = {"mdo", "ado", "mde", "ade", "outside", "coverage", "parameter_coverage"};
    st.after_round = &UpdatePositions;
    if (s.String("method") == "force") {
      st.name = "force";
      st.rounds_key = "force.rounds";
      st.tolerances = Tolerances(false);
      st.step = &ForceRound;
    } else {
      st.name = "least_squares";
      st.rounds_key = "schedule.outer_iterations";
      // The §4 thresholds (tolerance.*) stop Ceres the moment they all hold
      // (per iteration). Fitting (open grids) adds "outside" ≤
      // grid.fit_tolerance, checked at the end of each round only: a round
      // ends when the grid is good enough (or converged), and if it then
      // reaches beyond its patch the next round starts with L shrunk to fit
      // (FitLength). Watched per iteration, "outside" would keep a round
      // iterating while the grid, already good enough, grows beyond the
      // patch (100 × 100 function graph: 10 iterations instead of 2), and
      // without thresholds it would stop the first iteration.
      const bool fit = s.Number("grid.fit_tolerance") > 0 && s.String("grid.type") == "open" &&
                       !HoldsBoundary(s);
      st.tolerances = Tolerances(true);
      if (fit) st.tolerances.push_back({"outside", "grid.fit_tolerance"});
      st.before_round = &FitLength;
      st.rest_move = 1e-9;
    }
    return std::vector<Stage>{st};
  };
  d.analyses = {"grid"};
  d.colors = "orthogonality";
  return d;
}

}  // namespace archgeo::problems
