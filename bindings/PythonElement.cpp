#include "bindings/PythonElement.h"

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include "core/Domain.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"

namespace py = pybind11;

namespace beamsolid {

PythonElement::PythonElement(int tag, std::vector<int> nodeTags, std::string typeName, py::object impl)
    : Element(tag, std::move(nodeTags)), typeName_(std::move(typeName)), impl_(std::move(impl)) {}

PythonElement::~PythonElement() {
  // Commands run with the GIL held, so the Python object is released safely here.
  if (Py_IsInitialized()) impl_ = py::object();
  else impl_.release();
}

py::object PythonElement::callMethod(const char* method, bool required) const {
  if (!py::hasattr(impl_, method)) {
    if (required) throw OpenSeesError(context() + ": the Python element has no method " + method + "()");
    return py::none();
  }
  try {
    return impl_.attr(method)();
  } catch (py::error_already_set& e) {
    throw OpenSeesError(context() + ": Python " + method + "() raised " + e.what());
  }
}

void PythonElement::readMatrix(const py::object& value, const char* method, Matrix& out) const {
  try {
    out = value.cast<Matrix>();
  } catch (const py::cast_error&) {
    throw OpenSeesError(context() + ": " + method + "() must return a 2-D array of numbers");
  }
  if (out.rows() != numDOF() || out.cols() != numDOF())
    throw OpenSeesError(context() + ": " + method + "() returned a " + std::to_string(out.rows()) + "x" +
                        std::to_string(out.cols()) + " matrix, expected " + std::to_string(numDOF()) + "x" +
                        std::to_string(numDOF()));
}

void PythonElement::readVector(const py::object& value, const char* method, Vector& out) const {
  try {
    out = value.cast<Vector>();
  } catch (const py::cast_error&) {
    throw OpenSeesError(context() + ": " + method + "() must return a 1-D array of numbers");
  }
  if (out.size() != numDOF())
    throw OpenSeesError(context() + ": " + method + "() returned " + std::to_string(out.size()) +
                        " values, expected " + std::to_string(numDOF()));
}

void PythonElement::setDomain(Domain&) {
  py::list coords, ndf;
  for (const Node* n : nodes()) {
    coords.append(py::make_tuple(n->crd().x(), n->crd().y(), n->crd().z()));
    ndf.append(n->ndf());
  }
  try {
    impl_.attr("_connect")(coords, ndf);
  } catch (py::error_already_set& e) {
    throw OpenSeesError(context() + ": Python setup() raised " + e.what());
  }
  update();
}

void PythonElement::update() {
  py::list disps;
  for (const Node* n : nodes()) disps.append(py::cast(Vector(n->trialDisp())));
  try {
    impl_.attr("update")(disps);
  } catch (py::error_already_set& e) {
    throw OpenSeesError(context() + ": Python update() raised " + e.what());
  }
}

MatrixView PythonElement::tangentStiff() {
  readMatrix(callMethod("tangent", true), "tangent", tangent_);
  return viewOf(tangent_);
}

MatrixView PythonElement::initialStiff() {
  readMatrix(callMethod("initial_tangent", true), "initial_tangent", initial_);
  return viewOf(initial_);
}

VectorView PythonElement::resistingForce() {
  readVector(callMethod("force", true), "force", force_);
  return viewOf(force_);
}

MatrixView PythonElement::massMatrix() {
  py::object m = callMethod("mass", false);
  if (m.is_none()) mass_ = Matrix::Zero(numDOF(), numDOF());
  else readMatrix(m, "mass", mass_);
  return viewOf(mass_);
}

void PythonElement::commitState() { callMethod("commit", false); }
void PythonElement::revertToLastCommit() { callMethod("revert_to_last_commit", false); }
void PythonElement::revertToStart() { callMethod("revert_to_start", false); }

Response PythonElement::setResponse(const std::vector<std::string>& args) {
  auto call = [this, args]() -> py::object {
    try {
      return impl_.attr("response")(args);
    } catch (py::error_already_set& e) {
      throw OpenSeesError(context() + ": Python response() raised " + e.what());
    }
  };
  py::object first = call();
  if (first.is_none()) return {};
  Vector v;
  try {
    v = first.cast<Vector>();
  } catch (const py::cast_error&) {
    throw OpenSeesError(context() + ": response() must return a 1-D array of numbers or None");
  }
  return {Response::numberedNames(args.empty() ? "r" : args[0], static_cast<int>(v.size())), [this, call] {
            py::object r = call();
            return r.is_none() ? Vector() : Vector(r.cast<Vector>());
          }};
}

bool PythonElement::needsGeneralSolver() const {
  return py::hasattr(impl_, "general_solver") && impl_.attr("general_solver").cast<bool>();
}

void PythonElement::registerType(const std::string& name, py::object factory) {
  Registry& registry = Registry::global();
  if (registry.elements.has(name))
    throw OpenSeesError("register_element: element type '" + name + "' is already registered");
  // The registry outlives the interpreter; the factory reference is kept on purpose.
  std::string origin = "Python";
  try {
    origin += " " + py::str(factory.attr("__module__")).cast<std::string>() + "." +
              py::str(factory.attr("__qualname__")).cast<std::string>();
  } catch (const py::error_already_set&) {
    // A factory without a module or name (a lambda object, a partial) is just "Python".
  }
  auto* kept = new py::object(std::move(factory));
  registry.elements.add(name, [name, kept](CommandArgs& args, Domain&) -> std::unique_ptr<Element> {
    py::list pyArgs;
    while (!args.done()) {
      const auto& v = args.at(args.position());
      if (auto* i = std::get_if<long long>(&v)) pyArgs.append(*i);
      else if (auto* d = std::get_if<double>(&v)) pyArgs.append(*d);
      else pyArgs.append(std::get<std::string>(v));
      args.seek(args.position() + 1);
    }
    py::object impl;
    try {
      impl = (*kept)(*py::tuple(pyArgs));
    } catch (py::error_already_set& e) {
      args.fail(std::string("Python constructor raised ") + e.what());
    }
    int tag = 0;
    std::vector<int> nodes;
    try {
      tag = impl.attr("tag").cast<int>();
      nodes = impl.attr("nodes").cast<std::vector<int>>();
    } catch (const std::exception&) {
      args.fail("the Python element must set integer `tag` and a list of node tags `nodes`");
    }
    args.setContext("element " + name + " " + std::to_string(tag));
    if (nodes.empty()) args.fail("the Python element has no nodes");
    return std::make_unique<PythonElement>(tag, std::move(nodes), name, std::move(impl));
  }, origin);
}

}  // namespace beamsolid
