#pragma once
#include <string>

namespace beamsolid {

class Domain;

// A recorder's hold on the file it writes. Two recorders writing one file
// interleave their rows and the second truncates the first's, so a file has
// one writer in the whole process: a claim on a file already claimed (however
// its path is spelled, and from any model) is refused, before the file is
// opened. Released by release() (the recorder closed) or by destruction.
class OutputFileClaim {
 public:
  // The recorder that claims: recorder `tag` of `type` ("Node", "PVD") in `domain`.
  struct Holder {
    const Domain* domain = nullptr;
    int tag = -1;
    std::string type;

    // The recorder being built for `domain`: it gets the tag
    // Domain::addRecorder hands out next.
    static Holder beingAddedTo(const Domain& domain, std::string type);
  };

  // Throws an OpenSeesError prefixed by `context` that names the holder of
  // the file when `path` is claimed already.
  OutputFileClaim(const std::string& path, Holder holder, const std::string& context);
  ~OutputFileClaim();
  OutputFileClaim(const OutputFileClaim&) = delete;
  OutputFileClaim& operator=(const OutputFileClaim&) = delete;

  // Lets another recorder have the file. Later calls do nothing.
  void release();
  bool held() const { return held_; }

  // The key files are compared by: the absolute path with symbolic links,
  // '.' and '..' resolved as far as the path exists.
  static std::string canonical(const std::string& path);

 private:
  std::string key_;
  bool held_ = false;
};

}  // namespace beamsolid
