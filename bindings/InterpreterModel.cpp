// Model-building commands of the Interpreter.
#include <algorithm>
#include <cmath>
#include <exception>
#include <iostream>
#include <optional>

#include "bindings/Interpreter.h"

#include "analysis/DofMap.h"
#include "core/OpenSeesError.h"
#include "core/MultipleSupportPattern.h"
#include "core/Registry.h"
#include "core/UniformExcitation.h"

namespace beamsolid {

using Result = Interpreter::Result;

namespace {

// The ndf values nodes may have in a space of ndm dimensions: translations
// only, or with rotations (1D has no rotation).
bool ndfAllowed(int ndm, int ndf) {
  switch (ndm) {
    case 1: return ndf == 1;
    case 2: return ndf == 2 || ndf == 3;
    default: return ndf == 3 || ndf == 6;
  }
}

std::string allowedNdfText(int ndm) {
  switch (ndm) {
    case 1: return "1";
    case 2: return "2 or 3";
    default: return "3 or 6";
  }
}

}  // namespace

Result Interpreter::wipe(CommandArgs& a) {
  a.expectEnd();
  DofMap::resetWarnings();
  extraMassWarned_ = false;
  // A recorder that cannot write its file still leaves the model wiped; its
  // error is raised at the end.
  std::exception_ptr recorderFailure;
  try {
    domain_->removeRecorders();
  } catch (const OpenSeesError&) {
    recorderFailure = std::current_exception();
  }
  analysis_.reset();
  components_ = AnalysisComponents{};
  haveAnalysis_ = false;
  const int nextRecorderTag = domain_->nextRecorderTag();
  domain_ = std::make_unique<Domain>();
  domain_->setNextRecorderTag(nextRecorderTag);
  currentPatternTag_ = -1;
  currentSectionTag_ = -1;
  eigenvalues_.clear();
  haveModalProperties_ = false;
  parameters_.clear();
  sensitivityResults_.clear();
  testMaterial_.reset();
  if (recorderFailure) std::rethrow_exception(recorderFailure);
  return {};
}

Result Interpreter::model(CommandArgs& a) {
  const std::string type = a.nextString("type");
  if (type != "basic" && type != "Basic" && type != "BasicBuilder")
    a.fail("model type '" + type + "' is not supported (expected 'basic')");
  int ndm = 0, ndf = 0;
  while (!a.done()) {
    const std::string opt = a.nextString("option");
    if (opt == "-ndm") ndm = a.nextInt("ndm");
    else if (opt == "-ndf") ndf = a.nextInt("ndf");
    else a.fail("unknown option '" + opt + "' (expected -ndm or -ndf)");
  }
  if (ndm < 1 || ndm > 3) a.fail("-ndm must be 1, 2 or 3, got " + std::to_string(ndm));
  if (ndf == 0) ndf = ndm * (ndm + 1) / 2;  // OpenSees' default: 1, 3, 6
  if (!ndfAllowed(ndm, ndf))
    a.fail("-ndf must be " + allowedNdfText(ndm) + " in " + std::to_string(ndm) + "D, got " + std::to_string(ndf));
  domain_->setModelSpace(ndm, ndf);
  return {};
}

namespace {

// OpenSees takes a node's masses one per dof and drops values beyond its ndf
// (an OpenSeesPy test gives a 3-dof brick node six): kept for unchanged
// scripts, with a warning. Fewer values than dofs: the `mass` command leaves
// the missing masses zero, as OpenSees does (with a warning here: it may be a
// slip), while node's '-mass' refuses them, as OpenSees does too.
// `warned`: said once until wipe (a meshing loop repeats it per node).
Vector massPerDof(const Vector& given, int ndf, CommandArgs& a, bool& warned, bool padShort) {
  if (given.size() < ndf && (!padShort || given.size() == 0))
    a.fail("the node has " + std::to_string(ndf) + " dofs but " + std::to_string(given.size()) +
           " mass values were given");
  if (given.size() != ndf && !warned) {
    std::cerr << "WARNING " << a.context() << " - " << given.size() << " mass values for " << ndf << " dofs: "
              << (given.size() > ndf ? "the values beyond the " + std::to_string(ndf) + " are ignored"
                                     : "the missing ones are zero")
              << " (said once until wipe)\n";
    warned = true;
  }
  if (given.size() >= ndf) return given.head(ndf);
  Vector padded = Vector::Zero(ndf);
  padded.head(given.size()) = given;
  return padded;
}

}  // namespace

Result Interpreter::node(CommandArgs& a) {
  requireModel(a);
  const int tag = a.nextInt("nodeTag");
  a.setContext("node " + std::to_string(tag));
  const int ndm = domain_->ndm();
  // Exactly ndm coordinates; the rest of the 3 stay zero.
  Vector3 x = Vector3::Zero();
  int given = 0;
  while (a.nextIsNumber()) {
    const double value = a.nextDouble("coordinate");
    if (given < 3) x[given] = value;
    ++given;
  }
  if (given < ndm && !a.done()) {
    // Something that is not a number where a coordinate belongs (not an
    // option): say which argument and what it is.
    const auto s = a.peekString();
    if (!s || s->empty() || (*s)[0] != '-') a.nextDouble(given == 0 ? "x" : given == 1 ? "y" : "z");
  }
  if (given != ndm) {
    static const char* const names[3] = {"x", "x, y", "x, y, z"};
    a.fail("expected " + std::to_string(ndm) + " coordinate" + (ndm > 1 ? "s" : "") + " (" + names[ndm - 1] +
           ") in a model with -ndm " + std::to_string(ndm) + ", got " + std::to_string(given));
  }
  int ndf = domain_->ndf();
  Vector mass, disp;
  while (!a.done()) {
    const std::string opt = a.nextString("option");
    if (opt == "-ndf") {
      ndf = a.nextInt("ndf");
      if (!ndfAllowed(ndm, ndf))
        a.fail("-ndf must be " + allowedNdfText(ndm) + " in " + std::to_string(ndm) + "D, got " + std::to_string(ndf));
    } else if (opt == "-mass") {
      auto m = a.nextDoubles("mass", 1);
      mass = Eigen::Map<Vector>(m.data(), m.size());
    } else if (opt == "-disp") {
      auto d = a.nextDoubles("disp", 1);
      disp = Eigen::Map<Vector>(d.data(), d.size());
    } else {
      a.fail("unknown option '" + opt + "' (expected -ndf, -mass or -disp)");
    }
  }
  auto n = std::make_unique<Node>(tag, ndf, x, ndm);
  if (mass.size()) n->setMass(massPerDof(mass, ndf, a, extraMassWarned_, false));
  if (disp.size()) {
    if (disp.size() != ndf) a.fail("-disp needs " + std::to_string(ndf) + " values, got " + std::to_string(disp.size()));
    n->setTrialDisp(disp);
    n->commitState();
  }
  domain_->addNode(std::move(n), a.context());
  return {};
}

Result Interpreter::fix(CommandArgs& a) {
  const int tag = a.nextInt("nodeTag");
  a.setContext("fix " + std::to_string(tag));
  Node& n = domain_->node(tag, a.context());
  const auto flags = a.nextInts("constraint flags");
  a.expectEnd();
  if (static_cast<int>(flags.size()) != n.ndf())
    a.fail("node " + std::to_string(tag) + " has " + std::to_string(n.ndf()) + " dofs but " +
           std::to_string(flags.size()) + " flags were given");
  for (int d = 0; d < n.ndf(); ++d) {
    if (flags[d] != 0 && flags[d] != 1) a.fail("constraint flags must be 0 or 1, got " + std::to_string(flags[d]));
    if (flags[d]) domain_->addSP(SPConstraint{tag, d, 0.0, -1}, a.context());
  }
  return {};
}

Result Interpreter::fixX(CommandArgs& a) { return fixCoordinate(a, 0); }
Result Interpreter::fixY(CommandArgs& a) { return fixCoordinate(a, 1); }
Result Interpreter::fixZ(CommandArgs& a) { return fixCoordinate(a, 2); }

Result Interpreter::fixCoordinate(CommandArgs& a, int axis) {
  if (axis >= domain_->spaceDim())
    a.fail(std::string("fix") + "XYZ"[axis] + " needs a model with -ndm " + std::to_string(axis + 1) +
           " or more (this one has -ndm " + std::to_string(domain_->spaceDim()) + ")");
  const double coordinate = a.nextDouble("coordinate");
  std::vector<int> flags;
  double tol = 1e-10;
  while (!a.done()) {
    if (a.nextFlag("-tol")) tol = a.nextDouble("tol");
    else flags.push_back(a.nextInt("constraint flag"));
  }
  if (flags.empty()) a.fail("no constraint flags given");
  for (int f : flags)
    if (f != 0 && f != 1) a.fail("constraint flags must be 0 or 1, got " + std::to_string(f));
  int count = 0;
  for (const auto& [tag, n] : domain_->nodes()) {
    if (std::fabs(n->crd()[axis] - coordinate) > tol) continue;
    ++count;
    // Mixed models (beam nodes ndf 6, soil nodes ndf 3): flags beyond a
    // node's ndf are ignored; a dof already fixed stays fixed.
    for (int d = 0; d < n->ndf() && d < static_cast<int>(flags.size()); ++d) {
      if (!flags[d]) continue;
      if (!domain_->isFixed(tag, d)) domain_->addSP(SPConstraint{tag, d, 0.0, -1}, a.context());
    }
  }
  (void)count;
  return {};
}

Result Interpreter::equalDOF(CommandArgs& a) {
  const int r = a.nextInt("retainedNode");
  const int c = a.nextInt("constrainedNode");
  a.setContext("equalDOF " + std::to_string(r) + " " + std::to_string(c));
  const std::size_t at = a.position();
  const auto dofs = a.nextInts("dof", 1);
  a.expectEnd();
  MPConstraint mp;
  mp.retainedNode = r;
  mp.constrainedNode = c;
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    const int d = dofs[i];
    // Checked before d - 1, which overflows for the most negative int.
    if (d < 1) a.failAt(at + i, "dof", "dof numbers >= 1 (1-based)");
    mp.retainedDofs.push_back(d - 1);
    mp.constrainedDofs.push_back(d - 1);
  }
  mp.C = Matrix::Identity(dofs.size(), dofs.size());
  domain_->addMP(std::move(mp), a.context());
  return {};
}

