// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "spectral/morse_smale.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <unordered_map>

#include "spectral/morse_smale_detail.h"

namespace archgeo {
namespace {

using morse_smale::Draft;

// Rounds of local refinement at most while arcs cannot all be placed, and
// how many rings around the guides of the arcs left out each refines. (Six
// rounds placed no more complexes of the test sweeps than three.)
constexpr int kMsRefinements = 3;
constexpr int kMsRefineWidth = 2;

// f(u) > f(v), ties broken by index (as spectral/critical_points.h).
bool MsAbove(const Eigen::VectorXd& f, int u, int v) {
  return f[u] > f[v] || (f[u] == f[v] && u > v);
}

// The steepest path from `start` (already past the saddle): to the highest
// (lowest) neighbour while there is a higher (lower) one. On a double
// (`side` not empty), lane 0 keeps off the mirror images (whose values are
// their images'), lane 1 to the boundary.
std::vector<int> MsSteepest(const std::vector<std::vector<int>>& rings, const Eigen::VectorXd& f,
                            int saddle, int start, bool up, const std::vector<char>& side,
                            char lane) {
  std::vector<int> path{saddle, start};
  for (int v = start;;) {
    int next = v;
    for (int u : rings[v]) {
      if (!side.empty() && (lane == 1 ? side[size_t(u)] != 1 : side[size_t(u)] == 2)) continue;
      if (up ? MsAbove(f, u, next) : MsAbove(f, next, u)) next = u;
    }
    if (next == v) return path;
    path.push_back(v = next);
  }
}

// `path` without its loops (a vertex met again cuts what lay between).
std::vector<int> MsLoopErased(const std::vector<int>& path) {
  std::vector<int> out;
  std::unordered_map<int, size_t> at;
  for (int v : path) {
    auto it = at.find(v);
    if (it != at.end()) {
      for (size_t i = it->second + 1; i < out.size(); ++i) at.erase(out[i]);
      out.resize(it->second + 1);
      continue;
    }
    at[v] = out.size();
    out.push_back(v);
  }
  return out;
}

struct MsState {
  std::vector<MorseSmaleNode> nodes;
  std::vector<bool> node_alive;
  std::vector<Draft> drafts;
  std::vector<int> node_of;  // per vertex its node, or −1
  MorseSmaleMirror mirror;   // empty unless the mesh is a double
};

// On a double: the lane of a saddle's wedge (morse_smale_detail.h): a
// boundary saddle's wedge that holds a boundary vertex runs along the
// boundary, any other the side of the saddle or of its wedge.
char MsLane(const std::vector<char>& side, int saddle, const std::vector<int>& wedge) {
  if (side.empty()) return 0;
  if (side[size_t(saddle)] != 1) return side[size_t(saddle)];
  for (int u : wedge) {
    if (side[size_t(u)] == 1) return 1;
  }
  return side[size_t(wedge[0])];
}

// Classifies every vertex and traces one steepest path per saddle wedge
// (on a double the mirror images' wedges are left to MsTwins).
MsState MsTrace(const std::vector<std::vector<int>>& rings, const Eigen::VectorXd& f,
                const MorseSmaleMirror* mirror) {
  MsState s;
  if (mirror != nullptr) s.mirror = *mirror;
  const std::vector<char>& side = s.mirror.side;
  s.node_of.assign(rings.size(), -1);
  std::vector<int>& node_of = s.node_of;
  std::vector<std::pair<int, std::vector<std::vector<int>>>> saddle_wedges;
  for (int v = 0; v < int(rings.size()); ++v) {
    const std::vector<int>& ring = rings[v];
    const size_t n = ring.size();
    size_t changes = 0, first = n;
    for (size_t i = 0; i < n; ++i) {
      if (MsAbove(f, ring[i], v) != MsAbove(f, ring[(i + 1) % n], v)) {
        ++changes;
        if (first == n) first = (i + 1) % n;
      }
    }
    if (changes == 0) {
      node_of[v] = int(s.nodes.size());
      s.nodes.push_back({v, MsAbove(f, v, ring[0]) ? 1 : -1, 0});
    } else if (changes >= 4) {
      std::vector<std::vector<int>> wedges;
      for (size_t k = 0; k < n; ++k) {  // from the first vertex after a sign change
        const int u = ring[(first + k) % n];
        if (k == 0 || MsAbove(f, u, v) != MsAbove(f, wedges.back().back(), v)) wedges.emplace_back();
        wedges.back().push_back(u);
      }
      node_of[v] = int(s.nodes.size());
      s.nodes.push_back({v, 0, int(changes / 2) - 1});
      saddle_wedges.emplace_back(node_of[v], std::move(wedges));
    }
  }
  for (const MorseSmaleNode& n : s.nodes) {  // ties broken by index may break the symmetry
    const int image = side.empty() ? n.vertex : s.mirror.image[size_t(n.vertex)];
    const int m = node_of[size_t(image)];
    if (m < 0 || s.nodes[size_t(m)].kind != n.kind || s.nodes[size_t(m)].multiplicity != n.multiplicity) {
      throw std::invalid_argument("the function is not mirror-symmetric across the boundary");
    }
  }
  for (auto& [node, wedges] : saddle_wedges) {
    const int v = s.nodes[size_t(node)].vertex;
    for (std::vector<int>& wedge : wedges) {
      const bool up = MsAbove(f, wedge[0], v);
      Draft d;
      d.saddle = node;
      d.ascending = up;
      d.lane = MsLane(side, v, wedge);
      if (d.lane != 2) {
        int start = -1;
        for (int u : wedge) {
          if (d.lane == 1 && side[size_t(u)] != 1) continue;
          if (start < 0 || (up ? MsAbove(f, u, start) : MsAbove(f, start, u))) start = u;
        }
        d.guide = MsSteepest(rings, f, v, start, up, side, d.lane);
        d.target = node_of[size_t(d.guide.back())];
        if (d.target < 0) throw std::logic_error("morse_smale: a steepest path ends on a regular vertex");
      }
      d.wedge = std::move(wedge);
      s.drafts.push_back(std::move(d));
    }
  }
  s.node_alive.assign(s.nodes.size(), true);
  return s;
}

// On a double: each mirror image's draft (lane 2) becomes the image of the
// draft it mirrors (its twin), traced, cancelled and redirected on the
// surface. A connection of two boundary saddles along the boundary (the
// function rises along it from one to the other: the pair is its own
// mirror image, there is no side to pass it on) is traced from both ends:
// the second is placed as the first reversed (its twin), and the two
// saddles' polygons are one (SaddlePolygons).
void MsTwins(MsState& s) {
  const MorseSmaleMirror& m = s.mirror;
  if (m.side.empty()) return;
  for (size_t i = 0; i < s.drafts.size(); ++i) {
    Draft& d = s.drafts[i];
    if (!d.alive || d.lane != 1 || d.twin >= 0 || s.nodes[size_t(d.target)].kind != 0) continue;
    d.connection = true;
    for (size_t j = i + 1; j < s.drafts.size(); ++j) {
      Draft& e = s.drafts[j];
      if (e.alive && e.lane == 1 && e.saddle == d.target && e.target == d.saddle &&
          e.guide[1] == d.guide[d.guide.size() - 2]) {
        e.twin = int(i);
        e.connection = true;
      }
    }
  }
  std::unordered_map<long long, int> by_wedge;  // (saddle vertex, wedge vertex) → draft
  auto key = [&](int saddle, int v) { return (long long)saddle * (long long)m.image.size() + v; };
  for (size_t i = 0; i < s.drafts.size(); ++i) {
    const Draft& d = s.drafts[i];
    if (d.lane == 2) continue;
    for (int u : d.wedge) by_wedge[key(s.nodes[size_t(d.saddle)].vertex, u)] = int(i);
  }
  for (Draft& d : s.drafts) {
    if (d.lane != 2) continue;
    const int saddle = m.image[size_t(s.nodes[size_t(d.saddle)].vertex)];
    const auto it = by_wedge.find(key(saddle, m.image[size_t(d.wedge[0])]));
    if (it == by_wedge.end()) {  // ties broken by index moved a wedge's edge
      throw std::invalid_argument("the function is not mirror-symmetric across the boundary");
    }
    const Draft& t = s.drafts[size_t(it->second)];
    d.twin = it->second;
    d.alive = t.alive && s.node_alive[size_t(d.saddle)];
    d.guide.clear();
    for (int v : t.guide) d.guide.push_back(m.image[size_t(v)]);
    d.target = s.node_of[size_t(m.image[size_t(t.guide.back())])];
  }
}

struct MsPair {
  int saddle = -1, extremum = -1, partner = -1;
  double persistence = std::numeric_limits<double>::infinity();
};

// The least persistent pair of a simple saddle and an extremum joined by
// exactly one of its arcs; `by_saddle[s]` the saddle's live drafts.
MsPair MsWeakest(const MsState& s, const std::vector<std::vector<int>>& by_saddle,
                 const Eigen::VectorXd& f) {
  MsPair best;
  for (size_t n = 0; n < s.nodes.size(); ++n) {
    if (!s.node_alive[n] || s.nodes[n].kind != 0 || s.nodes[n].multiplicity != 1) continue;
    for (bool up : {true, false}) {
      std::vector<int> targets;
      for (int d : by_saddle[n]) {
        if (s.drafts[size_t(d)].ascending == up) targets.push_back(s.drafts[size_t(d)].target);
      }
      if (targets.size() != 2 || targets[0] == targets[1]) continue;
      // A connection along a double's boundary (MsTwins) is no pair.
      if (s.nodes[size_t(targets[0])].kind == 0 || s.nodes[size_t(targets[1])].kind == 0) continue;
      for (int i = 0; i < 2; ++i) {
        // On a double, a pair and its image are cancelled together: a pair
        // on the surface, or one on the boundary (its own image).
        if (!s.mirror.side.empty() &&
            s.mirror.side[size_t(s.nodes[n].vertex)] !=
                s.mirror.side[size_t(s.nodes[size_t(targets[i])].vertex)]) {
          continue;
        }
        const double p = std::abs(f[s.nodes[n].vertex] - f[s.nodes[size_t(targets[i])].vertex]);
        if (p < best.persistence) best = {int(n), targets[i], targets[1 - i], p};
      }
    }
  }
  return best;
}

// Removes the pair; the other arcs into its extremum go on through the
// pair's arc to the partner. (On a double the images' drafts are made
// afterwards, MsTwins.)
void MsCancel(MsState& s, std::vector<std::vector<int>>& by_saddle, const MsPair& p) {
  std::vector<int> to_extremum, to_partner;
  for (int d : by_saddle[size_t(p.saddle)]) {
    Draft& draft = s.drafts[size_t(d)];
    if (draft.target == p.extremum) to_extremum = draft.guide;
    if (draft.target == p.partner) to_partner = draft.guide;
    draft.alive = false;
  }
  by_saddle[size_t(p.saddle)].clear();
  std::vector<int> detour(to_extremum.rbegin() + 1, to_extremum.rend());  // back to the saddle
  detour.insert(detour.end(), to_partner.begin() + 1, to_partner.end());
  for (Draft& d : s.drafts) {
    if (!d.alive || d.lane == 2 || d.target != p.extremum) continue;
    d.guide.insert(d.guide.end(), detour.begin(), detour.end());
    d.guide = MsLoopErased(d.guide);
    d.target = p.partner;
  }
  for (int n : {p.saddle, p.extremum}) {
    s.node_alive[size_t(n)] = false;
    if (!s.mirror.side.empty()) {
      s.node_alive[size_t(s.node_of[size_t(s.mirror.image[size_t(s.nodes[size_t(n)].vertex)])])] = false;
    }
  }
}

void MsCancelPairs(MsState& s, const Eigen::VectorXd& f, const MorseSmaleOptions& options,
                   int& cancelled) {
  if (options.persistence <= 0 && options.target_extrema <= 0) return;
  std::vector<std::vector<int>> by_saddle(s.nodes.size());
  for (size_t d = 0; d < s.drafts.size(); ++d) {
    if (s.drafts[d].lane != 2) by_saddle[size_t(s.drafts[d].saddle)].push_back(int(d));
  }
  int extrema = 0;
  for (const MorseSmaleNode& n : s.nodes) extrema += n.kind != 0;
  while (options.target_extrema <= 0 || extrema > options.target_extrema) {
    const MsPair p = MsWeakest(s, by_saddle, f);
    if (p.saddle < 0) return;
    if (options.target_extrema <= 0 && p.persistence > options.persistence) return;
    MsCancel(s, by_saddle, p);
    const bool twice = !s.mirror.side.empty() && s.mirror.side[size_t(s.nodes[size_t(p.saddle)].vertex)] == 0;
    extrema -= twice ? 2 : 1;
    cancelled += twice ? 2 : 1;
  }
}

// Saddle–saddle connections (Gebreiter 2012, §7.1.3: "an ascent line
// reaching a saddle before it reaches a maximum"). A guide that enters the
// ring of another saddle s through a wedge of the opposite kind (a
// descending guide through an upper wedge of s: it comes down onto s) is
// continued as the flow perturbed to one side continues: round s's ring to
// the neighbouring wedge of its own kind, and along s's separatrix from
// there to its extremum. When the separatrix of s leaving by that wedge
// also runs onto the first saddle (the two are one connection traced from
// both ends), both turn the same way round their rings: the perturbed
// flow passes the lower saddle on one side and the upper on the other, and
// on a consistently oriented surface that is one sense of rotation. Else
// each turns to the nearer wedge. Without it a guide crosses s's ring
// wherever its steps fell and, rerouted round the ring on the shorter side,
// may pass s on the side away from its extremum.
struct MsTurn {
  size_t at = 0;       // the guide's first vertex in the ring of saddle `saddle`
  int saddle = -1;     // the saddle's vertex
  int partner = -1;    // the draft of that saddle leaving by the wedge entered
  size_t back = 0, ahead = 0;  // ring steps to a wedge of the guide's kind
};

void MsRedirect(MsState& s, const Eigen::VectorXd& f, const std::vector<std::vector<int>>& rings) {
  std::unordered_map<int, std::vector<size_t>> of_saddle;  // by the saddle's vertex
  for (size_t i = 0; i < s.drafts.size(); ++i) {
    if (s.drafts[i].alive && s.drafts[i].lane != 2) of_saddle[s.drafts[i].guide.front()].push_back(i);
  }
  std::unordered_map<int, std::vector<int>> ring_of;  // a ring vertex → the saddles' vertices
  for (const auto& [v, list] : of_saddle) {
    for (int u : rings[size_t(v)]) ring_of[u].push_back(v);
  }
  auto draft_by_wedge = [&](int saddle, int v) -> int {
    for (size_t e : of_saddle[saddle]) {
      const std::vector<int>& w = s.drafts[e].wedge;
      if (std::find(w.begin(), w.end(), v) != w.end()) return int(e);
    }
    return -1;
  };
  const std::vector<Draft> drafts = s.drafts;  // as traced: `along` and the partners' targets
  std::vector<MsTurn> turn(s.drafts.size());
  for (size_t i = 0; i < s.drafts.size(); ++i) {
    const Draft& d = s.drafts[i];
    // On a double the boundary's arcs keep to it (a connection along the
    // boundary is its own mirror image: no side to turn to).
    if (!d.alive || d.lane != 0) continue;
    for (size_t k = 1; k + 1 < d.guide.size() && turn[i].saddle < 0; ++k) {
      const auto it = ring_of.find(d.guide[k]);
      if (it == ring_of.end()) continue;
      for (int sv : it->second) {
        // Passing s on the guide's own side (below s, descending) is no
        // connection: the guide only runs near s.
        if (sv == d.guide.front() || MsAbove(f, d.guide[k], sv) == d.ascending) continue;
        const std::vector<int>& ring = rings[size_t(sv)];
      const size_t n = ring.size();
      const size_t pos = size_t(std::find(ring.begin(), ring.end(), d.guide[k]) - ring.begin());
      MsTurn& t = turn[i];
      while (t.back < n && MsAbove(f, ring[(pos + n - t.back) % n], sv) != d.ascending) ++t.back;
      while (t.ahead < n && MsAbove(f, ring[(pos + t.ahead) % n], sv) != d.ascending) ++t.ahead;
        t.at = k;
        t.saddle = sv;
        t.partner = draft_by_wedge(sv, d.guide[k]);
        break;
      }
    }
  }
  for (size_t i = 0; i < s.drafts.size(); ++i) {
    const MsTurn& t = turn[i];
    if (t.saddle < 0) continue;
    Draft& d = s.drafts[i];
    bool forward = t.ahead <= t.back;
    if (t.partner >= 0 && turn[size_t(t.partner)].saddle == d.guide.front()) {
      const MsTurn& p = turn[size_t(t.partner)];
      forward = t.ahead + p.ahead <= t.back + p.back;
    } else if (t.partner >= 0) {
      // The partner passes d's saddle further out: it turned the way that
      // reaches the extremum of d's neighbouring arc on that side.
      const std::vector<int>& own = rings[size_t(d.guide.front())];
      const size_t m = own.size();
      const size_t first = size_t(std::find(own.begin(), own.end(), d.wedge.front()) - own.begin());
      const size_t last = size_t(std::find(own.begin(), own.end(), d.wedge.back()) - own.begin());
      const int ahead = draft_by_wedge(d.guide.front(), own[(last + 1) % m]);
      const int behind = draft_by_wedge(d.guide.front(), own[(first + m - 1) % m]);
      const int reached = drafts[size_t(t.partner)].target;
      const bool to_ahead = ahead >= 0 && drafts[size_t(ahead)].target == reached;
      const bool to_behind = behind >= 0 && drafts[size_t(behind)].target == reached;
      if (to_ahead != to_behind) forward = to_ahead;
    }
    const std::vector<int>& ring = rings[size_t(t.saddle)];
    const size_t n = ring.size();
    const size_t pos = size_t(std::find(ring.begin(), ring.end(), d.guide[t.at]) - ring.begin());
    // On a double, round the side of the ring off the mirror images.
    auto crosses = [&](bool way) {
      const size_t steps = way ? t.ahead : t.back;
      for (size_t k = 0; k <= steps && !s.mirror.side.empty(); ++k) {
        if (s.mirror.side[size_t(ring[way ? (pos + k) % n : (pos + n - k) % n])] == 2) return true;
      }
      return false;
    };
    if (crosses(forward)) forward = !forward;
    if (crosses(forward)) continue;
    const int entry = ring[forward ? (pos + t.ahead) % n : (pos + n - t.back) % n];
    const int along = draft_by_wedge(t.saddle, entry);
    if (along < 0) continue;
    const Draft& a = drafts[size_t(along)];
    // Round the ring the chosen way to the separatrix's first step, so that
    // the arc, rerouted round the ring (which is kept for s's own arcs),
    // keeps to that side.
    std::vector<int> guide(d.guide.begin(), d.guide.begin() + long(t.at) + 1);
    for (size_t step = 1; step < n && guide.back() != a.guide[1]; ++step) {
      guide.push_back(ring[forward ? (pos + step) % n : (pos + n - step) % n]);
    }
    guide.insert(guide.end(), a.guide.begin() + 2, a.guide.end());
    d.guide = MsLoopErased(guide);
    d.target = a.target;
  }
}

}  // namespace

MorseSmaleComplex BuildMorseSmale(const std::vector<Eigen::Vector3d>& points,
                                  const std::vector<std::array<int, 3>>& triangles,
                                  const std::vector<std::vector<int>>& rings,
                                  const Eigen::VectorXd& f, const MorseSmaleOptions& options,
                                  const MorseSmaleMirror* mirror) {
  if (rings.size() != points.size() || f.size() != Eigen::Index(points.size())) {
    throw std::invalid_argument("one ring and one function value per vertex");
  }
  for (const std::vector<int>& ring : rings) {
    if (ring.size() < 3) throw std::invalid_argument("the Morse-Smale complex needs a closed mesh");
  }
  if (mirror != nullptr && (mirror->image.size() != points.size() || mirror->side.size() != points.size())) {
    throw std::invalid_argument("one mirror image and side per vertex");
  }
  MorseSmaleComplex base;
  MsState s = MsTrace(rings, f, mirror);
  MsCancelPairs(s, f, options, base.cancelled);
  MsRedirect(s, f, rings);
  MsTwins(s);
  std::vector<int> renumber(s.nodes.size(), -1);
  for (size_t n = 0; n < s.nodes.size(); ++n) {
    if (!s.node_alive[n]) continue;
    renumber[n] = int(base.nodes.size());
    base.nodes.push_back(s.nodes[n]);
    const MorseSmaleNode& node = s.nodes[n];
    base.maxima += node.kind == 1;
    base.minima += node.kind == -1;
    base.saddles += node.multiplicity;
  }
  // Round 0 places the arcs on the input; while some cannot be placed, the
  // next refines the surface around their guides (two rings wide), doubles
  // the valence of the extrema they are bound for, and places them all
  // again. The round with the fewest arcs left out is kept.
  morse_smale::ArcMesh mesh{points, rings, std::vector<double>(f.data(), f.data() + f.size()), s.mirror};
  const bool forward = morse_smale::RingsFollowTriangles(rings, triangles.at(0));
  MorseSmaleComplex out;
  for (int round = 0;; ++round) {
    MorseSmaleComplex trial = base;
    std::vector<bool> node_vertex(mesh.points.size(), false);
    for (const MorseSmaleNode& n : trial.nodes) node_vertex[size_t(n.vertex)] = true;
    for (size_t v = 0; v < mesh.mirror.side.size(); ++v) {
      if (mesh.mirror.side[v] == 2) node_vertex[v] = true;  // placed as images (EmbedArcs)
    }
    std::vector<size_t> unplaced;
    morse_smale::EmbedArcs(mesh, node_vertex, s.drafts, renumber, trial, unplaced);
    trial.triangles = round == 0 ? triangles : morse_smale::TrianglesOfRings(mesh.rings, forward);
    morse_smale::BuildCells(int(mesh.points.size()), trial.triangles, mesh.mirror, trial);
    trial.refinements = round;
    const bool last = trial.valid || round == kMsRefinements;
    if (round == 0 || trial.valid || trial.unresolved < out.unresolved) {
      trial.points = last ? std::move(mesh.points) : mesh.points;
      trial.values = last ? std::move(mesh.f) : mesh.f;
      trial.mirror_image = mesh.mirror.image;
      out = std::move(trial);
    }
    if (last) break;
    std::vector<int> where;  // the guides of the arcs left out, else the invalid cells' corners
    for (size_t i : unplaced) where.insert(where.end(), s.drafts[i].guide.begin(), s.drafts[i].guide.end());
    if (where.empty()) {
      for (const MorseSmaleCell& cell : out.cells) {
        if (cell.valid) continue;
        for (int c : cell.corners) where.push_back(out.nodes[size_t(c)].vertex);
      }
    }
    morse_smale::SplitAround(mesh, where, kMsRefineWidth, s.drafts);
    std::vector<int> targets;  // the extrema the arcs left out are bound for
    for (size_t i : unplaced) targets.push_back(s.drafts[i].guide.back());
    std::sort(targets.begin(), targets.end());
    targets.erase(std::unique(targets.begin(), targets.end()), targets.end());
    for (int v : targets) morse_smale::SplitLink(mesh, v, s.drafts);
    morse_smale::Rewedge(mesh, s.drafts);
  }
  return out;
}

}  // namespace archgeo
