"""uniaxialMaterial ModIMKPinching (modified Ibarra-Medina-Krawinkler, pinched hysteresis)
against closed forms from its arguments: the two-part reloading (towards Fpr times the peak
until the break strain A_pinch times the peak's zero-stress point, then to the peak), reloading
that starts beyond the break strain, the shared backbone, and bad arguments named. The backbone
and deterioration are ModIMKPeakOriented's (test_modimk_peak_oriented.py); point-by-point
comparisons with OpenSeesPy are in test_uniaxial_oracle.py (the ModIMKPinching-* cases) and
the oracle script imk_peak_frame_2d.

Tolerances: 1e-12 relative on stresses the model evaluates from straight lines (round-off only).
"""
import numpy as np
import pytest

import beamsolid

K0, AS_P, AS_N, MY_P, MY_N = 1000.0, 0.02, 0.03, 10.0, -8.0
FPR_P, FPR_N, A_PINCH = 0.3, 0.4, 0.6
GEO = [0.03, 0.04, 0.1, 0.12, 0.3, 0.25, 0.2, 0.25]


def args(fpr=(FPR_P, FPR_N), a=A_PINCH):
    return [K0, AS_P, AS_N, MY_P, MY_N, *fpr, a, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, *GEO, 1.0, 1.0]


def drive(m, a, strains):
    m.wipe()
    m.uniaxialMaterial("ModIMKPinching", 1, *a)
    m.testUniaxialMaterial(1)
    rows = []
    for e in strains:
        m.setStrain(e)
        rows.append((m.getStress(), m.getTangent()))
    return np.array(rows)


def hardening(theta, sign):
    My, a = (MY_P, AS_P) if sign > 0 else (MY_N, AS_N)
    return My + a * K0 * (theta - My / K0)


def pinched(z, peak, fpr, a, theta):
    """The two-part reloading from zero stress at z towards peak = (strain, stress)."""
    tp, fp = peak
    tb = a * (tp - fp / K0)  # A_pinch times where unloading from the peak reaches zero stress
    k1 = fpr * fp / (tp - z)  # towards (tp, Fpr fp)
    if np.sign(tp) * (theta - tb) < 0:
        return k1 * (theta - z), k1
    fb = k1 * (tb - z)
    k2 = (fp - fb) / (tp - tb)
    return fb + k2 * (theta - tb), k2


def test_reloading_goes_through_the_break_point(model):
    up = [0.01, 0.02]
    down = list(0.02 - np.arange(1, 21) * 0.002)  # to -0.02
    back = list(-0.02 + np.arange(1, 24) * 0.002)  # to 0.026
    rows = drive(model, args(), up + down + back)
    f_peak = hardening(0.02, 1)
    z1 = 0.02 - f_peak / K0
    checked = 0
    for i, e in enumerate(down):
        f, k = rows[len(up) + i]
        if e < z1 and e > MY_N / K0 + 1e-12:
            # Nothing reached on the negative side yet: the peak is the yield point, whose
            # zero-stress point is the origin, so the break strain is 0.
            fe, ke = pinched(z1, (MY_N / K0, MY_N), FPR_N, A_PINCH, e)
            assert f == pytest.approx(fe, rel=1e-12)
            assert k == pytest.approx(ke, rel=1e-12)
            checked += 1
    assert checked >= 8
    f_neg = hardening(-0.02, -1)
    assert rows[len(up) + len(down) - 1, 0] == pytest.approx(f_neg, rel=1e-12)
    z2 = -0.02 - f_neg / K0
    start = len(up) + len(down)
    breaks = 0
    for i, e in enumerate(back):
        f, k = rows[start + i]
        if e <= z2:
            assert f == pytest.approx(f_neg + K0 * (e + 0.02), rel=1e-12)
        elif e < 0.02 - 1e-12:
            fe, ke = pinched(z2, (0.02, f_peak), FPR_P, A_PINCH, e)
            assert f == pytest.approx(fe, rel=1e-12)
            assert k == pytest.approx(ke, rel=1e-12)
            breaks += e > A_PINCH * (0.02 - f_peak / K0)
        elif e > 0.02 + 1e-12:
            assert f == pytest.approx(hardening(e, 1), rel=1e-12)
    assert breaks >= 3  # points on both parts were checked
    # The break point itself lies below the straight line from z2 to the peak (pinching).
    tb = A_PINCH * (0.02 - f_peak / K0)
    assert pinched(z2, (0.02, f_peak), FPR_P, A_PINCH, tb)[0] < f_peak * (tb - z2) / (0.02 - z2)


def test_reloading_beyond_the_break_strain_aims_at_the_peak(model):
    # Peak 0.03 on the positive side (break strain 0.6 (0.03 - f/K0)); unloading to 0.014 crosses
    # zero stress; back from there the zero-stress point lies beyond the break strain.
    path = [0.01, 0.03, 0.02, 0.014, 0.02, 0.025]
    rows = drive(model, args(), path)
    f_peak = hardening(0.03, 1)
    tb = A_PINCH * (0.03 - f_peak / K0)
    z = 0.014 - rows[3, 0] / K0
    assert z > tb and rows[3, 0] < 0.0
    for i in (4, 5):
        assert rows[i, 0] == pytest.approx(f_peak * (path[i] - z) / (0.03 - z), rel=1e-12)


def test_bad_arguments_are_named(model):
    name = "ModIMKPinching"
    with pytest.raises(beamsolid.OpenSeesError, match=rf"{name}.*D_Neg"):
        model.uniaxialMaterial(name, 1, *args()[:-1])
    with pytest.raises(beamsolid.OpenSeesError, match=rf"{name}.*FprPos"):
        model.uniaxialMaterial(name, 1, *args(fpr=(1.5, 0.4)))
    with pytest.raises(beamsolid.OpenSeesError, match=rf"{name}.*FprNeg"):
        model.uniaxialMaterial(name, 1, *args(fpr=(0.3, -0.1)))
    with pytest.raises(beamsolid.OpenSeesError, match=rf"{name}.*A_pinch"):
        model.uniaxialMaterial(name, 1, *args(a=2.0))
    with pytest.raises(beamsolid.OpenSeesError, match=rf"{name}.*A_pinch"):
        a = args()
        a[7] = "x"
        model.uniaxialMaterial(name, 1, *a)
    with pytest.raises(beamsolid.OpenSeesError, match=rf"{name}"):
        model.uniaxialMaterial(name, 1, *args(), 1.0)
