"""RaphsonNewton and PeriodicNewton against the Newton forms they reduce to.

The model: a Steel02 bar loaded past yield in one step (smooth transition, so
every variant iterates). Identities that hold exactly, iteration by iteration:
PeriodicNewton with -maxDim 1 reforms the tangent every iteration (Newton);
RaphsonNewton with current tangents is Newton, with '-increment initial' it is
Newton -initialThenCurrent and with both tangents initial it is Newton
-initial. PeriodicNewton's default reuses the second iteration's tangent for
three iterations, so its third norm differs from Newton's while the first two
agree. All converge to the same displacement (1e-12).
"""
import pytest

import beamsolid.opensees as ops


def _solve(*algorithm, max_iter=60):
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    ops.node(2, 1.0)
    ops.fix(1, 1)
    ops.uniaxialMaterial("Steel02", 1, 1.0, 100.0, 0.05, 18.0, 0.925, 0.15)
    ops.element("Truss", 1, 1, 2, 1.0, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 1.3)
    ops.system("UmfPack")
    ops.numberer("Plain")
    ops.constraints("Plain")
    ops.test("NormUnbalance", 1.0e-12, max_iter)
    ops.algorithm(*algorithm)
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    code = ops.analyze(1)
    n = ops.numIter()
    result = code, ops.testIter(), n, ops.testNorm()[:n], ops.nodeDisp(2, 1)
    ops.wipe()
    return result


@pytest.mark.parametrize("variant, reference", [
    (("PeriodicNewton", "-maxDim", 1), ("Newton",)),
    (("RaphsonNewton",), ("Newton",)),
    (("RaphsonNewton", "-increment", "initial"), ("Newton", "-initialThenCurrent")),
    (("RaphsonNewton", "-iterate", "initial", "-increment", "initial"), ("Newton", "-initial")),
])
def test_variant_equals_its_newton_form(variant, reference):
    a, b = _solve(*variant), _solve(*reference)
    assert a[0] == b[0] and a[2] == b[2]
    assert a[3] == pytest.approx(b[3], rel=1e-12, abs=1e-15)
    assert a[4] == pytest.approx(b[4], rel=1e-12)


def test_periodic_newton_reuses_the_tangent_between_reforms():
    newton = _solve("Newton")
    periodic = _solve("PeriodicNewton")
    assert newton[0] == periodic[0] == 0
    assert periodic[3][:2] == pytest.approx(newton[3][:2], rel=1e-12)
    assert abs(periodic[3][2] - newton[3][2]) > 1e-6 * periodic[3][1]
    assert periodic[2] > newton[2]
    assert periodic[4] == pytest.approx(newton[4], rel=1e-12)
    # a larger maxDim reuses the tangent longer: more iterations
    assert _solve("PeriodicNewton", "-maxDim", 5)[2] > periodic[2] > _solve("PeriodicNewton", "-maxDim", 2)[2]


def test_failed_step_reports_one_past_the_iterations():
    code, test_iter, num_iter, _, u = _solve("ModifiedNewton", max_iter=30)
    assert code < 0
    assert num_iter == 30 and test_iter == 31
    assert u == 0.0  # reverted to the last converged state


@pytest.mark.parametrize("args, message", [
    (("PeriodicNewton", "-maxDim", 0), "-maxDim"),
    (("RaphsonNewton", "-iterate", "sideways"), "-iterate"),
    (("RaphsonNewton", "-bogus"), "-bogus"),
])
def test_bad_options_name_the_argument(args, message):
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    with pytest.raises(ops.OpenSeesError, match=message):
        ops.algorithm(*args)
    ops.wipe()
