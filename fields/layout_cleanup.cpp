// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Polygon-soup clean-ups of a layout (see fields/layout_cleanup.h).
#include "fields/layout_cleanup.h"

#include "core/newell.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include <Eigen/Geometry>

namespace archgeo {
namespace {

using V3 = Eigen::Vector3d;

// The Newell normal of a polygon (twice its vector area).
V3 Newell(const std::vector<V3>& p) {
  return NewellVector(int(p.size()), [&](int i) { return p[size_t(i)]; });
}

// Interior angles (radians, in [0, 2π)) of a polygon in the plane of its
// Newell normal, counter-clockwise about it.
std::vector<double> InteriorAngles(const std::vector<V3>& p) {
  const size_t n = p.size();
  V3 normal = Newell(p);
  std::vector<double> angles(n, M_PI);
  if (normal.norm() == 0.0) return angles;
  normal.normalize();
  for (size_t i = 0; i < n; ++i) {
    V3 a = p[(i + n - 1) % n] - p[i], b = p[(i + 1) % n] - p[i];
    a -= normal * a.dot(normal);
    b -= normal * b.dot(normal);
    double angle = std::atan2(b.cross(a).dot(normal), a.dot(b));
    if (angle < 0.0) angle += 2.0 * M_PI;
    angles[i] = angle;
  }
  return angles;
}

// Undirected edge (smaller index first) -> the faces that have it, in order.
using EdgeFaceMap = std::map<std::pair<int, int>, std::vector<int>>;
EdgeFaceMap EdgeFaces(const std::vector<std::vector<int>>& faces) {
  EdgeFaceMap edge_faces;
  for (size_t f = 0; f < faces.size(); ++f) {
    const std::vector<int>& c = faces[f];
    for (size_t i = 0; i < c.size(); ++i) {
      const int a = c[i], b = c[(i + 1) % c.size()];
      edge_faces[{std::min(a, b), std::max(a, b)}].push_back(static_cast<int>(f));
    }
  }
  return edge_faces;
}

}  // namespace

void CleanCycle(std::vector<int>* cycle) {
  bool changed = true;
  while (changed && !cycle->empty()) {
    changed = false;
    std::vector<int>& c = *cycle;
    for (size_t i = 0; i < c.size() && c.size() > 1; ++i) {
      const size_t j = (i + 1) % c.size();
      if (c[i] == c[j]) {
        c.erase(c.begin() + static_cast<long>(j));
        changed = true;
        break;
      }
    }
    if (changed || c.size() < 3) continue;
    for (size_t i = 0; i < c.size(); ++i) {
      const size_t j = (i + 1) % c.size(), k = (i + 2) % c.size();
      if (c[i] == c[k]) {  // spike at j: drop j and one copy of c[i]
        std::vector<int> next;
        for (size_t m = 0; m < c.size(); ++m)
          if (m != j && m != k) next.push_back(c[m]);
        c.swap(next);
        changed = true;
        break;
      }
    }
  }
}

void SimpleCycles(std::vector<int> cycle, std::vector<std::vector<int>>* out, int* dropped) {
  CleanCycle(&cycle);
  for (size_t i = 0; i < cycle.size(); ++i) {
    for (size_t j = i + 1; j < cycle.size(); ++j) {
      if (cycle[i] != cycle[j]) continue;
      std::vector<int> inner(cycle.begin() + static_cast<long>(i), cycle.begin() + static_cast<long>(j));
      std::vector<int> outer(cycle.begin(), cycle.begin() + static_cast<long>(i));
      outer.insert(outer.end(), cycle.begin() + static_cast<long>(j), cycle.end());
      SimpleCycles(inner, out, dropped);
      SimpleCycles(outer, out, dropped);
      return;
    }
  }
  if (cycle.size() >= 3) {
    out->push_back(cycle);
  } else {
    ++*dropped;
  }
}

void MergeValenceTwo(std::vector<std::vector<int>>* faces, int* merged, int* dropped) {
  for (bool changed = true; changed;) {
    changed = false;
    EdgeFaceMap edge_faces = EdgeFaces(*faces);
    std::map<int, std::set<int>> neighbours;
    for (const auto& [edge, around] : edge_faces) {
      neighbours[edge.first].insert(edge.second);
      neighbours[edge.second].insert(edge.first);
    }
    for (const auto& [v, around] : neighbours) {
      if (around.size() != 2) continue;
      const int a = *around.begin(), b = *around.rbegin();
      const std::vector<int>& fa = edge_faces[{std::min(v, a), std::max(v, a)}];
      const std::vector<int>& fb = edge_faces[{std::min(v, b), std::max(v, b)}];
      if (fa.size() != 2 || fb.size() != 2) continue;  // on the boundary
      const std::set<int> two(fa.begin(), fa.end());
      if (two.size() != 2 || two != std::set<int>(fb.begin(), fb.end())) continue;
      // Each face as the path after v around it (v dropped).
      // (A copy of v: C++17 lambdas cannot capture a structured binding.)
      auto after = [&, centre = v](int f) {
        const std::vector<int>& c = (*faces)[f];
        const size_t at = static_cast<size_t>(std::find(c.begin(), c.end(), centre) - c.begin());
        std::vector<int> path;
        for (size_t k = 1; k < c.size(); ++k) path.push_back(c[(at + k) % c.size()]);
        return path;
      };
      std::vector<int> first = after(*two.begin()), second = after(*two.rbegin());
      if (first.size() < 2 || second.size() < 2 || first.front() != second.back() ||
          first.back() != second.front()) {
        continue;
      }
      // first: (b … a), second: (a … b): the merged face is first + second's inside.
      std::vector<int> merged_face = first;
      merged_face.insert(merged_face.end(), second.begin() + 1, second.end() - 1);
      std::vector<std::vector<int>> next;
      for (size_t f = 0; f < faces->size(); ++f)
        if (two.count(static_cast<int>(f)) == 0) next.push_back((*faces)[f]);
      SimpleCycles(merged_face, &next, dropped);
      faces->swap(next);
      ++*merged;
      changed = true;
      break;
    }
  }
}

void MergeCaps(const std::vector<V3>& points, double cap_angle_deg,
               std::vector<std::vector<int>>* faces, int* merged, int* dropped) {
  const double limit = cap_angle_deg * M_PI / 180.0;
  for (bool changed = true; changed;) {
    changed = false;
    EdgeFaceMap edge_faces = EdgeFaces(*faces);
    for (size_t f = 0; f < faces->size() && !changed; ++f) {
      const std::vector<int>& t = (*faces)[f];
      if (t.size() != 3) continue;
      for (int k = 0; k < 3; ++k) {
        const int x = t[k], p = t[(k + 1) % 3], q = t[(k + 2) % 3];  // f runs x → p → q
        const V3 a = points[p] - points[x], b = points[q] - points[x];
        if (std::atan2(a.cross(b).norm(), a.dot(b)) <= limit) continue;
        const std::vector<int>& across = edge_faces[{std::min(p, q), std::max(p, q)}];
        if (across.size() != 2) break;  // a boundary side: keep the triangle
        const int g = across[0] == static_cast<int>(f) ? across[1] : across[0];
        std::vector<int> grown;  // g runs q → p: insert x between them
        const std::vector<int>& c = (*faces)[g];
        for (size_t i = 0; i < c.size(); ++i) {
          grown.push_back(c[i]);
          if (c[i] == q && c[(i + 1) % c.size()] == p) grown.push_back(x);
        }
        std::vector<std::vector<int>> next;
        for (size_t h = 0; h < faces->size(); ++h)
          if (h != f && static_cast<int>(h) != g) next.push_back((*faces)[h]);
        SimpleCycles(grown, &next, dropped);
        faces->swap(next);
        ++*merged;
        changed = true;
        break;
      }
    }
  }
}

void RemoveNearSlits(const std::vector<V3>& points, double angle_deg,
                     std::vector<std::vector<int>>* faces, int* removed, int* dropped) {
  const double limit = angle_deg * M_PI / 180.0;
  // Each removal takes a vertex out of one face; at most one per point.
  const int most = static_cast<int>(points.size());
  for (bool changed = true; changed && *removed < most;) {
    changed = false;
    const EdgeFaceMap edge_faces = EdgeFaces(*faces);
    for (size_t f = 0; f < faces->size() && !changed; ++f) {
      const std::vector<int> c = (*faces)[f];
      const size_t n = c.size();
      for (size_t i = 0; i < n && !changed; ++i) {
        const int x = c[i], prev = c[(i + n - 1) % n], next = c[(i + 1) % n];
        const V3 a = points[prev] - points[x], b = points[next] - points[x];
        if (std::atan2(a.cross(b).norm(), a.dot(b)) >= limit) continue;
        const bool prev_shorter = a.norm() < b.norm();
        const int q = prev_shorter ? prev : next, p = prev_shorter ? next : prev;
        // f runs x → p (p next) or p → x; the face across runs the other way.
        const int from = p == next ? p : x, to = p == next ? x : p;
        int g = -1;
        size_t at = 0;
        for (int h : edge_faces.at({std::min(from, to), std::max(from, to)})) {
          const std::vector<int>& d = (*faces)[h];
          for (size_t k = 0; k < d.size() && g < 0; ++k)
            if (h != static_cast<int>(f) && d[k] == from && d[(k + 1) % d.size()] == to) {
              g = h;
              at = k + 1;
            }
        }
        if (g < 0) continue;  // a boundary side
        std::vector<int>& across = (*faces)[g];
        if (std::find(across.begin(), across.end(), q) != across.end()) continue;
        across.insert(across.begin() + static_cast<long>(at), q);
        std::vector<int> rest;
        for (int v : c)
          if (v != x) rest.push_back(v);
        if (rest.size() >= 3) {
          (*faces)[f] = rest;
        } else {
          faces->erase(faces->begin() + static_cast<long>(f));
          ++*dropped;
        }
        ++*removed;
        changed = true;
      }
    }
  }
}

void SplitReflexCorners(const std::vector<V3>& points, const std::vector<bool>& on_boundary,
                        double margin_deg, std::vector<std::vector<int>>* faces, int* split,
                        double min_corner_deg) {
  const double limit = M_PI + margin_deg * M_PI / 180.0;
  const double min_corner = min_corner_deg * M_PI / 180.0;
  auto positions = [&](const std::vector<int>& c) {
    std::vector<V3> p;
    for (int v : c) p.push_back(points[v]);
    return p;
  };
  for (size_t f = 0; f < faces->size();) {  // f advances once it has no reflex corner left
    const std::vector<int> c = (*faces)[f];
    const size_t n = c.size();
    if (n < 4) {
      ++f;
      continue;
    }
    const std::vector<double> angle = InteriorAngles(positions(c));
    const V3 normal = Newell(positions(c));
    size_t x = n;
    for (size_t i = 0; i < n; ++i)
      if (!on_boundary[c[i]] && angle[i] > limit && (x == n || angle[i] > angle[x])) x = i;
    if (x == n) {
      ++f;
      continue;
    }
    double best_score = -1.0;
    std::vector<int> best_a, best_b;
    for (size_t k = 2; k + 1 < n; ++k) {
      const size_t y = (x + k) % n;
      std::vector<int> a, b;  // x … y and y … x
      for (size_t i = x;; i = (i + 1) % n) {
        a.push_back(c[i]);
        if (i == y) break;
      }
      for (size_t i = y;; i = (i + 1) % n) {
        b.push_back(c[i]);
        if (i == x) break;
      }
      // Both parts turn as the face does (a diagonal outside the face
      // would give a part folded onto the other).
      if (Newell(positions(a)).dot(normal) <= 0.0 || Newell(positions(b)).dot(normal) <= 0.0)
        continue;
      const std::vector<double> ea = InteriorAngles(positions(a)), eb = InteriorAngles(positions(b));
      const double corners[4] = {ea.front(), ea.back(), eb.front(), eb.back()};
      double smallest = M_PI;
      bool convex = true;
      for (double corner : corners) {
        convex = convex && corner < M_PI;
        smallest = std::min(smallest, corner);
      }
      if (!convex || smallest < min_corner) continue;
      const double score = (a.size() == 4) + (b.size() == 4) + smallest / M_PI;
      if (score > best_score) {
        best_score = score;
        best_a = a;
        best_b = b;
      }
    }
    if (best_score < 0.0) {
      ++f;
      continue;
    }
    (*faces)[f] = best_a;  // checked again: it may have another reflex corner
    faces->push_back(best_b);
    ++*split;
  }
}

}  // namespace archgeo
