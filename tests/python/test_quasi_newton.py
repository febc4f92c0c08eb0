"""SecantNewton, BFGS and Broyden on a bilinear (Hardening) two-bar truss whose
answer is known in closed form, plus a linear problem, and their options' errors.

Closed form: a symmetric V of two bars (angle theta from the horizontal, area
A, length L) under a vertical load P at the apex carries N = P / (2 sin theta)
per bar; the bar strain is N/(EA) below yield and eps_y + (N - N_y)/(A K) past it
(K = E H / (E + H)), the apex moving strain * L / sin theta (small strains,
Truss). Each algorithm must reach it to 1e-10. For a linear model every
method is exact in one iteration (the first correction is K^-1 R).
"""
import math

import pytest

from beamsolid.model import Model

E, FY, H, A, HALF, RISE = 1000.0, 20.0, 100.0, 2.0, 3.0, 4.0


def _vee(algorithm, hardening=True):
    ops = Model()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    ops.node(1, -HALF, 0.0)
    ops.node(2, HALF, 0.0)
    ops.node(3, 0.0, -RISE)
    ops.fix(1, 1, 1)
    ops.fix(2, 1, 1)
    ops.fix(3, 1, 0)
    if hardening:
        ops.uniaxialMaterial("Hardening", 1, E, FY, 0.0, H)
    else:
        ops.uniaxialMaterial("Elastic", 1, E)
    ops.element("Truss", 1, 1, 3, A, 1)
    ops.element("Truss", 2, 2, 3, A, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 0.0, -1.0)
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.system("FullGeneral")
    ops.test("NormDispIncr", 1e-13, 200)
    ops.algorithm(*algorithm)
    return ops


def _closed_form(P):
    length = math.hypot(HALF, RISE)
    sin = RISE / length
    n = P / (2.0 * sin)
    ny = FY * A
    k = E * H / (E + H)
    strain = n / (E * A) if n <= ny else FY / E + (n - ny) / (A * k)
    return -strain * length / sin


ALGORITHMS = [("SecantNewton",), ("SecantNewton", "-maxDim", 5), ("SecantNewton", "-iterate", "initial"),
              ("SecantNewton", "-numTerms", 3), ("SecantNewton", "-cutOut", 3.5, 0.3),
              ("BFGS",), ("BFGS", "-count", 2), ("BFGS", "-initial"),
              ("Broyden",), ("Broyden", "-count", 3), ("Broyden", "-initial")]


@pytest.mark.parametrize("algorithm", ALGORITHMS, ids=lambda a: " ".join(map(str, a)))
def test_bilinear_vee_closed_form(algorithm):
    ops = _vee(algorithm)
    ops.integrator("LoadControl", 10.0)
    ops.analysis("Static")
    for step in range(1, 9):  # yield at P = 2 Ny sin(theta) = 64: steps 7 and 8 are plastic
        assert ops.analyze(1) == 0, ops.last_error()
        expected = _closed_form(10.0 * step)
        assert ops.nodeDisp(3, 2) == pytest.approx(expected, rel=1e-10)


@pytest.mark.parametrize("algorithm", ALGORITHMS, ids=lambda a: " ".join(map(str, a)))
def test_linear_model_in_one_iteration(algorithm):
    ops = _vee(algorithm, hardening=False)
    ops.integrator("LoadControl", 10.0)
    ops.analysis("Static")
    assert ops.analyze(1) == 0
    assert ops.nodeDisp(3, 2) == pytest.approx(_closed_form(10.0), rel=1e-12)
    # One correction solves it; the test then sees an increment of round-off size.
    norms = [n for n in ops.testNorm() if n != 0.0]
    assert len(norms) <= 2


@pytest.mark.parametrize("args, message", [
    (("BFGS", "-count", 0), "BFGS.*-count must be at least 1"),
    (("Broyden", "-bogus"), "Broyden.*unknown option '-bogus'"),
    (("BFGS", "-secant"), "BFGS.*-secant.*not supported"),
    (("Broyden", "-count"), "Broyden.*count"),
    (("SecantNewton", "-iterate", "sometimes"), "SecantNewton.*-iterate 'sometimes'"),
    (("SecantNewton", "-maxDim", 0), "SecantNewton.*-maxDim"),
    (("SecantNewton", "-numTerms", 4), "SecantNewton.*-numTerms"),
    (("SecantNewton", "-cutOut", 3.5), "SecantNewton.*R2"),
])
def test_bad_options_name_the_algorithm(args, message):
    ops = Model()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    with pytest.raises(RuntimeError, match=message):
        ops.algorithm(*args)