Result Interpreter::rigidLink(CommandArgs& a) {
  const std::string type = a.nextString("type ('beam' or 'bar')");
  const int r = a.nextInt("retainedNode");
  const int c = a.nextInt("constrainedNode");
  a.setContext("rigidLink " + type + " " + std::to_string(r) + " " + std::to_string(c));
  a.expectEnd();
  if (type != "beam" && type != "bar") a.fail("type must be 'beam' or 'bar', got '" + type + "'");
  requireModel(a);
  const int ndm = domain_->spaceDim();
  const Node& rn = domain_->node(r, a.context());
  const Node& cn = domain_->node(c, a.context());
  MPConstraint mp;
  mp.kind = "rigidLink " + type;
  mp.retainedNode = r;
  mp.constrainedNode = c;
  if (type == "bar") {
    // Translations equal (small displacements).
    for (int d = 0; d < ndm; ++d) {
      mp.retainedDofs.push_back(d);
      mp.constrainedDofs.push_back(d);
    }
    mp.C = Matrix::Identity(ndm, ndm);
  } else if (ndm == 2) {
    if (rn.ndf() != 3) a.fail("the retained node of a rigid beam link needs 3 dofs in 2D (has " + std::to_string(rn.ndf()) + ")");
    // u_c = u_r + theta_r e_z x d, theta_c = theta_r, with d = X_c - X_r.
    const Vector3 d = cn.crd() - rn.crd();
    const int nc = cn.ndf() == 3 ? 3 : 2;
    for (int k = 0; k < 3; ++k) mp.retainedDofs.push_back(k);
    for (int k = 0; k < nc; ++k) mp.constrainedDofs.push_back(k);
    mp.C = Matrix::Zero(nc, 3);
    mp.C(0, 0) = mp.C(1, 1) = 1.0;
    mp.C(0, 2) = -d.y();
    mp.C(1, 2) = d.x();
    if (nc == 3) mp.C(2, 2) = 1.0;
  } else if (ndm == 3) {
    if (rn.ndf() != 6) a.fail("the retained node of a rigid beam link needs 6 dofs (has " + std::to_string(rn.ndf()) + ")");
    // u_c = u_r + theta_r x d, theta_c = theta_r, with d = X_c - X_r.
    const Vector3 d = cn.crd() - rn.crd();
    const int nc = cn.ndf() == 6 ? 6 : 3;
    for (int k = 0; k < 6; ++k) mp.retainedDofs.push_back(k);
    for (int k = 0; k < nc; ++k) mp.constrainedDofs.push_back(k);
    mp.C = Matrix::Zero(nc, 6);
    mp.C.block<3, 3>(0, 0).setIdentity();
    Matrix3 skew;
    skew << 0, -d.z(), d.y(), d.z(), 0, -d.x(), -d.y(), d.x(), 0;
    mp.C.block<3, 3>(0, 3) = -skew;  // theta x d = -d x theta
    if (nc == 6) mp.C.block<3, 3>(3, 3).setIdentity();
  } else {
    a.fail("a rigid beam link needs a 2D or 3D model (use 'bar' in 1D)");
  }
  domain_->addMP(std::move(mp), a.context());
  return {};
}

