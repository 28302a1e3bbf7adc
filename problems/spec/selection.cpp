// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/spec/selection.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>

#include "geometry/curves.h"
#include "core/input_error.h"
#include "mesh/topology.h"

namespace archgeo {
namespace {

namespace fs = std::filesystem;

const char* kForms =
    "all, boundary, interior, free, a list of site ids, or a mapping of boundary (true | "
    "false), free, ids, loop, degree, curve (+ within)";

class Parser {
 public:
  Parser(const Settings& s, std::string key) : s_(s), key_(std::move(key)), at_(s.Where(key_)) {}

  [[noreturn]] void Fail(const CustomValue& node, const std::string& sub,
                         const std::string& message) const {
    throw s_.ErrorAt(key_, node, sub.empty() ? key_ : key_ + "." + sub, message);
  }

  Selection Parse() {
    Selection out;
    out.line = at_.line;
    const CustomValue* custom = s_.Custom(key_);
    if (!custom) return out;  // the default: all
    const CustomValue& node = *custom;
    if (node.IsScalar()) {
      const std::string& form = node.text;
      if (form == "boundary") {
        out.side = Selection::Side::kBoundary;
      } else if (form == "interior") {
        out.side = Selection::Side::kInterior;
      } else if (form == "free") {
        out.free = true;
      } else if (form != "all") {
        Fail(node, "", "'" + form + "' is not a selection (" + kForms + ")");
      }
    } else if (node.IsList()) {
      out.by_ids = true;
      out.ids = Integers(node, "", 0);
    } else if (node.IsMap()) {
      std::set<std::string> seen;
      for (const CustomValue::Entry& entry : node.entries) {
        const std::string& k = entry.key.text;
        const CustomValue& v = entry.value;
        if (!seen.insert(k).second) Fail(entry.key, k, "duplicate key");
        if (k == "boundary") {
          out.side = Bool(v, k) ? Selection::Side::kBoundary : Selection::Side::kInterior;
        } else if (k == "free") {
          if (!Bool(v, k)) Fail(v, k, "only `free: true` is a condition (leave it out for all)");
          out.free = true;
        } else if (k == "ids") {
          if (!v.IsList()) Fail(v, k, "expected a list of site ids");
          out.by_ids = true;
          out.ids = Integers(v, k, 0);
        } else if (k == "loop") {
          out.loop = int(Integer(v, k, 0));
        } else if (k == "degree") {
          out.degrees = v.IsList() ? Integers(v, k, 1) : std::vector<long long>{Integer(v, k, 1)};
          if (out.degrees.empty()) Fail(v, k, "expected a degree or a list of degrees");
        } else if (k == "curve") {
          if (!v.IsScalar() || v.text.empty()) Fail(v, k, "expected an OBJ file of polylines");
          out.curve = Resolve(v.text);
        } else if (k == "within") {
          if (!v.number || !std::isfinite(*v.number) || !(*v.number > 0)) {
            Fail(v, k, "expected a distance > 0 (input mean edge lengths)");
          }
          out.within = *v.number;
        } else {
          Fail(entry.key, k, "unknown selection key (allowed: boundary, free, ids, loop, "
                               "degree, curve, within)");
        }
      }
      if (seen.count("within") && out.curve.empty()) {
        Fail(node, "within", "`within` goes with `curve`");
      }
      if (seen.empty()) Fail(node, "", std::string("an empty mapping; expected ") + kForms);
    } else {
      Fail(node, "", std::string("expected ") + kForms);
    }
    return out;
  }

 private:
  bool Bool(const CustomValue& v, const std::string& k) const {
    if (!v.boolean) Fail(v, k, "expected true or false");
    return *v.boolean;
  }

  long long Integer(const CustomValue& v, const std::string& k, long long lo) const {
    if (!v.integer || *v.integer < lo) Fail(v, k, "expected an integer ≥ " + std::to_string(lo));
    return *v.integer;
  }

  std::vector<long long> Integers(const CustomValue& list, const std::string& k,
                                  long long lo) const {
    std::vector<long long> out;
    for (const CustomValue& v : list.items) out.push_back(Integer(v, k, lo));
    return out;
  }

