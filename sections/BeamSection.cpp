#include "sections/BeamSection.h"

namespace beamsolid {

std::string BeamSection::context() const { return "section " + className() + " " + std::to_string(tag_); }

void BeamSection::print(std::ostream& os) const { os << "Section " << tag_ << " type " << className() << '\n'; }

}  // namespace beamsolid