// rigidDiaphragm(perpDirn, rNodeTag, *cNodeTags): the constrained nodes move
// with the retained node as a rigid plate in the plane perpendicular to axis
// perpDirn: in-plane translations u_c = u_r + theta_r e_p x d, and the same
// rotation about e_p. Out-of-plane motion stays free.
Result Interpreter::rigidDiaphragm(CommandArgs& a) {
  const int perp = a.nextInt("perpDirn");
  const int r = a.nextInt("rNodeTag");
  a.setContext("rigidDiaphragm " + std::to_string(perp) + " " + std::to_string(r));
  const std::vector<int> constrained = a.nextInts("cNodeTags");
  a.expectEnd();
  requireModel(a);
  if (domain_->spaceDim() != 3) a.fail("rigidDiaphragm needs a 3D model (-ndm 3)");
  if (perp < 1 || perp > 3) a.fail("perpDirn must be 1, 2 or 3 (the axis normal to the diaphragm), got " + std::to_string(perp));
  if (constrained.empty()) a.fail("missing the constrained node tags");
  const Node& rn = domain_->node(r, a.context());
  if (rn.ndf() != 6) a.fail("the retained node " + std::to_string(r) + " needs 6 dofs (has " + std::to_string(rn.ndf()) + ")");
  const int p = perp - 1, i = (p + 1) % 3, j = (p + 2) % 3;  // in-plane axes i, j
  for (int c : constrained) {
    const Node& cn = domain_->node(c, a.context());
    if (c == r) a.fail("node " + std::to_string(c) + " is the retained node");
    if (cn.ndf() != 6) a.fail("constrained node " + std::to_string(c) + " needs 6 dofs (has " + std::to_string(cn.ndf()) + ")");
    const Vector3 d = cn.crd() - rn.crd();
    const double span = std::max({std::abs(d.x()), std::abs(d.y()), std::abs(d.z()), 1.0});
    if (std::abs(d[p]) > 1e-10 * span)
      a.fail("node " + std::to_string(c) + " is not in the diaphragm's plane (its coordinate " + std::to_string(perp) +
             " differs from node " + std::to_string(r) + "'s by " + std::to_string(d[p]) + ")");
    MPConstraint mp;
    mp.kind = "rigidDiaphragm";
    mp.retainedNode = r;
    mp.constrainedNode = c;
    mp.retainedDofs = {i, j, 3 + p};
    mp.constrainedDofs = {i, j, 3 + p};
    // e_p x d: its i component is -d_j, its j component d_i.
    mp.C = Matrix::Identity(3, 3);
    mp.C(0, 2) = -d[j];
    mp.C(1, 2) = d[i];
    domain_->addMP(std::move(mp), a.context());
  }
  return {};
}

