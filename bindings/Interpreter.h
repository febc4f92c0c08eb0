#pragma once
#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "analysis/StaticAnalysis.h"
#include "analysis/TransientAnalysis.h"
#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "materials/uniaxial/UniaxialMaterial.h"

namespace beamsolid {

// The command interpreter behind beamsolid.opensees and beamsolid.Model:
// one method per OpenSeesPy command, each reading its CommandArgs and
// returning what OpenSeesPy returns (None, int, float, list or str).
class Interpreter {
 public:
  using Result = std::variant<std::monostate, long long, double, std::string, std::vector<double>, std::vector<int>,
                              std::map<std::string, std::vector<double>>>;
  using Command = Result (Interpreter::*)(CommandArgs&);

  Interpreter();
  ~Interpreter();

  // Runs one command; every failure is an OpenSeesError naming the command.
  Result call(const std::string& name, std::vector<CommandArgs::Value> args);
  // The command `name` (nullptr if there is none), so that a caller that runs
  // it many times looks it up once (beamsolid.opensees's functions).
  static const Command* find(const std::string& name);
  Result call(const Command& command, const std::string& name, std::vector<CommandArgs::Value> args);
  static std::vector<std::string> commandNames();

  Domain& domain() { return *domain_; }
  // Closes recorders (flushing them); used at interpreter exit.
  void closeRecorders() { domain_->removeRecorders(); }
  // Why the most recent analyze returned a negative code; empty after one that succeeded.
  const std::string& lastError() const { return lastError_; }
  // The linear system of the current analysis: what the user asked for, what
  // runs, and the condensation (see analysis/CondensedSolver.h).
  struct SolverInfo {
    std::string system, backend, note;
    bool condensed = false;
    int equations = 0, interior = 0, interface = 0, condensations = 0, condensationsReused = 0, factorizations = 0,
        analyses = 0;
    int interfaceFactorizations = 0;
    long krylovIterations = 0;
    double condenseSeconds = 0.0, interfaceFactorSeconds = 0.0, interfaceSolveSeconds = 0.0;
    double solverSeconds = 0.0;
  };
  SolverInfo solverInfo() const;

 private:
  static const std::map<std::string, Command>& commands();

  // --- model building (InterpreterModel.cpp) ---
  Result wipe(CommandArgs&);
  Result model(CommandArgs&);
  Result node(CommandArgs&);
  Result fix(CommandArgs&);
  Result fixX(CommandArgs&);
  Result fixY(CommandArgs&);
  Result fixZ(CommandArgs&);
  Result fixCoordinate(CommandArgs&, int axis);
  Result equalDOF(CommandArgs&);
  Result rigidLink(CommandArgs&);
  Result rigidDiaphragm(CommandArgs&);
  Result mass(CommandArgs&);
  Result uniaxialMaterial(CommandArgs&);
  Result nDMaterial(CommandArgs&);
  Result geomTransf(CommandArgs&);
  Result element(CommandArgs&);
  Result block2D(CommandArgs&);
  Result block3D(CommandArgs&);
  Result timeSeries(CommandArgs&);
  Result pattern(CommandArgs&);
  Result groundMotion(CommandArgs&);
  Result imposedMotion(CommandArgs&);
  Result load(CommandArgs&);
  Result sp(CommandArgs&);
  Result eleLoad(CommandArgs&);
  Result loadConst(CommandArgs&);
  Result setTime(CommandArgs&);
  Result getTime(CommandArgs&);
  Result remove(CommandArgs&);
  Result recorder(CommandArgs&);
  Result record(CommandArgs&);
  Result loadPlugin(CommandArgs&);
  Result setParameter(CommandArgs&);
  Result updateMaterialStage(CommandArgs&);
  Result initialStateAnalysis(CommandArgs&);

