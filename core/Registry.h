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
class BeamSection;
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

// Type name -> factory for one kind of object (element, nDMaterial, ...),
// with where each type came from ("built-in", a plugin's path, a Python class).
template <class Product>
class FactoryTable {
 public:
  explicit FactoryTable(std::string kind) : kind_(std::move(kind)) {}
  const std::string& kind() const { return kind_; }
  void add(const std::string& type, Factory<Product> factory, std::string origin = "built-in") {
    if (factories_.count(type))
      throw OpenSeesError("registry: " + kind_ + " type " + type + " is already registered (" +
                          factories_.at(type).origin + ")");
    factories_.emplace(type, Entry{std::move(factory), std::move(origin)});
  }
  bool has(const std::string& type) const { return factories_.count(type) > 0; }
  const Factory<Product>& get(const std::string& type) const {
    auto it = factories_.find(type);
    if (it == factories_.end()) throw OpenSeesError(kind_ + " type " + type + " is unknown");
    return it->second.factory;
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
  std::vector<std::pair<std::string, std::string>> typesWithOrigin() const {
    std::vector<std::pair<std::string, std::string>> out;
    for (const auto& [type, entry] : factories_) out.emplace_back(type, entry.origin);
    return out;
  }
  // "element 'X' (built-in)" for every type of `other` this table has already.
  std::vector<std::string> clashes(const FactoryTable& other) const {
    std::vector<std::string> out;
    for (const auto& kv : other.factories_)
      if (auto it = factories_.find(kv.first); it != factories_.end())
        out.push_back(kind_ + " '" + kv.first + "' (" + it->second.origin + ")");
    return out;
  }
  // Takes every type of `other` (checked with clashes() first), as from `origin`.
  void absorb(FactoryTable&& other, const std::string& origin) {
    for (auto& [type, entry] : other.factories_) factories_.emplace(type, Entry{std::move(entry.factory), origin});
    other.factories_.clear();
  }

 private:
  struct Entry {
    Factory<Product> factory;
    std::string origin;
  };
  std::string kind_;
  std::map<std::string, Entry> factories_;
};

// Maps type names to factories. Built-in types and plugins register the same
// way: a function `void f(Registry&)` that adds factories.
class Registry {
 public:
  FactoryTable<Element> elements{"element"};
  FactoryTable<UniaxialMaterial> uniaxialMaterials{"uniaxialMaterial"};
  FactoryTable<NDMaterial> ndMaterials{"nDMaterial"};
  FactoryTable<BeamSection> sections{"section"};
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
  // Loads a plugin (docs/plugins.md): a shared library exporting
  // `beamsolid_register(Registry&)` and the ABI stamp beamsolid_add_plugin()
  // embeds. A library that is no plugin, carries another stamp, throws while
  // registering or registers a type that exists already is refused with an
  // OpenSeesError, and the registry is left as it was. Loading the same file
  // again does nothing.
  void loadPlugin(const std::string& path);

  // Calls f(table) for every table, or f(mine, theirs) for every pair of
  // tables of one kind in this registry and `other`.
  template <class F>
  void forEachTable(F&& f) {
    forEachTablePair(*this, [&](auto& mine, auto&) { f(mine); });
  }
  template <class F>
  void forEachTablePair(Registry& other, F&& f) {
    f(elements, other.elements);
    f(uniaxialMaterials, other.uniaxialMaterials);
    f(ndMaterials, other.ndMaterials);
    f(sections, other.sections);
    f(beamIntegrations, other.beamIntegrations);
    f(geomTransfs, other.geomTransfs);
    f(timeSeries, other.timeSeries);
    f(recorders, other.recorders);
    f(constraintHandlers, other.constraintHandlers);
    f(numberers, other.numberers);
    f(systems, other.systems);
    f(tests, other.tests);
    f(algorithms, other.algorithms);
    f(integrators, other.integrators);
  }

 private:
  static std::vector<RegistrationFunction>& builtins();
  std::vector<std::string> plugins_;  // canonical paths of the plugins loaded
};

}  // namespace beamsolid

// One line at the end of a built-in's .cpp file: registers it exactly as a
// plugin's beamsolid_register would.
#define BEAMSOLID_CONCAT_(a, b) a##b
#define BEAMSOLID_CONCAT(a, b) BEAMSOLID_CONCAT_(a, b)
#define BEAMSOLID_REGISTER(fn) \
  static const bool BEAMSOLID_CONCAT(beamsolidRegistered_, __LINE__) = ::beamsolid::Registry::addBuiltin(&fn)
