// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// The degeneracies of the Morse–Smale complex (Gebreiter 2012, §7.1.3):
// guides that touch another guide or a node before their extremum are
// replaced by shortest paths clear of everything already placed.
#include <algorithm>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>

#include "spectral/morse_smale_detail.h"

namespace archgeo {
namespace morse_smale {
namespace {

// An arc that cuts off arcs still to be placed: how many times it is placed
// again, keeping their ways free.
constexpr int kEmbedLookahead = 3;

// Whether an arc may run through v: `used` marks the nodes and the arcs
// placed, `reserved` the one-rings of the saddles (kept for their own arcs).
// `corridor`, when not empty, the only vertices a rerouted tail may take.
// On a double, `side` the mirror's sides and `lane` the one side the arc
// being placed may run through; `entry` the one vertex of a saddle's ring a
// connection to that saddle may use (its last step).
struct EmbedSpace {
  std::vector<bool> used, reserved;
  std::vector<bool> corridor;
  const std::vector<char>* side = nullptr;
  char lane = 0;
  int entry = -1;
  bool OnLane(int v) const { return side == nullptr || (*side)[size_t(v)] == lane; }
  bool Free(int v, int target) const {
    return v == target || (!used[size_t(v)] && (!reserved[size_t(v)] || v == entry) && OnLane(v) &&
                           (corridor.empty() || corridor[size_t(v)]));
  }
};

// The vertices within `rings_out` rings of the guide's vertices from `from` on.
std::vector<bool> EmbedCorridor(const std::vector<std::vector<int>>& rings,
                                const std::vector<int>& guide, size_t from, int rings_out) {
  std::vector<bool> in(rings.size(), false);
  std::vector<int> front(guide.begin() + long(from), guide.end());
  for (int v : front) in[size_t(v)] = true;
  for (int r = 0; r < rings_out; ++r) {
    std::vector<int> next;
    for (int v : front) {
      for (int u : rings[size_t(v)]) {
        if (!in[size_t(u)]) {
          in[size_t(u)] = true;
          next.push_back(u);
        }
      }
    }
    front = std::move(next);
  }
  return in;
}

// Whether `target` can be reached from `sources` through free vertices: two
// breadth-first floods, from the sources and from the target, one layer of
// each in turn, until they meet (yes) or one runs out (no). A target cut off
// in a small region is found so at the cost of that region, not of all the
// free vertices on the other side.
bool EmbedReachable(const std::vector<std::vector<int>>& rings, const EmbedSpace& space,
                    const std::vector<int>& sources, int target) {
  thread_local std::vector<char> side;  // 0 none, 1 from the sources, 2 from the target
  side.resize(rings.size(), 0);
  std::vector<int> touched, front[2];
  auto mark = [&](int v, char s) {
    side[size_t(v)] = s;
    touched.push_back(v);
    front[s - 1].push_back(v);
  };
  bool met = false;
  for (int u : sources) {
    if (u == target) met = true;
    if (!space.used[size_t(u)] && space.OnLane(u) && side[size_t(u)] == 0) mark(u, 1);
  }
  mark(target, 2);
  while (!met && !front[0].empty() && !front[1].empty()) {
    for (char s : {char(1), char(2)}) {
      std::vector<int> next;
      std::swap(next, front[s - 1]);
      for (int v : next) {
        for (int u : rings[size_t(v)]) {
          if (met || !space.Free(u, target)) continue;
          if (side[size_t(u)] == 0) {
            mark(u, s);
          } else if (side[size_t(u)] != s) {
            met = true;
          }
        }
      }
      if (met || front[s - 1].empty()) break;
    }
  }
  for (int v : touched) side[size_t(v)] = 0;
  return met;
}

// The shortest path from `from` through one of `sources` (unused vertices
// adjacent to it) to `target`, through free vertices only; empty when there
// is none.
std::vector<int> EmbedShortest(const std::vector<Eigen::Vector3d>& points,
                               const std::vector<std::vector<int>>& rings, const EmbedSpace& space,
                               int from, const std::vector<int>& sources, int target) {
  if (!EmbedReachable(rings, space, sources, target)) return {};
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> dist(points.size(), inf);
  std::vector<int> previous(points.size(), -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
  for (int u : sources) {
    if ((space.used[size_t(u)] || !space.OnLane(u)) && u != target) continue;
    dist[size_t(u)] = (points[size_t(u)] - points[size_t(from)]).norm();
    previous[size_t(u)] = from;
    queue.push({dist[size_t(u)], u});
  }
  while (!queue.empty()) {
    const auto [d, v] = queue.top();
    queue.pop();
    if (d > dist[size_t(v)]) continue;
    if (v == target) break;
    for (int u : rings[size_t(v)]) {
      if (!space.Free(u, target)) continue;
      const double du = d + (points[size_t(u)] - points[size_t(v)]).norm();
      if (du < dist[size_t(u)]) {
        dist[size_t(u)] = du;
        previous[size_t(u)] = v;
        queue.push({du, u});
      }
    }
  }
  if (dist[size_t(target)] == inf) return {};
  std::vector<int> path;
  for (int v = target; v != from; v = previous[size_t(v)]) path.push_back(v);
  path.push_back(from);
  std::reverse(path.begin(), path.end());
  return path;
}

// The guide up to the first vertex it may not use, then the shortest path
// on from there; from the wedge when that fails.
std::vector<int> EmbedOne(const std::vector<Eigen::Vector3d>& points,
                          const std::vector<std::vector<int>>& rings, EmbedSpace& space,
                          const Draft& d) {
  const int target = d.guide.back();
  space.lane = d.lane;
  space.entry = d.connection ? d.guide[d.guide.size() - 2] : -1;
  std::vector<int> path{d.guide.front()};
  if (!space.used[size_t(d.guide[1])] && space.OnLane(d.guide[1])) {
    path.push_back(d.guide[1]);
    for (size_t i = 2; i < d.guide.size() && space.Free(d.guide[i], target); ++i) {
      path.push_back(d.guide[i]);
    }
  }
  if (path.back() == target) return path;
  if (path.size() > 1) {
    for (int v : path) space.used[size_t(v)] = true;
    std::vector<int> tail;
    // Alongside the arc it met first (one ring, then two), then anywhere.
    for (int width : {1, 2, 0}) {
      space.corridor = width ? EmbedCorridor(rings, d.guide, path.size(), width) : std::vector<bool>();
      std::vector<int> sources;
      for (int u : rings[size_t(path.back())]) {
        if (space.Free(u, target)) sources.push_back(u);
      }
      tail = EmbedShortest(points, rings, space, path.back(), sources, target);
      if (!tail.empty()) break;
    }
    space.corridor.clear();
    for (size_t i = 1; i < path.size(); ++i) space.used[size_t(path[i])] = false;
    if (!tail.empty()) {
      path.insert(path.end(), tail.begin() + 1, tail.end());
      return path;
    }
  }
  return EmbedShortest(points, rings, space, d.guide.front(), d.wedge, target);
}

// The components of the free vertices (neither used nor reserved), to tell
// which arcs still to be placed can reach their extrema: one that could
// and no longer can after an arc is placed has been cut off by it. Labelled
// once per pass, then kept in step as arcs are placed and taken back: a
// label is a union-find node, so freed vertices join their neighbours'
// components by union; marking vertices used splits at most the
// components they touched, found by searches from their free neighbours
// run side by side, so that only the pieces cut off are visited and
// relabelled (the largest piece keeps its label).
class EmbedComponents {
 public:
  explicit EmbedComponents(size_t n) : label_(n, -1), seen_(n, -1) {}

  void Label(const std::vector<std::vector<int>>& rings, const EmbedSpace& space) {
    std::fill(label_.begin(), label_.end(), -1);
    parent_.clear();
    std::vector<int> stack;
    for (size_t v = 0; v < rings.size(); ++v) {
      if (label_[v] >= 0 || !Open(space, int(v))) continue;
      const int l = NewLabel();
      label_[v] = l;
      stack.push_back(int(v));
      while (!stack.empty()) {
        const int w = stack.back();
        stack.pop_back();
        for (int u : rings[size_t(w)]) {
          if (label_[size_t(u)] < 0 && Open(space, u)) {
            label_[size_t(u)] = l;
            stack.push_back(u);
          }
        }
      }
    }
  }

  // The interior vertices of `path`, free now, join their free neighbours.
  void Restore(const std::vector<std::vector<int>>& rings, const EmbedSpace& space,
               const std::vector<int>& path) {
    for (size_t k = 1; k + 1 < path.size(); ++k) {
      const int v = path[k];
      if (!Open(space, v) || label_[size_t(v)] >= 0) continue;
      int l = -1;
      for (int u : rings[size_t(v)]) {
        if (label_[size_t(u)] < 0 || !Open(space, u)) continue;
        const int r = Root(label_[size_t(u)]);
        if (l < 0) {
          l = r;
        } else if (r != l) {
          parent_[size_t(r)] = l;
        }
      }
      label_[size_t(v)] = l < 0 ? NewLabel() : l;
    }
  }

  // The interior vertices of `path`, used now, leave their components.
  // Returns whether a component fell apart (pieces relabelled; their
  // vertices in Relabelled()).
  bool Remove(const std::vector<std::vector<int>>& rings, const EmbedSpace& space,
              const std::vector<int>& path) {
    const size_t labels = parent_.size();
    relabelled_.clear();
    std::vector<int> seeds;
    for (size_t k = 1; k + 1 < path.size(); ++k) label_[size_t(path[k])] = -1;
    for (size_t k = 1; k + 1 < path.size(); ++k) {
      for (int u : rings[size_t(path[k])]) {
        if (label_[size_t(u)] >= 0 && Open(space, u)) seeds.push_back(u);
      }
    }
    std::sort(seeds.begin(), seeds.end());
    seeds.erase(std::unique(seeds.begin(), seeds.end()), seeds.end());
    std::stable_sort(seeds.begin(), seeds.end(), [&](int a, int b) {
      return Root(label_[size_t(a)]) < Root(label_[size_t(b)]);
    });
    for (size_t a = 0; a < seeds.size();) {
      size_t b = a;
      const int root = Root(label_[size_t(seeds[a])]);
      while (b < seeds.size() && Root(label_[size_t(seeds[b])]) == root) ++b;
      Split(rings, space, std::vector<int>(seeds.begin() + long(a), seeds.begin() + long(b)));
      a = b;
    }
    return parent_.size() != labels;
  }

  // The vertices the last Remove gave new labels (the pieces cut off).
  const std::vector<int>& Relabelled() const { return relabelled_; }

  // Whether d's wedge reaches its extremum through free vertices (as
  // EmbedReachable, from the labels kept).
  bool Reaches(const std::vector<std::vector<int>>& rings, const EmbedSpace& space,
               const Draft& d) {
    const int target = d.guide.back();
    labels_.clear();
    for (int w : d.wedge) {
      if (space.used[size_t(w)]) continue;
      for (int u : rings[size_t(w)]) {
        if (u == target) return true;
        if (label_[size_t(u)] >= 0) labels_.push_back(Root(label_[size_t(u)]));
      }
    }
    for (int u : rings[size_t(target)]) {
      const int l = label_[size_t(u)];
      if (l >= 0 && std::find(labels_.begin(), labels_.end(), Root(l)) != labels_.end()) return true;
    }
    return false;
  }

 private:
  static bool Open(const EmbedSpace& space, int v) {
    return !space.used[size_t(v)] && !space.reserved[size_t(v)];
  }
  int NewLabel() {
    parent_.push_back(int(parent_.size()));
    return parent_.back();
  }
  int Root(int l) {
    while (parent_[size_t(l)] != l) {
      parent_[size_t(l)] = parent_[size_t(parent_[size_t(l)])];
      l = parent_[size_t(l)];
    }
    return l;
  }

  // Breadth-first searches from `seeds` (free vertices of one component)
  // in turn, one vertex each; searches that meet are one piece. A piece
  // whose searches have all ended is cut off and relabelled; the last
  // piece still searching keeps the component's label.
  void Split(const std::vector<std::vector<int>>& rings, const EmbedSpace& space,
             const std::vector<int>& seeds) {
    const size_t m = seeds.size();
    if (m < 2) return;
    std::vector<std::vector<int>> queue(m);
    std::vector<size_t> head(m, 0);
    std::vector<int> group(m);
    std::vector<bool> done(m, false);  // by group root: relabelled
    for (size_t s = 0; s < m; ++s) {
      group[s] = int(s);
      queue[s].push_back(seeds[s]);
      seen_[size_t(seeds[s])] = int(s);
    }
    auto find = [&](int s) {
      while (group[size_t(s)] != s) s = group[size_t(s)] = group[size_t(group[size_t(s)])];
      return s;
    };
    size_t searching = m;
    while (searching > 1) {
      for (size_t s = 0; s < m; ++s) {
        if (head[s] == queue[s].size() || done[size_t(find(int(s)))]) continue;
        const int w = queue[s][head[s]++];
        for (int u : rings[size_t(w)]) {
          if (label_[size_t(u)] < 0 || !Open(space, u)) continue;
          if (seen_[size_t(u)] < 0) {
            seen_[size_t(u)] = int(s);
            queue[s].push_back(u);
            continue;
          }
          const int a = find(int(s)), b = find(seen_[size_t(u)]);
          if (a != b) {
            group[size_t(b)] = a;
            --searching;
          }
        }
      }
      std::vector<bool> open(m, false);
      for (size_t s = 0; s < m; ++s) {
        if (head[s] < queue[s].size()) open[size_t(find(int(s)))] = true;
      }
      for (size_t s = 0; s < m && searching > 0; ++s) {
        const int g = find(int(s));
        if (group[s] != int(s) || done[size_t(g)] || open[size_t(g)]) continue;
        const int l = NewLabel();
        for (size_t t = 0; t < m; ++t) {
          if (find(int(t)) != g) continue;
          for (int v : queue[t]) label_[size_t(v)] = l;
          relabelled_.insert(relabelled_.end(), queue[t].begin(), queue[t].end());
        }
        done[size_t(g)] = true;
        --searching;
      }
    }
    for (const std::vector<int>& q : queue) {
      for (int v : q) seen_[size_t(v)] = -1;
    }
  }

  std::vector<int> label_, parent_, seen_;
  std::vector<int> labels_, relabelled_;
};

// One pass placing the drafts in `order`; the drafts left without a path
// are returned.
std::vector<size_t> EmbedPass(const ArcMesh& mesh, const std::vector<bool>& node_vertex,
                              const std::vector<Draft>& drafts, const std::vector<size_t>& order,
                              bool look_ahead, std::vector<std::vector<int>>& paths) {
  const std::vector<Eigen::Vector3d>& points = mesh.points;
  const std::vector<std::vector<int>>& rings = mesh.rings;
  const bool mirrored = !mesh.mirror.side.empty();
  EmbedSpace space{node_vertex, std::vector<bool>(points.size(), false), {},
                   mirrored ? &mesh.mirror.side : nullptr, 0};
  for (size_t i : order) {
    for (int u : rings[size_t(drafts[i].guide.front())]) space.reserved[size_t(u)] = true;
  }
  std::vector<size_t> failed;
  std::vector<int> owner(points.size(), -1);  // the draft whose arc holds a vertex
  auto place = [&](size_t i, bool mark) {
    for (size_t k = 1; k + 1 < paths[i].size(); ++k) {
      space.used[size_t(paths[i][k])] = mark;
      owner[size_t(paths[i][k])] = mark ? int(i) : -1;
    }
  };
  // Look ahead (in the passes after the first, which found arcs it could
  // not place): when an arc cuts off an arc still to be placed from its
  // extremum (the free vertices round its wedge and round its extremum fall
  // into different components), the way that arc had (its shortest path) is
  // kept free and the arc is placed again, up to kEmbedLookahead times.
  std::vector<bool> pending(drafts.size(), false), reaches(drafts.size(), false);
  for (size_t i : order) pending[i] = true;
  EmbedComponents components(points.size());
  // Per vertex: the drafts whose reach depends on it (their wedge, its
  // ring, their extremum's ring). A placement changes the reach of those
  // drafts only whose vertices it uses or cuts off (relabels).
  std::vector<std::vector<size_t>> watchers(look_ahead ? points.size() : 0);
  std::vector<size_t> rank(drafts.size(), 0);  // position in `order`
  for (size_t r = 0; r < order.size(); ++r) rank[order[r]] = r;
  if (look_ahead) {
    components.Label(rings, space);
    for (size_t i : order) {
      reaches[i] = components.Reaches(rings, space, drafts[i]);
      for (int w : drafts[i].wedge) {
        watchers[size_t(w)].push_back(i);
        for (int u : rings[size_t(w)]) watchers[size_t(u)].push_back(i);
      }
      for (int u : rings[size_t(drafts[i].guide.back())]) watchers[size_t(u)].push_back(i);
    }
  }
  for (size_t i : order) {
    pending[i] = false;
    paths[i] = EmbedOne(points, rings, space, drafts[i]);
    if (paths[i].empty()) failed.push_back(i);
    place(i, true);
    if (paths[i].empty() || !look_ahead) continue;
    const bool split = components.Remove(rings, space, paths[i]);
    std::vector<int> kept_free;  // vertices marked used while arc i is placed again
    for (int attempt = 0;; ++attempt) {
      std::vector<size_t> cut;
      std::vector<size_t> check;  // the drafts whose reach may have changed
      if (attempt == 0) {
        // Vertices neither on the arc nor in a piece cut off keep their
        // labels, so only the drafts watching those may change.
        for (size_t k = 1; k + 1 < paths[i].size(); ++k) {
          for (size_t z : watchers[size_t(paths[i][k])]) check.push_back(z);
        }
        if (split) {
          for (int v : components.Relabelled()) {
            for (size_t z : watchers[size_t(v)]) check.push_back(z);
          }
        }
        // Once each, in `order`'s order (as the full scan).
        std::sort(check.begin(), check.end(), [&](size_t a, size_t b) { return rank[a] < rank[b]; });
        check.erase(std::unique(check.begin(), check.end()), check.end());
      } else {
        check = order;
      }
      for (size_t z : check) {
        if (!pending[z]) continue;
        const bool now = components.Reaches(rings, space, drafts[z]);
        if (reaches[z] && !now) cut.push_back(z);
        reaches[z] = now;
      }
      if (cut.empty() || attempt == kEmbedLookahead) break;
      place(i, false);
      for (size_t z : cut) {
        const Draft& d = drafts[z];
        space.lane = d.lane;
        space.entry = d.connection ? d.guide[d.guide.size() - 2] : -1;
        for (int v : EmbedShortest(points, rings, space, d.guide.front(), d.wedge, d.guide.back())) {
          if (!space.used[size_t(v)]) {
            space.used[size_t(v)] = true;
            kept_free.push_back(v);
          }
        }
      }
      std::vector<int> other = EmbedOne(points, rings, space, drafts[i]);
      for (int v : kept_free) space.used[size_t(v)] = false;
      kept_free.clear();
      const bool found = !other.empty();
      if (found) std::swap(paths[i], other);
      place(i, true);
      if (found) {
        components.Restore(rings, space, other);
        components.Remove(rings, space, paths[i]);
      }
      if (!found) {
        for (size_t z : cut) reaches[z] = false;
        break;
      }
      for (size_t z : cut) reaches[z] = true;  // as before arc i: checked again above
    }
  }
  // Rip up and reroute: an arc left out whose way is barred by one arc
  // only is placed before that arc, which is then placed again.
  std::vector<size_t> still;
  for (size_t i : failed) {
    EmbedSpace open{node_vertex, space.reserved, {}, space.side, drafts[i].lane,
                    drafts[i].connection ? drafts[i].guide[drafts[i].guide.size() - 2] : -1};
    const std::vector<int> way =
        EmbedShortest(points, rings, open, drafts[i].guide.front(), drafts[i].wedge, drafts[i].guide.back());
    int barrier = -1;
    bool one = !way.empty();
    for (int v : way) {
      const int o = owner[size_t(v)];
      if (o < 0) continue;
      one = one && (barrier < 0 || barrier == o);
      barrier = o;
    }
    if (!one || barrier < 0) {
      still.push_back(i);
      continue;
    }
    const size_t j = size_t(barrier);
    const std::vector<int> old = paths[j];
    place(j, false);
    paths[i] = EmbedOne(points, rings, space, drafts[i]);
    place(i, true);
    paths[j] = paths[i].empty() ? std::vector<int>() : EmbedOne(points, rings, space, drafts[j]);
    if (paths[i].empty() || paths[j].empty()) {
      place(i, false);
      paths[i].clear();
      paths[j] = old;
      still.push_back(i);
    }
    place(j, true);
  }
  failed = still;
  return failed;
}

}  // namespace

// Passes in which the arcs left without a path, with their saddles' other
// arcs, go first, until every arc has one, kEmbedPasses have run or
// kEmbedStall passes in a row have not left fewer out; the pass with the
// fewest left out is kept.
void EmbedArcs(const ArcMesh& mesh, const std::vector<bool>& node_vertex,
               const std::vector<Draft>& drafts, const std::vector<int>& node_renumber,
               MorseSmaleComplex& complex, std::vector<size_t>& unplaced) {
  constexpr int kEmbedPasses = 32, kEmbedStall = 8;
  std::vector<size_t> order;
  for (size_t i = 0; i < drafts.size(); ++i) {
    if (drafts[i].alive && drafts[i].twin < 0) order.push_back(i);
  }
  std::vector<std::vector<int>> paths(drafts.size()), best;
  size_t best_failed = order.size() + 1;
  int last_improved = 0;
  for (int pass = 0; pass < kEmbedPasses; ++pass) {
    const std::vector<size_t> failed = EmbedPass(mesh, node_vertex, drafts, order, pass > 0, paths);
    if (failed.size() < best_failed) {
      last_improved = pass;
      best_failed = failed.size();
      best = paths;
      complex.unresolved = int(failed.size());
      unplaced = failed;
    }
    if (failed.empty() || pass - last_improved >= kEmbedStall) break;
    std::vector<bool> first(drafts.size(), false);
    for (size_t i : failed) {
      for (size_t j : order) first[j] = first[j] || drafts[j].saddle == drafts[i].saddle;
    }
    std::stable_partition(order.begin(), order.end(), [&](size_t i) { return first[i]; });
  }
  for (size_t i = 0; i < drafts.size(); ++i) {
    if (!drafts[i].alive || drafts[i].twin < 0) continue;
    // The image of its twin's arc, or (a connection) that arc reversed.
    const std::vector<int>& twin = best[size_t(drafts[i].twin)];
    if (drafts[i].lane == 2) {
      for (int v : twin) best[i].push_back(mesh.mirror.image[size_t(v)]);
    } else {
      best[i].assign(twin.rbegin(), twin.rend());
    }
    if (best[i].empty()) ++complex.unresolved;
  }
  for (size_t i = 0; i < drafts.size(); ++i) {
    if (best[i].empty()) continue;
    complex.rerouted += best[i] != drafts[i].guide;
    complex.arcs.push_back({node_renumber[size_t(drafts[i].saddle)],
                            node_renumber[size_t(drafts[i].target)], drafts[i].ascending,
                            std::move(best[i]), {{-1, -1}}, drafts[i].lane});
  }
}

}  // namespace morse_smale
}  // namespace archgeo
