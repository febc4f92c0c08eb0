#pragma once
#include "sections/SectionForceDeformation2d.h"

namespace beamsolid {

class CommandArgs;
class Domain;

// section('Elastic', tag, E, A, Iz, <G, alphaY>) in a 2D model: linear,
// ks = diag(EA, EIz) about the centroid, or with a shear modulus G and
// shear shape factor alphaY a third component Vy with stiffness alphaY G A.
class ElasticSection2d : public SectionForceDeformation2d {
 public:
  struct Properties {
    double E = 0.0, A = 0.0, Iz = 0.0;
    double G = 0.0, alphaY = 0.0;  // shear: only when G > 0
  };

  ElasticSection2d(int tag, const Properties& properties);
  // Reads E, A, Iz, <G, alphaY> after the tag (2D model).
  static std::unique_ptr<ElasticSection2d> build(CommandArgs& args, int tag);

  std::string className() const override { return "Elastic"; }
  std::unique_ptr<SectionForceDeformation2d> clone() const override;
  const std::vector<SectionCode>& codes() const override { return codes_; }

  void setTrialDeformation(const Vector& e) override;
  const Vector& deformation() const override { return deformation_; }
  const Vector& force() const override { return force_; }
  const Matrix& tangent() const override { return stiffness_; }
  const Matrix& initialTangent() const override { return stiffness_; }

  void commitState() override { committedDeformation_ = deformation_; }
  void revertToLastCommit() override { setTrialDeformation(committedDeformation_); }
  void revertToStart() override;

  void print(std::ostream& os) const override;
  const Properties& properties() const { return properties_; }

  // 'E', 'A', 'Iz' (or 'I'), and with shear 'G', 'alphaY'; no history.
  bool setParameter(const std::vector<std::string>& args, double value) override;
  int sensitivityParameter(const std::vector<std::string>& args) override;
  Vector forceSensitivity(int gradient, int parameterId) override;
  void commitSensitivity(const Vector&, int, int, int) override {}

 private:
  Matrix stiffnessOf(const Properties& p) const;
  Properties properties_;
  std::vector<SectionCode> codes_;
  Matrix stiffness_;
  Vector deformation_, force_, committedDeformation_;
};

}  // namespace beamsolid
