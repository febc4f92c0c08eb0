// The small commands of OpenSeesPy scripts: version, timers, the log file,
// parallel stand-ins, element and section shortcuts, constraint queries, and
// setting a node's state by hand.
#include <algorithm>
#include <cctype>
#include <iostream>
#include <set>

#include "bindings/Interpreter.h"
#include "core/LogFile.h"
#include "core/OpenSeesError.h"
#include "core/Version.h"

namespace beamsolid {

using Result = Interpreter::Result;

namespace {
std::vector<double> toList(const Vector& v) { return std::vector<double>(v.data(), v.data() + v.size()); }
}  // namespace

Result Interpreter::version(CommandArgs& a) {
  a.expectEnd();
  return std::string(BEAMSOLID_VERSION);
}

// As OpenSees: a single process (getNP 1, getPID 0) and a barrier that has
// nobody to wait for, so parallel-aware scripts run unchanged.
Result Interpreter::getNP(CommandArgs& a) {
  a.expectEnd();
  return 1LL;
}

Result Interpreter::getPID(CommandArgs& a) {
  a.expectEnd();
  return 0LL;
}

Result Interpreter::barrier(CommandArgs& a) {
  a.expectEnd();
  return {};
}

// Elements read their nodes when they are made and after setNodeCoord
// (Domain::nodeMoved): there is nothing left to update.
Result Interpreter::updateElementDomain(CommandArgs& a) {
  a.expectEnd();
  return {};
}

Result Interpreter::start(CommandArgs& a) {
  a.expectEnd();
  timerStart_ = std::chrono::steady_clock::now();
  timerRunning_ = true;
  return {};
}

Result Interpreter::stop(CommandArgs& a) {
  a.expectEnd();
  if (!timerRunning_) a.fail("no timer running: call start() first");
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - timerStart_).count();
  std::cerr << "TIME(sec) Real: " << seconds << "\n";
  return {};
}

Result Interpreter::logFile(CommandArgs& a) {
  const std::string file = a.nextString("fileName");
  bool append = false, echo = true;
  while (!a.done()) {
    const std::string opt = a.nextString("option");
    if (opt == "-append") append = true;
    else if (opt == "-noEcho") echo = false;
    else a.fail("unknown option '" + opt + "' (expected -append or -noEcho)");
  }
  try {
    LogFile::open(file, append, echo);
  } catch (const OpenSeesError& e) {
    a.fail(e.what());
  }
  return {};
}

// defaultUnits('-force', f, '-length', l, '-time', t, <'-temp', T>): OpenSees
// (Tcl) defines unit variables from it; the Python command only checks the
// names and returns None, as OpenSeesPy's. Nothing is scaled: the model's
// numbers stay in whatever units the script uses.
Result Interpreter::defaultUnits(CommandArgs& a) {
  static const std::set<std::string> forces = {"lb", "lbs", "kip", "kips", "N", "kN", "kn", "MN", "kgf", "tonf"};
  static const std::set<std::string> lengths = {"in", "inch", "ft", "feet", "mm", "cm", "m"};
  static const std::set<std::string> times = {"sec", "Sec", "msec"};
  bool force = false, length = false, time = false;
  while (!a.done()) {
    std::string flag = a.nextString("unit flag ('-force', '-length', '-time' or '-temp')");
    std::transform(flag.begin(), flag.end(), flag.begin(), [](unsigned char c) { return std::tolower(c); });
    auto check = [&](const char* what, const std::set<std::string>& valid, const char* options) {
      const std::string unit = a.nextString(what);
      if (!valid.count(unit)) a.fail("unknown " + std::string(what) + " '" + unit + "', valid options: " + options);
    };
    if (flag == "-force") {
      check("force unit", forces, "lb, lbs, kip, kips, N, kN, MN, kgf, tonf");
      force = true;
    } else if (flag == "-length") {
      check("length unit", lengths, "in, inch, ft, feet, mm, cm, m");
      length = true;
    } else if (flag == "-time") {
      check("time unit", times, "sec, msec");
      time = true;
    } else if (flag == "-temp") a.nextString("temperature unit");
    else a.fail("unrecognized unit flag '" + flag + "' (expected -force, -length, -time or -temp)");
  }
  if (!force || !length || !time) a.fail("missing a unit type: defaultUnits('-force', f, '-length', l, '-time', t)");
  return {};
}

Result Interpreter::nodeBounds(CommandArgs& a) {
  a.expectEnd();
  if (domain_->nodes().empty()) a.fail("the model has no nodes");
  Vector3 lo = Vector3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& [tag, n] : domain_->nodes()) {
    lo = lo.cwiseMin(n->crd());
    hi = hi.cwiseMax(n->crd());
  }
  // OpenSees pads to 3D: [xmin, ymin, zmin, xmax, ymax, zmax].
  return std::vector<double>{lo.x(), lo.y(), lo.z(), hi.x(), hi.y(), hi.z()};
}

