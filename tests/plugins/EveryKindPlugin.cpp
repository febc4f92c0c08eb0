// A test plugin that registers one type of every kind a script builds by
// name: element, uniaxialMaterial, nDMaterial, section, timeSeries, recorder.
// Its element is a cubic spring N = k d + c d^3 whose tangent is right
// ('PluginCubicSpring') or misses the 3 c d^2 term ('PluginWrongSpring'), for
// beamsolid.testing.check_tangent.
#include <fstream>
#include <memory>

#include "core/CommandArgs.h"
#include "core/Domain.h"
#include "core/PluginAbi.h"
#include "core/Recorder.h"
#include "core/Registry.h"
#include "core/TimeSeries.h"
#include "elements/Element.h"
#include "materials/nd/ElasticIsotropic3D.h"
#include "materials/uniaxial/ElasticMaterial.h"
#include "sections/ElasticSection3d.h"

namespace {

using namespace beamsolid;

// Along x between two ndf-3 nodes.
class CubicSpring : public Element {
 public:
  CubicSpring(int tag, int i, int j, double k, double c, bool wrongTangent)
      : Element(tag, {i, j}), k_(k), c_(c), wrongTangent_(wrongTangent) {}
  std::string className() const override { return wrongTangent_ ? "PluginWrongSpring" : "PluginCubicSpring"; }
  void setDomain(Domain&) override {
    for (Node* n : nodes())
      if (n->ndf() != 3) throw OpenSeesError(context() + ": nodes must have ndf 3");
  }
  void update() override { d_ = nodes()[1]->trialDisp()[0] - nodes()[0]->trialDisp()[0]; }
  MatrixView tangentStiff() override {
    const double kt = wrongTangent_ ? k_ : k_ + 3.0 * c_ * d_ * d_;
    K_.setZero();
    K_(0, 0) = K_(3, 3) = kt;
    K_(0, 3) = K_(3, 0) = -kt;
    return viewOf(K_);
  }
  MatrixView initialStiff() override {
    K_.setZero();
    K_(0, 0) = K_(3, 3) = k_;
    K_(0, 3) = K_(3, 0) = -k_;
    return viewOf(K_);
  }
  VectorView resistingForce() override {
    const double N = k_ * d_ + c_ * d_ * d_ * d_;
    f_.setZero();
    f_(0) = -N;
    f_(3) = N;
    return viewOf(f_);
  }
  Response setResponse(const std::vector<std::string>& args) override {
    if (!args.empty() && args[0] == "axialForce")
      return {{"N"}, [this] { return Vector::Constant(1, k_ * d_ + c_ * d_ * d_ * d_); }};
    return {};
  }

 private:
  double k_, c_, d_ = 0.0;
  bool wrongTangent_;
  Eigen::Matrix<double, 6, 6> K_;
  Eigen::Matrix<double, 6, 1> f_;
};

// factor(t) = rate * t.
class RampSeries : public TimeSeries {
 public:
  RampSeries(int tag, double rate) : TimeSeries(tag), rate_(rate) {}
  std::string className() const override { return "PluginRamp"; }
  double factor(double time) const override { return rate_ * time; }
  double slope(double) const override { return rate_; }

 private:
  double rate_;
};

// Writes the number of records so far, one line per record.
class CountingRecorder : public Recorder {
 public:
  explicit CountingRecorder(const std::string& path) : out_(path) {
    if (!out_) throw OpenSeesError("recorder PluginCounter: cannot open '" + path + "'");
  }
  std::string className() const override { return "PluginCounter"; }
  void record(Domain&, double time) override { out_ << ++count_ << ' ' << time << '\n'; }
  void flush() override { out_.flush(); }
  void close() override { out_.close(); }

 private:
  std::ofstream out_;
  int count_ = 0;
};

std::unique_ptr<Element> buildSpring(CommandArgs& a, bool wrong) {
  const int tag = a.nextInt("eleTag"), i = a.nextInt("iNode"), j = a.nextInt("jNode");
  const double k = a.nextDouble("k"), c = a.nextDouble("c");
  a.expectEnd();
  return std::make_unique<CubicSpring>(tag, i, j, k, c, wrong);
}

}  // namespace

BEAMSOLID_PLUGIN_REGISTER(r) {
  r.elements.add("PluginCubicSpring", [](CommandArgs& a, Domain&) { return buildSpring(a, false); });
  r.elements.add("PluginWrongSpring", [](CommandArgs& a, Domain&) { return buildSpring(a, true); });
  r.uniaxialMaterials.add("PluginElastic", [](CommandArgs& a, Domain&) -> std::unique_ptr<UniaxialMaterial> {
    const int tag = a.nextInt("matTag");
    const double E = a.nextDouble("E");
    a.expectEnd();
    return std::make_unique<ElasticMaterial>(tag, E, 0.0, E);
  });
  r.ndMaterials.add("PluginElasticIsotropic", [](CommandArgs& a, Domain&) -> std::unique_ptr<NDMaterial> {
    const int tag = a.nextInt("matTag");
    const double E = a.nextDouble("E"), nu = a.nextDouble("nu");
    a.expectEnd();
    return std::make_unique<ElasticIsotropic3D>(tag, E, nu, 0.0);
  });
  r.sections.add("PluginElastic", [](CommandArgs& a, Domain&) -> std::unique_ptr<SectionForceDeformation> {
    const int tag = a.nextInt("secTag");
    ElasticSection3d::Properties p;
    p.E = a.nextDouble("E");
    p.A = a.nextDouble("A");
    p.Iz = a.nextDouble("Iz");
    p.Iy = a.nextDouble("Iy");
    p.G = a.nextDouble("G");
    p.J = a.nextDouble("J");
    a.expectEnd();
    return std::make_unique<ElasticSection3d>(tag, p);
  });
  r.timeSeries.add("PluginRamp", [](CommandArgs& a, Domain&) -> std::unique_ptr<TimeSeries> {
    const int tag = a.nextInt("tag");
    const double rate = a.nextDouble("rate");
    a.expectEnd();
    return std::make_unique<RampSeries>(tag, rate);
  });
  r.recorders.add("PluginCounter", [](CommandArgs& a, Domain&) -> std::unique_ptr<Recorder> {
    const std::string path = a.nextString("file");
    a.expectEnd();
    return std::make_unique<CountingRecorder>(path);
  });
}