  // --- sections and beam integration (InterpreterSections.cpp) ---
  Result section(CommandArgs&);
  Result patch(CommandArgs&);
  Result layer(CommandArgs&);
  Result fiber(CommandArgs&);
  Result beamIntegration(CommandArgs&);

  // --- analysis (InterpreterAnalysis.cpp) ---
  Result constraints(CommandArgs&);
  Result numberer(CommandArgs&);
  Result system(CommandArgs&);
  Result test(CommandArgs&);
  Result algorithm(CommandArgs&);
  Result integrator(CommandArgs&);
  Result analysis(CommandArgs&);
  Result analyze(CommandArgs&);
  Result wipeAnalysis(CommandArgs&);
  Result eigen(CommandArgs&);
  Result modalProperties(CommandArgs&);
  Result responseSpectrumAnalysis(CommandArgs&);
  Result printA(CommandArgs&);
  Result printB(CommandArgs&);
  Result testIter(CommandArgs&);
  Result testNorm(CommandArgs&);
  Result systemSize(CommandArgs&);
  Result reactions(CommandArgs&);
  Result rayleigh(CommandArgs&);
  Result region(CommandArgs&);
  Result modalDamping(CommandArgs&);

  // --- queries (InterpreterQueries.cpp) ---
  Result nodeDisp(CommandArgs&);
  Result nodeVel(CommandArgs&);
  Result nodeAccel(CommandArgs&);
  Result nodeCoord(CommandArgs&);
  Result nodeReaction(CommandArgs&);
  Result nodeUnbalance(CommandArgs&);
  Result nodeMass(CommandArgs&);
  Result nodeEigenvector(CommandArgs&);
  Result nodeDOFs(CommandArgs&);
  Result getNDF(CommandArgs&);
  Result eleResponse(CommandArgs&);
  Result eleForce(CommandArgs&);
  Result eleDynamicalForce(CommandArgs&);
  Result eleNodes(CommandArgs&);
  Result eleType(CommandArgs&);
  Result getNodeTags(CommandArgs&);
  Result getEleTags(CommandArgs&);
  Result getLoadFactor(CommandArgs&);
  Result printModel(CommandArgs&);
  Result getEigenvalues(CommandArgs&);

  // --- small commands of OpenSeesPy scripts (InterpreterUtilities.cpp) ---
  Result version(CommandArgs&);
  Result getNP(CommandArgs&);
  Result getPID(CommandArgs&);
  Result barrier(CommandArgs&);
  Result updateElementDomain(CommandArgs&);
  Result start(CommandArgs&);
  Result stop(CommandArgs&);
  Result logFile(CommandArgs&);
  Result defaultUnits(CommandArgs&);
  Result nodeBounds(CommandArgs&);
  Result numIter(CommandArgs&);
  Result basicForce(CommandArgs&);
  Result basicDeformation(CommandArgs&);
  Result basicStiffness(CommandArgs&);
  Result sectionForce(CommandArgs&);
  Result sectionDeformation(CommandArgs&);
  Result sectionStiffness(CommandArgs&);
  Result sectionFlexibility(CommandArgs&);
  Result sectionLocation(CommandArgs&);
  Result sectionWeight(CommandArgs&);
  Result getFixedNodes(CommandArgs&);
  Result getFixedDOFs(CommandArgs&);
  Result getConstrainedNodes(CommandArgs&);
  Result getRetainedNodes(CommandArgs&);
  Result nodeResponse(CommandArgs&);
  Result setNodeCoord(CommandArgs&);
  Result setNodeDisp(CommandArgs&);
  Result setNodeVel(CommandArgs&);
  Result setNodeAccel(CommandArgs&);
  Result domainChange(CommandArgs&);
  Result elementShortcut(CommandArgs&, const char* command, const char* response);
  Result sectionQuery(CommandArgs&, const char* command, const char* what);
  Result integrationQuery(CommandArgs&, const char* command, const char* what);
  Result mpNodes(CommandArgs&, const char* command, bool constrained);
  Result setNodeState(CommandArgs&, const char* command, int which);

