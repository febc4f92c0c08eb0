"""KrylovNewton (Krylov-accelerated modified Newton) under load and
displacement control, on a three-bar truss (two equations) of Steel02 bars.

Checks: every converged step is in equilibrium (the sum of the support
reactions balances lambda times the reference load to 1e-10 of the load) and
equals Newton's answer to 1e-10; the subspace holds at most as many
directions as there are equations (any maxDim >= 2 iterates the same here);
'-initial' is accepted and changes nothing, as in OpenSees.
"""
import pytest

P_REF = (1.0, 0.0)


def truss(ops, algorithm, integrator):
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    for tag, xy in ((1, (0.0, 0.0)), (2, (72.0, 0.0)), (3, (168.0, 0.0)), (4, (48.0, 144.0))):
        ops.node(tag, *xy)
    for tag in (1, 2, 3):
        ops.fix(tag, 1, 1)
    ops.uniaxialMaterial("Steel02", 1, 36.0, 29000.0, 0.05, 18.0, 0.925, 0.15)
    for tag in (1, 2, 3):
        ops.element("Truss", tag, tag, 4, 4.0, 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(4, *P_REF)
    ops.system("BandGeneral")
    ops.numberer("Plain")
    ops.constraints("Plain")
    ops.integrator(*integrator)
    ops.test("NormDispIncr", 1e-12, 100)
    ops.algorithm(*algorithm)
    ops.analysis("Static")


def path(ops, algorithm, integrator, steps=12):
    truss(ops, algorithm, integrator)
    out = []
    for _ in range(steps):
        assert ops.analyze(1) == 0
        lam = ops.getLoadFactor(1)
        ops.reactions()
        rx = sum(ops.nodeReaction(n, 1) for n in (1, 2, 3))
        ry = sum(ops.nodeReaction(n, 2) for n in (1, 2, 3))
        # Equilibrium of the whole truss: reactions balance lambda * P.
        scale = abs(lam) * abs(P_REF[0])
        assert abs(rx + lam * P_REF[0]) < 1e-10 * scale
        assert abs(ry + lam * P_REF[1]) < 1e-10 * scale
        out.append((lam, ops.nodeDisp(4, 1), ops.nodeDisp(4, 2), ops.testIter()))
    return out


INTEGRATORS = [("DisplacementControl", 4, 1, 0.05), ("LoadControl", 12.0)]


@pytest.mark.parametrize("integrator", INTEGRATORS)
@pytest.mark.parametrize("options", [(), ("-increment", "initial"), ("-iterate", "initial")])
def test_krylov_newton_converges_to_newtons_path(ops, integrator, options):
    krylov = path(ops, ("KrylovNewton",) + options, integrator)
    newton = path(ops, ("Newton",), integrator)
    for (lk, xk, yk, _), (ln, xn, yn, _) in zip(krylov, newton):
        assert lk == pytest.approx(ln, rel=1e-10)
        assert xk == pytest.approx(xn, rel=1e-10)
        assert yk == pytest.approx(yn, rel=1e-10, abs=1e-10 * abs(xn))


@pytest.mark.parametrize("integrator", INTEGRATORS)
def test_subspace_is_capped_at_the_number_of_equations(ops, integrator):
    iterations = {d: [s[3] for s in path(ops, ("KrylovNewton", "-maxDim", d), integrator)] for d in (2, 3, 30)}
    assert iterations[3] == iterations[2]
    assert iterations[30] == iterations[2]
    assert iterations[2] != [s[3] for s in path(ops, ("KrylovNewton", "-maxDim", 1), integrator)]


def test_initial_flag_is_accepted_and_changes_nothing(ops):
    plain = path(ops, ("KrylovNewton",), INTEGRATORS[0])
    flagged = path(ops, ("KrylovNewton", "-initial"), INTEGRATORS[0])
    assert flagged == plain
