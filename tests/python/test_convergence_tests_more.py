"""NormDispAndUnbalance, NormDispOrUnbalance, RelativeEnergyIncr and
RelativeTotalNormDispIncr on a linear bar (closed form: the first Newton
increment is the exact displacement u = P L / (E A), after which the
unbalance is round-off) and on a hardening bar (several iterations), with
the testNorm layout: increment norms padded to iter, then unbalance norms.
"""
import pytest

import beamsolid

P, L, E, A = 5.0, 2.0, 1000.0, 0.5


def bar(m, material=("Elastic", 1, E)):
    m.model("basic", "-ndm", 1, "-ndf", 1)
    m.node(1, 0.0)
    m.node(2, L)
    m.fix(1, 1)
    m.uniaxialMaterial(*material)
    m.element("Truss", 1, 1, 2, A, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, P)
    m.system("UmfPack")
    m.constraints("Plain")
    m.numberer("Plain")


def analyze(m, test, algorithm="Newton", steps=1):
    m.test(*test)
    m.algorithm(algorithm)
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")
    return [m.analyze(1) for _ in range(steps)]


def test_and_needs_both_norms_or_needs_one(model):
    bar(model)
    # Increment norm of iteration 1 = u = P L / (E A) = 0.02 > tolIncr: And needs a second iteration.
    assert analyze(model, ("NormDispAndUnbalance", 1e-6, 1e-6, 5)) == [0]
    assert model.testIter() == 2
    norms = model.testNorm()
    assert len(norms) == 10
    assert norms[0] == pytest.approx(P * L / (E * A), rel=1e-12)
    assert abs(norms[1]) < 1e-14 and norms[2:5] == [0.0, 0.0, 0.0]
    assert abs(norms[5]) < 1e-12 and abs(norms[6]) < 1e-12 and norms[7:] == [0.0, 0.0, 0.0]
    model.wipe()
    bar(model)
    # Or: the unbalance after the first (exact) increment is round-off: one iteration.
    assert analyze(model, ("NormDispOrUnbalance", 1e-6, 1e-6, 5)) == [0]
    assert model.testIter() == 1
    assert model.testNorm()[0] == pytest.approx(P * L / (E * A), rel=1e-12)


def test_relative_tests_record_absolute_norms(model):
    bar(model)
    assert analyze(model, ("RelativeTotalNormDispIncr", 1e-10, 5)) == [0]
    norms = model.testNorm()
    assert model.testIter() == 2 and len(norms) == 5
    assert norms[0] == pytest.approx(P * L / (E * A), rel=1e-12)
    model.wipe()
    bar(model)
    # The exact increment leaves no unbalance: energy 0, converged at once.
    assert analyze(model, ("RelativeEnergyIncr", 1e-10, 5)) == [0]
    assert model.testIter() == 1 and model.testNorm() == [0.0] * 5


def test_hardening_bar_converges_and_fails_within_iter(model):
    """Steel02 past yield: Newton needs several iterations; with iter = 2 the
    step fails and testIter is iter + 1, as for the other tests."""
    steel = ("Steel02", 1, 4.0, E, 0.05)
    for test in [("NormDispAndUnbalance", 1e-12, 1e-10, 30), ("NormDispOrUnbalance", 1e-12, 1e-10, 30),
                 ("RelativeEnergyIncr", 1e-20, 30), ("RelativeTotalNormDispIncr", 1e-12, 30)]:
        model.wipe()
        bar(model, steel)
        assert analyze(model, test) == [0]
        # Equilibrium: the bar carries P (the material stress times A) to the tolerance.
        assert model.eleResponse(1, "axialForce")[0] == pytest.approx(P, rel=1e-8)
        assert model.testIter() > 2
        model.wipe()
        bar(model, steel)
        short = test[:-1] + (2,)
        assert analyze(model, short) == [-3]
        assert model.testIter() == 3


def test_max_incr_fails_a_step_whose_norms_grow(model):
    """Newton past yield: the second increment (0.23) is larger than the first
    (P L / (E A) = 0.02), then it converges. maxIncr 0 fails the step at that
    growth (testIter 3 = the failing iteration + 1), maxIncr 1 lets it converge."""
    bar(model, ("Steel02", 1, 4.0, E, 0.05))
    assert analyze(model, ("NormDispAndUnbalance", 1e-10, 1e-8, 50, 0, 2, 0)) == [-3]
    assert model.testIter() == 3
    model.wipe()
    bar(model, ("Steel02", 1, 4.0, E, 0.05))
    assert analyze(model, ("NormDispAndUnbalance", 1e-10, 1e-8, 50, 0, 2, 1)) == [0]
    assert model.testIter() == 4


@pytest.mark.parametrize("args, words", [
    (("NormDispAndUnbalance", 1e-6, 1e-6), "iter"),
    (("NormDispAndUnbalance", -1.0, 1e-6, 5), "tolIncr"),
    (("NormDispOrUnbalance", 1e-6, 0.0, 5), "tolR"),
    (("NormDispOrUnbalance", 1e-6, 1e-6, 0), "iter"),
    (("NormDispAndUnbalance", 1e-6, 1e-6, 5, 0, 2, 1, 9), "argument"),
    (("RelativeEnergyIncr", 1e-6), "maxIter"),
    (("RelativeTotalNormDispIncr", "x", 5), "tol"),
])
def test_bad_input_names_the_argument(model, args, words):
    bar(model)
    with pytest.raises(beamsolid.OpenSeesError) as info:
        model.test(*args)
    assert args[0] in str(info.value) and words in str(info.value)
