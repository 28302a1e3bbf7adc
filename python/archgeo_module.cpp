// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the Python module `archgeo` (pybind11, numpy arrays in and out)
// over the public C++ API (api/archgeo/archgeo.h). Input errors raise
// archgeo.InputError (a ValueError) with the CLI's message.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <fstream>
#include <sstream>

#include "archgeo/archgeo.h"

namespace py = pybind11;

namespace {

// V: (n, 3) floats; F: (m, k) integers or a list of index lists (polygons).
archgeo::MeshData ToMesh(const py::handle& v, const py::handle& f) {
  archgeo::MeshData mesh;
  const auto vertices = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(v);
  if (!vertices || vertices.ndim() != 2 || vertices.shape(1) != 3) {
    throw py::value_error("V must be an (n, 3) array of vertex positions");
  }
  const auto r = vertices.unchecked<2>();
  for (py::ssize_t i = 0; i < r.shape(0); ++i) mesh.vertices.push_back({r(i, 0), r(i, 1), r(i, 2)});
  if (py::isinstance<py::array>(f)) {
    const auto faces = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(f);
    if (!faces || faces.ndim() != 2 || faces.shape(1) < 3) {
      throw py::value_error("F must be an (m, k) integer array (k >= 3) or a list of index lists");
    }
    const auto q = faces.unchecked<2>();
    for (py::ssize_t i = 0; i < q.shape(0); ++i) {
      auto& face = mesh.faces.emplace_back();
      for (py::ssize_t j = 0; j < q.shape(1); ++j) face.push_back(int(q(i, j)));
    }
  } else {
    for (const py::handle& face : f) mesh.faces.push_back(face.cast<std::vector<int>>());
  }
  return mesh;
}

py::array_t<double> Vertices(const archgeo::MeshData& mesh) {
  py::array_t<double> out({py::ssize_t(mesh.vertices.size()), py::ssize_t(3)});
  auto w = out.mutable_unchecked<2>();
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    for (int c = 0; c < 3; ++c) w(i, c) = mesh.vertices[i][c];
  }
  return out;
}

// Quads/triangles only: an (m, k) array; mixed polygons: a list of lists.
py::object Faces(const archgeo::MeshData& mesh) {
  bool uniform = !mesh.faces.empty();
  for (const auto& f : mesh.faces) uniform = uniform && f.size() == mesh.faces.front().size();
  if (!uniform) return py::cast(mesh.faces);
  const size_t k = mesh.faces.front().size();
  py::array_t<long long> out({py::ssize_t(mesh.faces.size()), py::ssize_t(k)});
  auto w = out.mutable_unchecked<2>();
  for (size_t i = 0; i < mesh.faces.size(); ++i) {
    for (size_t j = 0; j < k; ++j) w(i, j) = mesh.faces[i][j];
  }
  return std::move(out);
}

py::object Json(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

// A spec: a dict (sent as JSON, which is YAML), YAML text, or a .yaml path.
std::pair<std::string, std::string> SpecText(const py::object& spec) {
  if (py::isinstance<py::dict>(spec)) {
    return {py::module_::import("json").attr("dumps")(spec).cast<std::string>(), "<spec>"};
  }
  const std::string s = spec.cast<std::string>();
  const bool path = s.find('\n') == std::string::npos &&
                    (s.size() > 5 && (s.substr(s.size() - 5) == ".yaml" ||
                                      s.substr(s.size() - 4) == ".yml"));
  if (!path) return {s, "<spec>"};
  std::ifstream in(s);
  if (!in) throw archgeo::Error(s + ": cannot read the spec file", s, 0, "");
  std::stringstream text;
  text << in.rdbuf();
  return {text.str(), s};
}

}  // namespace

PYBIND11_MODULE(archgeo, m) {
  m.doc() = "archgeo: optimisation of freeform-architecture meshes (planar quads, smooth "
            "meshes, principal-symmetric and H-nets). Meshes are numpy arrays in file units.";
  static py::exception<archgeo::Error> input_error(m, "InputError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const archgeo::Error& e) {
      input_error(e.what());
    }
  });

  m.def(
      "solve",
      [](const py::object& spec, const py::handle& v, const py::handle& f,
         const py::object& reference, const std::vector<std::string>& overrides) {
        const auto [text, name] = SpecText(spec);
        const archgeo::MeshData mesh = ToMesh(v, f);
        archgeo::MeshData ref;
        if (!reference.is_none()) {
          const py::tuple t = reference.cast<py::tuple>();
          ref = ToMesh(t[0], t[1]);
        }
        archgeo::SolveResult r;
        {
          py::gil_scoped_release release;
          r = archgeo::Solve(text, mesh, reference.is_none() ? nullptr : &ref, overrides, name);
        }
        py::dict report = Json(r.report);
        report["status"] = r.status;
        return py::make_tuple(r.mesh.vertices.empty() ? py::object(py::none()) : Vertices(r.mesh),
                              report);
      },
      py::arg("spec"), py::arg("V"), py::arg("F"), py::arg("reference") = py::none(),
      py::arg("overrides") = std::vector<std::string>{},
      "Solve a problem on (V, F). spec: a dict of spec keys, YAML text or a .yaml path "
      "(its relative paths anchor there; its `mesh` key is ignored). reference: (V, F) of the "
      "surface to stay close to. overrides: ['key=value', ...] as `archgeo solve --set`. "
      "Returns (V_out, report): V_out None when no valid result (report['status'] 3).");
  m.def(
      "measure",
      [](const py::handle& v, const py::handle& f, const py::object& reference) {
        const archgeo::MeshData mesh = ToMesh(v, f);
        if (reference.is_none()) return Json(archgeo::Measure(mesh));
        const py::tuple t = reference.cast<py::tuple>();
        const archgeo::MeshData ref = ToMesh(t[0], t[1]);
        return Json(archgeo::Measure(mesh, &ref));
      },
      py::arg("V"), py::arg("F"), py::arg("reference") = py::none(),
      "Metrics of (V, F) as `archgeo measure --json` (reference: (V, F) or None).");
  m.def(
      "generate",
      [](const std::string& surface, int nu, int nv, double noise, double scale, unsigned seed,
         int refinement) {
        archgeo::SurfaceOptions o;
        o.surface = surface;
        o.nu = nu;
        o.nv = nv;
        o.noise = noise;
        o.scale = scale;
        o.seed = seed;
        o.refinement = refinement;
        const archgeo::MeshData mesh = archgeo::Generate(o);
        return py::make_tuple(Vertices(mesh), Faces(mesh));
      },
      py::arg("surface") = "roof", py::arg("nu") = 20, py::arg("nv") = 15, py::arg("noise") = 0.1,
      py::arg("scale") = 1.0, py::arg("seed") = 1u, py::arg("refinement") = 1,
      "An analytic test mesh as (V, F), as `archgeo generate`.");
  m.def("problems", &archgeo::Problems, "The problem names.");
  m.def(
      "keys", [](const std::string& problem) { return Json(archgeo::ProblemKeys(problem)); },
      py::arg("problem"), "A problem's spec keys: [{name, default, doc}, ...].");
  m.attr("__version__") = archgeo::Version();
}
