#include "elements/ZeroLengthSection.h"

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "core/Registry.h"
#include "elements/ZeroLength.h"

namespace beamsolid {

ZeroLengthSection::ZeroLengthSection(int tag, int iNode, int jNode, const BeamSection& section,
                                     const Matrix3& localAxes, bool doRayleigh)
    : Element(tag, {iNode, jNode}), section_(section.cloneSection()), localAxes_(localAxes), doRayleigh_(doRayleigh) {
  section3d_ = dynamic_cast<SectionForceDeformation*>(section_.get());
  section2d_ = dynamic_cast<SectionForceDeformation2d*>(section_.get());
  if (section2d_) codes_ = section2d_->codes();
  else if (section3d_) codes_ = section3d_->responseCodes();  // shear (Vy, Vz) in the section's own order
  else throw OpenSeesError(context() + ": " + section.context() + " is neither a 2D nor a 3D beam section");
}

void ZeroLengthSection::setDomain(Domain&) {
  const int ndf = section2d_ ? 3 : 6;
  for (const Node* n : nodes())
    if (n->ndf() != ndf)
      throw OpenSeesError(context() + ": node " + std::to_string(n->tag()) + " has " + std::to_string(n->ndf()) +
                          " dofs; a " + (section2d_ ? "2D section needs nodes with ndf 3" : "3D section needs nodes with ndf 6"));
  const int order = static_cast<int>(codes_.size());
  gradient_ = Matrix::Zero(order, 2 * ndf);
  for (int r = 0; r < order; ++r) {
    const SectionCode c = codes_[r];
    const bool rotation = c == SectionCode::T || c == SectionCode::My || c == SectionCode::Mz;
    const int axis = (c == SectionCode::P || c == SectionCode::T) ? 0 : (c == SectionCode::Vy || c == SectionCode::My) ? 1 : 2;
    const Vector3 direction = localAxes_.row(axis).transpose();
    if (ndf == 3) {
      // In the plane: translations (ux, uy), the rotation rz about global Z.
      if (rotation) {
        gradient_(r, 2) = -direction.z();
        gradient_(r, 5) = direction.z();
      } else {
        gradient_.block<1, 2>(r, 0) = -direction.head<2>().transpose();
        gradient_.block<1, 2>(r, 3) = direction.head<2>().transpose();
      }
    } else {
      const int first = rotation ? 3 : 0;
      gradient_.block<1, 3>(r, first) = -direction.transpose();
      gradient_.block<1, 3>(r, 6 + first) = direction.transpose();
    }
  }
  displacement_ = Vector::Zero(2 * ndf);
  initialStiffness_ = gradient_.transpose() * sectionTangent(true) * gradient_;
  update();
}

Vector ZeroLengthSection::sectionDeformation() const {
  if (section2d_) return Vector(section2d_->deformation());
  if (section3d_->numShear() > 0) return section3d_->responseDeformation();
  return Vector(section3d_->deformation());
}

Vector ZeroLengthSection::sectionForce() const {
  if (section2d_) return Vector(section2d_->force());
  if (section3d_->numShear() > 0) return section3d_->responseForce();
  return Vector(section3d_->force());
}

Matrix ZeroLengthSection::sectionTangent(bool initial) const {
  if (section2d_) return Matrix(initial ? section2d_->initialTangent() : section2d_->tangent());
  if (section3d_->numShear() > 0) return section3d_->responseTangent(initial);
  return Matrix(initial ? section3d_->initialTangent() : section3d_->tangent());
}

void ZeroLengthSection::update() {
  const Node& ni = *nodes()[0];
  const Node& nj = *nodes()[1];
  const int ndf = ni.ndf();
  displacement_.head(ndf) = ni.trialDisp();
  displacement_.tail(ndf) = nj.trialDisp();
  if (section2d_) {
    const SectionForceDeformation2d::Vector e = gradient_ * displacement_;
    section2d_->setTrialDeformation(e);
  } else if (section3d_->numShear() > 0) {
    section3d_->setTrialResponseDeformation(gradient_ * displacement_);
  } else {
    const SectionForceDeformation::Vector4 e = gradient_ * displacement_;
    section3d_->setTrialDeformation(e);
  }
}

MatrixView ZeroLengthSection::tangentStiff() {
  stiffness_ = gradient_.transpose() * sectionTangent(false) * gradient_;
  return viewOf(stiffness_);
}

MatrixView ZeroLengthSection::initialStiff() { return viewOf(initialStiffness_); }

VectorView ZeroLengthSection::resistingForce() {
  force_ = gradient_.transpose() * sectionForce();
  return viewOf(force_);
}

void ZeroLengthSection::commitState() { section_->commitState(); }
void ZeroLengthSection::revertToLastCommit() { section_->revertToLastCommit(); }
void ZeroLengthSection::revertToStart() { section_->revertToStart(); }

Response ZeroLengthSection::setResponse(const std::vector<std::string>& args) {
  if (args.empty()) return {};
  const std::string& what = args[0];
  std::vector<std::string> forces, deformations;
  for (SectionCode c : codes_) {
    forces.push_back(sectionCodeName(c));
    deformations.push_back(sectionDeformationName(c));
  }
  if (what == "force" || what == "forces") {
    const int n = numDOF();
    return Response::named(Response::numberedNames("P", n), [this] { return Vector(resistingForce()); });
  }
  if (what == "basicForce" || what == "basicForces" || what == "localForce" || what == "localForces")
    return Response::named(forces, [this] { return sectionForce(); });
  if (what == "deformation" || what == "deformations" || what == "basicDeformation" || what == "basicDeformations")
    return Response::named(deformations, [this] { return sectionDeformation(); });
  if (what == "section" && args.size() >= 2)
    return section_->setResponse(std::vector<std::string>(args.begin() + 1, args.end()));
  for (int axis = 0; axis < 3; ++axis) {
    const std::string name(1, "xyz"[axis]);
    if (what == name + "axis" || what == name + "local")
      return {{name + "_X", name + "_Y", name + "_Z"},
              [this, axis] { return Vector(localAxes_.row(axis).transpose()); }};
  }
  return {};
}

void ZeroLengthSection::print(std::ostream& os) const {
  os << "Element " << tag() << " type zeroLengthSection nodes " << nodeTags()[0] << ' ' << nodeTags()[1]
     << " section " << section_->className() << ' ' << section_->tag() << '\n';
}

namespace {

std::unique_ptr<Element> buildZeroLengthSection(CommandArgs& args, Domain& domain) {
  const int tag = args.nextInt("eleTag");
  args.setContext("element zeroLengthSection " + std::to_string(tag));
  const int iNode = args.nextInt("iNode");
  const int jNode = args.nextInt("jNode");
  const std::size_t secAt = args.position();
  const int secTag = args.nextInt("secTag");
  const BeamSection& section = domain.sections.get(secTag, args.context());
  if (section.ndm() != domain.spaceDim())
    args.failAt(secAt, "secTag",
                "a section made in a " + std::to_string(domain.spaceDim()) + "D model; " + section.context() +
                    " is a " + std::to_string(section.ndm()) + "D section");
  Matrix3 axes = Matrix3::Identity();
  bool doRayleigh = false;
  while (!args.done()) {
    if (args.nextFlag("-doRayleigh")) {
      doRayleigh = args.nextInt("rFlag") != 0;
    } else if (args.nextFlag("-orient")) {
      const std::size_t at = args.position();
      const std::vector<double> v = args.nextDoubles("orientation vectors x and yp", 6);
      if (v.size() != 6) args.failAt(at + 6, "orientation vectors x and yp", "exactly 6 numbers (x1 x2 x3 yp1 yp2 yp3)");
      axes = ZeroLength::axesFromOrientation(Vector3(v[0], v[1], v[2]), Vector3(v[3], v[4], v[5]), args.context());
    } else {
      args.failAt(args.position(), "option", "'-orient' or '-doRayleigh'");
    }
  }
  return std::make_unique<ZeroLengthSection>(tag, iNode, jNode, section, axes, doRayleigh);
}

void registerZeroLengthSection(Registry& r) { r.elements.add("zeroLengthSection", &buildZeroLengthSection); }

}  // namespace

BEAMSOLID_REGISTER(registerZeroLengthSection);

}  // namespace beamsolid