  // Relative to the spec's folder (to the current folder for --set).
  std::string Resolve(const std::string& path) const {
    const fs::path p(path);
    if (p.is_absolute() || at_.file == "--set") return fs::absolute(p).lexically_normal().string();
    const std::string spec = at_.file.empty() ? s_.spec_file() : at_.file;
    return (fs::path(spec).parent_path() / p).lexically_normal().string();
  }

  const Settings& s_;
  std::string key_;
  Origin at_;
};

// The vertices of an element's site.
std::vector<int> SiteVertices(const Mesh& mesh, Site site, int index) {
  std::vector<int> vs;
  if (site == Site::kVertex) {
    vs.push_back(index);
  } else if (site == Site::kFace) {
    for (VertexIndex v : CGAL::vertices_around_face(mesh.halfedge(FaceIndex(index)), mesh)) {
      vs.push_back(int(v.idx()));
    }
  } else {
    const EdgeIndex e(index);
    vs = {int(mesh.vertex(e, 0).idx()), int(mesh.vertex(e, 1).idx())};
  }
  return vs;
}

size_t SiteCount(const Mesh& mesh, Site site) {
  return site == Site::kVertex ? mesh.number_of_vertices()
         : site == Site::kFace ? mesh.number_of_faces()
                               : mesh.number_of_edges();
}

const char* SiteName(Site site) {
  return site == Site::kVertex ? "vertices" : site == Site::kFace ? "faces" : "edges";
}

}  // namespace

Selection ParseSelection(const Settings& settings, const std::string& key) {
  return Parser(settings, key).Parse();
}

std::vector<size_t> SelectElements(const Selection& sel, const ElementSet& set, const Mesh& mesh,
                                   const std::vector<bool>& fixed, const Similarity& frame,
                                   const Settings& s, const std::string& key) {
  std::vector<size_t> keep;
  if (sel.all()) {
    for (size_t i = 0; i < set.size(); ++i) keep.push_back(i);
    return keep;
  }
  // Listed site ids.
  std::vector<bool> listed;
  if (sel.by_ids) {
    const size_t count = SiteCount(mesh, set.site);
    listed.assign(count, false);
    for (long long id : sel.ids) {
      if (id >= (long long)count) {
        throw s.Error(key, "id " + std::to_string(id) + " out of range: the " + set.name +
                               " of this mesh are on " + std::to_string(count) + " " +
                               SiteName(set.site));
      }
      listed[size_t(id)] = true;
    }
  }
  // Vertices of the boundary loop.
  std::vector<bool> on_loop;
  if (sel.loop >= 0) {
    const std::vector<std::vector<VertexIndex>> loops = BoundaryLoops(mesh);
    if (sel.loop >= int(loops.size())) {
      throw s.Error(key, "loop " + std::to_string(sel.loop) + " does not exist: the mesh has " +
                             std::to_string(loops.size()) + " boundary loop(s)");
    }
    on_loop.assign(mesh.number_of_vertices(), false);
    for (VertexIndex v : loops[size_t(sel.loop)]) on_loop[v.idx()] = true;
  }
  if (!sel.degrees.empty() && set.site == Site::kEdge) {
    throw s.Error(key, "`degree` selects faces (sides) or vertices (valence); " + set.name +
                           " are on edges");
  }
  // Vertices near the curve file's polylines.
  std::vector<bool> near;
  if (!sel.curve.empty()) {
    std::vector<Polyline> curves;
    try {
      curves = ReadPolylines(sel.curve);
    } catch (const InputError& e) {
      throw s.Error(key, std::string("curve ") + e.what());
    }
    std::vector<PolylineLocator> locators;
    for (const Polyline& c : curves) {
      std::vector<Vec3> points;
      for (const Vec3& p : c.points) points.push_back(frame.ToCanonical(p));
      locators.emplace_back(MakePolyline(points, c.closed, sel.curve, 0, key));
    }
    near.assign(mesh.number_of_vertices(), false);
    for (VertexIndex v : mesh.vertices()) {
      for (const PolylineLocator& l : locators) {
        if (l.Closest(ToVec3(mesh.point(v))).distance <= sel.within) near[v.idx()] = true;
      }
    }
  }
  for (size_t i = 0; i < set.size(); ++i) {
    const int site = set.sites[i];
    if (site < 0) continue;
    const bool boundary = set.Has(i, kBoundary);
    if (sel.side == Selection::Side::kBoundary && !boundary) continue;
    if (sel.side == Selection::Side::kInterior && boundary) continue;
    if (sel.by_ids && !listed[size_t(site)]) continue;
    const std::vector<int> vs = SiteVertices(mesh, set.site, site);
    if (sel.free) {
      bool any_free = false;
      for (int v : vs) any_free = any_free || !fixed[size_t(v)];
      if (!any_free) continue;
    }
    if (sel.loop >= 0) {
      bool touches = false;
      for (int v : vs) touches = touches || on_loop[size_t(v)];
      if (!touches || (set.site != Site::kVertex && !boundary)) continue;
    }
    if (!sel.degrees.empty()) {
      const long long degree = set.site == Site::kFace ? (long long)mesh.degree(FaceIndex(site))
                                                       : (long long)mesh.degree(VertexIndex(site));
      if (std::find(sel.degrees.begin(), sel.degrees.end(), degree) == sel.degrees.end()) continue;
    }
    if (!sel.curve.empty()) {
      bool all_near = true;
      for (int v : vs) all_near = all_near && near[size_t(v)];
      if (!all_near) continue;
    }
    keep.push_back(i);
  }
  if (keep.empty() && set.size() > 0) {
    throw s.Error(key, "selects none of the " + std::to_string(set.size()) + " " + set.name);
  }
  return keep;
}

std::vector<Polyline> TermCurves(const Settings& s, const std::string& key,
                                 const Similarity& frame, const Mesh& reference) {
  const std::string& path = s.String(key);
  std::vector<Polyline> polylines;
  const std::string points_key = key + "_points";
  if (const CustomValue* list = s.Custom(points_key)) {
    if (!path.empty()) throw s.Error(points_key, "give either " + key + " or " + points_key);
    std::vector<Vec3> xyz;
    const std::string form = "expected a list of points [x, y, z] (file units)";
    if (!list->IsList()) throw s.Error(points_key, form);
    for (const CustomValue& point : list->items) {
      Vec3 x;
      bool ok = point.IsList() && point.items.size() == 3;
      for (size_t i = 0; ok && i < 3; ++i) {
        const std::optional<double>& number = point.items[i].number;
        ok = number && std::isfinite(*number);
        if (ok) x[i] = *number;
      }
      if (!ok) {
        throw s.Error(points_key, form + "; point " + std::to_string(xyz.size() + 1) +
                                      " is not three finite numbers");
      }
      xyz.push_back(x);
    }
    const bool closed = xyz.size() > 2 && xyz.front() == xyz.back();
    if (closed) xyz.pop_back();
    for (Vec3& x : xyz) x = frame.ToCanonical(x);
    const Origin at = s.Where(points_key);
    polylines.push_back(MakePolyline(xyz, closed, at.file.empty() ? s.spec_file() : at.file,
                                     at.file == "--set" ? 0 : at.line, points_key));
    return polylines;
  }
  if (!path.empty()) {
    try {
      for (Polyline& p : ReadPolylines(path)) {
        for (Vec3& x : p.points) x = frame.ToCanonical(x);
        polylines.push_back(MakePolyline(p.points, p.closed, path, 0, key));
      }
    } catch (const InputError& e) {
      if (e.file() == path) throw s.Error(key, e.what());
      throw;
    }
    return polylines;
  }
  const std::vector<std::vector<VertexIndex>> loops = BoundaryLoops(reference);
  if (loops.empty()) {
    throw s.Error(key, "no curve file given, and the reference surface has no boundary");
  }
  for (const auto& loop : loops) polylines.push_back(LoopPolyline(reference, loop));
  return polylines;
}

}  // namespace archgeo
