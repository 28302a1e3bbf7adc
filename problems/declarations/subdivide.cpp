// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `subdivide`: constrained Loop / Catmull–Clark subdivision of the
// input mesh [Gebreiter 2012, §9]: boundary curves (the mesh's own boundary
// or polylines from an OBJ file) and crease curves taken up by the
// subdivided mesh by arc length (§9.2.1), or the boundary ring locked
// (§9.2.2), a number of levels or a target edge length, optionally the limit
// positions (§9.1.2); or reverse subdivision (§9.2.3), with the curves'
// rules when curves are given. The rules are in
// geometry/constrained_subdivision.h.
//
// The `net` hook makes the subdivided (or reversed) mesh; it is the net the
// run measures and writes (output.mesh). No solve follows. The report's
// details.subdivision gives the levels, counts, the largest distance of a
// curve vertex from its curve (relative to the diagonal), and for reverse
// subdivision the least-squares residual of each level; with a tangent
// surface (§9.2.2), how far the tangent planes along it turn from its.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "core/problem.h"
#include "geometry/constrained_subdivision.h"
#include "geometry/curves.h"
#include "geometry/reference.h"
#include "io/io.h"
#include "problems/runtime/model.h"

namespace archgeo::problems {
namespace {

PolyMesh SdArrays(const Mesh& mesh) {
  PolyMesh m;
  std::vector<int> index(mesh.number_of_vertices() + mesh.number_of_removed_vertices(), -1);
  for (VertexIndex v : mesh.vertices()) {
    index[v.idx()] = static_cast<int>(m.points.size());
    const Point& p = mesh.point(v);
    m.points.emplace_back(p.x(), p.y(), p.z());
  }
  for (FaceIndex f : mesh.faces()) {
    std::vector<int> face;
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) face.push_back(index[v.idx()]);
    m.faces.push_back(std::move(face));
  }
  return m;
}

Mesh SdMesh(const PolyMesh& m, const std::vector<Eigen::Vector3d>& points) {
  Mesh out;
  for (const Eigen::Vector3d& p : points) out.add_vertex(Point(p.x(), p.y(), p.z()));
  std::vector<VertexIndex> face;
  for (const auto& f : m.faces) {
    face.clear();
    for (int v : f) face.emplace_back(v);
    CHECK(out.add_face(face) != Mesh::null_face()) << "subdivide: the subdivided mesh is not a manifold";
  }
  return out;
}

// The 1-based line of each `l` record of an OBJ file (ReadPolylines keeps their order).
std::vector<int> SdLineRecords(const std::string& path) {
  std::vector<int> lines;
  std::ifstream in(path);
  std::string text;
  for (int line = 1; std::getline(in, text); ++line) {
    size_t i = text.find_first_not_of(" \t");
    if (i != std::string::npos && text[i] == 'l' && i + 1 < text.size() && (text[i + 1] == ' ' || text[i + 1] == '\t')) {
      lines.push_back(line);
    }
  }
  return lines;
}

struct SdCurves {
  std::vector<SubdivisionCurve> curves;
  std::vector<std::string> files, keys, shorts;  // per curve: where it came from, "curve k"
  std::vector<int> lines;
};

void SdReadCurves(const Settings& s, const std::string& key, bool boundary, SdCurves& out) {
  const std::string& path = s.String(key);
  if (path.empty()) return;
  const std::vector<Polyline> read = ReadPolylines(path);  // InputError: file, line (non-finite, …)
  const std::vector<int> lines = SdLineRecords(path);
  for (size_t k = 0; k < read.size(); ++k) {
    SubdivisionCurve c;
    for (const Vec3& p : read[k].points) c.points.emplace_back(p[0], p[1], p[2]);
    c.closed = read[k].closed;
    c.boundary = boundary;
    c.name = path + ": curve " + std::to_string(k + 1);
    if (k < lines.size()) c.name += " (line " + std::to_string(lines[k]) + ")";
    out.curves.push_back(std::move(c));
    out.files.push_back(path);
    out.keys.push_back(key);
    out.shorts.push_back("curve " + std::to_string(k + 1));
    out.lines.push_back(k < lines.size() ? lines[k] : 0);
  }
}

double SdMeanEdge(const PolyMesh& m) {
  double sum = 0;
  long count = 0;
  for (const auto& f : m.faces) {
    for (size_t i = 0; i < f.size(); ++i) {
      sum += (m.points[f[i]] - m.points[f[(i + 1) % f.size()]]).norm();
      ++count;
    }
  }
  return count ? sum / double(count) : 0;
}

// The curves of subdivision.boundary (mesh: the input's boundary loops;
// curves: boundary_curves) and subdivision.crease_curves.
SdCurves SdGatherCurves(const Settings& s, const Mesh& input, const std::string& mesh_file) {
  SdCurves curves;
  const std::string& boundary = s.String("subdivision.boundary");
  if (boundary == "curves" && s.String("subdivision.boundary_curves").empty()) {
    throw s.Error("subdivision.boundary", "boundary: curves needs subdivision.boundary_curves (an OBJ of 'l' polylines)");
  }
  if (boundary != "curves" && !s.String("subdivision.boundary_curves").empty()) {
    throw s.Error("subdivision.boundary_curves", "boundary curves are used with subdivision.boundary: curves");
  }
  if (boundary == "mesh") {
    int k = 0;
    for (const auto& loop : BoundaryLoops(input)) {
      const Polyline p = LoopPolyline(input, loop);
      SubdivisionCurve curve;
      for (const Vec3& q : p.points) curve.points.emplace_back(q[0], q[1], q[2]);
      curve.closed = true;
      curve.boundary = true;
      curve.name = mesh_file + ": boundary loop " + std::to_string(++k);
      curves.curves.push_back(std::move(curve));
      curves.files.push_back(mesh_file);
      curves.keys.push_back("subdivision.boundary");
      curves.shorts.push_back("boundary loop " + std::to_string(k));
      curves.lines.push_back(0);
    }
  }
  SdReadCurves(s, "subdivision.boundary_curves", true, curves);
  SdReadCurves(s, "subdivision.crease_curves", false, curves);
  return curves;
}

// A SubdivisionError of the tagging as an InputError naming the curve's
// file, line and key (or the mesh's).
[[noreturn]] void SdCurveError(const SubdivisionError& e, const SdCurves& curves, const std::string& mesh_file) {
  const std::string what = e.what();
  for (size_t k = 0; k < curves.curves.size(); ++k) {
    const std::string& name = curves.curves[k].name;
    if (what.rfind(name, 0) == 0) {
      throw InputError(curves.files[k], curves.lines[k], curves.keys[k], curves.shorts[k] + what.substr(name.size()));
    }
  }
  throw InputError(mesh_file, 0, "subdivision.scheme", what);
}

SubdivisionOptions SdOptions(const Settings& s, SubdivisionScheme scheme) {
  SubdivisionOptions options;
  options.scheme = scheme;
  options.boundary =
      s.String("subdivision.boundary") == "locked" ? SubdivisionBoundary::kLocked : SubdivisionBoundary::kStandard;
  options.tolerance = s.Number("subdivision.curve_tolerance");
  options.kink_degrees = s.Number("subdivision.kink_angle");
  return options;
}

// The boundary surfaces of subdivision.tangent_surface (§9.2.2), put into
// options.tangent: a point within tangent_tolerance × the coarse mesh's
// diagonal of the surface lies on it, with the surface's interpolated normal.
std::unique_ptr<ReferenceSurface> SdTangentSurface(const Settings& s, const PolyMesh& coarse,
                                                   SubdivisionOptions& options) {
  const std::string& path = s.String("subdivision.tangent_surface");
  if (path.empty()) return nullptr;
  if (s.String("subdivision.boundary") == "locked") {
    throw s.Error("subdivision.tangent_surface", "a tangent surface moves the ring that boundary: locked keeps; "
                                                 "give one or the other");
  }
  std::unique_ptr<ReferenceSurface> surface;
  try {
    surface = std::make_unique<ReferenceSurface>(ReadMesh(path));
  } catch (const std::invalid_argument& e) {
    throw InputError(path, 0, "subdivision.tangent_surface", e.what());
  }
  Eigen::Vector3d lo = coarse.points[0], hi = coarse.points[0];
  for (const auto& p : coarse.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  const double tolerance = s.Number("subdivision.tangent_tolerance") * (hi - lo).norm();
  const ReferenceSurface* on = surface.get();
  options.tangent = [on, tolerance](const Eigen::Vector3d& p, Eigen::Vector3d* normal) {
    const ReferenceSurface::SurfacePoint q = on->Closest({p.x(), p.y(), p.z()});
    if (!((Eigen::Vector3d(q.point[0], q.point[1], q.point[2]) - p).norm() <= tolerance)) return false;
    *normal = Eigen::Vector3d(q.normal[0], q.normal[1], q.normal[2]);
    return true;
  };
  return surface;
}

void SdNet(HookContext& c) {
  const Settings& s = *c.settings;
  const Mesh& input = *c.input;
  const std::string mesh_file = s.String("mesh");
  const SubdivisionScheme scheme =
      s.String("subdivision.scheme") == "loop" ? SubdivisionScheme::kLoop : SubdivisionScheme::kCatmullClark;
  const PolyMesh coarse = SdArrays(input);
  nlohmann::json details = nlohmann::json::object();
  details["scheme"] = s.String("subdivision.scheme");
  details["input"] = {{"vertices", coarse.points.size()}, {"faces", coarse.faces.size()}};
  const int reverse = int(s.Integer("subdivision.reverse"));
  char line[512];
  if (reverse > 0) {
    if (s.Integer("subdivision.levels") > 0 || s.Number("subdivision.target_edge_length") > 0 ||
        s.Bool("subdivision.limit") || !s.String("subdivision.tangent_surface").empty()) {
      throw s.Error("subdivision.reverse", "reverse subdivision takes no levels, target_edge_length, limit or "
                                           "tangent_surface: give one or the other");
    }
    PolyMesh m = coarse;
    nlohmann::json levels = nlohmann::json::array();
    std::string summary;
    const SdCurves curves = SdGatherCurves(s, input, mesh_file);
    for (int k = 0; k < reverse; ++k) {
      ReverseResult r;
      std::unique_ptr<ConstrainedSubdivision> tagged;
      if (!curves.curves.empty()) {
        try {
          tagged = std::make_unique<ConstrainedSubdivision>(m, curves.curves, SdOptions(s, scheme));
        } catch (const SubdivisionError& e) {
          SdCurveError(e, curves, mesh_file);
        }
      }
      try {
        r = tagged ? tagged->Reverse() : ReverseSubdivision(m, scheme);
      } catch (const SubdivisionError& e) {
        throw InputError(mesh_file, 0, "subdivision.reverse",
                         "level " + std::to_string(k + 1) + " of the reverse subdivision: " + e.what());
      }
      const double diagonal = [&] {
        Eigen::Vector3d lo = m.points[0], hi = m.points[0];
        for (const auto& p : m.points) {
          lo = lo.cwiseMin(p);
          hi = hi.cwiseMax(p);
        }
        return (hi - lo).norm();
      }();
      levels.push_back({{"vertices", r.coarse.points.size()}, {"faces", r.coarse.faces.size()},
                        {"residual_max_relative", r.residual_max / diagonal},
                        {"residual_rms_relative", r.residual_rms / diagonal}, {"unique", r.unique}});
      std::snprintf(line, sizeof line,
                    "reverse level %d: %zu vertices, %zu faces, least-squares residual max %.2e rms %.2e of "
                    "the diagonal%s\n",
                    k + 1, r.coarse.points.size(), r.coarse.faces.size(), r.residual_max / diagonal,
                    r.residual_rms / diagonal, r.unique ? "" : " (not unique: the masks are singular here)");
      summary += line;
      m = std::move(r.coarse);
    }
    details["reverse"] = levels;
    details["curves"] = curves.curves.size();
    details["output"] = {{"vertices", m.points.size()}, {"faces", m.faces.size()}};
    c.net.mesh = SdMesh(m, m.points);
    c.net.headline = summary;
  } else {
    const std::string& boundary = s.String("subdivision.boundary");
    const SdCurves curves = SdGatherCurves(s, input, mesh_file);
    SubdivisionOptions options = SdOptions(s, scheme);
    const std::unique_ptr<ReferenceSurface> tangent = SdTangentSurface(s, coarse, options);
    std::unique_ptr<ConstrainedSubdivision> cs;
    try {
      cs = std::make_unique<ConstrainedSubdivision>(coarse, curves.curves, options);
    } catch (const SubdivisionError& e) {
      SdCurveError(e, curves, mesh_file);
    }
    const double target = s.Number("subdivision.target_edge_length");
    const int max_levels = int(s.Integer("subdivision.max_levels"));
    const long max_faces = long(s.Integer("subdivision.max_faces"));
    auto next_faces = [&] {
      const PolyMesh& m = cs->mesh();
      long f = 0;
      for (const auto& face : m.faces) f += scheme == SubdivisionScheme::kLoop ? 4 : long(face.size());
      return f;
    };
    const int wanted = target > 0 ? max_levels : int(s.Integer("subdivision.levels"));
    while (cs->levels() < wanted) {
      if (target > 0 && SdMeanEdge(cs->mesh()) <= target) break;
      if (next_faces() > max_faces) {
        throw s.Error(target > 0 ? "subdivision.target_edge_length" : "subdivision.levels",
                      "level " + std::to_string(cs->levels() + 1) + " would have " + std::to_string(next_faces()) +
                          " faces, more than subdivision.max_faces = " + std::to_string(max_faces));
      }
      cs->Step();
    }
    if (target > 0 && SdMeanEdge(cs->mesh()) > target) {
      throw s.Error("subdivision.target_edge_length",
                    "the mean edge length is still " + std::to_string(SdMeanEdge(cs->mesh())) + " after " +
                        std::to_string(max_levels) + " levels (subdivision.max_levels)");
    }
    std::vector<Eigen::Vector3d> points = cs->mesh().points;
    if (s.Bool("subdivision.limit")) {
      try {
        points = cs->LimitPositions();
      } catch (const SubdivisionError& e) {
        throw s.Error("subdivision.limit", e.what());
      }
    }
    const double diagonal = cs->diagonal();
    // Curve vertices on their curve, measured afresh on the output positions.
    const double distance = cs->MaxCurveDistance(points) / diagonal;
    PolyMesh out_mesh = cs->mesh();
    out_mesh.points = points;
    details["levels"] = cs->levels();
    details["limit"] = s.Bool("subdivision.limit");
    details["boundary"] = boundary;
    details["curves"] = curves.curves.size();
    details["curve_vertices"] = cs->CurveVertexCount();
    details["corners"] = cs->CornerCount();
    details["curve_distance_max_relative"] = distance;
    details["mean_edge_length"] = SdMeanEdge(out_mesh);
    details["output"] = {{"vertices", out_mesh.points.size()}, {"faces", out_mesh.faces.size()}};
    std::string tangency_line;
    if (tangent) {
      const TangencyMeasure m = cs->Tangency(points);
      if (m.vertices == 0) {
        throw s.Error("subdivision.tangent_surface",
                      "no curve vertex of the subdivided mesh lies on the tangent surface (within "
                      "subdivision.tangent_tolerance): the surface must carry a boundary or crease curve");
      }
      details["tangency"] = {{"vertices", m.vertices}, {"deviation_max_deg", m.max_degrees},
                             {"deviation_mean_deg", m.mean_degrees}};
      std::snprintf(line, sizeof line,
                    "tangent surface: %d curve vertices on it; tangent planes turn from its by %.3g° at most "
                    "(mean %.3g°)\n",
                    m.vertices, m.max_degrees, m.mean_degrees);
      tangency_line = line;
    }
    c.net.mesh = SdMesh(out_mesh, points);
    std::snprintf(line, sizeof line,
                  "%s, %d levels%s: %zu vertices, %zu faces, mean edge %.4g; %zu curves, %d curve vertices "
                  "(max distance from their curve %.2e of the diagonal), %d corners\n",
                  s.String("subdivision.scheme").c_str(), cs->levels(), s.Bool("subdivision.limit") ? " + limit" : "",
                  out_mesh.points.size(), out_mesh.faces.size(), SdMeanEdge(out_mesh), curves.curves.size(),
                  cs->CurveVertexCount(), distance, cs->CornerCount());
    c.net.headline = line + tangency_line;
  }
  c.net.derived = true;
  c.net.source.clear();
  c.details["subdivision"] = std::move(details);
}

std::vector<Stage> SdStages(const Settings&) {
  return {ResultWithoutSolve("subdivide", "the subdivided mesh is the result (no solve)")};
}

}  // namespace

ProblemDecl subdivide() {
  ProblemDecl d;
  d.name = "subdivide";
  d.summary = "constrained Loop / Catmull–Clark subdivision with boundary and crease curves, limit, reverse";
  d.paper = "[Gebreiter 2012, §9]";
  d.input = InputKind::kAny;
  d.keys = {
      ChoiceKey("subdivision.scheme", "catmull_clark", {"catmull_clark", "loop"},
                "the masks: catmull_clark (any polygons) or loop (triangles)"),
      IntegerKey("subdivision.levels", 1, 0, 8, "subdivision levels (unless target_edge_length is given)"),
      NumberKey("subdivision.target_edge_length", 0, 0, 1e300,
                "subdivide until the mean edge length is at most this (file units; 0: use levels)"),
      IntegerKey("subdivision.max_levels", 8, 1, 8, "at most this many levels for target_edge_length"),
      IntegerKey("subdivision.max_faces", 4000000, 1, 100000000, "refuse a level with more faces"),
      ChoiceKey("subdivision.boundary", "standard", {"standard", "mesh", "curves", "locked"},
                "standard crease masks; mesh: stay on the input's boundary polylines; curves: on "
                "boundary_curves; locked: boundary vertices and their neighbours fixed"),
      PathKey("subdivision.boundary_curves", Type::kInputPath,
              "OBJ polylines ('l' records) through boundary vertices of the mesh (boundary: curves)"),
      PathKey("subdivision.crease_curves", Type::kInputPath,
              "OBJ polylines ('l' records) through mesh vertices along edges: creases"),
      NumberKey("subdivision.curve_tolerance", 1e-6, 0, 0.1,
                "a mesh vertex this close to a curve (fraction of the diagonal) lies on it"),
      NumberKey("subdivision.kink_angle", 30, 0, 180,
                "a curve point turning more than this (degrees) at a mesh vertex makes it a fixed corner"),
      BoolKey("subdivision.limit", false, "move the last level's vertices to their limit positions"),
      PathKey("subdivision.tangent_surface", Type::kInputPath,
              "a mesh of boundary surfaces (e.g. columns) the subdivided surface meets tangentially along "
              "the curves on it (§9.2.2): at every level the cross-boundary edges are put into its tangent "
              "plane"),
      NumberKey("subdivision.tangent_tolerance", 1e-3, 0, 0.1,
                "a curve vertex this close to the tangent surface (fraction of the diagonal) lies on it"),
      IntegerKey("subdivision.reverse", 0, 0, 6,
                 "reverse subdivision: this many levels back by least squares (instead of subdividing); with "
                 "the boundary and crease curves of the forward run, their rules reversed too")};
  d.net = &SdNet;
  d.stages = &SdStages;
  d.colors = "none";
  return d;
}

}  // namespace archgeo::problems
