// The pybind11 module: the only C++ that knows Python.
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <deque>
#include <map>
#include <memory>
#include <optional>

#include "bindings/Interpreter.h"
#include "bindings/PythonElement.h"
#include "core/BlasKernel.h"
#include "core/LogFile.h"
#include "core/PluginAbi.h"
#include "elements/TangentCheck.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace py = pybind11;
using beamsolid::CommandArgs;
using beamsolid::Interpreter;
using beamsolid::OpenSeesError;

namespace {

// Python arguments -> command values. bool/int/numpy integers -> integer,
// float/numpy floats -> number, str -> string; anything else is an error
// naming the command and the position.
std::vector<CommandArgs::Value> convertArgs(const std::string& command, PyObject* const* items, std::size_t count) {
  std::vector<CommandArgs::Value> values;
  values.reserve(count);
  std::size_t i = 0;
  for (std::size_t k = 0; k < count; ++k) {
    ++i;
    PyObject* o = items[k];
    const py::handle h(o);
    // Fast paths for the exact built-in types (nearly every argument of a
    // script): no attribute lookups, no temporary Python objects.
    if (PyFloat_CheckExact(o)) {
      values.emplace_back(PyFloat_AS_DOUBLE(o));
      continue;
    }
    if (PyLong_CheckExact(o)) {
      int overflow = 0;
      const long long v = PyLong_AsLongLongAndOverflow(o, &overflow);
      if (overflow) throw OpenSeesError(command + ": argument " + std::to_string(i) + ": integer out of range");
      values.emplace_back(v);
      continue;
    }
    if (PyUnicode_CheckExact(o)) {
      Py_ssize_t size = 0;
      const char* text = PyUnicode_AsUTF8AndSize(o, &size);
      if (!text) throw py::error_already_set();
      values.emplace_back(std::string(text, static_cast<std::size_t>(size)));
      continue;
    }
    if (PyObject_HasAttrString(o, "ndim") && PyObject_HasAttrString(o, "shape") &&
        py::int_(h.attr("ndim")).cast<long>() > 0) {
      // A NumPy array (even of one element) is not a number: say so rather
      // than fail in the integer conversion its __index__ offers.
      throw OpenSeesError(command + ": argument " + std::to_string(i) + ": expected a number or a string, got an array " +
                          std::string(py::str(h.attr("shape"))) + " (pass an element, e.g. x[0], or unpack it with *)");
    }
    if (py::isinstance<py::str>(h)) {
      values.emplace_back(h.cast<std::string>());
      continue;
    }
    if (py::isinstance<py::bool_>(h)) {
      values.emplace_back(static_cast<long long>(h.cast<bool>()));
      continue;
    }
    if (PyIndex_Check(o)) {
      // An integer type (NumPy's included). PyNumber_Index refuses what is
      // not an integer, where __int__ would truncate a 0-d float array.
      if (PyObject* index = PyNumber_Index(o)) {
        int overflow = 0;
        const long long v = PyLong_AsLongLongAndOverflow(index, &overflow);
        Py_DECREF(index);
        if (overflow) throw OpenSeesError(command + ": argument " + std::to_string(i) + ": integer out of range");
        values.emplace_back(v);
        continue;
      }
      if (!PyErr_ExceptionMatches(PyExc_TypeError)) throw py::error_already_set();
      PyErr_Clear();  // not an integer: read it as a number below
    }
    if (py::isinstance<py::float_>(h) || py::hasattr(h, "__float__")) {
      values.emplace_back(py::float_(py::reinterpret_borrow<py::object>(h)).cast<double>());
      continue;
    }
    const std::string type = py::str(py::type::of(h).attr("__name__"));
    throw OpenSeesError(command + ": argument " + std::to_string(i) + ": expected a number or a string, got " + type +
                        (type == "list" || type == "tuple" ? " (unpack it with *)" : ""));
  }
  return values;
}

std::vector<CommandArgs::Value> convertArgs(const std::string& command, const py::args& args) {
  return convertArgs(command, PySequence_Fast_ITEMS(args.ptr()), static_cast<std::size_t>(args.size()));
}

py::object toPython(const Interpreter::Result& r) {
  return std::visit(
      [](const auto& v) -> py::object {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::monostate>) return py::none();
        else return py::cast(v);
      },
      r);
}

PyObject* openSeesErrorType = nullptr;

// One command of one interpreter as a plain CPython function (vectorcall, no
// argument tuple, no pybind11 dispatch): beamsolid.opensees binds its
// module-level commands this way, since scripts call node and element
// hundreds of thousands of times. `self` is (interpreter object, capsule with
// its address, command name, capsule with the command looked up once); the
// tuple keeps the interpreter alive.
PyObject* fastCommand(PyObject* self, PyObject* const* args, Py_ssize_t nargs) {
  auto* interpreter = static_cast<Interpreter*>(PyCapsule_GetPointer(PyTuple_GET_ITEM(self, 1), nullptr));
  if (!interpreter) return nullptr;
  const auto* command = static_cast<const Interpreter::Command*>(PyCapsule_GetPointer(PyTuple_GET_ITEM(self, 3), nullptr));
  if (!command) return nullptr;
  Py_ssize_t size = 0;
  const char* text = PyUnicode_AsUTF8AndSize(PyTuple_GET_ITEM(self, 2), &size);
  if (!text) return nullptr;
  try {
    const std::string name(text, static_cast<std::size_t>(size));
    auto values = convertArgs(name, args, static_cast<std::size_t>(nargs));
    return toPython(interpreter->call(*command, name, std::move(values))).release().ptr();
  } catch (const OpenSeesError& e) {
    PyErr_SetString(openSeesErrorType, e.what());
  } catch (py::error_already_set& e) {
    e.restore();
  } catch (const std::exception& e) {
    PyErr_SetString(PyExc_RuntimeError, e.what());
  }
  return nullptr;
}

