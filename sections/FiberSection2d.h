#pragma once
#include <memory>
#include <vector>

#include "materials/uniaxial/UniaxialMaterial.h"
#include "sections/FiberGeometry.h"
#include "sections/SectionForceDeformation2d.h"

namespace beamsolid {

class CommandArgs;
class Domain;

// section('Fiber', tag, <'-GJ', GJ>) in a 2D model: the fibers of the patch,
// layer and fiber commands with their z dropped (a 2D section bends about z
// only; '-GJ' is accepted and has nothing to act on). As OpenSees, the
// reference axis is the area centroid yBar of the fibers, so a fiber strains
// by eps - (y - yBar) kappa and a symmetric or unsymmetric section alike has
// no axial-flexural coupling while elastic and homogeneous. Order [P, Mz].
class FiberSection2d : public SectionForceDeformation2d {
 public:
  struct Fiber {
    std::unique_ptr<UniaxialMaterial> material;
    double y = 0.0, area = 0.0;
  };

  explicit FiberSection2d(int tag);
  FiberSection2d(const FiberSection2d& other);
  FiberSection2d& operator=(const FiberSection2d&) = delete;

  // Reads the options after the tag (2D model).
  static std::unique_ptr<FiberSection2d> build(CommandArgs& args, Domain& domain, int tag);

  std::string className() const override { return "Fiber"; }
  std::unique_ptr<SectionForceDeformation2d> clone() const override;
  const std::vector<SectionCode>& codes() const override;

  // A fiber with its own copy of `material`; throws for area <= 0.
  void addFiber(const UniaxialMaterial& material, double y, double area);
  // A patch's or layer's fibers at once: the centroid and sums are formed once.
  void addFibers(const UniaxialMaterial& material, const std::vector<FiberPoint>& points);
  std::size_t numFibers() const { return fibers_.size(); }
  const Fiber& fiber(std::size_t i) const { return fibers_.at(i); }
  double centroid() const { return yBar_; }
  // The fiber nearest to y, optionally of one material; -1 if none.
  int nearestFiber(double y, int materialTag = -1) const;

  void setTrialDeformation(const Vector& e) override;
  const Vector& deformation() const override { return deformation_; }
  const Vector& force() const override { return force_; }
  const Matrix& tangent() const override { return tangent_; }
  const Matrix& initialTangent() const override { return initialTangent_; }

  void commitState() override;
  void revertToLastCommit() override;
  void revertToStart() override;

  // Besides the base responses: 'fiber', y, z, <matTag>, *materialArgs (the
  // fiber nearest in y), 'fiber', index, *materialArgs (0-based), 'fiberData'
  // (y, 0, area, stress, strain of every fiber), 'numFibers'.
  Response setResponse(const std::vector<std::string>& args) override;
  void print(std::ostream& os) const override;

  // Materials' parameters reach every fiber whose material has the name;
  // geometric ones (geometryParameter) move and resize the fibers.
  bool setParameter(const std::vector<std::string>& args, double value) override;
  int sensitivityParameter(const std::vector<std::string>& args) override;
  // Materials' parts by their own sensitivities; a geometric parameter's by
  // central differences of the section at the trial deformation with the
  // history held (exact for the fiber layouts, which are linear in theta).
  Vector forceSensitivity(int gradient, int parameterId) override;
  void commitSensitivity(const Vector& deformationSensitivity, int gradient, int parameterId,
                         int numGradients) override;

 protected:
  // Geometric parameters of a section that lays out its own fibers (id > 0,
  // 0 if none of that name), their values, and the fibers at a new value.
  virtual int geometryParameter(const std::vector<std::string>&) const { return 0; }
  virtual double geometryValue(int) const { return 0.0; }
  virtual void setGeometry(int, double) {}
  // Moves fiber i (setGeometry); updateGeometry() then sums the section anew
  // without touching the fibers' states.
  void placeFiber(std::size_t i, double y, double area);
  void updateGeometry();

  // Sums over the fibers about y = 0, shifted to the centroid when read.
  struct Sums {
    double force = 0.0, firstMoment = 0.0;                 // sum sigma A, sum sigma A y
    double stiffness = 0.0, stiffY = 0.0, stiffYY = 0.0;   // sum E A, sum E A y, sum E A y^2
  };
  void fromSums(const Sums& current, const Sums& initial);

 private:
  void sumFibers();
  // The state about the (new) centroid after fibers were added.
  void refresh();
  bool deferred_ = false;
  // (y - yBar) of every fiber with geometry parameter `id` at `value`.
  std::vector<double> offsetsAt(int id, double value);
  // Sensitivity parameters: what names them, the geometric id (0 for a
  // material's), each fiber material's id.
  struct SensitivityBinding {
    std::vector<std::string> args;
    int geometry = 0;
    std::vector<int> fiberIds;
  };
  std::vector<SensitivityBinding> sensitivity_;

  std::vector<Fiber> fibers_;
  double area_ = 0.0, areaY_ = 0.0, yBar_ = 0.0;
  Sums initialSums_;

  Vector deformation_ = Vector::Zero(2);
  Vector committedDeformation_ = Vector::Zero(2);
  Vector force_ = Vector::Zero(2);
  Matrix tangent_ = Matrix::Zero(2, 2);
  Matrix initialTangent_ = Matrix::Zero(2, 2);
};

}  // namespace beamsolid
