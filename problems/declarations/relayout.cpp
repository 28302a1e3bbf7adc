// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — planar_quads' relayout (see relayout.h).
#include "problems/declarations/relayout.h"

#include <CGAL/boost/graph/iterator.h>
#include <glog/logging.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/no_result.h"
#include "fields/layout_cleanup.h"
#include "mesh/similarity.h"
#include "problems/declarations/field_pipeline.h"
#include "problems/declarations/suitability.h"

namespace archgeo {
namespace {

// "mean 0.40, max 0.76, bound 0.25" from the suitability figures.
std::string ConjugacyText(const nlohmann::json& figures) {
  if (!figures.contains("conjugacy_mean")) return "not measured";
  char text[160];
  std::snprintf(text, sizeof text, "conjugacy mean %.2f, max %.2f; bound %.2f, 0 for a conjugate net",
                figures.at("conjugacy_mean").get<double>(),
                figures.at("conjugacy_max").get<double>(),
                figures.at("bound_conjugacy_mean").get<double>());
  return text;
}

int Panels(const Mesh& mesh) {
  int panels = 0;
  for (FaceIndex f : mesh.faces()) panels += mesh.degree(f) > 3 ? 1 : 0;
  return panels;
}


// The level sets of the net's surface for a layout of `faces` faces (on its
// design surface, split where it is coarser: field_pipeline.h).
std::shared_ptr<const LevelSetResult> LayOutNet(const Settings& s, const Mesh& net, long long faces,
                                                const ProgressSink& progress) {
  int refinements = 0;
  const Mesh design = DesignSurface(s, net, faces, &refinements);
  std::map<std::string, Value> overrides = SplitDesignOverrides(s, refinements);
  overrides["level_sets.target_faces"] = faces;
  return SolveLevelSets(s, design, progress, overrides);
}

// relayout: auto on an unsuitable net: its surface's conjugate layout
// becomes the net solved.
void Relayout(HookContext& c) {
  const Settings& s = *c.settings;
  const Mesh& net = *c.input;
  const long long faces = (long long)net.number_of_faces();
  if (c.progress) {
    c.progress("relayout: auto: laying out the net's surface along a conjugate field (" +
               std::to_string(faces) + " target faces)");
  }
  const std::shared_ptr<const LevelSetResult> result =
      LayOutNet(s, net, faces, c.progress);
  if (!result->layout.ok) {
    throw NoResult("the net's surface could not be laid out anew (relayout: auto): " +
                   result->layout.error);
  }
  const int split =
      UseLayoutAsNet(c, result, "conjugate layout of the input's surface (relayout: auto)");
  const long long after = (long long)c.net.mesh.number_of_faces();
  const int panels_before = Panels(net), panels_after = Panels(c.net.mesh);
  c.details["relayout"] = {{"mode", "auto"},
                           {"relaid", true},
                           {"connectivity_changed", true},
                           {"faces_before", faces},
                           {"faces_after", after},
                           {"panels_before", panels_before},
                           {"panels_after", panels_after},
                           {"panel_difference", panels_after - panels_before},
                           {"split_bent_panels", split},
                           {"vertices_before", net.number_of_vertices()},
                           {"vertices_after", c.net.mesh.number_of_vertices()}};
  char text[256];
  std::snprintf(text, sizeof text,
                "relayout: the net was replaced by a conjugate layout of its surface: the "
                "connectivity changed, %d panels instead of %d (%+d), %lld faces instead of %lld\n",
                panels_after, panels_before, panels_after - panels_before, after, faces);
  c.net.headline = result->field->headline + result->headline + text;
}

}  // namespace

std::string RelayoutCommand(const Settings& s, const Mesh& net) {
  const std::string& file = s.String("mesh");  // "" for a net given in memory
  const std::string mesh =
      file.empty() ? "NET_FILE" : std::filesystem::absolute(file).lexically_normal().string();
  return "archgeo solve examples/conjugate_layout.yaml --set mesh=" + mesh +
         " --set level_sets.target_faces=" + std::to_string(net.number_of_faces());
}

void CheckOrRelayout(HookContext& c) {
  if (c.settings->String("relayout") != "auto") {
    CheckConjugateNet(c, *c.input);
    return;
  }
  if (CheckConjugateNetNow(c, *c.input)) {
    c.details["relayout"] = {{"mode", "auto"}, {"relaid", false}};
    return;
  }
  Relayout(c);
}

void SuggestRelayout(HookContext& c) {
  const Settings& s = *c.settings;
  if (s.String("relayout") != "suggest") return;
  const double bound = s.Number("tolerance.pq_normalized_max");
  if (!(bound > 0) || c.Measure("pq_normalized_max") <= bound) return;
  const nlohmann::json figures =
      c.details.contains("suitability") ? c.details["suitability"] : nlohmann::json::object();
  const std::string command = RelayoutCommand(s, *c.input);
  c.details["relayout"] = {{"mode", "suggest"}, {"relaid", false}, {"command", command}};
  const std::string line =
      "the tolerance was missed on this net (" + ConjugacyText(figures) +
      "): planar quads need edges along conjugate directions. Lay the net's surface out anew "
      "along a conjugate field and planarise that (a new net, about as many faces), from the "
      "archgeo folder:\n  " + command + "\n(or relayout: auto in this spec)";
  c.headline += "WAY OUT: " + line + "\n";
}

int UseLayoutAsNet(HookContext& c, std::shared_ptr<const LevelSetResult> layout,
                   const std::string& what) {
  c.net.derived = true;
  c.net.mesh = InFileUnits(layout->layout.mesh, layout->frame);
  int dissolved = 0;
  const int split = SplitBentPanels(
      c.net.mesh, c.settings->Number("terms.convexity.margin_degrees"), &dissolved);
  c.net.source.clear();  // layout vertices are not input vertices
  c.net.details = layout->details;
  c.net.details["net"] = what;
  c.net.details["split_bent_panels"] = split;
  c.net.details["dissolved_straight_boundary_vertices"] = dissolved;
  c.level_sets = std::move(layout);
  return split;
}

namespace {

// The largest turn (degrees, in space) of a boundary that counts as
// straight at a vertex: the vertex then lies within 0.9% of the chord's
// length from the chord between its neighbours.
constexpr double kStraightBoundaryDegrees = 2.0;

// A boundary vertex that only one panel uses, where the boundary runs
// straight (its two sides within kStraightBoundaryDegrees, or the margin if
// larger, of a line, in space), is not a corner of that panel but a point on
// one of its sides: it leaves the panel if at least three corners stay. A
// quad through such a vertex is a triangle in shape; split at that corner it
// would be two triangles, one of them a sliver, and the split's diagonal
// would end at an interior vertex of valence 5. Returns how many left.
int DissolveStraightBoundaryVertices(const std::vector<Eigen::Vector3d>& points,
                                     double margin_degrees, std::vector<std::vector<int>>* faces) {
  std::vector<int> uses(points.size(), 0);
  for (const std::vector<int>& face : *faces)
    for (int v : face) ++uses[size_t(v)];
  const double straight =
      M_PI * (1.0 - std::max(margin_degrees, kStraightBoundaryDegrees) / 180.0);
  int dissolved = 0;
  for (std::vector<int>& face : *faces) {
    for (size_t i = 0; i < face.size() && face.size() > 3;) {
      const size_t n = face.size();
      const Eigen::Vector3d& x = points[size_t(face[i])];
      const Eigen::Vector3d a = points[size_t(face[(i + n - 1) % n])] - x,
                            b = points[size_t(face[(i + 1) % n])] - x;
      if (uses[size_t(face[i])] == 1 && std::atan2(a.cross(b).norm(), a.dot(b)) >= straight) {
        face.erase(face.begin() + long(i));
        ++dissolved;
      } else {
        ++i;
      }
    }
  }
  return dissolved;
}

}  // namespace

int SplitBentPanels(Mesh& mesh, double margin_degrees, int* dissolved) {
  // Corners judged in the mesh's local frame (mesh/similarity.h): the same
  // for a layout far from the origin or at any scale (cross products of
  // file units scaled by 1e100 overflow).
  const Similarity local = LocalFrame(mesh);
  std::vector<Eigen::Vector3d> points;
  for (VertexIndex v : mesh.vertices()) {
    const Vec3 p = local.ToCanonical(ToVec3(mesh.point(v)));
    points.emplace_back(p[0], p[1], p[2]);
  }
  std::vector<std::vector<int>> faces;
  for (FaceIndex f : mesh.faces()) {
    std::vector<int> face;
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(f), mesh)) face.push_back(int(v.idx()));
    faces.push_back(face);
  }
  const int gone = DissolveStraightBoundaryVertices(points, margin_degrees, &faces);
  if (dissolved) *dissolved = gone;
  int split = 0;
  // A split that leaves a corner under 5° (validity.min_corner_degrees'
  // default) would trade the bent corner for a sliver: the corner stays.
  SplitReflexCorners(points, std::vector<bool>(points.size(), false), -margin_degrees, &faces, &split,
                     5.0);
  if (split == 0 && gone == 0) return 0;
  // The vertices a panel still uses, in their order.
  std::vector<int> index(points.size(), -1);
  for (const std::vector<int>& face : faces)
    for (int v : face) index[size_t(v)] = 0;
  Mesh out;
  for (VertexIndex v : mesh.vertices())
    if (index[v.idx()] == 0) index[v.idx()] = int(out.add_vertex(mesh.point(v)).idx());
  for (const std::vector<int>& face : faces) {
    std::vector<VertexIndex> vs;
    for (int v : face) vs.push_back(VertexIndex(index[size_t(v)]));
    CHECK(out.add_face(vs) != Mesh::null_face()) << "a split panel is not manifold";
  }
  mesh = std::move(out);
  return split;
}

}  // namespace archgeo
