// SPDX-FileCopyrightText: The archgeo authors
// SPDX-License-Identifier: GPL-3.0-or-later
// archgeo — the extension module `archgeo._archgeo` (pybind11): converts
// numpy arrays to the public C++ API's meshes (api/archgeo/archgeo.h), calls
// it and converts back. The package's __init__.py (python/archgeo/) builds
// the Python interface on it (Result, keyword arguments, exceptions).
// Input errors raise archgeo.InputError (a ValueError) with the CLI's
// message and its file, line and key.
#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <atomic>
#include <cmath>
#include <limits>
#include <optional>

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

// Faces of one size: an (m, k) array; mixed polygons: a list of lists.
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

py::object MeshTuple(const archgeo::MeshData& mesh) {
  return py::make_tuple(Vertices(mesh), Faces(mesh));
}

// {name: values} (numpy arrays or sequences) as the API's named values.
std::vector<archgeo::NamedValues> Named(const py::dict& values) {
  std::vector<archgeo::NamedValues> named;
  for (const auto& [name, array] : values) {
    const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(array);
    if (!a || a.ndim() != 1) throw py::value_error("values must be one-dimensional arrays");
    named.push_back({name.cast<std::string>(), std::vector<double>(a.data(), a.data() + a.size())});
  }
  return named;
}

// The Python error now set (taken off the interpreter), as an object.
py::object TakeError() {
  PyObject *type, *value, *traceback;
  PyErr_Fetch(&type, &value, &traceback);
  PyErr_NormalizeException(&type, &value, &traceback);
  if (traceback) PyException_SetTraceback(value, traceback);
  Py_XDECREF(type);
  Py_XDECREF(traceback);
  return py::reinterpret_steal<py::object>(value);
}

// A progress event as a dict (None for what the event does not have).
py::dict EventDict(const archgeo::SolveProgress& e) {
  const auto number = [](double x) { return std::isnan(x) ? py::object(py::none()) : py::float_(x); };
  py::dict info;
  info["kind"] = e.kind;
  info["line"] = e.line;
  info["stage"] = e.stage;
  info["round"] = e.round;
  info["stage_round"] = e.stage_round;
  info["stage_rounds"] = e.stage_rounds;
  info["iteration"] = e.iteration >= 0 ? py::object(py::int_(e.iteration)) : py::none();
  info["measure"] = e.measure.empty() ? py::object(py::none()) : py::str(e.measure);
  info["value"] = number(e.value);
  info["target"] = number(e.target);
  info["elapsed"] = e.elapsed;
  return info;
}

// One solve with the GIL released. Each progress event goes to `on_event`
// as a dict (with the GIL); after it, pending signals are handled (a SIGINT
// raises KeyboardInterrupt there). Such an error, or one `on_event` raises,
// or `on_event` returning archgeo.STOP, sets the stop flag: the solve ends after the
// current iteration with the last valid state, and the error is handed back
// for the caller to raise with that result.
class GuardedSolve {
 public:
  explicit GuardedSolve(py::object on_event) : on_event_(std::move(on_event)) {}

  // (status, V or None, F or None, report JSON, summary, stopped, error or None)
  py::tuple Run(const std::function<archgeo::SolveResult(const archgeo::SolveControl&)>& solve) {
    archgeo::SolveControl control;
    control.stop = &stop_;
    control.progress = [this](const archgeo::SolveProgress& event) { Event(event); };
    archgeo::SolveResult r;
    {
      py::gil_scoped_release release;
      r = solve(control);
    }
    const bool has_mesh = !r.mesh.vertices.empty();
    return py::make_tuple(r.status, has_mesh ? py::object(Vertices(r.mesh)) : py::none(),
                          has_mesh ? Faces(r.mesh) : py::none(), r.report, r.summary, r.stopped,
                          error_ ? *error_ : py::none());
  }

 private:
  void Event(const archgeo::SolveProgress& event) {
    if (stop_.load()) return;
    py::gil_scoped_acquire gil;
    if (!on_event_.is_none()) {
      try {
        const py::object answer = on_event_(EventDict(event));
        if (answer.is(py::module_::import("archgeo._archgeo").attr("STOP"))) stop_ = true;
      } catch (py::error_already_set& e) {
        e.restore();
        Stop(TakeError());
        return;
      }
    }
    if (PyErr_CheckSignals() != 0) Stop(TakeError());
  }

