#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/CommandArgs.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

class Domain;
class Element;
class UniaxialMaterial;
class NDMaterial;
class CrdTransf;
class TimeSeries;
class SectionForceDeformation;
class BeamIntegration;
class Recorder;
class ConstraintHandler;
class Numberer;
class LinearSolver;
class ConvergenceTest;
class Algorithm;
class Integrator;

// A factory parses a command's arguments (after the type name) and builds
// the object. For tagged objects the tag is read by the factory.
template <class Product>
using Factory = std::function<std::unique_ptr<Product>(CommandArgs&, Domain&)>;

// Type name -> factory for one kind of object (element, nDMaterial, ...).
template <class Product>
class FactoryTable {
 public:
  explicit FactoryTable(std::string kind) : kind_(std::move(kind)) {}
  void add(const std::string& type, Factory<Product> factory) {
    if (factories_.count(type))
      throw OpenSeesError("registry: " + kind_ + " type " + type + " is already registered");
    factories_.emplace(type, std::move(factory));
  }
  bool has(const std::string& type) const { return factories_.count(type) > 0; }
  const Factory<Product>& get(const std::string& type) const {
    auto it = factories_.find(type);
    if (it == factories_.end()) throw OpenSeesError(kind_ + " type " + type + " is unknown");
    return it->second;
  }
  // Reads the type name from `args` and builds it; an unknown type lists the known ones.
  std::unique_ptr<Product> build(CommandArgs& args, Domain& domain) const {
    const std::string type = args.nextString("type");
    if (!has(type)) {
      std::string known;
      for (const auto& kv : factories_) known += (known.empty() ? "" : ", ") + kv.first;
      args.fail("type '" + type + "' is unknown (known: " + known + ")");
    }
    args.setContext(args.command() + " " + type);
    return get(type)(args, domain);
  }
  std::vector<std::string> types() const {
    std::vector<std::string> out;
    for (const auto& kv : factories_) out.push_back(kv.first);
    return out;
  }

 private:
  std::string kind_;
  std::map<std::string, Factory<Product>> factories_;
};

// Maps type names to factories. Built-in types and plugins register the same
// way: a function `void f(Registry&)` that adds factories.
class Registry {
 public:
  FactoryTable<Element> elements{"element"};
  FactoryTable<UniaxialMaterial> uniaxialMaterials{"uniaxialMaterial"};
  FactoryTable<NDMaterial> ndMaterials{"nDMaterial"};
  FactoryTable<SectionForceDeformation> sections{"section"};
  FactoryTable<BeamIntegration> beamIntegrations{"beamIntegration"};
  FactoryTable<CrdTransf> geomTransfs{"geomTransf"};
  FactoryTable<TimeSeries> timeSeries{"timeSeries"};
  FactoryTable<Recorder> recorders{"recorder"};
  FactoryTable<ConstraintHandler> constraintHandlers{"constraints"};
  FactoryTable<Numberer> numberers{"numberer"};
  FactoryTable<LinearSolver> systems{"system"};
  FactoryTable<ConvergenceTest> tests{"test"};
  FactoryTable<Algorithm> algorithms{"algorithm"};
  FactoryTable<Integrator> integrators{"integrator"};

  using RegistrationFunction = void (*)(Registry&);

  // The process-wide registry, with every built-in registration applied.
  static Registry& global();
  // Built-ins announce their registration function at static-init time.
  static bool addBuiltin(RegistrationFunction fn);
  // dlopen a plugin and call its `beamsolid_register(Registry&)`.
  void loadPlugin(const std::string& path);

 private:
  static std::vector<RegistrationFunction>& builtins();
};

}  // namespace beamsolid

// One line at the end of a built-in's .cpp file: registers it exactly as a
// plugin's beamsolid_register would.
#define BEAMSOLID_CONCAT_(a, b) a##b
#define BEAMSOLID_CONCAT(a, b) BEAMSOLID_CONCAT_(a, b)
#define BEAMSOLID_REGISTER(fn) \
  static const bool BEAMSOLID_CONCAT(beamsolidRegistered_, __LINE__) = ::beamsolid::Registry::addBuiltin(&fn)
