// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the variable store: one CGAL Surface_mesh holds the topology,
// the vertex positions (its points) and every named variable block
// (core/term.h BlockDecl) as a property map of fixed-width double arrays, or
// global blocks (a count given by the problem, e.g. one jump constant per
// cut). Ceres parameter blocks are pointers into these maps.
//
// Pointers stay valid while the topology is unchanged (subdivision makes a
// new Store). Include only from mesh/ and problems/ (it pulls in CGAL).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/term.h"
#include "mesh/similarity.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

class Store {
 public:
  explicit Store(Mesh mesh);
  Store(const Store&) = delete;
  Store& operator=(const Store&) = delete;

  Mesh& mesh() { return mesh_; }
  const Mesh& mesh() const { return mesh_; }

  // Adds the block (zero-initialised) unless one of that name exists (then
  // the declarations must agree). `count`: the number of global blocks
  // (Site of a global block: decl.on is ignored when count > 0).
  void Declare(const BlockDecl& decl, int count = 0);
  bool Has(const std::string& name) const { return index_.count(name) > 0; }
  const BlockDecl& Decl(const std::string& name) const;
  std::vector<std::string> Names() const;  // in declaration order
  // Number of blocks (elements of its kind, or the global count).
  int Count(const std::string& name) const;
  double* At(std::string_view name, int index);
  const double* At(std::string_view name, int index) const;
  // A block by its position in declaration order (Find), for callers that
  // read many elements of one block: At(Find(name), i) == At(name, i).
  size_t Find(std::string_view name) const;
  double* At(size_t block, int index);
  bool IsGlobal(const std::string& name) const;

  // Every variable: positions, then each block's values, in order.
  std::vector<double> Save() const;
  void Restore(const std::vector<double>& state);

  // A block's values (count × width, by element index) in file units
  // (core/term.h FrameMap), for outputs.
  std::vector<double> InFileUnits(const std::string& name, const Similarity& frame) const;
  // A block's values moved to the canonical frame from file units.
  void FromFileUnits(const std::string& name, const std::vector<double>& values,
                     const Similarity& frame);

 private:
  struct Entry {
    BlockDecl decl;
    int count = 0;                      // global blocks
    std::vector<double> global;         // global blocks' values
    std::function<double*(int)> at;     // element blocks
  };
  int Count(const Entry& e) const;
  Mesh mesh_;
  std::vector<Entry> blocks_;
  std::map<std::string, size_t, std::less<>> index_;  // by name
};

// Maps `width` values of a block between file units and the canonical frame.
void BlockToCanonical(FrameMap map, const Similarity& frame, double* values, int width);
void BlockFromCanonical(FrameMap map, const Similarity& frame, double* values, int width);

}  // namespace archgeo