Result Interpreter::mass(CommandArgs& a) {
  const int tag = a.nextInt("nodeTag");
  a.setContext("mass " + std::to_string(tag));
  Node& n = domain_->node(tag, a.context());
  auto m = a.nextDoubles("mass", 1);
  a.expectEnd();
  n.setMass(massPerDof(Eigen::Map<Vector>(m.data(), m.size()), n.ndf(), a, extraMassWarned_, true));
  return {};
}


Result Interpreter::uniaxialMaterial(CommandArgs& a) {
  auto m = Registry::global().uniaxialMaterials.build(a, *domain_);
  const int tag = m->tag();
  domain_->uniaxialMaterials.add(tag, std::move(m), a.context());
  return {};
}

Result Interpreter::nDMaterial(CommandArgs& a) {
  auto m = Registry::global().ndMaterials.build(a, *domain_);
  const int tag = m->tag();
  domain_->ndMaterials.add(tag, std::move(m), a.context());
  return {};
}

Result Interpreter::geomTransf(CommandArgs& a) {
  auto t = Registry::global().geomTransfs.build(a, *domain_);
  const int tag = t->tag();
  domain_->geomTransfs.add(tag, std::move(t), a.context());
  return {};
}

Result Interpreter::timeSeries(CommandArgs& a) {
  auto t = Registry::global().timeSeries.build(a, *domain_);
  const int tag = t->tag();
  domain_->timeSeries.add(tag, std::move(t), a.context());
  return {};
}

Result Interpreter::element(CommandArgs& a) {
  requireModel(a);
  auto e = Registry::global().elements.build(a, *domain_);
  domain_->addElement(std::move(e), a.context());
  return {};
}

Result Interpreter::pattern(CommandArgs& a) {
  const std::string type = a.nextString("type");
  if (type == "UniformExcitation") return uniformExcitation(a);
  if (type == "MultipleSupport") {
    const int tag = a.nextInt("patternTag");
    a.setContext("pattern MultipleSupport " + std::to_string(tag));
    if (!a.done()) a.failAt(a.position(), "argument", "nothing after the tag");
    domain_->addPattern(std::make_unique<MultipleSupportPattern>(tag), a.context());
    currentPatternTag_ = tag;
    return {};
  }
  if (type != "Plain")
    a.fail("pattern type '" + type + "' is not supported (expected 'Plain', 'UniformExcitation' or 'MultipleSupport')");
  const int tag = a.nextInt("patternTag");
  a.setContext("pattern Plain " + std::to_string(tag));
  const int seriesTag = a.nextInt("tsTag");
  double factor = 1.0;
  while (!a.done()) {
    if (a.nextFlag("-fact") || a.nextFlag("-factor")) factor = a.nextDouble("factor");
    else a.fail("unknown option " + CommandArgs::describe(a.at(a.position())) + " (expected -fact)");
  }
  auto series = domain_->timeSeries.shared(seriesTag, a.context());
  domain_->addPattern(std::make_unique<LoadPattern>(tag, series, factor), a.context());
  currentPatternTag_ = tag;
  return {};
}

