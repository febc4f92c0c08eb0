"""uniaxialMaterial('BoucWen', ...) against closed forms (the OpenSeesPy
comparison, point by point, is in test_uniaxial_oracle.py).

With n = 1 and no degradation, monotonic loading from rest follows
dz/deps = Ao - (gamma + beta) z, so z = Ao / (gamma + beta) (1 - exp(-(gamma
+ beta) eps)); unloading (deps z < 0) follows dz/deps = Ao - (gamma - beta) z.
Backward Euler converges to these at first order in the step.
"""
import math

import pytest

import beamsolid

ALPHA, KO, GAMMA, BETA, AO = 0.1, 100.0, 0.3, 0.6, 1.0


def drive(m, strains, *params):
    m.model("basic", "-ndm", 1, "-ndf", 1)
    m.uniaxialMaterial("BoucWen", 1, *params)
    m.testUniaxialMaterial(1)
    out = []
    for e in strains:
        m.setStrain(e)
        out.append((m.getStress(), m.getTangent()))
    return out


def z_loading(eps):
    s = GAMMA + BETA
    return AO / s * (1.0 - math.exp(-s * eps))


@pytest.mark.parametrize("steps", [200, 400])
def test_monotonic_loading_follows_the_closed_form(model, steps):
    eps_max = 3.0
    strains = [eps_max * (k + 1) / steps for k in range(steps)]
    got = drive(model, strains, ALPHA, KO, 1.0, GAMMA, BETA, AO, 0.0, 0.0, 0.0)
    h = eps_max / steps
    for e, (stress, tangent) in zip(strains[::20], got[::20]):
        exact = ALPHA * KO * e + (1 - ALPHA) * KO * z_loading(e)
        # First order: |error| <= h times the largest curvature of z (gamma + beta) Ao, on (1 - alpha) ko.
        assert stress == pytest.approx(exact, abs=(1 - ALPHA) * KO * h * (GAMMA + BETA) * AO)
        z = z_loading(e)
        assert tangent == pytest.approx(ALPHA * KO + (1 - ALPHA) * KO * (AO - (GAMMA + BETA) * z),
                                        abs=(1 - ALPHA) * KO * h * 2.0)


def test_unloading_follows_the_other_branch(model):
    # Load to eps1 (z1 from the loading branch), then unload by d: dz/deps = Ao - (gamma - beta) z
    # with deps < 0, i.e. z = Ao/(gamma - beta) + (z1 - Ao/(gamma - beta)) exp(-(gamma - beta)(eps - eps1)).
    n, eps1, d = 4000, 2.0, 0.5
    up = [eps1 * (k + 1) / n for k in range(n)]
    down = [eps1 - d * (k + 1) / n for k in range(n)]
    got = drive(model, up + down, ALPHA, KO, 1.0, GAMMA, BETA, AO, 0.0, 0.0, 0.0)
    z1 = z_loading(eps1)
    c = AO / (GAMMA - BETA)
    e = down[-1]
    z = c + (z1 - c) * math.exp(-(GAMMA - BETA) * (e - eps1))
    assert got[-1][0] == pytest.approx(ALPHA * KO * e + (1 - ALPHA) * KO * z, rel=2e-3)


def test_degradation_lowers_the_strength_with_the_dissipated_energy(model):
    # deltaA > 0: each cycle dissipates energy and A = Ao - deltaA e shrinks, so the stress
    # at the same peak strain falls from cycle to cycle; without it, the loop settles (the
    # peaks of cycles 2 and 3 within 0.5 %).
    cycle = [1.5 * math.sin(2 * math.pi * k / 200) for k in range(1, 201)]
    def peaks(deltaA):
        model.wipe()
        got = drive(model, cycle * 3, ALPHA, KO, 1.0, GAMMA, BETA, AO, deltaA, 0.0, 0.0)
        return [got[50 + 200 * c][0] for c in range(3)]
    steady, degrading = peaks(0.0), peaks(0.002)
    assert steady[1] == pytest.approx(steady[2], rel=5e-3)
    assert degrading[0] > degrading[1] > degrading[2]
    assert degrading[2] < 0.9 * steady[2]


def test_bad_input(model):
    model.model("basic", "-ndm", 1, "-ndf", 1)
    for args, words in [((1.5, KO, 1.0, GAMMA, BETA, AO, 0.0, 0.0, 0.0), r"argument 3 \(alpha\)"),
                        ((ALPHA, -1.0, 1.0, GAMMA, BETA, AO, 0.0, 0.0, 0.0), r"argument 4 \(ko\)"),
                        ((ALPHA, KO, 0.0, GAMMA, BETA, AO, 0.0, 0.0, 0.0), r"argument 5 \(n\)"),
                        ((ALPHA, KO, 1.0, GAMMA, BETA, AO, 0.0, 0.0), r"deltaEta"),
                        ((ALPHA, KO, 1.0, GAMMA, BETA, AO, 0.0, 0.0, 0.0, -1.0), r"tolerance")]:
        with pytest.raises(beamsolid.OpenSeesError, match=r"uniaxialMaterial BoucWen 1: .*" + words):
            model.uniaxialMaterial("BoucWen", 1, *args)
