#include "core/Registry.h"

#include <dlfcn.h>

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

void Registry::loadPlugin(const std::string& path) {
  // RTLD_GLOBAL so that a plugin's own dependents can see its symbols.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
  if (!handle) throw OpenSeesError(std::string("loadPlugin: cannot load '") + path + "': " + dlerror());
  auto fn = reinterpret_cast<RegistrationFunction>(dlsym(handle, "beamsolid_register"));
  if (!fn)
    throw OpenSeesError("loadPlugin: '" + path + "' does not export beamsolid_register(beamsolid::Registry&)");
  fn(*this);
}

}  // namespace beamsolid
