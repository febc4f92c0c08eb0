#include "core/OutputFileClaim.h"

#include <filesystem>
#include <map>
#include <mutex>
#include <system_error>

#include "core/Domain.h"
#include "core/OpenSeesError.h"

namespace beamsolid {

namespace fs = std::filesystem;

namespace {

struct Claim {
  OutputFileClaim::Holder holder;
  std::string path;  // as the holder spelled it
};

// Every claimed file of the process, by canonical path. Models may live on
// different threads, hence the mutex.
struct Claims {
  std::mutex mutex;
  std::map<std::string, Claim> byFile;
};

// Never destroyed: a model freed after the static destructors ran (Python's
// teardown) must still find the table to release its claims.
Claims& claims() {
  static Claims* table = new Claims;
  return *table;
}

}  // namespace

OutputFileClaim::Holder OutputFileClaim::Holder::beingAddedTo(const Domain& domain, std::string type) {
  return Holder{&domain, domain.nextRecorderTag(), std::move(type)};
}

std::string OutputFileClaim::canonical(const std::string& path) {
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  if (ec) return fs::path(path).lexically_normal().string();
  const fs::path resolved = fs::weakly_canonical(absolute, ec);
  return (ec ? absolute.lexically_normal() : resolved).string();
}

OutputFileClaim::OutputFileClaim(const std::string& path, Holder holder, const std::string& context)
    : key_(canonical(path)) {
  Claims& table = claims();
  std::lock_guard<std::mutex> lock(table.mutex);
  auto [it, inserted] = table.byFile.try_emplace(key_, Claim{holder, path});
  if (!inserted) {
    const Claim& held = it->second;
    std::string message = context + ": file '" + path + "' is already written by recorder " +
                          std::to_string(held.holder.tag) + " (" + held.holder.type + ")";
    if (held.holder.domain != holder.domain) message += " in another model";
    if (held.path != path) message += ", which opened it as '" + held.path + "'";
    throw OpenSeesError(message + "; remove that recorder first or choose another file");
  }
  held_ = true;
}

OutputFileClaim::~OutputFileClaim() { release(); }

void OutputFileClaim::release() {
  if (!held_) return;
  held_ = false;
  Claims& table = claims();
  std::lock_guard<std::mutex> lock(table.mutex);
  table.byFile.erase(key_);
}

}  // namespace beamsolid