  // --- queries and commands of scripts and post-processors (InterpreterScripting.cpp) ---
  Result getNDM(CommandArgs&);
  Result getNumElements(CommandArgs&);
  Result getCrdTransfTags(CommandArgs&);
  Result getPatterns(CommandArgs&);
  Result getNodeLoadTags(CommandArgs&);
  Result getNodeLoadData(CommandArgs&);
  Result getEleLoadTags(CommandArgs&);
  Result getEleLoadData(CommandArgs&);
  Result getEleLoadClassTags(CommandArgs&);
  Result getEleClassTags(CommandArgs&);
  Result classType(CommandArgs&);
  Result getConstrainedDOFs(CommandArgs&);
  Result getRetainedDOFs(CommandArgs&);
  Result setPrecision(CommandArgs&);
  Result setStartNodeTag(CommandArgs&);
  Result setNumThreads(CommandArgs&);
  Result getNumThreads(CommandArgs&);
  Result numFact(CommandArgs&);
  Result totalCPU(CommandArgs&);
  Result solveCPU(CommandArgs&);
  Result accelCPU(CommandArgs&);
  Result reset(CommandArgs&);
  Result parameter(CommandArgs&);
  Result addToParameter(CommandArgs&);
  Result updateParameter(CommandArgs&);
  Result getParamTags(CommandArgs&);
  Result getParamValue(CommandArgs&);
  Result sensitivityAlgorithm(CommandArgs&);
  Result computeGradients(CommandArgs&);
  Result sensNodeDisp(CommandArgs&);
  Result sensLambda(CommandArgs&);
  Result setElementRayleighDampingFactors(CommandArgs&);
  std::vector<const LoadPattern*> loadPatterns(CommandArgs&, const char* command);
  Result mpDofs(CommandArgs&, const char* command, bool constrained);
  Result algorithmCounter(CommandArgs&, const char* command);
  Result parameterCommand(CommandArgs&, const char* command, bool add);

  // --- driving one uniaxial material (InterpreterMaterials.cpp) ---
  Result testUniaxialMaterial(CommandArgs&);
  Result setStrain(CommandArgs&);
  Result getStrain(CommandArgs&);
  Result getStress(CommandArgs&);
  Result getTangent(CommandArgs&);

  // Helpers
  Result nodeVectorQuery(CommandArgs&, const char* what, const Vector& (Node::*get)() const);
  void requireModel(CommandArgs& a) const;
  LoadPattern& currentPattern(CommandArgs& a) const;
  Result uniformExcitation(CommandArgs& a);
  void ensureAnalysisDefaults();

  std::unique_ptr<Domain> domain_;
  int currentPatternTag_ = -1;
  // patch, layer and fiber add to the most recent section.
  int currentSectionTag_ = -1;
  bool haveAnalysis_ = false;
  AnalysisComponents components_;
  std::unique_ptr<Analysis> analysis_;
  std::string lastError_;
  std::chrono::steady_clock::time_point timerStart_;
  bool timerRunning_ = false;
  bool extraMassWarned_ = false;  // mass values beyond a node's ndf, said once until wipe
  std::vector<double> eigenvalues_;
  // modalProperties has run since the last eigen (responseSpectrumAnalysis needs it, as OpenSees).
  bool haveModalProperties_ = false;
  // setNumThreads; 0 until set (getNumThreads then reports the cores).
  int numThreads_ = 0;
  // parameter(...): each maps one value onto objects' arguments.
  ParameterMap parameters_;
  // The last sensitivities (sensitivityAlgorithm); kept past wipeAnalysis.
  SensitivityResults sensitivityResults_;
  // A copy of the material under testUniaxialMaterial; setStrain commits it.
  std::unique_ptr<UniaxialMaterial> testMaterial_;
};

}  // namespace beamsolid
