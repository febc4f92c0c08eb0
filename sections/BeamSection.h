#pragma once
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "core/Response.h"

namespace beamsolid {

// What every section command makes, whatever its space: a tag, trial and
// committed state, responses. The section store holds these; an element
// asks for the kind it can use (SectionForceDeformation for 3D,
// SectionForceDeformation2d for 2D) and a section of the other space is a
// clear error there, not a silent reinterpretation.
class BeamSection {
 public:
  explicit BeamSection(int tag) : tag_(tag) {}
  virtual ~BeamSection() = default;

  int tag() const { return tag_; }
  virtual std::string className() const = 0;
  // The model dimension the section was made for (2 or 3).
  virtual int ndm() const = 0;
  virtual std::unique_ptr<BeamSection> cloneSection() const = 0;

  virtual void commitState() = 0;
  virtual void revertToLastCommit() = 0;
  virtual void revertToStart() = 0;

  // An empty Response when the arguments name nothing this section has.
  virtual Response setResponse(const std::vector<std::string>& args) = 0;
  virtual void print(std::ostream& os) const;

  // "section <className> <tag>", the prefix of this section's messages.
  std::string context() const;

 private:
  int tag_;
};

}  // namespace beamsolid
