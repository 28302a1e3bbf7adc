// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
#include "problems/spec/schema.h"

#include <glog/logging.h>

#include <algorithm>
#include <sstream>
#include <variant>

#include "core/solver_options.h"
#include "energies/registry.h"
#include "fabrication/units.h"
#include "mesh/elements.h"
#include "problems/declarations/registry.h"

namespace archgeo {
namespace {

std::vector<Key> CommonKeys(const ProblemDecl& d) {
  std::vector<Key> keys;
  keys.push_back(PathKey("mesh", Type::kInputPath,
                         "required: the input mesh (OBJ, OFF or PLY; polygonal faces)"));
  keys.push_back(PathKey("reference", Type::kInputPath,
                         "surface to stay close to (default: the input mesh itself)"));
  keys.push_back(ChoiceKey("problem", "planar_quads", ProblemNames(),
                           "the problem (`archgeo spec NAME` lists its keys)"));
  keys.push_back(ChoiceKey("units", "none", LengthUnitNames(),
                           "the mesh's length unit: tolerances and sheets in millimetres are "
                           "converted through it (docs/fabrication.md); none = not said"));
  Key fixed = ChoiceKey("fixed", "none", {"none", "corners", "boundary"},
                        "hard-fixed vertices: none, corners, boundary, or a list of 0-based "
                        "vertex indices");
  fixed.type = Type::kChoiceOrIntegers;
  fixed.lo = 0;
  keys.push_back(fixed);
  keys.push_back(IntegerKey("schedule.outer_iterations", 12, 1, 100000,
                            "rounds at most (re-projection, reweighting, continuation)"));
  keys.push_back(NumberKey("schedule.max_seconds", 0, 0, 1e9,
                           "wall-time limit of the whole solve; 0 = none (the report says "
                           "when it was hit)"));
  keys.push_back(IntegerKey("multiresolution.levels", 0, 0, 6,
                            "solve, subdivide and solve again this many times [Pellis 2019, §6]"));
  keys.push_back(ChoiceKey("multiresolution.scheme", "loop",
                           {"loop", "sqrt3", "catmull_clark", "doo_sabin"},
                           "loop, sqrt3 (triangle meshes), catmull_clark, doo_sabin (any mesh); "
                           "Loop and Catmull-Clark keep vertex ids"));
  keys.push_back(IntegerKey("limits.max_vertices", 50000000, 1, 2000000000,
                            "refuse input meshes (and grids) with more vertices (raise it for bigger "
                            "meshes)"));
  keys.push_back(IntegerKey("limits.max_faces", 50000000, 1, 2000000000,
                            "refuse input meshes with more faces"));
  keys.push_back(IntegerKey("limits.max_face_degree", 1000, 3, 1000000,
                            "refuse faces with more vertices"));
  keys.push_back(IntegerKey("limits.max_file_bytes", 8589934592LL, 1, 1LL << 50,
                            "refuse input files larger than this (they are read whole)"));
  keys.push_back(NumberKey("limits.weld_distance", 1e-6, 0, 0.5,
                           "weld input vertices closer than this (in mean edge lengths) into one, "
                           "as a per-face-vertices export needs (io/weld.h); 0: never"));
  keys.push_back(IntegerKey("limits.max_subdivided_faces", 20000000, 1, 2000000000,
                            "refuse a multiresolution level with more faces; also bounds the splitting of a "
                            "layout's design surface (conjugate_layout)"));
  keys.push_back(NumberKey("validity.max_reflex_degrees", 10, 0, 180,
                           "a panel corner bent inward by more than this makes the result "
                           "invalid (see allow_input_defects)"));
  keys.push_back(NumberKey("validity.max_flip_degrees", 90, 0, 180,
                           "a face normal turned by more than this against the input's is a fold"));
  keys.push_back(NumberKey("validity.min_edge_relative", 0.1, 0, 1,
                           "an edge shorter than this × the input's mean edge length (and than "
                           "half its own input length) has collapsed; one the input had "
                           "shorter than 1e-3 × it is an input defect"));
  keys.push_back(NumberKey("validity.max_crease_increase_degrees", 30, 0, 180,
                           "an edge whose dihedral angle grew by more than this is a new crease"));
  keys.push_back(NumberKey("validity.min_corner_degrees", 5, 0, 90,
                           "warning: panel corners below this (where the input had none)"));
  keys.push_back(NumberKey("validity.max_aspect", 20, 1, 1e6,
                           "warning: faces whose longest side exceeds this × their shortest"));
  keys.push_back(BoolKey("validity.keep_last_valid", true,
                         "when the last round is not valid, the output is the last valid round "
                         "(said in the report); false: such a result is not written (exit 3)"));
  keys.push_back(BoolKey("validity.allow_input_defects", false,
                         "panels the input already had reflex or bow-tied, and edges it had "
                         "collapsed, do not fail validity; the report says so. false: every "
                         "such panel fails (exit 5, the result written)"));
  keys.push_back(BoolKey("validity.self_intersections", true,
                         "check the result's surface for self-intersections (CGAL)"));
  keys.push_back(PathKey("output.mesh", Type::kOutputPath,
                         "the optimised mesh (.obj, .off, .ply; PLY gets face colours); "
                         "empty: not written"));
  keys.push_back(PathKey("output.report", Type::kOutputPath,
                         "the JSON run report; empty: not written"));
  Key color_max = NumberKey("output.color_max", 0, 1e-12, 1e12,
                            "the value shown as pure red in the face colours and pictures; "
                            "unset: the problem's tolerance (problems/report/colors.h)");
  color_max.fallback = std::monostate{};
  color_max.example = "0.001";
  keys.push_back(color_max);
  keys.push_back(PathKey("output.image", Type::kOutputPath,
                         "a PNG picture (or, named .html, a page to rotate): input and output "
                         "side by side, faces coloured by the problem's per-face value with a "
                         "colour bar; empty: not drawn"));
  keys.push_back(BoolKey("output.arrays", false,
                         "the report lists the per-face value of the colours, the per-face "
                         "planarity (pq, pq_normalized, warp: meshes with faces of 4+ sides) "
                         "and the per-vertex displacement (arrays.face, arrays.vertex)"));
  keys.push_back(BoolKey("output.ascii_ply", true,
                         "ASCII PLY (every reader, Debian's meshio 5 included, reads its face "
                         "colours and values); false: binary little-endian, smaller (meshio 5 "
                         "misreads binary face properties)"));
  keys.push_back(BoolKey("output.blocks", false,
                         "the report lists every output variable block per element (file units)"));
  keys.push_back(PathKey("output.panels", Type::kOutputPath,
                         "the panel table (.csv): per face its vertices, flatness, area, edges, "
                         "corner angles, diagonals and tolerances met (docs/fabrication.md); "
                         "empty: not written"));
  keys.push_back(PathKey("output.cutting", Type::kOutputPath,
                         "every panel flattened into its best-fit plane, with its id, laid out "
                         "on sheets for cutting (.dxf, R12; needs `units`); empty: not written"));
  keys.push_back(PathKey("output.nodes", Type::kOutputPath,
                         "node axes (.csv): per vertex its area-weighted normal, or the cone's "
                         "axis where the run made the mesh conical (docs/fabrication.md); empty: "
                         "not written"));
  keys.push_back(PathKey("output.beams", Type::kOutputPath,
                         "beams (.csv): per edge its length, the plane of its node axes and their "
                         "twist (docs/fabrication.md); empty: not written"));
  for (const std::string& k : d.output_keys) {
    keys.push_back(PathKey("output." + k, Type::kOutputPath,
                           "the problem's `" + k + "` output; empty: not written"));
  }
  Key sheet;
  sheet.name = "cutting.sheet";
  sheet.type = Type::kNumbers;
  sheet.size = 2;
  sheet.lo = 1e-6;
  sheet.hi = 1e9;
  sheet.fallback = std::vector<double>{3000, 6000};
  sheet.doc = "width and height of a sheet in millimetres (output.cutting)";
  keys.push_back(sheet);
  keys.push_back(NumberKey("cutting.gap", 10, 0, 1e9,
                           "millimetres between panels and from the sheet's edges (output.cutting)"));
  keys.push_back(NumberKey("beams.depth", 0, -1e9, 1e9,
                           "millimetres from the panels to the beams' far edges along the node "
                           "axes, positive on the side the face normals point to (output.beams: "
                           "columns far0_*, far1_*; needs `units`); 0: not written"));
  return keys;
}

std::vector<Key> TermKeys(const ProblemDecl& d) {
  std::vector<Key> keys;
  for (const TermUse& use : d.terms) {
    const TermSpec* spec = FindTerm(use.term);
    CHECK(spec) << d.name << ": term '" << use.term << "' is not registered";
    const std::string p = "terms." + use.term + ".";
    keys.push_back(NumberKey(p + "weight", use.weight, 0, 1e12,
                             std::string(spec->summary) + " " + spec->paper +
                                 " (energies/" + use.term + ".h)"));
    std::vector<std::string> sets = {use.elements.empty() ? spec->elements : use.elements};
    for (const std::string& s : spec->element_choices) {
      if (std::find(sets.begin(), sets.end(), s) == sets.end()) sets.push_back(s);
    }
    if (std::string(spec->elements) != sets.front() &&
        std::find(sets.begin(), sets.end(), spec->elements) == sets.end()) {
      sets.push_back(spec->elements);
    }
    keys.push_back(ChoiceKey(p + "on", sets.front(), sets,
                             "the elements it acts on (mesh/elements.h)"));
    // Parsed by the problem layer (problems/spec/selection.h).
    Key select;
    select.name = p + "select";
    select.type = Type::kCustom;
    select.fallback = std::string("all");
    select.example = "all";
    select.doc = "which of them: all, boundary, interior, free (all but fixed), a list of site "
                 "ids (vertex, face or edge indices), or a mapping whose conditions all hold: "
                 "{boundary: true|false, free: true, ids: [...], loop: k (boundary loop k, "
                 "longest first), degree: n (face sides / vertex valence), curve: FILE.obj "
                 "(+ within: d mean edge lengths, default 1e-3)}";
    keys.push_back(select);
    keys.push_back(ChoiceKey(p + "loss", "none",
                             {"none", "huber", "soft_l1", "cauchy", "arctan", "tolerant"},
                             "robust loss on each residual (Ceres loss functions)"));
    keys.push_back(NumberKey(p + "loss_scale", 1, 1e-12, 1e12, "scale of the robust loss"));
    for (Key option : spec->options) {
      const auto it = use.options.find(option.name);
      if (it != use.options.end()) option.fallback = it->second;
      option.name = p + option.name;
      keys.push_back(option);
    }
  }
  return keys;
}

std::string Quote(const std::string& s) {
  if (s.empty()) return "\"\"";
  for (char c : s) {
    if (c == ':' || c == '#' || c == '[' || c == '{' || c == '"' || c == '\'') {
      std::string q = "\"";
      for (char d : s) q += d == '"' ? std::string("\\\"") : std::string(1, d);
      return q + "\"";
    }
  }
  return s;
}

bool IsUnset(const Key& k) {
  return !k.required && std::holds_alternative<std::monostate>(k.fallback);
}

std::string DefaultText(const Key& k) {
  if (k.type == Type::kCustom) return k.example;
  const std::string text = ToText(k.fallback);
  if (k.type == Type::kChoice || k.type == Type::kString || k.type == Type::kInputPath ||
      k.type == Type::kOutputPath || k.type == Type::kChoiceOrIntegers) {
    return Quote(text);
  }
  return text.empty() ? "\"\"" : text;
}

}  // namespace

Schema ProblemSchema(const ProblemDecl& d) {
  Schema schema;
  for (Key k : CommonKeys(d)) {
    if (k.name == "problem") k.fallback = d.name;
    schema.Add(k);
  }
  for (Key k : SolverKeys()) schema.Add(k);
  schema.Add(TermKeys(d));
  schema.Add(d.keys);
  Schema out;
  for (Key k : schema.keys()) {
    const auto it = d.defaults.find(k.name);
    if (it != d.defaults.end()) k.fallback = it->second;
    out.Add(k);
  }
  return out;
}

std::string SpecTemplate(const ProblemDecl& d) {
  std::ostringstream out;
  out << "# archgeo problem `" << d.name << "`: " << d.summary << "\n# " << d.paper
      << "\n# Every key with its default; delete what you do not change. A key shown as a\n"
         "# comment is unset by default (the value there is an example). A term listed\n"
         "# under `terms` with weight 0 is off. Lengths are unit-free (the problem is\n"
         "# solved at unit mean edge length).\n";
  if (d.name == "custom") {
    out << "# `terms` is the one key a custom spec must give: the terms below (those of\n"
           "# examples/planar_smooth.yaml) are an example; `archgeo terms` lists them all.\n";
  }
  const Schema schema = ProblemSchema(d);
  std::vector<std::string> open;  // the sections of the previous key
  for (const Key& k : schema.keys()) {
    // A problem that makes its own net (makes_input) reads no mesh.
    if (d.makes_input && (k.name == "mesh" || k.name == "reference")) continue;
    std::vector<std::string> parts;
    std::stringstream ss(k.name);
    for (std::string part; std::getline(ss, part, '.');) parts.push_back(part);
    size_t common = 0;
    while (common < open.size() && common + 1 < parts.size() && open[common] == parts[common]) {
      ++common;
    }
    open.resize(common);
    for (size_t i = common; i + 1 < parts.size(); ++i) {
      out << std::string(2 * i, ' ') << parts[i] << ":\n";
      open.push_back(parts[i]);
    }
    const std::string indent(2 * (parts.size() - 1), ' ');
    // A key without a default that the spec need not give: its example as a comment.
    if (IsUnset(k) && !k.example.empty()) {
      out << indent << "# " << parts.back() << ": " << k.example << "   # an example; unset by default\n";
      out << indent << "  # " << k.doc << "\n";
      continue;
    }
    std::string value = k.name == "mesh" ? "REQUIRED.obj" : DefaultText(k);
    if (k.type == Type::kChoice) value += "   # " + [&] {
      std::string list;
      for (const std::string& c : k.choices) list += (list.empty() ? "" : " | ") + c;
      return list;
    }();
    if (k.required && k.type == Type::kCustom) value += "   # required; an example";
    out << indent << parts.back() << ": " << value << "\n";
    out << indent << "  # " << k.doc << "\n";
  }
  return out.str();
}

std::string KeyTable(const ProblemDecl& d, bool common) {
  std::ostringstream out;
  out << "| key | default | meaning |\n|---|---|---|\n";
  const Schema schema = ProblemSchema(d);
  const Schema base = ProblemSchema(ProblemDecl{});
  for (const Key& k : schema.keys()) {
    const bool is_common = k.name.rfind("terms.", 0) != 0 && base.Find(k.name) != nullptr;
    if (is_common != common) continue;
    std::string def = k.type == Type::kCustom ? "see below" : ToText(k.fallback);
    if (def.empty()) def = "none";
    std::string doc = k.doc;
    if (k.type == Type::kChoice && !k.choices.empty()) {
      std::string list;
      for (const std::string& c : k.choices) list += (list.empty() ? "" : ", ") + ("`" + c + "`");
      doc += " (" + list + ")";
    }
    for (char& c : doc) {
      if (c == '|') c = '/';
    }
    out << "| `" << k.name << "` | `" << def << "` | " << doc << " |\n";
  }
  return out.str();
}

}  // namespace archgeo