// pattern('UniformExcitation', tag, dir, '-accel'|'-vel'|'-disp', tsTag, ..., <'-vel0', v0>, <'-fact', f>)
Result Interpreter::uniformExcitation(CommandArgs& a) {
  const int tag = a.nextInt("patternTag");
  a.setContext("pattern UniformExcitation " + std::to_string(tag));
  const int dir = a.nextInt("dir");
  const int ndf = domain_->ndf() > 0 ? domain_->ndf() : 6;
  if (dir < 1 || dir > ndf) a.fail("dir must be 1.." + std::to_string(ndf) + ", got " + std::to_string(dir));
  std::shared_ptr<TimeSeries> accel, vel, disp;
  double fact = 1.0, vel0 = 0.0;
  while (!a.done()) {
    if (a.nextFlag("-accel") || a.nextFlag("-acceleration")) accel = domain_->timeSeries.shared(a.nextInt("accelSeriesTag"), a.context());
    else if (a.nextFlag("-vel") || a.nextFlag("-velocity")) vel = domain_->timeSeries.shared(a.nextInt("velSeriesTag"), a.context());
    else if (a.nextFlag("-disp") || a.nextFlag("-displacement")) disp = domain_->timeSeries.shared(a.nextInt("dispSeriesTag"), a.context());
    else if (a.nextFlag("-vel0")) vel0 = a.nextDouble("vel0");
    else if (a.nextFlag("-fact") || a.nextFlag("-factor")) fact = a.nextDouble("fact");
    else a.failAt(a.position(), "option", "one of '-accel', '-vel', '-disp', '-vel0', '-fact'");
  }
  if (!accel && !vel && !disp) a.fail("no ground motion: give '-accel', '-vel' or '-disp' with a timeSeries tag");
  auto p = std::make_unique<UniformExcitation>(tag, dir - 1, accel, vel, disp, fact, vel0);
  const UniformExcitation& pattern = *p;
  domain_->addPattern(std::move(p), a.context());
  pattern.applyInitialVelocity(*domain_);
  currentPatternTag_ = tag;
  return {};
}

// groundMotion(gmTag, 'Plain', '-accel'|'-vel'|'-disp', tsTag, ..., <'-int', 'Trapezoidal'>, <'-fact', f>)
Result Interpreter::groundMotion(CommandArgs& a) {
  const int tag = a.nextInt("gmTag");
  const std::string type = a.nextString("type");
  a.setContext("groundMotion " + std::to_string(tag));
  if (type != "Plain") a.fail("ground motion type '" + type + "' is not supported (expected 'Plain')");
  LoadPattern* current = domain_->findPattern(currentPatternTag_);
  auto* pattern = dynamic_cast<MultipleSupportPattern*>(current);
  if (!pattern) a.fail("no MultipleSupport pattern: call pattern('MultipleSupport', tag) first");
  std::shared_ptr<TimeSeries> accel, vel, disp;
  double fact = 1.0;
  while (!a.done()) {
    if (a.nextFlag("-accel") || a.nextFlag("-acceleration")) accel = domain_->timeSeries.shared(a.nextInt("accelSeriesTag"), a.context());
    else if (a.nextFlag("-vel") || a.nextFlag("-velocity")) vel = domain_->timeSeries.shared(a.nextInt("velSeriesTag"), a.context());
    else if (a.nextFlag("-disp") || a.nextFlag("-displacement")) disp = domain_->timeSeries.shared(a.nextInt("dispSeriesTag"), a.context());
    else if (a.nextFlag("-fact") || a.nextFlag("-factor")) fact = a.nextDouble("fact");
    else if (a.nextFlag("-int")) {
      const std::string rule = a.nextString("integrator");
      if (rule != "Trapezoidal")
        a.fail("integrator '" + rule + "' is not supported (expected 'Trapezoidal', OpenSees' default)");
    } else {
      a.failAt(a.position(), "option", "one of '-accel', '-vel', '-disp', '-int', '-fact'");
    }
  }
  if (!accel && !vel && !disp) a.fail("no series: give '-accel', '-vel' or '-disp' with a timeSeries tag");
  pattern->addGroundMotion(std::make_unique<GroundMotion>(tag, accel, vel, disp, fact, a.context()), a.context());
  return {};
}

