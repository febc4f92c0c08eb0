#pragma once
#include <string>

namespace beamsolid {

class Domain;

// Called at every commit (and by record()); writes files. A recorder
// flushes on flush(), and everything is on disk after close().
class Recorder {
 public:
  virtual ~Recorder() = default;
  virtual std::string className() const = 0;
  // Non-const Domain: a reaction recorder asks the Domain to compute reactions.
  virtual void record(Domain& domain, double time) = 0;
  virtual void flush() = 0;
  virtual void close() = 0;
};

}  // namespace beamsolid