// OpenSees' numIter: the iterations the last step made (testIter reports
// one more when the step failed).
Result Interpreter::numIter(CommandArgs& a) {
  a.expectEnd();
  if (!components_.test) a.fail("no convergence test: call test(...) or analysis(...) first");
  return static_cast<long long>(components_.test->numIterations());
}

Result Interpreter::elementShortcut(CommandArgs& a, const char* command, const char* response) {
  const int tag = a.nextInt("eleTag");
  a.setContext(std::string(command) + " " + std::to_string(tag));
  a.expectEnd();
  Element& e = domain_->element(tag, a.context());
  Response r = e.setResponse({response});
  if (!r) a.fail("element " + e.className() + " " + std::to_string(tag) + " has no " + response);
  return toList(r.value());
}

Result Interpreter::basicForce(CommandArgs& a) { return elementShortcut(a, "basicForce", "basicForce"); }
Result Interpreter::basicDeformation(CommandArgs& a) {
  return elementShortcut(a, "basicDeformation", "basicDeformation");
}
Result Interpreter::basicStiffness(CommandArgs& a) { return elementShortcut(a, "basicStiffness", "basicStiffness"); }

// sectionForce(eleTag, secNum, <dof>) and its kin: the element's response
// 'section', secNum, what; one entry (1-based dof) or the list.
Result Interpreter::sectionQuery(CommandArgs& a, const char* command, const char* what) {
  const int tag = a.nextInt("eleTag");
  const int section = a.nextInt("secNum");
  a.setContext(std::string(command) + " " + std::to_string(tag));
  Element& e = domain_->element(tag, a.context());
  Response r = e.setResponse({"section", std::to_string(section), what});
  if (!r)
    a.fail("element " + e.className() + " " + std::to_string(tag) + " has no section " + std::to_string(section) +
           " with a " + what + " response");
  const Vector v = r.value();
  if (a.done()) return toList(v);
  const int dof = a.nextInt("dof");
  a.expectEnd();
  if (dof < 1 || dof > v.size())
    a.fail("dof " + std::to_string(dof) + " is out of range 1.." + std::to_string(v.size()));
  return v[dof - 1];
}

Result Interpreter::sectionForce(CommandArgs& a) { return sectionQuery(a, "sectionForce", "force"); }
Result Interpreter::sectionDeformation(CommandArgs& a) { return sectionQuery(a, "sectionDeformation", "deformation"); }
Result Interpreter::sectionStiffness(CommandArgs& a) { return sectionQuery(a, "sectionStiffness", "stiffness"); }
Result Interpreter::sectionFlexibility(CommandArgs& a) { return sectionQuery(a, "sectionFlexibility", "flexibility"); }

// sectionLocation / sectionWeight(eleTag, <secNum>): from the element's
// integrationPoints / integrationWeights.
Result Interpreter::integrationQuery(CommandArgs& a, const char* command, const char* what) {
  const int tag = a.nextInt("eleTag");
  a.setContext(std::string(command) + " " + std::to_string(tag));
  Element& e = domain_->element(tag, a.context());
  Response r = e.setResponse({what});
  if (!r) a.fail("element " + e.className() + " " + std::to_string(tag) + " has no " + what);
  const Vector v = r.value();
  if (a.done()) return toList(v);
  const int section = a.nextInt("secNum");
  a.expectEnd();
  if (section < 1 || section > v.size())
    a.fail("secNum " + std::to_string(section) + " is out of range 1.." + std::to_string(v.size()));
  return v[section - 1];
}

Result Interpreter::sectionLocation(CommandArgs& a) { return integrationQuery(a, "sectionLocation", "integrationPoints"); }
Result Interpreter::sectionWeight(CommandArgs& a) { return integrationQuery(a, "sectionWeight", "integrationWeights"); }

Result Interpreter::getFixedNodes(CommandArgs& a) {
  a.expectEnd();
  std::set<int> tags;
  for (const auto& sp : domain_->sps()) tags.insert(sp.nodeTag);
  return std::vector<int>(tags.begin(), tags.end());
}

Result Interpreter::getFixedDOFs(CommandArgs& a) {
  const int tag = a.nextInt("nodeTag");
  a.setContext("getFixedDOFs " + std::to_string(tag));
  a.expectEnd();
  domain_->node(tag, a.context());
  std::set<int> dofs;
  for (const auto& sp : domain_->sps())
    if (sp.nodeTag == tag) dofs.insert(sp.dof + 1);
  return std::vector<int>(dofs.begin(), dofs.end());
}