// imposedMotion(nodeTag, dof, gmTag)
Result Interpreter::imposedMotion(CommandArgs& a) {
  const int nodeTag = a.nextInt("nodeTag");
  a.setContext("imposedMotion " + std::to_string(nodeTag));
  const int dof = a.nextInt("dof");
  const int gmTag = a.nextInt("gmTag");
  if (!a.done()) a.failAt(a.position(), "argument", "nothing after gmTag");
  const Node& n = domain_->node(nodeTag, a.context());
  if (dof < 1 || dof > n.ndf())
    a.fail("dof " + std::to_string(dof) + " is out of range 1.." + std::to_string(n.ndf()));
  auto* pattern = dynamic_cast<MultipleSupportPattern*>(domain_->findPattern(currentPatternTag_));
  if (!pattern) a.fail("no MultipleSupport pattern: call pattern('MultipleSupport', tag) first");
  // A fixed dof may take an imposed motion (it then governs, see DofMap).
  for (const auto& [ptag, p] : domain_->patterns())
    for (const auto& s : p->sps())
      if (s.nodeTag == nodeTag && s.dof == dof - 1)
        a.fail("dof " + std::to_string(dof) + " already has an imposed value in pattern " + std::to_string(ptag));
  pattern->addImposedMotion(nodeTag, dof - 1, gmTag, a.context());
  domain_->touch();
  return {};
}

Result Interpreter::load(CommandArgs& a) {
  const int tag = a.nextInt("nodeTag");
  a.setContext("load " + std::to_string(tag));
  const Node& n = domain_->node(tag, a.context());
  auto values = a.nextDoubles("load", 1);
  while (!a.done()) {
    const std::string opt = a.nextString("option");
    if (opt != "-const" && opt != "-pattern") a.fail("unknown option '" + opt + "'");
    if (opt == "-pattern") currentPatternTag_ = a.nextInt("patternTag");
  }
  if (static_cast<int>(values.size()) != n.ndf())
    a.fail("node " + std::to_string(tag) + " has " + std::to_string(n.ndf()) + " dofs but " +
           std::to_string(values.size()) + " load values were given");
  currentPattern(a).addNodalLoad(tag, Eigen::Map<Vector>(values.data(), values.size()));
  return {};
}

Result Interpreter::sp(CommandArgs& a) {
  const int tag = a.nextInt("nodeTag");
  a.setContext("sp " + std::to_string(tag));
  const int dof = a.nextInt("dof");
  const double value = a.nextDouble("value");
  while (!a.done()) {
    const std::string opt = a.nextString("option");
    if (opt != "-const" && opt != "-subtractInit") a.fail("unknown option '" + opt + "'");
  }
  const Node& n = domain_->node(tag, a.context());
  if (dof < 1 || dof > n.ndf())
    a.fail("dof " + std::to_string(dof) + " is out of range 1.." + std::to_string(n.ndf()));
  // A fixed dof may take an sp (it then governs, see DofMap).
  for (const auto& [ptag, p] : domain_->patterns())
    if (p->hasSP(tag, dof - 1))
      a.fail("dof " + std::to_string(dof) + " already has an sp in pattern " + std::to_string(ptag));
  currentPattern(a).addSP(SPConstraint{tag, dof - 1, value, currentPatternTag_});
  domain_->touch();
  return {};
}