  void Stop(py::object error) {
    error_ = std::move(error);
    stop_ = true;
  }

  py::object on_event_;
  std::atomic<bool> stop_{false};
  std::optional<py::object> error_;
};

std::optional<archgeo::MeshData> Optional(const py::handle& v, const py::handle& f) {
  if (v.is_none()) return std::nullopt;
  return ToMesh(v, f);
}

// Raises archgeo.InputError with the error's file, line and key as attributes.
void RaiseInputError(const py::handle& type, const archgeo::Error& e) {
  py::object error = type(e.what());
  error.attr("file") = e.file();
  error.attr("line") = e.line();
  error.attr("key") = e.key();
  PyErr_SetObject(type.ptr(), error.ptr());
}

}  // namespace

PYBIND11_MODULE(_archgeo, m) {
  m.doc() = "archgeo's extension module: the C++ API on numpy arrays (use the package archgeo).";
  static py::exception<archgeo::Error> input_error(m, "InputError", PyExc_ValueError);
  input_error.doc() =
      "An error in the user's input (a spec key, a mesh file, V or F): the message the command "
      "line prints; attributes file, line (0: unknown) and key ('' when none).";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const archgeo::Error& e) {
      RaiseInputError(input_error, e);
    }
  });

  m.def(
      "solve",
      [](const std::string& text, const std::string& name, const py::handle& v, const py::handle& f,
         const py::handle& ref_v, const py::handle& ref_f,
         const std::vector<std::string>& overrides, const py::object& on_event) {
        const archgeo::MeshData mesh = Optional(v, f).value_or(archgeo::MeshData{});
        const std::optional<archgeo::MeshData> ref = Optional(ref_v, ref_f);
        return GuardedSolve(on_event).Run([&](const archgeo::SolveControl& control) {
          return archgeo::Solve(text, mesh, ref ? &*ref : nullptr, overrides, name, control);
        });
      },
      py::arg("text"), py::arg("name"), py::arg("V"), py::arg("F"), py::arg("reference_V"),
      py::arg("reference_F"), py::arg("overrides"), py::arg("on_event"),
      "archgeo::Solve on (V, F) (V None: no mesh): (status, V, F, report JSON, summary, "
      "stopped, error).");
  m.def(
      "solve_file",
      [](const std::string& path, const std::vector<std::string>& overrides,
         const py::object& on_event) {
        return GuardedSolve(on_event).Run([&](const archgeo::SolveControl& control) {
          return archgeo::SolveFile(path, overrides, control);
        });
      },
      py::arg("path"), py::arg("overrides"), py::arg("on_event"),
      "archgeo::SolveFile: the spec's own mesh; returns as solve.");
  m.def(
      "measure",
      [](const py::handle& v, const py::handle& f, const py::handle& ref_v,
         const py::handle& ref_f) {
        const archgeo::MeshData mesh = ToMesh(v, f);
        const std::optional<archgeo::MeshData> ref = Optional(ref_v, ref_f);
        py::gil_scoped_release release;
        return archgeo::Measure(mesh, ref ? &*ref : nullptr, true);
      },
      py::arg("V"), py::arg("F"), py::arg("reference_V"), py::arg("reference_F"),
      "archgeo::Measure with arrays: the report as JSON text.");
  m.def(
      "read_mesh",
      [](const std::string& path) {
        archgeo::MeshData mesh;
        {
          py::gil_scoped_release release;
          mesh = archgeo::ReadMeshFile(path);
        }
        return MeshTuple(mesh);
      },
      py::arg("path"), "archgeo::ReadMeshFile: (V, F).");
  m.def(
      "write_mesh",
      [](const std::string& path, const py::handle& v, const py::handle& f,
         const py::dict& face_values, const py::dict& vertex_values) {
        const archgeo::MeshData mesh = ToMesh(v, f);
        const auto faces = Named(face_values), vertices = Named(vertex_values);
        py::gil_scoped_release release;
        archgeo::WriteMeshFile(path, mesh, faces, vertices);
      },
      py::arg("path"), py::arg("V"), py::arg("F"), py::arg("face_values"),
      py::arg("vertex_values"), "archgeo::WriteMeshFile.");
  m.def(
      "generate",
      [](const std::string& surface, int nu, int nv, std::optional<double> noise, double scale,
         unsigned seed, int refinement) {
        archgeo::SurfaceOptions o;
        o.surface = surface;
        o.nu = nu;
        o.nv = nv;
        if (noise) o.noise = *noise;
        o.scale = scale;
        o.seed = seed;
        o.refinement = refinement;
        return MeshTuple(archgeo::Generate(o));
      },
      py::arg("surface") = "roof", py::arg("nu") = 20, py::arg("nv") = 15, py::arg("noise") = py::none(),
      py::arg("scale") = 1.0, py::arg("seed") = 1u, py::arg("refinement") = 1,
      "An analytic test mesh as (V, F), as `archgeo generate` (see its --help for the "
      "surfaces; noise None: the surface's default).");
  py::class_<archgeo::Session>(m, "Session",
                                "archgeo::Session on numpy arrays (use archgeo.Session).")
      .def(py::init([](const std::string& text, const std::string& name, const py::handle& v,
                       const py::handle& f, const py::handle& ref_v, const py::handle& ref_f,
                       const std::vector<std::string>& overrides) {
             const archgeo::MeshData mesh = Optional(v, f).value_or(archgeo::MeshData{});
             const std::optional<archgeo::MeshData> ref = Optional(ref_v, ref_f);
             py::gil_scoped_release release;
             return archgeo::Session(text, mesh, ref ? &*ref : nullptr, overrides, name);
           }),
           py::arg("text"), py::arg("name"), py::arg("V"), py::arg("F"), py::arg("reference_V"),
           py::arg("reference_F"), py::arg("overrides"))
      .def(
          "solve",
          [](archgeo::Session& session, const py::object& on_event) {
            return GuardedSolve(on_event).Run(
                [&](const archgeo::SolveControl& control) { return session.Solve(control); });
          },
          py::arg("on_event"), "archgeo::Session::Solve; returns as solve.")
      .def(
          "move",
          [](archgeo::Session& session, const py::handle& ids, const py::handle& positions) {
            const auto i = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure(ids);
            const auto p =
                py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(positions);
            if (!i || i.ndim() != 1) throw py::value_error("ids must be a sequence of vertex indices");
            if (!p || p.ndim() != 2 || p.shape(1) != 3 || p.shape(0) != i.shape(0)) {
              throw py::value_error("positions must be an (n, 3) array, one row per vertex id");
            }
            std::vector<int> vertices;
            std::vector<std::array<double, 3>> points;
            const auto iv = i.unchecked<1>();
            const auto pv = p.unchecked<2>();
            for (py::ssize_t k = 0; k < iv.shape(0); ++k) {
              const long long id = iv(k);
              if (id < std::numeric_limits<int>::min() || id > std::numeric_limits<int>::max()) {
                throw archgeo::Error("vertex index " + std::to_string(id) + " out of range",
                                     "<session>", 0, "vertex");
              }
              vertices.push_back(int(id));
              points.push_back({pv(k, 0), pv(k, 1), pv(k, 2)});
            }
            session.MoveVertices(vertices, points);
          },
          py::arg("ids"), py::arg("positions"), "archgeo::Session::MoveVertices.")
      .def("set_weight", &archgeo::Session::SetWeight, py::arg("term"), py::arg("weight"),
           "archgeo::Session::SetWeight.")
      .def("weight", &archgeo::Session::Weight, py::arg("term"), "archgeo::Session::Weight.")
      .def(
          "current", [](const archgeo::Session& session) { return MeshTuple(session.Current()); },
          "archgeo::Session::Current: (V, F).");
  m.def("problems", &archgeo::Problems, "The problem names.");
  m.def("keys", &archgeo::ProblemKeys, py::arg("problem"),
        "A problem's spec keys as JSON text: [{name, default, doc}, ...].");
  m.attr("__version__") = archgeo::Version();
  // on_iteration returns it to stop the solve (its result is returned).
  m.attr("STOP") = py::module_::import("builtins").attr("object")();
}
