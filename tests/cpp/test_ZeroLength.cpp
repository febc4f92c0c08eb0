// zeroLength: oriented springs (force = k * local deformation, rotated back),
// rotational directions, default global axes, finite-difference tangent with
// a yielded ElasticPP spring, a solved spring support, responses and errors.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "SolidsTestSupport.h"
#include "core/OpenSeesError.h"
#include "elements/ZeroLength.h"
#include "support/ErrorOf.h"

using namespace beamsolid;
using namespace beamsolid::solidstest;

namespace {

using Vector6 = Eigen::Matrix<double, 6, 1>;

using beamsolid::testsupport::errorOf;

}  // namespace

TEST(ZeroLength, OrientedSpringsForceIsStiffnessTimesLocalDeformationRotated) {
  // -orient x = (1, 1, 0), yp = (-1, 1, 0): local axes by hand
  // x' = (1, 1, 0)/sqrt2, y' = (-1, 1, 0)/sqrt2, z' = x' cross y' = (0, 0, 1).
  const double r = 1.0 / std::sqrt(2.0);
  Matrix3 R;
  R << r, r, 0, -r, r, 0, 0, 0, 1;
  const double k[6] = {100, 200, 300, 50, 0, 70};  // direction 5 unused
  Domain d;
  addNode(d, 1, 6, 1.0, 2.0, 3.0);
  addNode(d, 2, 6, 1.0, 2.0, 3.0);
  for (int dir : {1, 2, 3, 4, 6}) addUniaxialMaterial(d, "Elastic", dir, k[dir - 1]);
  Element& e = addElement(d, "zeroLength", 1, 1, 2, "-mat", std::vector<int>{1, 2, 3, 4, 6}, "-dir",
                          std::vector<int>{1, 2, 3, 4, 6}, "-orient", 1.0, 1.0, 0.0, -1.0, 1.0, 0.0);
  EXPECT_LE((dynamic_cast<ZeroLength&>(e).localAxes() - R).cwiseAbs().maxCoeff(), 1e-15);
  Vector6 ui, uj;
  ui << 0.01, -0.02, 0.005, 0.001, 0.002, -0.003;
  uj << 0.03, 0.01, -0.01, 0.004, -0.001, 0.002;
  d.node(1, "test").setTrialDisp(ui);
  d.node(2, "test").setTrialDisp(uj);
  e.update();
  const Vector3 du = (uj - ui).head<3>(), dth = (uj - ui).tail<3>();
  const Vector3 localDu = R * du, localDth = R * dth;
  Vector3 force = Vector3::Zero(), moment = Vector3::Zero();
  for (int a = 0; a < 3; ++a) force += k[a] * localDu(a) * R.row(a).transpose();
  moment += k[3] * localDth(0) * R.row(0).transpose() + k[5] * localDth(2) * R.row(2).transpose();
  const Vector f = e.resistingForce();
  ASSERT_EQ(f.size(), 12);
  EXPECT_LE((f.segment<3>(6) - force).norm(), 1e-13 * force.norm());
  EXPECT_LE((f.segment<3>(9) - moment).norm(), 1e-13 * moment.norm());
  EXPECT_LE((f.head<6>() + f.tail<6>()).norm(), 1e-15);
  // Per-spring deformations are the local components.
  const Vector def = e.setResponse({"deformation"}).value();
  const Vector expected = (Vector(5) << localDu(0), localDu(1), localDu(2), localDth(0), localDth(2)).finished();
  EXPECT_LE((def - expected).cwiseAbs().maxCoeff(), 1e-16);
  EXPECT_DOUBLE_EQ(e.setResponse({"material", "2", "stress"}).value()(0), k[1] * localDu(1));
  const Vector springK = (Vector(5) << k[0], k[1], k[2], k[3], k[5]).finished();
  const Vector springForces = e.setResponse({"basicForce"}).value();
  EXPECT_LE((springForces - springK.cwiseProduct(expected)).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(ZeroLength, AxesPermutedByOrientation) {
  // x = (0, 0, 1), yp = (1, 0, 0): z' = x cross yp = (0, 1, 0), y' = z' cross x' = (1, 0, 0).
  Domain d;
  addNode(d, 1, 3, 0, 0, 0);
  addNode(d, 2, 3, 0, 0, 0);
  addUniaxialMaterial(d, "Elastic", 1, 10.0);
  Element& e = addElement(d, "zeroLength", 1, 1, 2, "-mat", 1, 1, 1, "-dir", 1, 2, 3, "-orient", 0.0, 0.0, 2.0,
                          3.0, 0.0, 0.0);
  d.node(2, "test").setTrialDisp(Vector3(0.1, 0.2, 0.3));
  e.update();
  const Vector def = e.setResponse({"deformations"}).value();
  EXPECT_DOUBLE_EQ(def(0), 0.3);  // local x = global z
  EXPECT_DOUBLE_EQ(def(1), 0.1);  // local y = global x
  EXPECT_DOUBLE_EQ(def(2), 0.2);  // local z = global y
  const Vector f = e.resistingForce();
  EXPECT_LE((f.tail<3>() - Vector3(1.0, 2.0, 3.0)).norm(), 1e-14);
}

TEST(ZeroLength, DefaultAxesAreGlobalAndOnlyNamedDirectionsResist) {
  Domain d;
  addNode(d, 1, 3, 0, 0, 0);
  addNode(d, 2, 3, 0, 0, 0);
  addUniaxialMaterial(d, "Elastic", 1, 10.0);
  Element& e = addElement(d, "zeroLength", 1, 1, 2, "-mat", 1, "-dir", 2, "-doRayleigh", 1);
  EXPECT_TRUE(dynamic_cast<ZeroLength&>(e).doRayleigh());
  d.node(2, "test").setTrialDisp(Vector3(0.5, 0.25, -1.0));
  e.update();
  const Vector f = e.resistingForce();
  const Vector expected = (Vector(6) << 0, -2.5, 0, 0, 2.5, 0).finished();
  EXPECT_EQ(f, expected);
  const Matrix K = e.tangentStiff();
  EXPECT_EQ(K(1, 1), 10.0);
  EXPECT_EQ(K(1, 4), -10.0);
  EXPECT_EQ(K.cwiseAbs().sum(), 40.0);
}

TEST(ZeroLength, FiniteDifferenceTangentWithYieldedSpring) {
  // Piecewise-linear springs away from their kinks: central differences are
  // exact to round-off; h = 1e-8, tolerance 1e-7 relative.
  Domain d;
  addNode(d, 1, 6, 0, 0, 0);
  addNode(d, 2, 6, 0, 0, 0);
  addUniaxialMaterial(d, "ElasticPP", 1, 1000.0, 0.001);
  addUniaxialMaterial(d, "Elastic", 2, 300.0, 0.0, 100.0);
  Element& e = addElement(d, "zeroLength", 1, 1, 2, "-mat", 1, 2, 2, 1, "-dir", 1, 2, 5, 6, "-orient", 1.0, 2.0,
                          -0.5, 0.3, 1.0, 2.0);
  Vector6 uj;
  uj << 0.02, -0.01, 0.03, 0.01, 0.02, -0.015;
  d.node(2, "test").setTrialDisp(uj);
  e.update();
  EXPECT_DOUBLE_EQ(dynamic_cast<ZeroLength&>(e).material(0).tangent(), 0.0);  // yielded
  const TangentCheck c = checkTangent(e, 1e-8);
  EXPECT_GT(c.maxEntry, 0.0);
  EXPECT_LE(c.relativeError(), 1e-7) << c.maxError;
}

TEST(ZeroLength, SpringSupportSolvedForNodalLoad) {
  // Node 2 on three oriented springs to a fixed node 1 under load P:
  // K = sum k_a r_a r_a^T with the hand-built axes of the first test, so
  // u = R^T diag(1/k) R P.
  const double r = 1.0 / std::sqrt(2.0);
  Matrix3 R;
  R << r, r, 0, -r, r, 0, 0, 0, 1;
  Domain d;
  addNode(d, 1, 3, 0, 0, 0);
  addNode(d, 2, 3, 0, 0, 0);
  addUniaxialMaterial(d, "Elastic", 1, 100.0);
  addUniaxialMaterial(d, "Elastic", 2, 400.0);
  addElement(d, "zeroLength", 1, 1, 2, "-mat", 1, 2, 1, "-dir", 1, 2, 3, "-orient", 1.0, 1.0, 0.0, -1.0, 1.0, 0.0);
  DenseStatics statics(d);
  statics.fixAll(1);
  const Vector3 P(3.0, -1.0, 2.0);
  for (int k = 0; k < 3; ++k) statics.load()(statics.index(2, k)) = P(k);
  ASSERT_GE(statics.solve(1e-12), 0);
  const Vector3 expected = R.transpose() * Vector3(1.0 / 100.0, 1.0 / 400.0, 1.0 / 100.0).asDiagonal() * (R * P);
  EXPECT_LE((d.node(2, "test").trialDisp() - expected).norm(), 1e-12 * expected.norm());
}

TEST(ZeroLength, CommitAndRevertFollowTheMaterials) {
  Domain d;
  addNode(d, 1, 3, 0, 0, 0);
  addNode(d, 2, 3, 0, 0, 0);
  addUniaxialMaterial(d, "ElasticPP", 1, 100.0, 0.01);
  Element& e = addElement(d, "zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1);
  d.node(2, "test").setTrialDisp(Vector3(0.05, 0, 0));
  e.update();
  e.commitState();  // plastic deformation 0.04
  d.node(2, "test").setTrialDisp(Vector3(0.0, 0, 0));
  e.update();
  EXPECT_DOUBLE_EQ(Vector(e.resistingForce())(3), -1.0);  // 100*(0 - 0.04) capped at -1
  e.revertToLastCommit();
  EXPECT_DOUBLE_EQ(Vector(e.resistingForce())(3), 1.0);
  e.revertToStart();
  EXPECT_DOUBLE_EQ(Vector(e.resistingForce())(3), 0.0);
}

TEST(ZeroLength, InputErrorsAreClear) {
  Domain d;
  addNode(d, 1, 6, 0, 0, 0);
  addNode(d, 2, 3, 0, 0, 0);
  addNode(d, 3, 3, 0, 0, 0);
  addUniaxialMaterial(d, "Elastic", 1, 10.0);
  const std::string rot = errorOf([&] { addElement(d, "zeroLength", 5, 1, 2, "-mat", 1, "-dir", 4); });
  EXPECT_NE(rot.find("element zeroLength 5: direction 4 is a rotation, but node 2 has ndf 3"), std::string::npos)
      << rot;
  const std::string count = errorOf([&] { addElement(d, "zeroLength", 5, 2, 3, "-mat", 1, 1, "-dir", 1); });
  EXPECT_NE(count.find("one direction per material"), std::string::npos) << count;
  const std::string dir = errorOf([&] { addElement(d, "zeroLength", 5, 2, 3, "-mat", 1, "-dir", 7); });
  EXPECT_NE(dir.find("direction 7 is not 1-6"), std::string::npos) << dir;
  const std::string parallel = errorOf(
      [&] { addElement(d, "zeroLength", 5, 2, 3, "-mat", 1, "-dir", 1, "-orient", 1.0, 0.0, 0.0, 2.0, 0.0, 0.0); });
  EXPECT_NE(parallel.find("parallel"), std::string::npos) << parallel;
  const std::string short3 =
      errorOf([&] { addElement(d, "zeroLength", 5, 2, 3, "-mat", 1, "-dir", 1, "-orient", 1.0, 0.0, 0.0); });
  EXPECT_NE(short3.find("orientation vectors"), std::string::npos) << short3;
  const std::string noMat = errorOf([&] { addElement(d, "zeroLength", 5, 2, 3, "-dir", 1); });
  EXPECT_NE(noMat.find("missing '-mat'"), std::string::npos) << noMat;
  const std::string missing = errorOf([&] { addElement(d, "zeroLength", 5, 2, 3, "-mat", 8, "-dir", 1); });
  EXPECT_NE(missing.find("element zeroLength 5: uniaxialMaterial 8 does not exist"), std::string::npos) << missing;
  const std::string option = errorOf([&] { addElement(d, "zeroLength", 5, 2, 3, "-mat", 1, "-dir", 1, "-foo"); });
  EXPECT_NE(option.find("'-mat', '-dir', '-doRayleigh' or '-orient'"), std::string::npos) << option;
  EXPECT_EQ(d.elements().size(), 0u);
  // Translational directions work between ndf 6 and ndf 3 nodes.
  EXPECT_EQ(errorOf([&] { addElement(d, "zeroLength", 6, 1, 2, "-mat", 1, "-dir", 3); }), "(no error)");
  EXPECT_EQ(d.findElement(6)->numDOF(), 9);
  EXPECT_FALSE(d.findElement(6)->setResponse({"material", "2", "stress"}));
}

TEST(ZeroLength, PlaneSpringsSeeTheInPlaneAxesAndTheRotation) {
  // 2D, ndf 3, -orient x = (3, 4, 0) (yp ignored): local x = (0.6, 0.8),
  // y = (-0.8, 0.6); direction 3 is the rotation. Forces by hand.
  Domain d;
  d.setModelSpace(2, 3);
  addNode(d, 1, 3, 0.0, 0.0, 0.0);
  addNode(d, 2, 3, 0.0, 0.0, 0.0);
  addUniaxialMaterial(d, "Elastic", 1, 100.0);
  addUniaxialMaterial(d, "Elastic", 2, 40.0);
  addUniaxialMaterial(d, "Hardening", 3, 10.0, 0.05, 1.0, 2.0);
  Element& e = addElement(d, "zeroLength", 1, 1, 2, "-mat", std::vector<int>{1, 2, 3}, "-dir",
                          std::vector<int>{1, 2, 3}, "-orient", 3.0, 4.0, 0.0, 0.0, 0.0, 1.0);
  d.findNode(2)->setTrialDisp(0, 0.02);
  d.findNode(2)->setTrialDisp(1, -0.01);
  d.findNode(2)->setTrialDisp(2, 0.03);  // past the rotational spring's yield (0.005)
  e.update();
  const double dx = 0.6 * 0.02 + 0.8 * -0.01, dy = -0.8 * 0.02 + 0.6 * -0.01;
  const double fx = 100.0 * dx, fy = 40.0 * dy;
  const double H = 3.0, m = 0.05 + 10.0 * H / (10.0 + H) * (0.03 - 0.005);
  const Vector f = e.resistingForce();
  const double expected[6] = {-(0.6 * fx - 0.8 * fy), -(0.8 * fx + 0.6 * fy), -m, 0.6 * fx - 0.8 * fy,
                              0.8 * fx + 0.6 * fy, m};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(f(k), expected[k], 1e-14) << k;
  EXPECT_LE(checkTangent(e, 1e-7).relativeError(), 1e-7);
}

TEST(ZeroLength, OneDimensionalSpringTakesTheXComponentOfItsAxis) {
  Domain d;
  d.setModelSpace(1, 1);
  addNode(d, 1, 1, 0.0, 0.0, 0.0);
  addNode(d, 2, 1, 0.0, 0.0, 0.0);
  addUniaxialMaterial(d, "Elastic", 1, 50.0);
  Element& e = addElement(d, "zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1, "-orient", -2.0, 0.0, 0.0, 0.0, 1.0, 0.0);
  d.findNode(2)->setTrialDisp(0, 0.1);
  e.update();
  const Vector f = e.resistingForce();
  EXPECT_DOUBLE_EQ(f(1), 5.0);  // reversed axis: deformation -0.1, force -5 along -x
  EXPECT_DOUBLE_EQ(f(0), -5.0);
  EXPECT_DOUBLE_EQ(dynamic_cast<ZeroLength&>(e).material(0).strain(), -0.1);
}