Result Interpreter::eleLoad(CommandArgs& a) {
  std::vector<int> tags;
  ElementLoad load;
  bool haveType = false;
  while (!a.done()) {
    const std::string opt = a.nextString("option");
    if (opt == "-ele") {
      auto t = a.nextInts("element tag", 1);
      tags.insert(tags.end(), t.begin(), t.end());
    } else if (opt == "-range") {
      const int from = a.nextInt("first element"), to = a.nextInt("last element");
      for (const auto& [tag, e] : domain_->elements())
        if (tag >= from && tag <= to) tags.push_back(tag);
    } else if (opt == "-type") {
      const std::string type = a.nextString("load type");
      haveType = true;
      // In 2D OpenSees takes (Wy, <Wx>) and (Py, xL, <Px>); they are kept in
      // ElementLoad's 3D layout with Wz = Pz = 0.
      const bool planar = domain_->spaceDim() == 2;
      if (planar && (type == "-beamUniform" || type == "beamUniform")) {
        load.type = ElementLoad::Type::BeamUniform;
        // OpenSees 3.7 also reads (Wya, Wxa, aOverL, bOverL, Wyb, Wxb): a load
        // over aL..bL varying linearly from Wya, Wxa to Wyb, Wxb (Wyb, Wxb
        // default to Wya, Wxa with four values; Wxb to 0 once Wyb is given).
        // Only its full-span uniform case is built here.
        const auto w = a.nextDoubles("Wy, <Wx>, <aOverL, bOverL, Wyb, Wxb>", 1);
        if (w.size() > 6) a.fail("-beamUniform takes at most Wy, Wx, aOverL, bOverL, Wyb, Wxb in a 2D model");
        const double wy = w[0], wx = w.size() > 1 ? w[1] : 0.0;
        const double aL = w.size() > 2 ? w[2] : 0.0, bL = w.size() > 3 ? w[3] : 1.0;
        const double wyb = w.size() > 4 ? w[4] : wy, wxb = w.size() > 5 ? w[5] : (w.size() > 4 ? 0.0 : wx);
        if (aL < 0.0 || aL > 1.0 || bL < 0.0 || bL > 1.0 || aL >= bL)
          a.fail("-beamUniform aOverL and bOverL must satisfy 0 <= aOverL < bOverL <= 1, got " + std::to_string(aL) +
                 ", " + std::to_string(bL));
        if (aL != 0.0 || bL != 1.0 || wyb != wy || wxb != wx)
          a.fail("-beamUniform over part of the element (aOverL, bOverL) or varying (Wyb, Wxb) is not supported; "
                 "only a uniform load over the whole element");
        load.values = {wy, 0.0, wx};
      } else if (planar && (type == "-beamPoint" || type == "beamPoint")) {
        load.type = ElementLoad::Type::BeamPoint;
        const auto w = a.nextDoubles("Py, xL, <Px>", 2);
        if (w.size() > 3) a.fail("-beamPoint takes Py, xL and optionally Px in a 2D model");
        if (w[1] < 0.0 || w[1] > 1.0) a.fail("-beamPoint xL must lie in [0, 1]");
        load.values = {w[0], 0.0, w[1], w.size() > 2 ? w[2] : 0.0};
      } else if (type == "-beamUniform" || type == "beamUniform") {
        load.type = ElementLoad::Type::BeamUniform;
        load.values = a.nextDoubles("Wy, Wz, <Wx>", 2);
        if (load.values.size() > 3) a.fail("-beamUniform takes Wy, Wz and optionally Wx");
        load.values.resize(3, 0.0);
      } else if (type == "-beamPoint" || type == "beamPoint") {
        load.type = ElementLoad::Type::BeamPoint;
        load.values = a.nextDoubles("Py, Pz, xL, <Px>", 3);
        if (load.values.size() > 4) a.fail("-beamPoint takes Py, Pz, xL and optionally Px");
        load.values.resize(4, 0.0);
        if (load.values[2] < 0.0 || load.values[2] > 1.0) a.fail("-beamPoint xL must lie in [0, 1]");
      } else if (planar && (type == "-selfWeight" || type == "selfWeight")) {
        // 2D: factors on the element's b1, b2, and a bz OpenSees accepts and ignores.
        load.type = ElementLoad::Type::SelfWeight;
        load.values = a.nextDoubles("bx, by, <bz>", 2);
        if (load.values.size() > 3) a.fail("-selfWeight takes bx, by (and an unused bz) in a 2D model");
        load.values.resize(2);
        load.values.push_back(0.0);
      } else if (type == "-selfWeight" || type == "selfWeight") {
        load.type = ElementLoad::Type::SelfWeight;
        load.values = a.nextDoubles("bx, by, bz", 3);
        if (load.values.size() != 3) a.fail("-selfWeight takes bx, by, bz");
      } else {
        a.fail("unknown load type '" + type + "' (expected -beamUniform, -beamPoint or -selfWeight)");
      }
    } else {
      a.fail("unknown option '" + opt + "' (expected -ele, -range or -type)");
    }
  }
  if (!haveType) a.fail("missing '-type'");
  if (tags.empty()) a.fail("no elements given (-ele tags or -range first last)");
  LoadPattern& p = currentPattern(a);
  for (int t : tags) {
    Element& e = domain_->element(t, a.context());
    if (!e.acceptsLoad(load.type))
      a.fail("element " + e.className() + " " + std::to_string(t) + " does not accept " + ElementLoad::typeName(load.type));
  }
  for (int t : tags) p.addElementLoad(t, load);
  return {};
}

Result Interpreter::loadConst(CommandArgs& a) {
  std::optional<double> time;
  while (!a.done()) {
    if (a.nextFlag("-time")) time = a.nextDouble("time");
    else a.fail("unknown option " + CommandArgs::describe(a.at(a.position())) + " (expected -time)");
  }
  domain_->setLoadConst();
  if (time) {
    domain_->setCurrentTime(*time);
    domain_->setCommittedTime(*time);
  }
  return {};
}

Result Interpreter::setTime(CommandArgs& a) {
  const double t = a.nextDouble("time");
  a.expectEnd();
  domain_->setCurrentTime(t);
  domain_->setCommittedTime(t);
  return {};
}

Result Interpreter::getTime(CommandArgs& a) {
  a.expectEnd();
  return domain_->currentTime();
}

