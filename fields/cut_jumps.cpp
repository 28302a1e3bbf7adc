// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "fields/cut_jumps.h"

#include <cmath>
#include <map>
#include <queue>
#include <sstream>

#include <glog/logging.h>

#include "fields/conjugate.h"

namespace archgeo {

namespace {

// Integer linear combination of the chains' jump constants k = α/Δw.
using Linear = std::map<int, long>;

Linear Combine(const Linear& a, long sa, const Linear& b, long sb) {
  Linear out;
  for (const auto& [c, v] : a) out[c] += sa * v;
  for (const auto& [c, v] : b) out[c] += sb * v;
  for (auto it = out.begin(); it != out.end();) it = it->second == 0 ? out.erase(it) : std::next(it);
  return out;
}

}  // namespace

std::vector<JumpConstraint> JumpConstraints(const CutGraph& cut,
                                            const std::vector<int>& chain_sign) {
  CHECK_EQ(chain_sign.size(), cut.chains.size());
  for (int s : chain_sign) CHECK(s == 1 || s == -1);
  const int n = cut.num_wedges;
  std::vector<std::vector<int>> incident(n);
  for (size_t r = 0; r < cut.relations.size(); ++r) {
    incident[cut.relations[r].left_wedge].push_back(static_cast<int>(r));
    if (cut.relations[r].right_wedge != cut.relations[r].left_wedge)
      incident[cut.relations[r].right_wedge].push_back(static_cast<int>(r));
  }
  // Every wedge of a related group as u = a + b·x, a symbolic in the k's.
  std::vector<Linear> a(n);
  std::vector<long> b(n, 0);
  std::vector<int> group(n, -1);
  int groups = 0;
  for (int w0 = 0; w0 < n; ++w0) {
    if (group[w0] >= 0 || incident[w0].empty()) continue;
    group[w0] = groups;
    b[w0] = 1;
    std::queue<int> queue;
    queue.push(w0);
    while (!queue.empty()) {
      const int w = queue.front();
      queue.pop();
      for (int r : incident[w]) {
        const JumpRelation& rel = cut.relations[r];
        const long s = chain_sign[rel.chain];
        const Linear e = {{rel.chain, 1}};
        const int other = rel.left_wedge == w ? rel.right_wedge : rel.left_wedge;
        if (group[other] >= 0) continue;
        group[other] = groups;
        if (rel.left_wedge == w) {  // u_R = s (u_L − k)
          a[other] = Combine(a[w], s, e, -s);
        } else {  // u_L = k + s u_R
          a[other] = Combine(e, 1, a[w], s);
        }
        b[other] = s * b[w];
        queue.push(other);
      }
    }
    ++groups;
  }
  // Each relation: (b_L − s b_R) x = k + s a_R − a_L.
  std::vector<bool> fixed(groups, false);
  std::vector<Linear> fixed_rhs(groups);
  std::vector<long> fixed_coef(groups, 0);
  std::vector<JumpConstraint> out;
  auto add = [&](const Linear& row, VertexIndex v) {
    if (row.empty()) return;
    JumpConstraint c;
    c.terms.assign(row.begin(), row.end());
    c.vertex = v;
    out.push_back(c);
  };
  for (const JumpRelation& rel : cut.relations) {
    const long s = chain_sign[rel.chain];
    const int L = rel.left_wedge, R = rel.right_wedge, id = group[L];
    const long coef = b[L] - s * b[R];
    const Linear rhs = Combine(Combine({{rel.chain, 1}}, 1, a[R], s), 1, a[L], -1);
    if (coef == 0) {
      add(rhs, rel.vertex);
    } else if (!fixed[id]) {
      fixed[id] = true;
      fixed_rhs[id] = rhs;
      fixed_coef[id] = coef;
    } else {  // rhs/coef == fixed_rhs/fixed_coef
      add(Combine(rhs, fixed_coef[id], fixed_rhs[id], -coef), rel.vertex);
    }
  }
  return out;
}

bool RoundJumps(const CutGraph& cut, const std::vector<int>& chain_sign,
                const std::vector<double>& alpha, double spacing, int parity,
                std::vector<double>* rounded, std::string* message) {
  CHECK_EQ(alpha.size(), cut.chains.size());
  CHECK(spacing > 0.0);
  CHECK(parity == 0 || parity == 1);
  const size_t nc = cut.chains.size();
  // Parity a chain's k must have (see the header): −1 any.
  auto wanted = [&](int c) {
    if (!cut.chains[c].from_singularity) return -1;
    return chain_sign[c] < 0 ? parity : 0;
  };
  auto half_singular = [&](int c) { return wanted(c) >= 0; };
  // Forward elimination: pivots (chain, expression over the other chains).
  std::vector<std::pair<int, Linear>> pivots;
  std::vector<bool> is_pivot(nc, false);
  bool ok = true;
  std::ostringstream notes;
  for (const JumpConstraint& c : JumpConstraints(cut, chain_sign)) {
    Linear row(c.terms.begin(), c.terms.end());
    for (const auto& [p, expr] : pivots) {  // substitute earlier pivots
      auto it = row.find(p);
      if (it == row.end()) continue;
      const long v = it->second;
      row.erase(it);
      row = Combine(row, 1, expr, v);
    }
    if (row.empty()) continue;  // implied by earlier constraints
    int pivot = -1;
    for (const auto& [chain, v] : row) {
      if (std::abs(v) != 1) continue;
      if (pivot < 0 || (half_singular(pivot) && !half_singular(chain))) pivot = chain;
    }
    if (pivot < 0) {
      ok = false;
      notes << "the jumps around vertex " << c.vertex.idx() << " have no unit coefficient; ";
      continue;
    }
    const long v = row[pivot];
    row.erase(pivot);
    Linear expr;  // k_pivot = −v Σ row (v = ±1)
    for (const auto& [chain, x] : row) expr[chain] = -v * x;
    pivots.push_back({pivot, expr});
    is_pivot[pivot] = true;
  }
  std::vector<double> k(nc);
  for (size_t c = 0; c < nc; ++c) {
    if (is_pivot[c]) continue;
    const double x = alpha[c] / spacing;
    if (half_singular(static_cast<int>(c))) {
      k[c] = wanted(static_cast<int>(c)) == 0 ? 2.0 * std::round(0.5 * x)
                                               : 2.0 * std::floor(0.5 * x) + 1.0;
    } else {
      k[c] = std::round(x);
    }
  }
  for (auto it = pivots.rbegin(); it != pivots.rend(); ++it) {
    double value = 0.0;
    for (const auto& [chain, x] : it->second) value += static_cast<double>(x) * k[chain];
    k[it->first] = value;
    if (half_singular(it->first) &&
        std::abs(std::fmod(std::abs(value), 2.0) - wanted(it->first)) > 0.5) {
      ok = false;
      notes << "chain " << it->first << " (from a singularity) is fixed by the others to "
            << value << " spacings, not of the parity it needs; ";
    }
  }
  rounded->resize(nc);
  for (size_t c = 0; c < nc; ++c) (*rounded)[c] = k[c] * spacing;
  if (message != nullptr) *message = notes.str();
  return ok;
}

FieldOrientation OrientField(const Mesh& mesh, const CutGraph& cut,
                             const std::vector<EdgeTransport>& transports,
                             const std::vector<int>& edge_to_transport,
                             const std::vector<Eigen::Vector2d>& direction) {
  const size_t nf = mesh.number_of_faces();
  CHECK_EQ(direction.size(), nf);
  CHECK_EQ(edge_to_transport.size(), mesh.number_of_edges());
  auto defined = [&](FaceIndex f) {
    const Eigen::Vector2d& d = direction[f.idx()];
    return d.allFinite() && d.squaredNorm() > 0.0;
  };
  auto rotate = [](const Eigen::Vector2d& x, double a) {
    return Eigen::Vector2d(std::cos(a) * x.x() - std::sin(a) * x.y(),
                           std::sin(a) * x.x() + std::cos(a) * x.y());
  };
  // A vector of g's frame expressed in f's frame.
  auto in_frame_of = [&](FaceIndex f, FaceIndex g, EdgeIndex e, const Eigen::Vector2d& x) {
    const int t = edge_to_transport[e.idx()];
    CHECK_GE(t, 0);
    return rotate(x, TransportAngle(transports[t], g, f));
  };
  FieldOrientation out;
  out.face_sign.assign(nf, 1);
  std::vector<Eigen::Vector2d> reference(nf, Eigen::Vector2d::Zero());  // oriented direction
  std::vector<bool> seen(nf, false);
  for (FaceIndex root : mesh.faces()) {
    if (seen[root.idx()]) continue;
    seen[root.idx()] = true;
    reference[root.idx()] = defined(root) ? direction[root.idx()] : Eigen::Vector2d(1, 0);
    std::queue<FaceIndex> queue;
    queue.push(root);
    while (!queue.empty()) {
      const FaceIndex f = queue.front();
      queue.pop();
      for (HalfedgeIndex h : mesh.halfedges_around_face(mesh.halfedge(f))) {
        const EdgeIndex e = mesh.edge(h);
        if (mesh.is_border(e) || cut.is_cut_edge[e.idx()]) continue;
        const FaceIndex g = mesh.face(mesh.opposite(h));
        if (seen[g.idx()]) continue;
        seen[g.idx()] = true;
        // f's reference in g's frame.
        const Eigen::Vector2d ref = in_frame_of(g, f, e, reference[f.idx()]);
        if (defined(g)) {
          out.face_sign[g.idx()] = ref.dot(direction[g.idx()]) >= 0.0 ? 1 : -1;
          reference[g.idx()] = out.face_sign[g.idx()] * direction[g.idx()];
        } else {
          reference[g.idx()] = ref;
        }
        queue.push(g);
      }
    }
  }
  auto matching = [&](EdgeIndex e) {  // +1 / −1: orientations across e agree / not
    const FaceIndex f = mesh.face(mesh.halfedge(e, 0)), g = mesh.face(mesh.halfedge(e, 1));
    return reference[f.idx()].dot(in_frame_of(f, g, e, reference[g.idx()])) >= 0.0 ? 1 : -1;
  };
  std::vector<int> votes(cut.chains.size(), 0);
  for (EdgeIndex e : mesh.edges()) {
    if (mesh.is_border(e)) continue;
    if (cut.is_cut_edge[e.idx()]) {
      votes[cut.edge_chain[e.idx()]] += matching(e);
    } else if (matching(e) < 0) {
      ++out.mismatched_edges;
    }
  }
  out.chain_sign.resize(cut.chains.size());
  for (size_t c = 0; c < cut.chains.size(); ++c) out.chain_sign[c] = votes[c] >= 0 ? 1 : -1;
  for (EdgeIndex e : mesh.edges()) {
    if (mesh.is_border(e) || !cut.is_cut_edge[e.idx()]) continue;
    if (matching(e) != out.chain_sign[cut.edge_chain[e.idx()]]) ++out.mismatched_cut_edges;
  }
  return out;
}

PairOrientation OrientPair(const Mesh& mesh, const CutGraph& cut,
                           const std::vector<EdgeTransport>& transports,
                           const std::vector<int>& edge_to_transport,
                           const std::vector<Eigen::Vector2d>& v,
                           const std::vector<Eigen::Vector2d>& w) {
  const size_t nf = mesh.number_of_faces();
  CHECK_EQ(v.size(), nf);
  CHECK_EQ(w.size(), nf);
  auto defined = [](const Eigen::Vector2d& d) { return d.allFinite() && d.squaredNorm() > 0.0; };
  auto rotate = [](const Eigen::Vector2d& x, double a) {
    return Eigen::Vector2d(std::cos(a) * x.x() - std::sin(a) * x.y(),
                           std::sin(a) * x.x() + std::cos(a) * x.y());
  };
  std::vector<Eigen::Vector2d> bisector(nf, Eigen::Vector2d::Zero());
  std::vector<double> turn(nf, 0.0);  // δ: from line v to line w, counter-clockwise
  for (size_t f = 0; f < nf; ++f) {
    if (!defined(v[f]) || !defined(w[f])) continue;
    const double b = BisectorAngle(v[f], w[f]);
    bisector[f] = Eigen::Vector2d(std::cos(b), std::sin(b));
    turn[f] = LineAngle(w[f]) - LineAngle(v[f]);
    if (turn[f] < 0.0) turn[f] += M_PI;
  }
  const FieldOrientation b = OrientField(mesh, cut, transports, edge_to_transport, bisector);
  PairOrientation out{b, b};
  for (size_t f = 0; f < nf; ++f) {
    if (bisector[f].isZero()) continue;
    const Eigen::Vector2d oriented = static_cast<double>(b.face_sign[f]) * bisector[f];
    out.v.face_sign[f] = v[f].dot(rotate(oriented, -0.5 * turn[f])) >= 0.0 ? 1 : -1;
    out.w.face_sign[f] = w[f].dot(rotate(oriented, 0.5 * turn[f])) >= 0.0 ? 1 : -1;
  }
  return out;
}

bool ProjectOntoJumps(const CutGraph& cut, const std::vector<double>& k,
                      const std::vector<int>& sign, std::vector<double>* values,
                      double* max_change, std::string* error) {
  CHECK_EQ(values->size(), static_cast<size_t>(cut.num_wedges));
  CHECK_EQ(k.size(), cut.chains.size());
  CHECK_EQ(sign.size(), cut.chains.size());
  const int n = cut.num_wedges;
  std::vector<std::vector<int>> incident(n);
  for (size_t r = 0; r < cut.relations.size(); ++r) {
    incident[cut.relations[r].left_wedge].push_back(static_cast<int>(r));
    if (cut.relations[r].right_wedge != cut.relations[r].left_wedge)
      incident[cut.relations[r].right_wedge].push_back(static_cast<int>(r));
  }
  std::vector<double> a(n, 0.0), b(n, 0.0);
  std::vector<int> group(n, -1);
  std::vector<std::vector<int>> members;
  for (int w0 = 0; w0 < n; ++w0) {
    if (group[w0] >= 0 || incident[w0].empty()) continue;
    const int id = static_cast<int>(members.size());
    members.emplace_back();
    group[w0] = id;
    a[w0] = 0.0;
    b[w0] = 1.0;
    std::queue<int> queue;
    queue.push(w0);
    while (!queue.empty()) {
      const int w = queue.front();
      queue.pop();
      members[id].push_back(w);
      for (int r : incident[w]) {
        const JumpRelation& rel = cut.relations[r];
        const double kc = k[rel.chain], s = sign[rel.chain];
        int other;
        double ao, bo;
        if (rel.left_wedge == w) {  // u_R = s (u_L − k)
          other = rel.right_wedge;
          ao = s * (a[w] - kc);
          bo = s * b[w];
        } else {  // u_L = k + s u_R
          other = rel.left_wedge;
          ao = kc + s * a[w];
          bo = s * b[w];
        }
        if (group[other] >= 0) continue;
        group[other] = id;
        a[other] = ao;
        b[other] = bo;
        queue.push(other);
      }
    }
  }
  std::vector<double> fixed(members.size(), std::nan(""));
  for (const JumpRelation& rel : cut.relations) {
    const int L = rel.left_wedge, R = rel.right_wedge;
    const double kc = k[rel.chain], s = sign[rel.chain];
    const double coef = b[L] - s * b[R], rhs = kc + s * a[R] - a[L];
    const int id = group[L];
    if (coef == 0.0) {
      if (rhs != 0.0) {
        std::ostringstream m;
        m << "the jumps around vertex " << rel.vertex.idx()
          << " do not compose to the identity (rounded jump constants disagree by " << rhs
          << " spacings)";
        *error = m.str();
        return false;
      }
      continue;
    }
    const double x = rhs / coef;
    if (std::isnan(fixed[id])) {
      fixed[id] = x;
    } else if (std::abs(fixed[id] - x) > 1e-9) {
      std::ostringstream m;
      m << "the jumps at vertex " << rel.vertex.idx() << " fix its value twice (" << fixed[id]
        << " and " << x << " spacings)";
      *error = m.str();
      return false;
    }
  }
  *max_change = 0.0;
  for (size_t id = 0; id < members.size(); ++id) {
    double x = fixed[id];
    if (std::isnan(x)) {
      x = 0.0;
      for (int w : members[id]) x += b[w] * ((*values)[w] - a[w]);
      x /= static_cast<double>(members[id].size());
    }
    for (int w : members[id]) {
      const double projected = a[w] + b[w] * x;
      *max_change = std::max(*max_change, std::abs(projected - (*values)[w]));
      (*values)[w] = projected;
    }
  }
  return true;
}

}  // namespace archgeo
