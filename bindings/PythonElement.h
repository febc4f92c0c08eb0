#pragma once
#include <pybind11/pybind11.h>

#include <string>

#include "elements/Element.h"

namespace beamsolid {

// An element written in Python (a beamsolid.Element subclass), for
// prototyping a formulation before it is written in C++. The adapter calls
// the Python object's methods by name and copies their NumPy results into
// its own matrices; Python exceptions become OpenSeesError naming the element.
class PythonElement : public Element {
 public:
  PythonElement(int tag, std::vector<int> nodeTags, std::string typeName, pybind11::object impl);
  ~PythonElement() override;

  std::string className() const override { return typeName_; }
  void update() override;
  MatrixView tangentStiff() override;
  MatrixView initialStiff() override;
  VectorView resistingForce() override;
  MatrixView massMatrix() override;
  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;
  Response setResponse(const std::vector<std::string>& args) override;
  bool needsGeneralSolver() const override;

  // Registers `factory` (a class or callable returning a beamsolid.Element)
  // as element type `name` in the global Registry.
  static void registerType(const std::string& name, pybind11::object factory);

 protected:
  void setDomain(Domain& domain) override;

 private:
  pybind11::object callMethod(const char* method, bool required) const;
  void readMatrix(const pybind11::object& value, const char* method, Matrix& out) const;
  void readVector(const pybind11::object& value, const char* method, Vector& out) const;

  std::string typeName_;
  pybind11::object impl_;
  Matrix tangent_, initial_, mass_;
  Vector force_;
};

}  // namespace beamsolid
