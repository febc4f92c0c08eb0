"""Iteration norms of the convergence tests against a hand-worked Newton
iteration: one dof carried by an ElasticPP bar (k1 = 100, yield force 1) and
an elastic bar (k2 = 50) in parallel, loaded by P = 3 in one step.

Newton from u = 0 with the initial tangent k1 + k2: x1 = P/150 = 0.02, the
ElasticPP bar yields, unbalance b1 = P - (1 + 50 x1) = 1. Then the tangent is
k2: x2 = b1/50 = 0.02 and b2 = 0. The tests measure after each update, with
b the unbalance after it (OpenSees' convention, checked against OpenSeesPy
3.7.1): NormUnbalance |b|, NormDispIncr |x|, EnergyIncr 0.5 |x . b|.
Tolerance 1e-12 relative (round-off of a two-dof solve).
"""
import pytest

X1, B1, X2 = 0.02, 1.0, 0.02
EXPECTED = {
    "NormUnbalance": [B1, 0.0],
    "NormDispIncr": [X1, X2, 0.0],
    "EnergyIncr": [0.5 * X1 * B1, 0.0],
}


def _two_bars(ops, test):
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 1.0, 0.0, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 0, 1, 1)
    ops.uniaxialMaterial("ElasticPP", 1, 100.0, 0.01)
    ops.uniaxialMaterial("Elastic", 2, 50.0)
    ops.element("truss", 1, 1, 2, 1.0, 1)
    ops.element("truss", 2, 1, 2, 1.0, 2)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 3.0, 0.0, 0.0)
    ops.system("UmfPack")
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.test(test, 1e-12, 10)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")


@pytest.mark.parametrize("test", sorted(EXPECTED))
def test_iteration_norms_follow_the_hand_worked_newton_steps(ops, test):
    _two_bars(ops, test)
    assert ops.analyze(1) == 0
    assert ops.nodeDisp(2, 1) == pytest.approx(X1 + X2, rel=1e-12)
    expected = EXPECTED[test]
    # NormDispIncr needs a third iteration to see the zero increment.
    assert ops.testIter() == len(expected)
    norms = ops.testNorm()
    assert norms[: len(expected)] == pytest.approx(expected, rel=1e-12, abs=1e-12)


def test_test_norm_has_max_iter_values_and_queries_need_a_test(ops):
    # OpenSees' layout: maxIter values, zeros after the last iteration; both
    # queries raise while no convergence test exists.
    with pytest.raises(ops.OpenSeesError, match="no convergence test"):
        ops.testIter()
    with pytest.raises(ops.OpenSeesError, match="no convergence test"):
        ops.testNorm()
    _two_bars(ops, "NormUnbalance")
    assert ops.analyze(1) == 0
    norms = ops.testNorm()
    assert len(norms) == 10
    assert norms[ops.testIter():] == [0.0] * (10 - ops.testIter())


def test_test_norm_pads_at_most_100000_values(ops):
    # A "never give up" maxIter of 2^31 - 1 must not allocate 16 GB of zeros (found by the fuzzer).
    _two_bars(ops, "NormUnbalance")
    ops.test("NormUnbalance", 1e-12, 2**31 - 1)
    assert ops.analyze(1) == 0
    norms = ops.testNorm()
    assert len(norms) == 100000
    assert norms[0] == pytest.approx(B1, rel=1e-12) and norms[ops.testIter():ops.testIter() + 5] == [0.0] * 5


def test_failure_message_prints_small_norms_readably(ops, capfd):
    # NormDispIncr needs three iterations here; with two the step fails after
    # norms 0.02, 0.02, and the warning shows them as numbers, not 0.000000.
    _two_bars(ops, "NormDispIncr")
    ops.test("NormDispIncr", 1e-20, 2)
    ops.analysis("Static")
    assert ops.analyze(1) < 0
    err = capfd.readouterr().err
    assert "last norm 0.02, tolerance 1e-20" in err