// getConstrainedNodes(<rNodeTag>), getRetainedNodes(<cNodeTag>): the nodes of
// the multi-point constraints (equalDOF, rigidLink, rigidDiaphragm).
Result Interpreter::mpNodes(CommandArgs& a, const char* command, bool constrained) {
  int other = 0;
  const bool filter = !a.done();
  if (filter) other = a.nextInt(constrained ? "rNodeTag" : "cNodeTag");
  a.setContext(command);
  a.expectEnd();
  std::set<int> tags;
  for (const auto& mp : domain_->mps()) {
    if (filter && (constrained ? mp.retainedNode : mp.constrainedNode) != other) continue;
    tags.insert(constrained ? mp.constrainedNode : mp.retainedNode);
  }
  return std::vector<int>(tags.begin(), tags.end());
}

Result Interpreter::getConstrainedNodes(CommandArgs& a) { return mpNodes(a, "getConstrainedNodes", true); }
Result Interpreter::getRetainedNodes(CommandArgs& a) { return mpNodes(a, "getRetainedNodes", false); }

// nodeResponse(nodeTag, dof, responseID), OpenSees' codes: 1 disp, 2 vel,
// 3 accel, 6 reaction, 7 unbalanced load.
Result Interpreter::nodeResponse(CommandArgs& a) {
  const int tag = a.nextInt("nodeTag");
  const int dof = a.nextInt("dof");
  const int id = a.nextInt("responseID");
  a.setContext("nodeResponse " + std::to_string(tag));
  a.expectEnd();
  const Node& n = domain_->node(tag, a.context());
  if (dof < 1 || dof > n.ndf()) a.fail("dof " + std::to_string(dof) + " is out of range 1.." + std::to_string(n.ndf()));
  switch (id) {
    case 1: return n.trialDisp()[dof - 1];
    case 2: return n.trialVel()[dof - 1];
    case 3: return n.trialAccel()[dof - 1];
    case 6: return n.reaction()[dof - 1];
    case 7: return n.unbalancedLoad()[dof - 1];
    default: a.fail("responseID " + std::to_string(id) + " is not one of 1 (disp), 2 (vel), 3 (accel), 6 (reaction), 7 (unbalance)");
  }
  return {};
}

// setNodeCoord(nodeTag, dim, value): moves an undeformed node; elements
// re-read their geometry, as after any model change.
Result Interpreter::setNodeCoord(CommandArgs& a) {
  const int tag = a.nextInt("nodeTag");
  const int dim = a.nextInt("dim");
  const double value = a.nextDouble("value");
  a.setContext("setNodeCoord " + std::to_string(tag));
  a.expectEnd();
  Node& n = domain_->node(tag, a.context());
  if (dim < 1 || dim > n.ndm()) a.fail("dim " + std::to_string(dim) + " is out of range 1.." + std::to_string(n.ndm()));
  const double old = n.crd()[dim - 1];
  n.setCoordinate(dim - 1, value);
  try {
    domain_->nodeMoved(tag, a.context());
  } catch (const OpenSeesError&) {
    n.setCoordinate(dim - 1, old);
    domain_->nodeMoved(tag, a.context());
    throw;
  }
  return {};
}

// setNodeDisp/Vel/Accel(nodeTag, dof, value, <'-commit'>).
Result Interpreter::setNodeState(CommandArgs& a, const char* command, int which) {
  const int tag = a.nextInt("nodeTag");
  const int dof = a.nextInt("dof");
  const double value = a.nextDouble("value");
  a.setContext(std::string(command) + " " + std::to_string(tag));
  bool commit = false;
  while (!a.done()) {
    const std::string opt = a.nextString("option");
    if (opt == "-commit") commit = true;
    else a.fail("unknown option '" + opt + "' (expected -commit)");
  }
  Node& n = domain_->node(tag, a.context());
  if (dof < 1 || dof > n.ndf()) a.fail("dof " + std::to_string(dof) + " is out of range 1.." + std::to_string(n.ndf()));
  Vector v = which == 0 ? n.trialDisp() : which == 1 ? n.trialVel() : n.trialAccel();
  v[dof - 1] = value;
  if (which == 0) n.setTrialDisp(v);
  else if (which == 1) n.setTrialVel(v);
  else n.setTrialAccel(v);
  if (commit) n.commitState();
  return {};
}

Result Interpreter::setNodeDisp(CommandArgs& a) { return setNodeState(a, "setNodeDisp", 0); }
Result Interpreter::setNodeVel(CommandArgs& a) { return setNodeState(a, "setNodeVel", 1); }
Result Interpreter::setNodeAccel(CommandArgs& a) { return setNodeState(a, "setNodeAccel", 2); }

// domainChange(): the next analyze sets the analysis up again.
Result Interpreter::domainChange(CommandArgs& a) {
  a.expectEnd();
  domain_->touch();
  return {};
}

}  // namespace beamsolid
