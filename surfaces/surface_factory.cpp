// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "surfaces/surface_factory.h"

#include <cmath>
#include <functional>
#include <limits>
#include <sstream>

#include "core/input_error.h"
#include "core/magnitude.h"

namespace archgeo {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A tower sector within this of 2π is the closed tower.
constexpr double kSectorSnap = 1e-6;

// One parameter of a surface type: its member, range and documentation.
template <typename S>
struct Field {
  const char* name;
  double S::*member;
  double min, max;
  bool min_open, max_open;
  const char* doc;
};

template <typename S>
std::vector<Field<S>> FieldsOf();

template <>
std::vector<Field<Plane>> FieldsOf() {
  return {{"a", &Plane::a, 0, kInf, true, true, "domain length in u"},
          {"b", &Plane::b, 0, kInf, true, true, "domain length in v"}};
}
template <>
std::vector<Field<Cylinder>> FieldsOf() {
  return {{"R", &Cylinder::R, 0, kInf, true, true, "radius"},
          {"H", &Cylinder::H, 0, kInf, true, true, "height (v ∈ [0, H])"}};
}
template <>
std::vector<Field<Torus>> FieldsOf() {
  return {{"R", &Torus::R, 0, kInf, true, true, "radius of the tube's centre line (> r)"},
          {"r", &Torus::r, 0, kInf, true, true, "tube radius (< R)"}};
}
template <>
std::vector<Field<Catenoid>> FieldsOf() {
  return {{"c", &Catenoid::c, 0, kInf, true, true, "waist radius"},
          {"H", &Catenoid::H, 0, kInf, true, true, "height (v ∈ [−H/2, H/2])"}};
}
template <>
std::vector<Field<Helicoid>> FieldsOf() {
  return {{"c", &Helicoid::c, 0, kInf, true, true, "rise per radian of turn"},
          {"radius", &Helicoid::radius, 0, kInf, true, true, "v ∈ [−radius, radius]"},
          {"angle", &Helicoid::angle, 0, kInf, true, true, "turning angle, u ∈ [0, angle] (radians)"}};
}
template <>
std::vector<Field<KleinBottle>> FieldsOf() {
  return {{"R", &KleinBottle::R, 0, kInf, true, true,
           "radius of the circle the figure 8 is swept around (> a·m(b), see klein_bottle.h)"},
          {"a", &KleinBottle::a, 0, kInf, true, true, "size of the figure 8"},
          {"b", &KleinBottle::b, 0, kInf, true, true,
           "height of the figure 8's lobes relative to their width (1: classical)"}};
}
template <>
std::vector<Field<Tower>> FieldsOf() {
  return {{"a", &Tower::a, 0, kInf, true, true, "waist radius"},
          {"c", &Tower::c, 0, kInf, true, true,
           "hyperboloid axis parameter: the radius is a·√2 at |v − z_w| = c"},
          {"z_w", &Tower::z_w, -kInf, kInf, true, true, "waist height"},
          {"H", &Tower::H, 0, kInf, true, true, "height (v ∈ [0, H])"},
          {"twist", &Tower::twist, -kInf, kInf, true, true,
           "turn of the v-lines over the height (radians)"},
          {"sector", &Tower::sector, 0, 2.0 * M_PI + kSectorSnap, true, false,
           "u ∈ [0, sector] (radians), ≤ 2π; 2π (to within 1e-6) closes the tower in u"}};
}
template <>
std::vector<Field<DupinCyclide>> FieldsOf() {
  return {{"a", &DupinCyclide::a, 0, kInf, true, true, "cyclide parameter a (> c)"},
          {"c", &DupinCyclide::c, 0, kInf, false, true, "cyclide parameter c (≥ 0, < a)"},
          {"mu", &DupinCyclide::mu, 0, kInf, true, true, "cyclide parameter μ (c < μ < a)"},
          {"u_lo", &DupinCyclide::u_lo, -kInf, kInf, true, true, "patch start along the ring (radians)"},
          {"u_hi", &DupinCyclide::u_hi, -kInf, kInf, true, true, "patch end along the ring (radians)"},
          {"v_lo", &DupinCyclide::v_lo, -kInf, kInf, true, true, "patch start around the tube (radians)"},
          {"v_hi", &DupinCyclide::v_hi, -kInf, kInf, true, true, "patch end around the tube (radians)"},
          {"shear", &DupinCyclide::shear, -kInf, kInf, true, true,
           "α = u + shear·(v − v_lo): 0 gives the curvature-line net"}};
}
template <>
std::vector<Field<FunctionGraph>> FieldsOf() {
  return {{"a", &FunctionGraph::a, 0, kInf, true, true, "plan length in u"},
          {"b", &FunctionGraph::b, 0, kInf, true, true, "plan length in v"},
          {"h", &FunctionGraph::h, -kInf, kInf, true, true, "dome height"},
          {"s", &FunctionGraph::s, -kInf, kInf, true, true, "saddle height (f = ±s at the corners)"}};
}

std::string Number(double x) {
  std::ostringstream os;
  os.precision(17);
  os << x;
  return os.str();
}

// A combination of values the formula does not allow: the key's parameter
// name and the message, or an empty name if fine.
struct Violation {
  std::string parameter, message;
};

Violation Check(const Plane&) { return {}; }
Violation Check(const Cylinder&) { return {}; }
Violation Check(const Catenoid&) { return {}; }
Violation Check(const Helicoid&) { return {}; }
Violation Check(const KleinBottle& k) {
  if (k.R <= k.a * k.MaxOffset()) {
    return {"R", "must exceed a·m(b) = " + Number(k.a * k.MaxOffset()) + " (ρ = R + a w > 0)"};
  }
  return {};
}
Violation Check(const FunctionGraph&) { return {}; }
Violation Check(const Torus& t) {
  if (t.r >= t.R) return {"r", "must be smaller than R (a ring torus), got r = " +
                                   std::to_string(t.r) + ", R = " + std::to_string(t.R)};
  return {};
}
Violation Check(const Tower&) { return {}; }
Violation Check(const DupinCyclide& d) {
  if (d.c >= d.a) return {"c", "must be smaller than a"};
  if (d.mu <= d.c || d.mu >= d.a) return {"mu", "must lie strictly between c and a (a ring cyclide)"};
  if (d.u_hi <= d.u_lo) return {"u_hi", "must be greater than u_lo"};
  if (d.v_hi <= d.v_lo) return {"v_hi", "must be greater than v_lo"};
  if (d.u_hi - d.u_lo > 2.0 * M_PI) return {"u_hi", "the patch must not exceed one turn (u_hi − u_lo ≤ 2π)"};
  if (d.v_hi - d.v_lo > 2.0 * M_PI) return {"v_hi", "the patch must not exceed one turn (v_hi − v_lo ≤ 2π)"};
  return {};
}

void Snap(Tower* t) {
  if (std::abs(t->sector - 2.0 * M_PI) <= kSectorSnap) t->sector = 2.0 * M_PI;
}
template <typename S>
void Snap(S*) {}

std::string Join(const std::vector<std::string>& names) {
  std::string s;
  for (const std::string& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

// One factory name: its surface type with the name's defaults.
struct Named {
  std::string name;
  std::function<std::vector<SurfaceParameter>()> parameters;
  std::function<Surface(const ParameterValues&, const InputContext&)> make;
};

template <typename S>
Named Entry(const std::string& name, S defaults) {
  Named entry;
  entry.name = name;
  entry.parameters = [defaults] {
    std::vector<SurfaceParameter> out;
    for (const Field<S>& f : FieldsOf<S>()) {
      out.push_back({f.name, defaults.*(f.member), f.min, f.max, f.min_open, f.max_open, f.doc});
    }
    return out;
  };
  entry.make = [name, defaults](const ParameterValues& values, const InputContext& where) {
    const std::vector<Field<S>> fields = FieldsOf<S>();
    std::vector<std::string> known;
    for (const Field<S>& f : fields) known.push_back(f.name);
    S s = defaults;
    for (const auto& [key, value] : values) {
      const Field<S>* field = nullptr;
      for (const Field<S>& f : fields) {
        if (key == f.name) field = &f;
      }
      if (field == nullptr) {
        throw InputError(where.file, where.line, where.ParameterKey(key),
                         "unknown parameter of surface '" + name + "' (known: " + Join(known) + ")");
      }
      if (!std::isfinite(value)) {
        throw InputError(where.file, where.line, where.ParameterKey(key), "must be finite");
      }
      if (std::abs(value) >= kMaxSurfaceParameter ||
          (value != 0 && std::abs(value) < kMinSurfaceParameter)) {
        throw InputError(where.file, where.line, where.ParameterKey(key),
                         "must be 0 or between 1e-75 and 1e75 in magnitude, got " + Number(value) +
                             ": the grid multiplies four of the surface's lengths, which would "
                             "overflow or underflow (core/magnitude.h)");
      }
      const bool below = field->min_open ? value <= field->min : value < field->min;
      const bool above = field->max_open ? value >= field->max : value > field->max;
      if (below || above) {
        const std::string lo = field->min == -kInf ? "(−∞" : (field->min_open ? "(" : "[") + Number(field->min);
        const std::string hi = field->max == kInf ? "∞)" : Number(field->max) + (field->max_open ? ")" : "]");
        throw InputError(where.file, where.line, where.ParameterKey(key),
                         "must lie in " + lo + ", " + hi + ", got " + Number(value));
      }
      s.*(field->member) = value;
    }
    Snap(&s);
    const Violation violation = Check(s);
    if (!violation.parameter.empty()) {
      throw InputError(where.file, where.line, where.ParameterKey(violation.parameter),
                       violation.message);
    }
    return Surface(s);
  };
  return entry;
}

Tower TowerRingsDefaults() {
  Tower t;
  t.a = 6.0;
  t.c = 15.0;
  t.z_w = 30.0;
  t.H = 40.0;
  t.twist = 0.5 * M_PI;
  t.sector = M_PI;
  return t;
}

const std::vector<Named>& Registry() {
  static const std::vector<Named> registry = {
      Entry("klein_bottle", KleinBottle{}), Entry("tower", Tower{}),
      Entry("tower_rings", TowerRingsDefaults()), Entry("dupin_bridge", DupinCyclide{}),
      Entry("function_graph", FunctionGraph{}), Entry("plane", Plane{}),
      Entry("cylinder", Cylinder{}), Entry("torus", Torus{}),
      Entry("catenoid", Catenoid{}), Entry("helicoid", Helicoid{})};
  return registry;
}

const Named& Find(const std::string& name, const InputContext& where) {
  for (const Named& n : Registry()) {
    if (n.name == name) return n;
  }
  throw InputError(where.file, where.line, where.name_key,
                   "unknown surface '" + name + "' (known: " + Join(SurfaceNames()) + ")");
}

template <typename S>
ParameterValues ValuesOf(const S& s) {
  ParameterValues values;
  for (const Field<S>& f : FieldsOf<S>()) values[f.name] = s.*(f.member);
  return values;
}

}  // namespace

std::vector<std::string> SurfaceNames() {
  std::vector<std::string> names;
  for (const Named& n : Registry()) names.push_back(n.name);
  return names;
}

std::vector<SurfaceParameter> SurfaceParameters(const std::string& name,
                                                const InputContext& where) {
  return Find(name, where).parameters();
}

Surface MakeSurface(const std::string& name, const ParameterValues& parameters,
                    const InputContext& where) {
  return Find(name, where).make(parameters, where);
}

ParameterValues SurfaceParameterValues(const Surface& surface) {
  return std::visit([](const auto& s) { return ValuesOf(s); }, surface.kind());
}

}  // namespace archgeo
