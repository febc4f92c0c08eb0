"""Series with '-iter': the converged series of Elastic, Steel01 and
Hardening against the closed form, including one jump of strain far past
yield and an unloading from the hardening branch (elastic, with the
series' elastic stiffness). Both are where a repeated one-pass update (and
OpenSees' '-iter') overshoots on a component's plastic tangent."""
import pytest

from beamsolid.model import Model

E1 = 300.0                                   # Elastic
FY2, E2, B2 = 20.0, 500.0, 0.02              # Steel01
E3, FY3, HISO, HKIN = 400.0, 25.0, 10.0, 5.0  # Hardening
K_ELASTIC = 1.0 / (1.0 / E1 + 1.0 / E2 + 1.0 / E3)
H3 = E3 * (HISO + HKIN) / (E3 + HISO + HKIN)


def strain_at(sigma):
    """Monotonic loading: each component's strain at the common stress sigma."""
    e = sigma / E1
    e += sigma / E2 if sigma <= FY2 else FY2 / E2 + (sigma - FY2) / (B2 * E2)
    e += sigma / E3 if sigma <= FY3 else FY3 / E3 + (sigma - FY3) / H3
    return e


def stress_at(strain):
    """Inverse of strain_at (increasing): on the branch that holds it, linear."""
    for low, high in ((0.0, FY2), (FY2, FY3), (FY3, 1e9)):
        if strain <= strain_at(high):
            return low + (strain - strain_at(low)) * (high - low) / (strain_at(high) - strain_at(low)) \
                if high < 1e9 else low + (strain - strain_at(low)) / (1 / E1 + 1 / (B2 * E2) + 1 / H3)
    raise AssertionError("unreachable")


def _series(*options):
    ops = Model()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.uniaxialMaterial("Elastic", 1, E1)
    ops.uniaxialMaterial("Steel01", 2, FY2, E2, B2)
    ops.uniaxialMaterial("Hardening", 3, E3, FY3, HISO, HKIN)
    ops.uniaxialMaterial("Series", 10, 1, 2, 3, *options)
    ops.testUniaxialMaterial(10)
    return ops


@pytest.mark.parametrize("options", [("-iter", 20, 1e-12), ("-iter", 5, 1e-10)])
def test_jump_past_yield_and_elastic_unloading(options):
    ops = _series(*options)
    ops.setStrain(0.5)  # one jump from zero, far past both yields
    assert strain_at(ops.getStress()) == pytest.approx(0.5, rel=1e-10)
    assert ops.getStress() == pytest.approx(stress_at(0.5), rel=1e-10)
    peak = stress_at(4.5)
    for e in (1.0, 2.0, 4.5):
        ops.setStrain(e)
        assert ops.getStress() == pytest.approx(stress_at(e), rel=1e-10)
    ops.setStrain(4.4)  # unloading: every component elastic again
    assert ops.getStress() == pytest.approx(peak - K_ELASTIC * 0.1, rel=1e-10)
    assert ops.getTangent() == pytest.approx(K_ELASTIC, rel=1e-10)
    ops.setStrain(4.2)
    assert ops.getStress() == pytest.approx(peak - K_ELASTIC * 0.3, rel=1e-10)


def test_softening_component_and_residual_plateau():
    """Elastic + Concrete01 in compression: before the peak the series is the
    exact root of eps = sigma/E + eps_c(sigma) (Hognestad parabola); past it
    the softening branch is followed; on the residual plateau the stress is
    fpcu and the tangent OpenSees' 1e-12 floor, with or without '-iter'."""
    fpc, e0, fpcu, ecu, E = -4.0, -0.002, -1.0, -0.006, 3000.0

    def strain_before_peak(sigma):
        return sigma / E + e0 * (1.0 - (1.0 - sigma / fpc) ** 0.5)

    for options in ((), ("-iter", 30, 1e-12)):
        ops = Model()
        ops.model("basic", "-ndm", 1, "-ndf", 1)
        ops.uniaxialMaterial("Elastic", 1, E)
        ops.uniaxialMaterial("Concrete01", 2, fpc, e0, fpcu, ecu)
        ops.uniaxialMaterial("Series", 10, 1, 2, *options)
        ops.testUniaxialMaterial(10)
        for k in range(1, 31):
            ops.setStrain(-0.0003 * k)
            if options and k <= 9:
                assert strain_before_peak(ops.getStress()) == pytest.approx(-0.0003 * k, rel=1e-10)
        assert ops.getStress() == pytest.approx(fpcu, rel=1e-12)
        assert ops.getTangent() == pytest.approx(1e-12, rel=1e-6)
