// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "mesh/store.h"

#include <glog/logging.h>

namespace archgeo {
namespace {

// A property map of Block<W> on the elements of `on`, as a pointer getter.
template <int W>
std::function<double*(int)> AddMap(Mesh& mesh, const std::string& name, Site on) {
  switch (on) {
    case Site::kVertex: {
      auto map = mesh.add_property_map<VertexIndex, Block<W>>("v:" + name, Block<W>{}).first;
      return [map](int i) mutable { return map[VertexIndex(i)].data(); };
    }
    case Site::kFace: {
      auto map = mesh.add_property_map<FaceIndex, Block<W>>("f:" + name, Block<W>{}).first;
      return [map](int i) mutable { return map[FaceIndex(i)].data(); };
    }
    case Site::kEdge: {
      auto map = mesh.add_property_map<EdgeIndex, Block<W>>("e:" + name, Block<W>{}).first;
      return [map](int i) mutable { return map[EdgeIndex(i)].data(); };
    }
  }
  return nullptr;
}

std::function<double*(int)> AddMap(Mesh& mesh, const std::string& name, Site on, int width) {
  switch (width) {
    case 1: return AddMap<1>(mesh, name, on);
    case 2: return AddMap<2>(mesh, name, on);
    case 3: return AddMap<3>(mesh, name, on);
    case 4: return AddMap<4>(mesh, name, on);
    case 5: return AddMap<5>(mesh, name, on);
    case 6: return AddMap<6>(mesh, name, on);
    case 7: return AddMap<7>(mesh, name, on);
    case 8: return AddMap<8>(mesh, name, on);
    case 9: return AddMap<9>(mesh, name, on);
  }
  LOG(FATAL) << "block '" << name << "': width " << width << " not in 1..9";
  return nullptr;
}

int Elements(const Mesh& mesh, Site on) {
  switch (on) {
    case Site::kVertex: return int(mesh.number_of_vertices());
    case Site::kFace: return int(mesh.number_of_faces());
    case Site::kEdge: return int(mesh.number_of_edges());
  }
  return 0;
}

}  // namespace

Store::Store(Mesh mesh) : mesh_(std::move(mesh)) {
  CHECK(!mesh_.has_garbage()) << "Store: collect the mesh's garbage first";
}

void Store::Declare(const BlockDecl& decl, int count) {
  CHECK(decl.width >= 1 && decl.width <= 9) << decl.name;
  CHECK(!decl.unit || decl.width == 3) << decl.name << ": unit blocks are 3-vectors";
  if (const auto it = index_.find(decl.name); it != index_.end()) {
    const Entry& e = blocks_[it->second];
    CHECK(e.decl.width == decl.width && e.decl.on == decl.on && e.count == count &&
          e.decl.unit == decl.unit)
        << "block '" << decl.name << "' declared twice, differently";
    return;
  }
  Entry e;
  e.decl = decl;
  e.count = count;
  if (count > 0) {
    e.global.assign(size_t(count) * decl.width, 0.0);
  } else {
    e.at = AddMap(mesh_, decl.name, decl.on, decl.width);
  }
  index_[decl.name] = blocks_.size();
  blocks_.push_back(std::move(e));
}

const BlockDecl& Store::Decl(const std::string& name) const {
  const auto it = index_.find(name);
  CHECK(it != index_.end()) << "no block '" << name << "'";
  return blocks_[it->second].decl;
}

std::vector<std::string> Store::Names() const {
  std::vector<std::string> names;
  for (const Entry& e : blocks_) names.push_back(e.decl.name);
  return names;
}

int Store::Count(const std::string& name) const {
  const auto it = index_.find(name);
  CHECK(it != index_.end()) << "no block '" << name << "'";
  return Count(blocks_[it->second]);
}

bool Store::IsGlobal(const std::string& name) const {
  const auto it = index_.find(name);
  CHECK(it != index_.end()) << "no block '" << name << "'";
  return blocks_[it->second].count > 0;
}

size_t Store::Find(std::string_view name) const {
  const auto it = index_.find(name);
  CHECK(it != index_.end()) << "no block '" << name << "'";
  return it->second;
}

int Store::Count(const Entry& e) const { return e.count > 0 ? e.count : Elements(mesh_, e.decl.on); }

double* Store::At(size_t block, int index) {
  Entry& e = blocks_[block];
  CHECK(index >= 0 && index < Count(e)) << "block '" << e.decl.name << "' index " << index;
  return e.count > 0 ? e.global.data() + size_t(index) * e.decl.width : e.at(index);
}

double* Store::At(std::string_view name, int index) { return At(Find(name), index); }

const double* Store::At(std::string_view name, int index) const {
  return const_cast<Store*>(this)->At(name, index);
}

std::vector<double> Store::Save() const {
  Store& self = const_cast<Store&>(*this);  // At is the same lookup either way
  size_t size = 3 * mesh_.number_of_vertices();
  for (const Entry& e : blocks_) size += size_t(Count(e)) * size_t(e.decl.width);
  std::vector<double> state;
  state.reserve(size);
  for (VertexIndex v : mesh_.vertices()) {
    const Point& p = mesh_.point(v);
    state.insert(state.end(), {p.x(), p.y(), p.z()});
  }
  for (size_t b = 0; b < blocks_.size(); ++b) {
    const int n = Count(blocks_[b]);
    for (int i = 0; i < n; ++i) {
      const double* x = self.At(b, i);
      state.insert(state.end(), x, x + blocks_[b].decl.width);
    }
  }
  return state;
}

void Store::Restore(const std::vector<double>& state) {
  size_t k = 0;
  for (VertexIndex v : mesh_.vertices()) {
    CHECK_LE(k + 3, state.size()) << "Store::Restore: state of another store";
    mesh_.point(v) = Point(state[k], state[k + 1], state[k + 2]);
    k += 3;
  }
  for (size_t b = 0; b < blocks_.size(); ++b) {
    const int n = Count(blocks_[b]);
    const int width = blocks_[b].decl.width;
    for (int i = 0; i < n; ++i) {
      double* x = At(b, i);
      CHECK_LE(k + width, state.size()) << "Store::Restore: state of another store";
      for (int j = 0; j < width; ++j) x[j] = state[k++];
    }
  }
  CHECK_EQ(k, state.size()) << "Store::Restore: state of another store";
}

void BlockToCanonical(FrameMap map, const Similarity& frame, double* x, int width) {
  switch (map) {
    case FrameMap::kPosition:
    case FrameMap::kDirection:
    case FrameMap::kVector:
      for (int j = 0; j + 3 <= width; j += 3) {
        Vec3 v{x[j], x[j + 1], x[j + 2]};
        if (map == FrameMap::kPosition) {
          v = frame.ToCanonical(v);
        } else {
          Vec3 r{0, 0, 0};
          for (int i = 0; i < 3; ++i) {
            for (int c = 0; c < 3; ++c) r[i] += frame.axes[i][c] * v[c];
          }
          const double s = map == FrameMap::kVector ? 1.0 / frame.scale : 1.0;
          v = {r[0] * s, r[1] * s, r[2] * s};
        }
        x[j] = v[0], x[j + 1] = v[1], x[j + 2] = v[2];
      }
      break;
    case FrameMap::kLength:
      for (int j = 0; j < width; ++j) x[j] /= frame.scale;
      break;
    case FrameMap::kInverseLength:
      for (int j = 0; j < width; ++j) x[j] *= frame.scale;
      break;
    case FrameMap::kInvariant:
      break;
  }
}

void BlockFromCanonical(FrameMap map, const Similarity& frame, double* x, int width) {
  switch (map) {
    case FrameMap::kPosition:
    case FrameMap::kDirection:
    case FrameMap::kVector:
      for (int j = 0; j + 3 <= width; j += 3) {
        Vec3 v{x[j], x[j + 1], x[j + 2]};
        if (map == FrameMap::kPosition) {
          v = frame.FromCanonical(v);
        } else {
          const double s = map == FrameMap::kVector ? frame.scale : 1.0;
          Vec3 r{0, 0, 0};
          for (int i = 0; i < 3; ++i) {
            for (int c = 0; c < 3; ++c) r[c] += frame.axes[i][c] * v[i] * s;
          }
          v = r;
        }
        x[j] = v[0], x[j + 1] = v[1], x[j + 2] = v[2];
      }
      break;
    case FrameMap::kLength:
      for (int j = 0; j < width; ++j) x[j] *= frame.scale;
      break;
    case FrameMap::kInverseLength:
      for (int j = 0; j < width; ++j) x[j] /= frame.scale;
      break;
    case FrameMap::kInvariant:
      break;
  }
}

std::vector<double> Store::InFileUnits(const std::string& name, const Similarity& frame) const {
  const BlockDecl& d = Decl(name);
  const int n = Count(name);
  std::vector<double> values;
  values.reserve(size_t(n) * d.width);
  for (int i = 0; i < n; ++i) {
    const double* x = At(name, i);
    std::vector<double> v(x, x + d.width);
    BlockFromCanonical(d.frame, frame, v.data(), d.width);
    values.insert(values.end(), v.begin(), v.end());
  }
  return values;
}

void Store::FromFileUnits(const std::string& name, const std::vector<double>& values,
                          const Similarity& frame) {
  const BlockDecl& d = Decl(name);
  const int n = Count(name);
  CHECK_EQ(values.size(), size_t(n) * d.width) << "block '" << name << "'";
  for (int i = 0; i < n; ++i) {
    double* x = At(name, i);
    for (int j = 0; j < d.width; ++j) x[j] = values[size_t(i) * d.width + j];
    BlockToCanonical(d.frame, frame, x, d.width);
  }
}

}  // namespace archgeo
