"""uniaxialMaterial Bilin (modified Ibarra-Medina-Krawinkler, bilinear hysteresis) against
closed forms from its arguments: the backbone's corner points and branches in both directions
(with and without nFactor), kinematic bounds under cycles without deterioration, one
excursion's strength and unloading-stiffness deterioration from the energy the test integrates
itself, and bad arguments named. Point-by-point comparisons with OpenSeesPy are in
test_uniaxial_oracle.py (the Bilin-* cases).

Tolerances: 1e-12 relative on stresses the model evaluates from straight lines (round-off
only).
"""
import numpy as np
import pytest

import beamsolid

K0, AS_P, AS_N, MY_P, MY_N = 1000.0, 0.02, 0.03, 10.0, -8.0
TP_P, TP_N, TPC_P, TPC_N, RES_P, RES_N, TU_P, TU_N = 0.03, 0.04, 0.1, 0.12, 0.3, 0.25, 0.2, 0.25


def bilin_args(ls=0.0, lc=0.0, la=0.0, lk=0.0, c=(1.0, 1.0, 1.0, 1.0), d=(1.0, 1.0), n=None):
    args = [K0, AS_P, AS_N, MY_P, MY_N, ls, lc, la, lk, *c, TP_P, TP_N, TPC_P, TPC_N, RES_P, RES_N, TU_P, TU_N, *d]
    return args + ([n] if n is not None else [])


def drive(m, args, strains):
    m.wipe()
    m.uniaxialMaterial("Bilin", 1, *args)
    m.testUniaxialMaterial(1)
    rows = []
    for e in strains:
        m.setStrain(e)
        rows.append((m.getStress(), m.getTangent()))
    return np.array(rows)


def backbone(theta, sign, n=0.0):
    """The documented backbone of one side (sign +1 or -1), as stress and slope."""
    My, a, tp, tpc, res = (MY_P, AS_P, TP_P, TPC_P, RES_P) if sign > 0 else (MY_N, AS_N, TP_N, TPC_N, RES_N)
    Ke = (1 + n) * K0
    a_mod = a / (1 + n * (1 - a))
    ty = My / Ke
    tc = ty + sign * tp
    Mc = My + a_mod * Ke * (tc - ty)
    ac = -abs(Mc) / (tpc * K0)
    kc = ac / (1 + n * (1 - ac)) * Ke
    if sign * theta <= sign * ty:
        return Ke * theta, Ke
    if sign * theta <= sign * tc:
        return My + a_mod * Ke * (theta - ty), a_mod * Ke
    f = Mc + kc * (theta - tc)
    if sign * f > res * abs(My):
        return f, kc
    return sign * res * abs(My), 1e-7


@pytest.mark.parametrize("n", [None, 10.0])
@pytest.mark.parametrize("sign", [1, -1])
def test_monotonic_backbone_follows_the_corner_points(model, sign, n):
    nn = 0.0 if n is None else n
    tu = TU_P if sign > 0 else TU_N
    strains = sign * np.arange(1, 140) * 0.002
    rows = drive(model, bilin_args(n=n), strains)
    entered_residual = False
    for e, (f, k) in zip(strains, rows):
        if abs(e) >= tu:
            # Failed: OpenSees' +-1e-10 with the step's sign, slope 1e-7.
            assert f == sign * 1e-10 and k == 1e-7
            continue
        fb, kb = backbone(e, sign, nn)
        if kb == 1e-7 and not entered_residual:
            # The step that enters the residual: OpenSees gives Res*|My| + 1e-7*theta.
            assert f == pytest.approx(fb + 1e-7 * e, rel=1e-13)
            entered_residual = True
        else:
            assert f == pytest.approx(fb, rel=1e-12, abs=1e-12)
        assert k == pytest.approx(kb, rel=1e-10)
    assert entered_residual
    # The corner points themselves: yield at My/Ke, cap at theta_y + theta_p with
    # Mc = My (1 + as' Ke theta_p / My).
    Ke = (1 + nn) * K0
    My, a, tp = (MY_P, AS_P, TP_P) if sign > 0 else (MY_N, AS_N, TP_N)
    a_mod = a / (1 + nn * (1 - a))
    corners = [My / Ke, My / Ke + sign * tp]
    rows = drive(model, bilin_args(n=n), corners)
    assert rows[0, 0] == pytest.approx(My, rel=1e-13)
    assert rows[1, 0] == pytest.approx(My + sign * a_mod * Ke * tp, rel=1e-13)


def test_failure_lasts_only_while_beyond_theta_u(model):
    rows = drive(model, bilin_args(), [0.19, 0.21, 0.1, -0.02])
    assert rows[1, 0] == 1e-10
    # Back inside: unloading from ~0 stress meets the negative hardening line.
    assert rows[2, 0] == pytest.approx(MY_N + AS_N * K0 * (0.1 - MY_N / K0), rel=1e-12)
    assert rows[3, 0] == pytest.approx(MY_N + AS_N * K0 * (-0.02 - MY_N / K0), rel=1e-12)