// One method definition per command name (CPython keeps a pointer to it for
// the function's lifetime, and the name is the function's __name__).
PyMethodDef* fastCommandDef(const std::string& name) {
  static std::map<std::string, std::unique_ptr<PyMethodDef>> defs;
  static std::deque<std::string> names;
  auto& def = defs[name];
  if (!def) {
    names.push_back(name);
    def = std::make_unique<PyMethodDef>(PyMethodDef{names.back().c_str(),
                                                    reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(fastCommand)),
                                                    METH_FASTCALL, "OpenSeesPy command; see docs/commands.md."});
  }
  return def.get();
}

}  // namespace

PYBIND11_MODULE(_beamsolid, m) {
  m.doc() = "BeamSolid: OpenSees-style finite elements with beam-solid contact";
  openSeesErrorType = py::register_exception<OpenSeesError>(m, "OpenSeesError", PyExc_RuntimeError).ptr();

  py::class_<Interpreter>(m, "Interpreter")
      .def(py::init<>())
      .def(
          "call",
          [](Interpreter& self, const std::string& name, const py::args& args) {
            auto values = convertArgs(name, args);
            // The GIL stays held: one model is never entered by two threads at once.
            return toPython(self.call(name, std::move(values)));
          },
          py::arg("name"))
      .def(
          "command",
          [](py::object self, const std::string& name) {
            const Interpreter::Command* command = Interpreter::find(name);
            if (!command) throw OpenSeesError("unknown command '" + name + "'");
            // The capsule holds a pointer into the static command table.
            py::tuple state = py::make_tuple(self, py::capsule(self.cast<Interpreter*>()), name,
                                             py::capsule(const_cast<Interpreter::Command*>(command)));
            PyObject* f = PyCFunction_NewEx(fastCommandDef(name), state.ptr(), nullptr);
            if (!f) throw py::error_already_set();
            return py::reinterpret_steal<py::object>(f);
          },
          py::arg("name"), "The command `name` of this interpreter as a fast callable (beamsolid.opensees).")
      .def("close_recorders", &Interpreter::closeRecorders)
      .def("last_error", &Interpreter::lastError)
      .def("solver_info",
           [](const Interpreter& self) {
             const auto i = self.solverInfo();
             py::dict d;
             d["system"] = i.system;
             d["backend"] = i.backend;
             d["note"] = i.note;
             d["condensed"] = i.condensed;
             d["equations"] = i.equations;
             d["interior"] = i.interior;
             d["interface"] = i.interface;
             d["condensations"] = i.condensations;
             d["condensations_reused"] = i.condensationsReused;
             d["interface_factorizations"] = i.interfaceFactorizations;
             d["krylov_iterations"] = i.krylovIterations;
             d["condense_seconds"] = i.condenseSeconds;
             d["interface_factor_seconds"] = i.interfaceFactorSeconds;
             d["interface_solve_seconds"] = i.interfaceSolveSeconds;
             d["factorizations"] = i.factorizations;
             d["analyses"] = i.analyses;
             d["solver_seconds"] = i.solverSeconds;
             return d;
           })
      .def(
          "tangent_check",
          [](Interpreter& self, int eleTag, double h) {
            auto check = beamsolid::TangentCheck::of(self.domain().element(eleTag, "check_tangent"), h);
            return py::make_tuple(check.tangent, check.difference);
          },
          py::arg("eleTag"), py::arg("h"));

  m.def("command_names", &Interpreter::commandNames);
  m.def("close_log_file", &beamsolid::LogFile::close, "Stop copying warnings to the logFile and close it.");
  m.def("register_element", &beamsolid::PythonElement::registerType, py::arg("name"), py::arg("factory"),
        "Register a Python element class (a beamsolid.Element subclass) as element type `name`.");
  // registered_types(kind): the type names of one kind; registered_types():
  // every kind, each type with where it came from (built-in, a plugin's path,
  // a Python class).
  m.def(
      "registered_types",
      [](const std::optional<std::string>& kind) -> py::object {
        auto& r = beamsolid::Registry::global();
        py::dict all;
        py::object found = py::none();
        r.forEachTable([&](auto& table) {
          if (kind && table.kind() == *kind) found = py::cast(table.types());
          py::dict origins;
          for (const auto& [type, origin] : table.typesWithOrigin()) origins[py::str(type)] = origin;
          all[py::str(table.kind())] = origins;
        });
        if (!kind) return all;
        if (found.is_none()) throw OpenSeesError("registered_types: unknown kind '" + *kind + "'");
        return found;
      },
      py::arg("kind") = py::none());
  m.def("plugin_abi", &beamsolid::pluginAbi, "The ABI stamp a plugin must carry to be loaded (core/PluginAbi.h).");
  m.attr("__version__") = BEAMSOLID_VERSION;

  // What beamsolid.blas_info() reports: the OpenBLAS loaded and the CPU's flags.
  m.def("_blas_state", []() {
    using beamsolid::BlasKernel;
    py::dict d;
    const auto cpu = BlasKernel::thisCpu();
    d["cpu_vendor"] = cpu.vendor;
    d["cpu_flags"] = std::vector<std::string>(cpu.flags.begin(), cpu.flags.end());
    if (const auto l = BlasKernel::loaded()) {
      d["library"] = l->library;
      d["config"] = l->config;
      d["kernel"] = l->core;
      d["threads"] = l->threads;
      d["kernel_requires"] = BlasKernel::requiredFlags(l->core).value_or(std::vector<std::string>{});
    }
    return d;
  });
}
