// 2D sections (ElasticSection2d, FiberSection2d, WFSection2d,
// SectionAggregator2d/3d), the 2D beam-columns (ForceBeamColumn2d,
// DispBeamColumn2d) and ZeroLengthSection: section tangents and element
// tangents against central differences, the fiber section's centroid, copies
// and commit/revert, the force-based element's exact elastic flexibility,
// and the errors for sections of the wrong space.
#include <gtest/gtest.h>

#include <cmath>

#include "core/Node.h"
#include "core/OpenSeesError.h"
#include "elements/DispBeamColumn2d.h"
#include "elements/ForceBeamColumn2d.h"
#include "elements/ZeroLengthSection.h"
#include "elements/TangentCheck.h"
#include "sections/ElasticSection2d.h"
#include "sections/FiberSection2d.h"
#include "sections/SectionAggregator2d.h"
#include "sections/SectionAggregator3d.h"
#include "support/Script.h"

namespace beamcolumns2dtest {

using beamsolid::BeamSection;
using beamsolid::Element;
using beamsolid::FiberSection2d;
using beamsolid::Node;
using beamsolid::OpenSeesError;
using beamsolid::SectionBeamColumn2d;
using beamsolid::SectionForceDeformation;
using beamsolid::SectionForceDeformation2d;
using beamsolid::TangentCheck;
using beamsolid::Vector;
using beamsolid::testing::Script;
using SVector = SectionForceDeformation2d::Vector;
using SMatrix = SectionForceDeformation2d::Matrix;

BeamSection& sectionOf(Script& s, int tag) { return s.interp.domain().sections.get(tag, "test"); }

SMatrix finiteDifferenceTangent(SectionForceDeformation2d& section, const SVector& e, double h) {
  const int n = section.order();
  SMatrix k(n, n);
  for (int j = 0; j < n; ++j) {
    SVector ep = e, em = e;
    ep[j] += h;
    em[j] -= h;
    section.setTrialDeformation(ep);
    const SVector fp = section.force();
    section.setTrialDeformation(em);
    const SVector fm = section.force();
    k.col(j) = (fp - fm) / (2.0 * h);
  }
  section.setTrialDeformation(e);
  return k;
}

void model2d(Script& s) { s("model", "basic", "-ndm", 2, "-ndf", 3); }

// A T-shaped steel section (unsymmetric in y) with an extra elastic bar.
void teeSection(Script& s, int tag) {
  s("uniaxialMaterial", "Steel01", 1, 50.0, 29000.0, 0.02);
  s("uniaxialMaterial", "Elastic", 2, 29000.0);
  s("section", "Fiber", tag);
  s("patch", "rect", 1, 4, 1, 10.0, -4.0, 12.0, 4.0);
  s("patch", "rect", 1, 20, 1, 0.0, -0.5, 10.0, 0.5);
  s("fiber", 1.0, 0.0, 0.5, 2);
}

TEST(FiberSection2d, CentroidIsTheReferenceAxis) {
  Script s;
  model2d(s);
  teeSection(s, 1);
  auto& sec = dynamic_cast<FiberSection2d&>(sectionOf(s, 1));
  // Area-weighted centroid: flange 16 at y = 11, web 10 at y = 5, bar 0.5 at y = 1.
  const double yBar = (16.0 * 11.0 + 10.0 * 5.0 + 0.5 * 1.0) / 26.5;
  EXPECT_NEAR(sec.centroid(), yBar, 1e-14 * yBar);
  // Homogeneous and elastic: no axial-flexural coupling about the centroid.
  EXPECT_LT(std::fabs(sec.initialTangent()(0, 1)), 1e-9 * sec.initialTangent()(0, 0));
  EXPECT_NEAR(sec.initialTangent()(0, 0), 29000.0 * 26.5, 1e-12 * 29000.0 * 26.5);
  // A pure axial strain gives no moment.
  SVector e(2);
  e << 1e-4, 0.0;
  sec.setTrialDeformation(e);
  EXPECT_NEAR(sec.force()[0], 29000.0 * 26.5 * 1e-4, 1e-9);
  EXPECT_LT(std::fabs(sec.force()[1]), 1e-9);
}

TEST(FiberSection2d, TangentMatchesFiniteDifferencesWhenYielded) {
  Script s;
  model2d(s);
  teeSection(s, 1);
  auto& sec = dynamic_cast<FiberSection2d&>(sectionOf(s, 1));
  SVector e(2);
  e << 4e-4, 3e-4;  // the bottom of the web yields in tension
  sec.setTrialDeformation(e);
  const SMatrix k = sec.tangent();
  EXPECT_LT(k(0, 0), sec.initialTangent()(0, 0) * 0.9);
  const SMatrix fd = finiteDifferenceTangent(sec, e, 1e-9);
  EXPECT_LT((k - fd).norm(), 1e-5 * k.norm()) << k << "\n" << fd;
}

TEST(FiberSection2d, CopiesAndCommitRevertAreIndependent) {
  Script s;
  model2d(s);
  teeSection(s, 1);
  auto& prototype = dynamic_cast<FiberSection2d&>(sectionOf(s, 1));
  auto copy = prototype.clone();
  SVector e(2);
  e << 0.0, 1e-3;
  copy->setTrialDeformation(e);
  copy->commitState();
  const SVector committed = copy->force();
  EXPECT_EQ(prototype.force().norm(), 0.0);
  SVector further(2);
  further << 2e-3, -2e-3;
  copy->setTrialDeformation(further);
  copy->revertToLastCommit();
  EXPECT_LT((copy->force() - committed).norm(), 1e-12 * committed.norm());
  copy->revertToStart();
  EXPECT_EQ(copy->force().norm(), 0.0);
}

TEST(ElasticSection2d, DiagonalStiffnessWithAndWithoutShear) {
  Script s;
  model2d(s);
  s("section", "Elastic", 1, 200.0, 3.0, 5.0);
  s("section", "Elastic", 2, 200.0, 3.0, 5.0, 80.0, 0.5);
  auto& plain = dynamic_cast<SectionForceDeformation2d&>(sectionOf(s, 1));
  auto& shear = dynamic_cast<SectionForceDeformation2d&>(sectionOf(s, 2));
  ASSERT_EQ(plain.order(), 2);
  ASSERT_EQ(shear.order(), 3);
  SVector e(3);
  e << 1e-3, -2e-3, 4e-3;
  shear.setTrialDeformation(e);
  EXPECT_DOUBLE_EQ(shear.force()[0], 600.0 * 1e-3);
  EXPECT_DOUBLE_EQ(shear.force()[1], 1000.0 * -2e-3);
  EXPECT_DOUBLE_EQ(shear.force()[2], 0.5 * 80.0 * 3.0 * 4e-3);  // alphaY G A gamma
  EXPECT_THROW(s("section", "Elastic", 3, 200.0, 3.0, 5.0, 80.0), OpenSeesError);
  EXPECT_THROW(s("section", "Elastic", 4, 200.0, -3.0, 5.0), OpenSeesError);
}

TEST(WFSection2d, FibersAreMidHeightStrips) {
  Script s;
  model2d(s);
  s("uniaxialMaterial", "Elastic", 1, 1.0);
  s("section", "WFSection2d", 1, 1, 12.0, 0.5, 8.0, 1.0, 5, 4);
  auto& wf = dynamic_cast<FiberSection2d&>(sectionOf(s, 1));
  ASSERT_EQ(wf.numFibers(), 4u + 5u + 4u);
  EXPECT_EQ(wf.className(), "WFSection2d");
  // Exact area; the midpoint strips give I = sum of strip I's about their own
  // centroids missing: I_exact - sum(b t^3 / 12) per strip.
  const double area = 2 * 8.0 * 1.0 + 0.5 * 10.0;
  EXPECT_NEAR(wf.initialTangent()(0, 0), area, 1e-12 * area);
  const double exact = 8.0 * (std::pow(12.0, 3) - std::pow(10.0, 3)) / 12.0 + 0.5 * std::pow(10.0, 3) / 12.0;
  const double stripsOwn = 2 * 4 * 8.0 * std::pow(0.25, 3) / 12.0 + 5 * 0.5 * std::pow(2.0, 3) / 12.0;
  EXPECT_NEAR(wf.initialTangent()(1, 1), exact - stripsOwn, 1e-12 * exact);
  EXPECT_NEAR(wf.centroid(), 0.0, 1e-14);
}

TEST(SectionAggregator2d, AppendsMaterialsAfterTheSection) {
  Script s;
  model2d(s);
  teeSection(s, 1);
  s("uniaxialMaterial", "Elastic", 5, 123.0);
  s("section", "Aggregator", 2, 5, "Vy", "-section", 1);
  auto& agg = dynamic_cast<SectionForceDeformation2d&>(sectionOf(s, 2));
  ASSERT_EQ(agg.order(), 3);
  EXPECT_EQ(agg.codes()[2], beamsolid::SectionCode::Vy);
  SVector e(3);
  e << 3e-4, 2e-4, 0.01;
  agg.setTrialDeformation(e);
  EXPECT_NEAR(agg.force()[2], 1.23, 1e-14);
  const SMatrix fd = finiteDifferenceTangent(agg, e, 1e-9);
  EXPECT_LT((agg.tangent() - fd).norm(), 1e-5 * agg.tangent().norm());
}

TEST(SectionAggregator3d, MaterialTakesOverTheTorsion) {
  Script s;
  s("model", "basic", "-ndm", 3, "-ndf", 6);
  s("uniaxialMaterial", "Elastic", 1, 29000.0);
  s("uniaxialMaterial", "Steel01", 2, 10.0, 1000.0, 0.1);
  s("section", "Fiber", 1, "-GJ", 5.0e4);
  s("patch", "rect", 1, 4, 4, -2.0, -1.0, 2.0, 1.0);
  s("section", "Aggregator", 2, 2, "T", "-section", 1);
  auto& agg = dynamic_cast<SectionForceDeformation&>(sectionOf(s, 2));
  SectionForceDeformation::Vector4 e(1e-4, 2e-4, -1e-4, 0.02);
  agg.setTrialDeformation(e);
  // Torque from Steel01: yield at 10 (strain 0.01), then 10 + 100 * 0.01.
  EXPECT_NEAR(agg.force()[3], 11.0, 1e-12);
  EXPECT_NEAR(agg.tangent()(3, 3), 100.0, 1e-12);
  auto& fiber = dynamic_cast<SectionForceDeformation&>(sectionOf(s, 1));
  fiber.setTrialDeformation(e);
  EXPECT_LT((agg.force().head<3>() - fiber.force().head<3>()).norm(), 1e-12 * fiber.force().norm());
}

// A 2D column, node 1 fixed, node 2 free, of `type` with the tee section.
Element& teeColumn(Script& s, const char* type, const char* transf) {
  model2d(s);
  teeSection(s, 1);
  s("node", 1, 0.0, 0.0);
  s("node", 2, 30.0, 80.0);
  s("fix", 1, 1, 1, 1);
  s("geomTransf", transf, 1);
  s("beamIntegration", "Lobatto", 1, 1, 5);
  if (std::string(type) == "forceBeamColumn") s("element", type, 1, 1, 2, 1, 1, "-iter", 50, 1e-26);
  else s("element", type, 1, 1, 2, 1, 1);
  return s.interp.domain().element(1, "test");
}

TEST(BeamColumns2d, TangentMatchesFiniteDifferencesInAPlasticState) {
  for (const char* type : {"forceBeamColumn", "dispBeamColumn"})
    // Linear only: the PDelta transformation's tangent leaves out the change of
    // the chord shear N dv/L with N (as OpenSees), so it is no exact derivative.
    for (const char* transf : {"Linear"}) {
      Script s;
      auto& e = dynamic_cast<SectionBeamColumn2d&>(teeColumn(s, type, transf));
      Node& n2 = s.interp.domain().node(2, "test");
      Vector u(3);
      u << 0.3, -0.05, 0.012;
      n2.setTrialDisp(u);
      e.update();
      e.commitState();
      n2.commitState();
      n2.setTrialDisp(1.4 * u);
      e.update();
      EXPECT_GT(e.plasticDeformation().norm(), 1e-4) << type << ": the state should be plastic";
      const TangentCheck check = TangentCheck::of(e, 1e-7);
      const double scale = check.tangent.norm();
      EXPECT_LT((check.tangent - check.difference).norm(), 1e-5 * scale) << type << ' ' << transf;
    }
}

TEST(BeamColumns2d, ForceBasedJumpReachesTheStateOfSmallSteps) {
  // One jump far into the plastic range with few element iterations against
  // the same monotonic path in 40 committed steps.
  auto build = [](Script& s) -> beamsolid::ForceBeamColumn2d& {
    model2d(s);
    s("uniaxialMaterial", "ElasticPP", 1, 29000.0, 50.0 / 29000.0);
    s("section", "Fiber", 1);
    s("patch", "rect", 1, 20, 1, -5.0, -2.0, 5.0, 2.0);
    s("node", 1, 0.0, 0.0);
    s("node", 2, 0.0, 100.0);
    s("geomTransf", "Linear", 1);
    s("beamIntegration", "Lobatto", 1, 1, 5);
    s("element", "forceBeamColumn", 1, 1, 2, 1, 1, "-iter", 4, 1e-20);
    return dynamic_cast<beamsolid::ForceBeamColumn2d&>(s.interp.domain().element(1, "test"));
  };
  Vector u(3);
  u << 2.0, -0.01, -0.03;
  Script jump, steps;
  auto& a = build(jump);
  jump.interp.domain().node(2, "test").setTrialDisp(u);
  a.update();
  EXPECT_TRUE(a.converged());
  EXPECT_GE(a.lastIterations(), 2);
  auto& b = build(steps);
  Node& n = steps.interp.domain().node(2, "test");
  for (int k = 1; k <= 40; ++k) {
    n.setTrialDisp(u * (k / 40.0));
    b.update();
    ASSERT_TRUE(b.converged()) << k;
    b.commitState();
    n.commitState();
  }
  const auto qa = a.basicForce(), qb = b.basicForce();
  EXPECT_LT((qa - qb).norm(), 1e-8 * qb.norm()) << qa.transpose() << " / " << qb.transpose();
  EXPECT_GT(b.plasticDeformation().norm(), 1e-3);
}

TEST(BeamColumns2d, ElasticForceBasedMatchesTheClosedFormStiffness) {
  Script s;
  model2d(s);
  s("section", "Elastic", 1, 200.0, 3.0, 5.0);
  s("node", 1, 0.0, 0.0);
  s("node", 2, 4.0, 3.0);
  s("geomTransf", "Linear", 1);
  s("beamIntegration", "Legendre", 1, 1, 2);
  s("element", "forceBeamColumn", 1, 1, 2, 1, 1);
  s("element", "dispBeamColumn", 2, 1, 2, 1, 1);
  s("element", "elasticBeamColumn", 3, 1, 2, 3.0, 200.0, 5.0, 1);
  Element& elastic = s.interp.domain().element(3, "test");
  for (int tag : {1, 2}) {
    Element& e = s.interp.domain().element(tag, "test");
    const beamsolid::Matrix diff = beamsolid::Matrix(e.tangentStiff()) - beamsolid::Matrix(elastic.tangentStiff());
    EXPECT_LT(diff.norm(), 1e-12 * beamsolid::Matrix(elastic.tangentStiff()).norm()) << tag;
  }
}

TEST(ZeroLengthSection, TangentAndForceFollowTheOrientation) {
  Script s;
  model2d(s);
  teeSection(s, 1);
  s("uniaxialMaterial", "Elastic", 5, 300.0);
  s("section", "Aggregator", 2, 5, "Vy", "-section", 1);
  s("node", 1, 0.0, 0.0);
  s("node", 2, 0.0, 0.0);
  s("element", "zeroLengthSection", 1, 1, 2, 2, "-orient", 0.6, 0.8, 0.0, -0.8, 0.6, 0.0);
  Element& e = s.interp.domain().element(1, "test");
  Node& n2 = s.interp.domain().node(2, "test");
  Vector u(3);
  u << 0.002, -0.001, 0.0004;
  n2.setTrialDisp(u);
  e.update();
  auto& zl = dynamic_cast<beamsolid::ZeroLengthSection&>(e);
  const Vector d = zl.sectionDeformation();
  EXPECT_NEAR(d[0], 0.6 * 0.002 + 0.8 * -0.001, 1e-16);   // along local x
  EXPECT_NEAR(d[1], 0.0004, 1e-16);                      // rotation about z
  EXPECT_NEAR(d[2], -0.8 * 0.002 + 0.6 * -0.001, 1e-16);  // along local y
  const TangentCheck check = TangentCheck::of(e, 1e-8);
  EXPECT_LT((check.tangent - check.difference).norm(), 1e-6 * check.tangent.norm());
}

TEST(BeamColumns2d, SectionsOfTheOtherSpaceAreErrors) {
  Script s;
  model2d(s);
  s("section", "Elastic", 1, 200.0, 3.0, 5.0);
  s("model", "basic", "-ndm", 3, "-ndf", 6);
  s("node", 1, 0.0, 0.0, 0.0);
  s("node", 2, 0.0, 0.0, 1.0);
  s("geomTransf", "Linear", 1, 1.0, 0.0, 0.0);
  s("beamIntegration", "Lobatto", 1, 1, 3);
  try {
    s("element", "dispBeamColumn", 1, 1, 2, 1, 1);
    FAIL() << "a 2D section in a 3D element";
  } catch (const OpenSeesError& e) {
    EXPECT_NE(std::string(e.what()).find("element dispBeamColumn 1: section Elastic 1 is a 2D section"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(s("element", "nonlinearBeamColumn", 2, 1, 2, 3, 1, 1), OpenSeesError);
}

}  // namespace beamcolumns2dtest
