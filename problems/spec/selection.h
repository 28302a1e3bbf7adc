// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — `terms.<t>.select`: which elements of a term's element set it
// acts on. Each element has a site (a vertex, face or edge; core/elements.h)
// and the selection tests the site. Forms (YAML):
//
//   select: all                 every element (the default)
//   select: boundary            sites on the boundary (kBoundary: a boundary
//                               vertex; a face or interior edge with a
//                               boundary vertex; for `edges` and
//                               `boundary_edges`, a border edge)
//   select: interior            the others
//   select: free                "all but fixed": vertex sites that are not
//                               fixed; face and edge sites with a free vertex
//   select: [0, 5, 17]          site ids (vertex, face or edge indices)
//   select: {loop: 0}           the boundary part (as `boundary`) that belongs
//                               to boundary loop k, loops numbered by vertex
//                               count, longest first (geometry/curves.h
//                               BoundaryLoops): a vertex on the loop; a face or
//                               edge with a vertex on it
//   select: {degree: 4}         faces with that many sides (vertex sites: that
//                               valence); an integer or a list
//   select: {curve: FILE}       sites whose every vertex lies within `within`
//                               (default 1e-3; input mean edge lengths) of a
//                               polyline of the OBJ file (`l` records; path
//                               relative to the spec's folder)
//   select: {boundary: true, free: true}   a mapping of several conditions
//                               selects what meets all of them (keys: boundary
//                               (true | false), free (true), ids, loop, degree,
//                               curve, within)
//
// Errors (an unknown form or key, a loop that does not exist, an id out of
// range, an unreadable curve file, `degree` on edges, a selection that picks
// none of a non-empty set) are InputErrors naming the spec file, the line and
// the key (terms.<t>.select...).
#pragma once

#include <string>
#include <vector>

#include "core/elements.h"
#include "core/settings.h"
#include "geometry/curves.h"
#include "mesh/similarity.h"
#include "mesh/surface_mesh.h"

namespace archgeo {

struct Selection {
  enum class Side { kAny, kBoundary, kInterior };
  Side side = Side::kAny;
  bool free = false;               // sites not fixed
  bool by_ids = false;
  std::vector<long long> ids;
  int loop = -1;                   // ≥ 0: boundary loop k
  std::vector<long long> degrees;  // non-empty: face sides / vertex valences
  std::string curve;               // non-empty: OBJ polylines (absolute path)
  double within = 1e-3;            // distance to the curve, canonical lengths
  int line = 0;                    // where it was given (for messages)

  bool all() const {
    return side == Side::kAny && !free && !by_ids && loop < 0 && degrees.empty() && curve.empty();
  }
};

// The selection `key` ("terms.<t>.select": a kCustom setting, or its default
// "all"). Throws InputError.
Selection ParseSelection(const Settings& settings, const std::string& key);

// The indices of the elements of `set` that `selection` keeps, in order.
// `mesh`: the mesh the set was built from (canonical frame); `fixed`: per
// vertex; `frame`: file units → canonical (for curve files). Throws
// InputError (naming `key` in `settings`) for what only the mesh reveals.
std::vector<size_t> SelectElements(const Selection& selection, const ElementSet& set,
                                   const Mesh& mesh, const std::vector<bool>& fixed,
                                   const Similarity& frame, const Settings& settings,
                                   const std::string& key);

// The curves of a term option (core/term.h TermContext::Curves) in the
// canonical frame: the polylines of the OBJ file the setting `key` names
// (file units, moved by `frame`); or the one polyline of the kCustom setting
// `key`_points, if the term declares it — a list of points [x, y, z]
// (file units), closed when the last point repeats the first; or, when
// neither is given, the boundary loops of `reference` (canonical; longest
// first). Throws InputError naming the key for an unreadable file, a
// malformed point list, both forms given, or when there is no curve.
std::vector<Polyline> TermCurves(const Settings& settings, const std::string& key,
                                 const Similarity& frame, const Mesh& reference);

}  // namespace archgeo
