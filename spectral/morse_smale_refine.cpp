// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// Local refinement for the arcs of the Morse–Smale complex (Gebreiter 2012,
// §7.1.3: "in case these still merge, the local vertex valence is increased
// by local subdivision"). The edges near the arcs that could not be placed
// are split at their midpoints, f linear along each edge, so the surface
// and the piecewise-linear function stay the same and so do the critical
// points:
//  - an end a of the split edge ab sees the midpoint m where it saw b, on
//    b's side (f(m) − f(a) = (f(b) − f(a))/2);
//  - the two opposite vertices x, y see m between a and b: on their side if
//    both are, and one sign change between a and b either way;
//  - m's ring (a, x, b, y) has a and b on opposite sides, hence two changes:
//    m is regular.
// A split whose midpoint value rounds onto a neighbour's is not made (ties
// would be broken by index, which could flip a sign). Where every edge of a
// region is split, its resolution doubles: two arcs that met on a vertex
// there, or an arc and another saddle's ring, have a vertex between them.
#include <algorithm>
#include <stdexcept>

#include "spectral/morse_smale_detail.h"

namespace archgeo {
namespace morse_smale {
namespace {

size_t RefineFind(const std::vector<int>& ring, int v) {
  const auto it = std::find(ring.begin(), ring.end(), v);
  if (it == ring.end()) throw std::logic_error("morse_smale: ring and edge disagree");
  return size_t(it - ring.begin());
}

// Inserts m between a and b, consecutive in `ring`.
void RefineInsertBetween(std::vector<int>& ring, int a, int b, int m) {
  const size_t n = ring.size(), ia = RefineFind(ring, a), ib = RefineFind(ring, b);
  const size_t at = (ia + 1) % n == ib ? ia + 1 : ib + 1;
  ring.insert(ring.begin() + long(at), m);
}

// Splits edge ab; false (nothing changed) when the midpoint's value equals
// one of its four neighbours'.
bool RefineSplitEdge(ArcMesh& mesh, int a, int b, std::vector<Draft>& drafts);

// Splits ab and, on a double, its mirror image (a and b taken on the
// surface's side first); the midpoints are each other's images.
void RefineSplitPair(ArcMesh& mesh, int a, int b, std::vector<Draft>& drafts) {
  MorseSmaleMirror& m = mesh.mirror;
  if (m.side.empty()) {
    RefineSplitEdge(mesh, a, b, drafts);
    return;
  }
  if (m.side[size_t(a)] == 2 || m.side[size_t(b)] == 2) {
    a = m.image[size_t(a)];
    b = m.image[size_t(b)];
  }
  const int first = int(mesh.points.size());
  if (!RefineSplitEdge(mesh, a, b, drafts)) return;
  const bool boundary = m.side[size_t(a)] == 1 && m.side[size_t(b)] == 1;
  m.image.push_back(first);
  m.side.push_back(boundary ? 1 : 0);
  if (boundary) return;
  // The image's neighbours carry the same values: it splits too.
  if (!RefineSplitEdge(mesh, m.image[size_t(a)], m.image[size_t(b)], drafts)) {
    throw std::invalid_argument("the function is not mirror-symmetric across the boundary");
  }
  m.image[size_t(first)] = first + 1;
  m.image.push_back(first);
  m.side.push_back(2);
}

bool RefineSplitEdge(ArcMesh& mesh, int a, int b, std::vector<Draft>& drafts) {
  std::vector<int>& ra = mesh.rings[size_t(a)];
  const size_t n = ra.size(), ib = RefineFind(ra, b);
  const int x = ra[(ib + n - 1) % n], y = ra[(ib + 1) % n];
  const double value = 0.5 * (mesh.f[size_t(a)] + mesh.f[size_t(b)]);
  for (int u : {a, b, x, y}) {
    if (value == mesh.f[size_t(u)]) return false;
  }
  const int m = int(mesh.points.size());
  mesh.points.push_back(0.5 * (mesh.points[size_t(a)] + mesh.points[size_t(b)]));
  mesh.f.push_back(value);
  mesh.rings[size_t(a)][ib] = m;
  std::vector<int>& rb = mesh.rings[size_t(b)];
  rb[RefineFind(rb, a)] = m;
  RefineInsertBetween(mesh.rings[size_t(x)], a, b, m);
  RefineInsertBetween(mesh.rings[size_t(y)], a, b, m);
  mesh.rings.push_back({a, x, b, y});  // the orientation of a's ring (x, b, y)
  for (Draft& d : drafts) {
    if (!d.alive) continue;
    for (size_t i = 0; i + 1 < d.guide.size(); ++i) {
      const int p = d.guide[i], q = d.guide[i + 1];
      if ((p == a && q == b) || (p == b && q == a)) {
        d.guide.insert(d.guide.begin() + long(i) + 1, m);
        break;
      }
    }
  }
  return true;
}

}  // namespace

void SplitLink(ArcMesh& mesh, int v, std::vector<Draft>& drafts) {
  const MorseSmaleMirror& m = mesh.mirror;
  v = OnSurface(m, v);
  const std::vector<int> ring = mesh.rings[size_t(v)];
  for (size_t i = 0; i < ring.size(); ++i) {
    const int a = ring[i], b = ring[(i + 1) % ring.size()];
    // A boundary vertex's link edges among the images: split as the images
    // of the surface's.
    if (!m.side.empty() && (m.side[size_t(a)] == 2 || m.side[size_t(b)] == 2)) continue;
    RefineSplitPair(mesh, a, b, drafts);
  }
}

void SplitAround(ArcMesh& mesh, const std::vector<int>& seeds, int width,
                 std::vector<Draft>& drafts) {
  std::vector<char> in(mesh.points.size(), 0);
  std::vector<int> region, front;
  for (int v : seeds) {
    v = OnSurface(mesh.mirror, v);  // a double's region is mirrored (below)
    if (!in[size_t(v)]) {
      in[size_t(v)] = 1;
      front.push_back(v);
    }
  }
  region = front;
  for (int r = 0; r < width; ++r) {
    std::vector<int> next;
    for (int v : front) {
      for (int u : mesh.rings[size_t(v)]) {
        if (!in[size_t(u)]) {
          in[size_t(u)] = 1;
          next.push_back(u);
        }
      }
    }
    region.insert(region.end(), next.begin(), next.end());
    front = std::move(next);
  }
  std::vector<std::pair<int, int>> edges;
  const std::vector<char>& side = mesh.mirror.side;
  for (int v : region) {
    for (int u : mesh.rings[size_t(v)]) {
      if (!in[size_t(u)]) continue;
      if (!side.empty() && (side[size_t(v)] == 2 || side[size_t(u)] == 2)) continue;
      if (v < u) edges.emplace_back(v, u);
    }
  }
  for (const auto& [a, b] : edges) RefineSplitPair(mesh, a, b, drafts);
}

void Rewedge(const ArcMesh& mesh, std::vector<Draft>& drafts) {
  for (Draft& d : drafts) {
    if (!d.alive) continue;
    const int s = d.guide.front();
    const std::vector<int>& ring = mesh.rings[size_t(s)];
    const size_t n = ring.size(), at = RefineFind(ring, d.guide[1]);
    const bool up = Above(mesh.f, ring[at], s);
    size_t lo = at, hi = at;  // the run of ring vertices on d's side around its first step
    size_t count = 1;
    while (count < n && Above(mesh.f, ring[(lo + n - 1) % n], s) == up) lo = (lo + n - 1) % n, ++count;
    while (count < n && Above(mesh.f, ring[(hi + 1) % n], s) == up) hi = (hi + 1) % n, ++count;
    d.wedge.clear();
    for (size_t k = lo;; k = (k + 1) % n) {
      d.wedge.push_back(ring[k]);
      if (k == hi) break;
    }
  }
}

bool RingsFollowTriangles(const std::vector<std::vector<int>>& rings,
                          const std::array<int, 3>& t) {
  const std::vector<int>& r0 = rings[size_t(t[0])];
  return r0[(RefineFind(r0, t[1]) + 1) % r0.size()] == t[2];
}

std::vector<std::array<int, 3>> TrianglesOfRings(const std::vector<std::vector<int>>& rings,
                                                 bool forward) {
  std::vector<std::array<int, 3>> out;
  for (int v = 0; v < int(rings.size()); ++v) {
    const std::vector<int>& ring = rings[size_t(v)];
    for (size_t i = 0; i < ring.size(); ++i) {
      const int p = ring[i], q = ring[(i + 1) % ring.size()];
      if (v < p && v < q) out.push_back(forward ? std::array<int, 3>{v, p, q} : std::array<int, 3>{v, q, p});
    }
  }
  return out;
}

}  // namespace morse_smale
}  // namespace archgeo