def test_cycles_without_deterioration_stay_between_fixed_lines(model):
    # Positive yield, elastic unloading with K0, the negative hardening line, reloading to the
    # positive one: the lines do not move (Lamda = 0 switches deterioration off).
    path = list(np.arange(1, 11) * 0.0025) + list(0.025 - np.arange(1, 23) * 0.0025) + \
        list(-0.03 + np.arange(1, 25) * 0.0025)
    rows = drive(model, bilin_args(), path)
    for i, e in enumerate(path):
        f, k = rows[i]
        upper = MY_P + AS_P * K0 * (e - MY_P / K0)
        lower = MY_N + AS_N * K0 * (e - MY_N / K0)
        assert lower - 1e-12 <= f <= upper + 1e-12
        if i > 0 and k == K0:
            assert f - rows[i - 1, 0] == pytest.approx(K0 * (e - path[i - 1]), rel=1e-9)
    assert rows[9, 0] == pytest.approx(MY_P + AS_P * K0 * (0.025 - MY_P / K0), rel=1e-13)
    assert rows[31, 0] == pytest.approx(MY_N + AS_N * K0 * (-0.03 - MY_N / K0), rel=1e-13)
    assert rows[-1, 0] == pytest.approx(MY_P + AS_P * K0 * (path[-1] - MY_P / K0), rel=1e-13)
    # Huge Lamdas give the same response as Lamda = 0 (the energy is a vanishing fraction).
    huge = drive(model, bilin_args(ls=1e12, lc=1e12, la=1e12, lk=1e12), path)
    np.testing.assert_allclose(huge[:, 0], rows[:, 0], rtol=0, atol=1e-9)


def _work(path, stresses):
    th = np.r_[0.0, path]
    f = np.r_[0.0, stresses]
    return np.cumsum((f[1:] + f[:-1]) / 2 * np.diff(th))


def test_strength_deterioration_after_one_excursion(model):
    # One positive excursion (yield to 0.025), unloading through zero stress: the excursion's
    # energy E (work up to the crossing step) scales the negative side's My and hardening slope
    # by 1 - beta, beta = E / (Lamda_S My_Plus - E).
    lam = 1.0
    path = list(np.arange(1, 11) * 0.0025) + list(0.025 - np.arange(1, 14) * 0.0025)
    rows = drive(model, bilin_args(ls=lam), path)
    work = _work(path, rows[:, 0])
    crossing = next(i for i in range(1, len(path)) if rows[i - 1, 0] > 0 > rows[i, 0])
    E = work[crossing]
    beta = E / (lam * MY_P - E)
    My = MY_N * (1 - beta)
    ks = AS_N * K0 * (1 - beta)
    e = path[-1]
    assert rows[-1, 1] == pytest.approx(ks, rel=1e-12)
    assert rows[-1, 0] == pytest.approx(My + ks * (e - My / K0), rel=1e-12)


def test_unloading_stiffness_deterioration_at_a_reversal(model):
    # At the reversal the unloading stiffness drops by 1 - beta_K,
    # beta_K = E / (2 Lamda_K My_Plus - E), E = work - f^2 / (2 K0).
    lam = 1.0
    path = list(np.arange(1, 11) * 0.0025) + [0.0225]
    rows = drive(model, bilin_args(lk=lam), path)
    work = _work(path, rows[:, 0])
    E = work[9] - rows[9, 0] ** 2 / (2 * K0)
    beta = E / (2 * lam * MY_P - E)
    assert rows[10, 1] == pytest.approx(K0 * (1 - beta), rel=1e-12)
    assert rows[10, 0] == pytest.approx(rows[9, 0] - K0 * (1 - beta) * 0.0025, rel=1e-12)


def test_bad_arguments_are_named(model):
    with pytest.raises(beamsolid.OpenSeesError, match=r"Bilin.*D_Neg"):
        model.uniaxialMaterial("Bilin", 1, *bilin_args()[:-1])
    with pytest.raises(beamsolid.OpenSeesError, match=r"Bilin.*theta_p_Plus"):
        args = bilin_args()
        args[13] = "x"
        model.uniaxialMaterial("Bilin", 1, *args)
    with pytest.raises(beamsolid.OpenSeesError, match=r"Bilin.*My_Neg"):
        args = bilin_args()
        args[4] = 8.0
        model.uniaxialMaterial("Bilin", 1, *args)
    with pytest.raises(beamsolid.OpenSeesError, match=r"Bilin.*K0"):
        model.uniaxialMaterial("Bilin", 1, 0.0, *bilin_args()[1:])
    with pytest.raises(beamsolid.OpenSeesError, match=r"Bilin.*nFactor"):
        model.uniaxialMaterial("Bilin", 1, *bilin_args(n=-1.0))
    with pytest.raises(beamsolid.OpenSeesError, match=r"Bilin"):
        model.uniaxialMaterial("Bilin", 1, *bilin_args(n=1.0), 5.0)
    with pytest.raises(beamsolid.OpenSeesError, match=r"Bilin.*matTag"):
        model.uniaxialMaterial("Bilin", "a", *bilin_args())
