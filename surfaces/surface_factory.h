// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — surfaces by name, with validated parameters (no CGAL).
//
// Names and what they stand for (each header has the formula):
//   klein_bottle    Table 1 "Klein Bottle" (C2): the figure-8 immersion, closed
//                   in u (with a reflection of v) and in v   surfaces/klein_bottle.h
//   tower           Table 1 "Tower" (C1): twisted hyperboloid, closed in u
//                   (sector 2π), open in v                   surfaces/tower.h
//   tower_rings     Table 1 "Tower (Rings)" (C0): an open sector of a twisted
//                   hyperboloid tower (the Tower kind, other defaults)
//   dupin_bridge    Table 1 "Bridge" (C0): a sheared open patch of a ring
//                   Dupin cyclide                            surfaces/dupin_cyclide.h
//   function_graph  Table 1 "Function Graph" (C0): z = dome + saddle over a
//                   rectangle                                surfaces/function_graph.h
//   plane, cylinder, torus, catenoid, helicoid: test surfaces.
#pragma once

#include <string>
#include <vector>

#include "surfaces/parametric.h"
#include "surfaces/surface.h"

namespace archgeo {

// Where the values came from, for InputError (core/input_error.h): the file
// and line of the spec, the key of the surface's name and the key prefix of
// its parameters (a parameter's key is `parameter_key_prefix + "." + name`,
// or `name` if the prefix is empty).
struct InputContext {
  std::string file;
  int line = 0;
  std::string name_key = "surface";
  std::string parameter_key_prefix = "surface";

  std::string ParameterKey(const std::string& name) const {
    return parameter_key_prefix.empty() ? name : parameter_key_prefix + "." + name;
  }
};

// One documented parameter of a named surface.
struct SurfaceParameter {
  std::string name;
  double default_value;
  double min, max;           // admissible range
  bool min_open, max_open;   // an open end excludes the bound itself
  std::string doc;
};

// Every factory name, in the order above.
std::vector<std::string> SurfaceNames();

// The documented parameters of `name` with their defaults and ranges; throws
// InputError (key where.name_key) for an unknown name.
std::vector<SurfaceParameter> SurfaceParameters(const std::string& name,
                                                const InputContext& where = {});

// The named surface with `parameters` over its defaults. Throws InputError
// for an unknown name (key where.name_key), an unknown parameter, a
// non-finite value or one outside its range, and a combination its formula
// does not allow (torus r ≥ R, cyclide μ outside (c, a), an empty patch);
// the key names the parameter.
Surface MakeSurface(const std::string& name, const ParameterValues& parameters = {},
                    const InputContext& where = {});

// The parameters of `surface`'s kind by name (for the report); with the
// names of MakeSurface, MakeSurface(name, SurfaceParameterValues(s)) == s up
// to placement.
ParameterValues SurfaceParameterValues(const Surface& surface);

}  // namespace archgeo
