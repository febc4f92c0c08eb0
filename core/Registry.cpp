#include "core/Registry.h"

#include <dlfcn.h>

#include <algorithm>
#include <filesystem>

#include "core/PluginAbi.h"

namespace beamsolid {

std::vector<Registry::RegistrationFunction>& Registry::builtins() {
  static std::vector<RegistrationFunction> list;
  return list;
}

bool Registry::addBuiltin(RegistrationFunction fn) {
  builtins().push_back(fn);
  return true;
}

Registry& Registry::global() {
  static Registry* registry = [] {
    auto* r = new Registry();
    for (RegistrationFunction fn : builtins()) fn(*r);
    return r;
  }();
  return *registry;
}

const char* pluginAbi() { return BEAMSOLID_PLUGIN_ABI; }

void Registry::loadPlugin(const std::string& path) {
  std::error_code ec;
  const std::string canonical = std::filesystem::weakly_canonical(std::filesystem::absolute(path), ec).string();
  const std::string key = ec ? path : canonical;
  if (std::find(plugins_.begin(), plugins_.end(), key) != plugins_.end()) return;
  const std::string where = "loadPlugin '" + path + "'";
  // RTLD_GLOBAL so that a plugin's own dependents can see its symbols.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
  if (!handle) throw OpenSeesError(where + ": cannot load it: " + dlerror());
  auto refuse = [&](const std::string& why) {
    dlclose(handle);
    throw OpenSeesError(where + ": " + why);
  };
  auto registerFn = reinterpret_cast<RegistrationFunction>(dlsym(handle, "beamsolid_register"));
  if (!registerFn)
    refuse("not a BeamSolid plugin: it does not export beamsolid_register(beamsolid::Registry&) "
           "(BEAMSOLID_PLUGIN_REGISTER in core/PluginAbi.h)");
  auto stampFn = reinterpret_cast<const char* (*)()>(dlsym(handle, "beamsolid_plugin_abi"));
  if (!stampFn)
    refuse(std::string("the plugin carries no ABI stamp; build it with beamsolid_add_plugin() from "
                       "find_package(BeamSolid), which embeds it (this library is ") +
           pluginAbi() + ")");
  const std::string stamp = stampFn();
  if (stamp != pluginAbi())
    refuse("the plugin was built for " + stamp + ", but this is " + pluginAbi() +
           "; rebuild the plugin against this BeamSolid");

  // Registration goes to an empty registry first: a plugin that throws, or
  // that names a type which exists already, leaves the real one untouched.
  std::string failure;
  {
    Registry staging;
    try {
      registerFn(staging);
    } catch (const std::exception& e) {
      failure = std::string("beamsolid_register threw: ") + e.what();
    } catch (...) {
      failure = "beamsolid_register threw an exception that is not a std::exception";
    }
    if (failure.empty()) {
      std::vector<std::string> clashes;
      forEachTablePair(staging, [&](auto& mine, auto& theirs) {
        for (std::string& c : mine.clashes(theirs)) clashes.push_back(std::move(c));
      });
      for (const std::string& c : clashes) failure += (failure.empty() ? "it registers types that exist already: " : ", ") + c;
    }
    if (failure.empty()) {
      forEachTablePair(staging, [&](auto& mine, auto& theirs) { mine.absorb(std::move(theirs), key); });
      plugins_.push_back(key);
      return;  // the library stays loaded: its factories are in the registry now
    }
  }  // the staged factories, code of the plugin's, are gone before it is unloaded
  refuse(failure + "; nothing was registered");
}

}  // namespace beamsolid