Result Interpreter::remove(CommandArgs& a) {
  const std::string what = a.nextString("what");
  a.setContext("remove " + what);
  if (what == "ele" || what == "element") {
    const int tag = a.nextInt("eleTag");
    domain_->removeElement(tag, a.context());
  } else if (what == "node") {
    const int tag = a.nextInt("nodeTag");
    domain_->removeNode(tag, a.context());
  } else if (what == "loadPattern" || what == "pattern") {
    const int tag = a.nextInt("patternTag");
    if (!domain_->removePattern(tag)) a.fail("load pattern " + std::to_string(tag) + " does not exist");
  } else if (what == "recorder") {
    const int tag = a.nextInt("recorderTag");
    if (!domain_->removeRecorder(tag)) a.fail("recorder " + std::to_string(tag) + " does not exist");
  } else if (what == "recorders") {
    domain_->removeRecorders();
  } else if (what == "sp") {
    // remove('sp', nodeTag, dof, <patternTag>): with the pattern, only its sp.
    const int node = a.nextInt("nodeTag"), dof = a.nextInt("dof");
    if (dof < 1) a.failAt(a.position() - 1, "dof", "a dof number >= 1 (1-based)");
    if (!a.done()) {
      const int patternTag = a.nextInt("patternTag");
      LoadPattern* p = domain_->findPattern(patternTag);
      if (!p) a.fail("load pattern " + std::to_string(patternTag) + " does not exist");
      if (!p->removeSP(node, dof - 1))
        a.fail("load pattern " + std::to_string(patternTag) + " has no sp on node " + std::to_string(node) + " dof " +
               std::to_string(dof));
      domain_->touch();
    } else if (!domain_->removeSP(node, dof - 1)) {
      a.fail("node " + std::to_string(node) + " dof " + std::to_string(dof) + " has no single-point constraint");
    }
  } else if (what == "mp") {
    const int node = a.nextInt("constrainedNode");
    if (!domain_->removeMP(node)) a.fail("node " + std::to_string(node) + " has no multi-point constraint");
  } else if (what == "timeSeries") {
    const int tag = a.nextInt("tsTag");
    if (!domain_->timeSeries.remove(tag)) a.fail("timeSeries " + std::to_string(tag) + " does not exist");
  } else if (what == "parameter") {
    a.nextInt("paramTag");
  } else {
    a.fail("cannot remove '" + what + "' (expected ele, node, loadPattern, recorder, recorders, sp, mp, timeSeries)");
  }
  a.expectEnd();
  return {};
}

Result Interpreter::recorder(CommandArgs& a) {
  auto r = Registry::global().recorders.build(a, *domain_);
  return static_cast<long long>(domain_->addRecorder(std::move(r)));
}

Result Interpreter::record(CommandArgs& a) {
  a.expectEnd();
  domain_->record();
  domain_->flushRecorders();
  return {};
}

Result Interpreter::loadPlugin(CommandArgs& a) {
  const std::string path = a.nextString("path");
  a.expectEnd();
  Registry::global().loadPlugin(path);
  return {};
}

Result Interpreter::setParameter(CommandArgs& a) {
  if (!a.nextFlag("-val")) a.fail("expected '-val', value first");
  const double value = a.nextDouble("value");
  std::vector<int> tags;
  if (a.nextFlag("-ele")) {
    tags = a.nextInts("element tag", 1);
  } else if (a.nextFlag("-eleRange")) {
    const int from = a.nextInt("first element"), to = a.nextInt("last element");
    for (const auto& [tag, e] : domain_->elements())
      if (tag >= from && tag <= to) tags.push_back(tag);
  } else {
    for (const auto& [tag, e] : domain_->elements()) tags.push_back(tag);
  }
  const auto args = a.restAsStrings();
  if (args.empty()) a.fail("missing parameter name (e.g. 'friction')");
  int recognized = 0;
  for (int t : tags)
    if (domain_->element(t, a.context()).setParameter(args, value)) ++recognized;
  if (recognized == 0) a.fail("no element recognizes parameter '" + args[0] + "'");
  return {};
}

Result Interpreter::initialStateAnalysis(CommandArgs& a) {
  const std::string flag = a.nextString("flag");
  a.expectEnd();
  if (flag != "on" && flag != "off") a.fail("flag must be 'on' or 'off', got '" + flag + "'");
  domain_->initialStateAnalysis(flag == "on");
  return {};
}

Result Interpreter::updateMaterialStage(CommandArgs& a) {
  int matTag = 0, stage = 0;
  bool haveMat = false, haveStage = false;
  while (!a.done()) {
    const std::string opt = a.nextString("option");
    if (opt == "-material") { matTag = a.nextInt("matTag"); haveMat = true; }
    else if (opt == "-stage") { stage = a.nextInt("stage"); haveStage = true; }
    else if (opt == "-parameter") a.nextInt("paramTag");
    else a.fail("unknown option '" + opt + "' (expected -material, -stage)");
  }
  if (!haveMat || !haveStage) a.fail("needs '-material', matTag, '-stage', stage");
  NDMaterial* m = domain_->ndMaterials.find(matTag);
  if (!m) a.fail("nDMaterial " + std::to_string(matTag) + " does not exist");
  m->updateStage(stage);
  for (const auto& [tag, e] : domain_->elements()) e->updateMaterialStage(matTag, stage);
  return {};
}

}  // namespace beamsolid
