"""uniaxialMaterial ModIMKPeakOriented (modified Ibarra-Medina-Krawinkler, peak-oriented
hysteresis) against closed forms from its arguments: the backbone's corner points in both
directions with the residual and theta_u, reloading that aims at the previous peak (the yield
point before any), at the point a side last turned back from, one excursion's strength,
post-capping and unloading-stiffness deterioration from the energy the test integrates itself,
and bad arguments named. Point-by-point comparisons with OpenSeesPy are in
test_uniaxial_oracle.py (the ModIMKPeakOriented-* cases) and the oracle script
imk_peak_frame_2d.

Tolerances: 1e-12 relative on stresses the model evaluates from straight lines (round-off only).
"""
import numpy as np
import pytest

import beamsolid

K0, AS_P, AS_N, MY_P, MY_N = 1000.0, 0.02, 0.03, 10.0, -8.0
TP_P, TP_N, TPC_P, TPC_N, RES_P, RES_N, TU_P, TU_N = 0.03, 0.04, 0.1, 0.12, 0.3, 0.25, 0.2, 0.25
OFF = 1e12  # a Lamda this large leaves a mode without effect (E/E_t ~ 1e-13)


def args(ls=0.0, lc=0.0, la=0.0, lk=0.0, c=(1.0, 1.0, 1.0, 1.0), d=(1.0, 1.0)):
    return [K0, AS_P, AS_N, MY_P, MY_N, ls, lc, la, lk, *c, TP_P, TP_N, TPC_P, TPC_N, RES_P, RES_N, TU_P, TU_N, *d]


def drive(m, a, strains):
    m.wipe()
    m.uniaxialMaterial("ModIMKPeakOriented", 1, *a)
    m.testUniaxialMaterial(1)
    rows = []
    for e in strains:
        m.setStrain(e)
        rows.append((m.getStress(), m.getTangent()))
    return np.array(rows)


def hardening(theta, sign, My=None, a=None):
    My = (MY_P if sign > 0 else MY_N) if My is None else My
    a = (AS_P if sign > 0 else AS_N) if a is None else a
    return My + a * K0 * (theta - My / K0)


def line(z, target, theta):
    """The reloading line from zero stress at z through the target point."""
    return target[1] * (theta - z) / (target[0] - z)


@pytest.mark.parametrize("sign", [1, -1])
def test_monotonic_backbone_corners_residual_and_failure(model, sign):
    My, a, tp, tpc, res, tu = ((MY_P, AS_P, TP_P, TPC_P, RES_P, TU_P) if sign > 0 else
                               (MY_N, AS_N, TP_N, TPC_N, RES_N, TU_N))
    ty = My / K0
    tc = ty + sign * tp
    Mc = My + a * K0 * sign * tp
    kc = -abs(Mc) / tpc  # post-capping slope, ac*K0 with ac = -Mc/(theta_pc K0)
    tr = tc + (sign * res * abs(My) - Mc) / kc  # where the post-capping line meets the residual
    rows = drive(model, args(), [ty, tc, 0.5 * (tc + tr), tr + sign * 0.01, sign * (tu + 0.001), sign * (tu + 0.01)])
    assert rows[0, 0] == pytest.approx(My, rel=1e-13)
    assert rows[1, 0] == pytest.approx(Mc, rel=1e-13)
    assert rows[2, 0] == pytest.approx(Mc + kc * 0.5 * (tr - tc), rel=1e-12)
    assert rows[2, 1] == pytest.approx(kc, rel=1e-12)
    # On the residual: Res*|My| + 1e-7 theta, slope 1e-7 (as OpenSees reports it).
    e = tr + sign * 0.01
    assert rows[3, 0] == pytest.approx(sign * res * abs(My) + 1e-7 * e, rel=1e-13)
    assert rows[3, 1] == 1e-7
    # Beyond theta_u: one step of +1e-10 (either side, as OpenSees), then nothing, for good.
    assert rows[4, 0] == 1e-10 and rows[4, 1] == 1e-7
    assert rows[5, 0] == 0.0 and rows[5, 1] == 0.0
    assert drive(model, args(), [sign * (tu + 0.001), 0.0, -sign * 0.002])[2, 0] == 0.0


def test_reloading_aims_at_the_previous_peak(model):
    # Yield to 0.02, unload through zero: reloading aims at the negative yield point (nothing
    # reached there yet), then follows the hardening line to -0.02; back through zero it aims at
    # the positive peak (0.02, f(0.02)) and beyond it follows the backbone.
    up = [0.005, 0.01, 0.015, 0.02]
    down = [0.015, 0.01, 0.005, 0.0, -0.005, -0.01, -0.015, -0.02]
    back = [-0.015, -0.01, 0.0, 0.01, 0.02, 0.025]
    rows = drive(model, args(), up + down + back)
    f_peak = hardening(0.02, 1)
    z1 = 0.02 - f_peak / K0
    neg_yield = (MY_N / K0, MY_N)
    for i, e in enumerate(down):
        f = rows[len(up) + i, 0]
        if e > z1:
            assert f == pytest.approx(f_peak - K0 * (0.02 - e), rel=1e-12)
        elif e > neg_yield[0]:
            assert f == pytest.approx(line(z1, neg_yield, e), rel=1e-12)
            assert rows[len(up) + i, 1] == pytest.approx(neg_yield[1] / (neg_yield[0] - z1), rel=1e-12)
        else:
            assert f == pytest.approx(hardening(e, -1), rel=1e-12)
    f_neg = hardening(-0.02, -1)
    z2 = -0.02 - f_neg / K0
    k = len(up) + len(down)
    for i, e in enumerate(back):
        f = rows[k + i, 0]
        if e < z2:
            assert f == pytest.approx(f_neg + K0 * (e + 0.02), rel=1e-12)
        elif e <= 0.02:
            assert f == pytest.approx(line(z2, (0.02, f_peak), e), rel=1e-12)
        else:
            assert f == pytest.approx(hardening(e, 1), rel=1e-12)
    assert rows[k + 4, 0] == pytest.approx(f_peak, rel=1e-12)


def test_reloading_aims_first_at_where_a_side_turned_back(model):
    # After the peaks 0.02 and -0.012, a positive excursion that turns back at 0.005 (on the
    # line to the peak) and a small negative one: the next positive reloading starts further
    # left, so the line to the peak passes below the turning point; it aims at the turning
    # point first, then goes on along the line from it to the peak.
    path = [0.01, 0.02, 0.0, -0.012, 0.0, 0.005, 0.0, -0.004, 0.0, 0.004, 0.005, 0.01, 0.02]
    rows = drive(model, args(), path)
    f_peak = hardening(0.02, 1)
    f_turn = rows[5, 0]
    z = -0.004 - rows[7, 0] / K0  # zero stress of the unloading from (-0.004, f)
    assert f_turn > line(z, (0.02, f_peak), 0.005)  # the turning point lies outside the line
    assert rows[9, 0] == pytest.approx(line(z, (0.005, f_turn), 0.004), rel=1e-12)
    assert rows[10, 0] == pytest.approx(f_turn, rel=1e-12)
    slope = (f_peak - f_turn) / 0.015
    assert rows[11, 0] == pytest.approx(f_turn + slope * 0.005, rel=1e-12)
    assert rows[11, 1] == pytest.approx(slope, rel=1e-12)
    assert rows[12, 0] == pytest.approx(f_peak, rel=1e-12)


def _work(path, stresses):
    th = np.r_[0.0, path]
    f = np.r_[0.0, stresses]
    return np.cumsum((f[1:] + f[:-1]) / 2 * np.diff(th))


def _one_excursion(model, a):
    # Yield to 0.025, unload through zero stress in steps of 0.0025, then on to -0.0125.
    path = list(np.arange(1, 11) * 0.0025) + list(0.025 - np.arange(1, 16) * 0.0025)
    rows = drive(model, a, path)
    work = _work(path, rows[:, 0])
    crossing = next(i for i in range(1, len(path)) if rows[i - 1, 0] > 0 > rows[i, 0])
    return path, rows, work, crossing


def test_strength_deterioration_after_one_excursion(model):
    # At the zero crossing the excursion's energy E (work up to and with the crossing step)
    # scales the negative side's My and hardening ratio by 1 - beta, beta = E/(Lamda_S My_Plus - E);
    # from the next step reloading aims at the deteriorated backbone at the yield strain.
    lam = 1.0
    path, rows, work, i = _one_excursion(model, args(ls=lam, lc=OFF))
    z = 0.025 - rows[9, 0] / K0
    # The crossing step still aims at the undeteriorated yield point.
    assert rows[i, 0] == pytest.approx(line(z, (MY_N / K0, MY_N), path[i]), rel=1e-12)
    beta = work[i] / (lam * MY_P - work[i])
    target = (MY_N / K0, hardening(MY_N / K0, -1, My=MY_N * (1 - beta), a=AS_N * (1 - beta)))
    assert rows[i + 1, 0] == pytest.approx(line(z, target, path[i + 1]), rel=1e-12)
    e = path[-1]
    assert rows[-1, 0] == pytest.approx(hardening(e, -1, My=MY_N * (1 - beta), a=AS_N * (1 - beta)), rel=1e-12)
    assert rows[-1, 1] == pytest.approx(AS_N * K0 * (1 - beta), rel=1e-12)


def test_post_capping_deterioration_after_one_excursion(model):
    # The post-capping line of the side entered keeps its slope; its intercept at theta = 0
    # shrinks by 1 - beta_C (D = 0.8 here: 1 - D beta_C).
    lam, D = 1.5, 0.8
    path, rows, work, i = _one_excursion(model, args(lc=lam, d=(1.0, D)))
    beta = work[i] / (lam * MY_P - work[i])
    Mc = MY_N - AS_N * K0 * TP_N
    tc = MY_N / K0 - TP_N
    kc = -abs(Mc) / TPC_N  # ac*K0, ac = -|Mc|/(theta_pc K0): on the negative side the stress rises to zero
    intercept = (Mc - kc * tc) * (1 - D * beta)
    e = -0.07  # on the moved post-capping line
    rows2 = drive(model, args(lc=lam, d=(1.0, D)), path + [-0.03, e])
    assert rows2[-1, 0] == pytest.approx(intercept + kc * e, rel=1e-12)
    assert rows2[-1, 1] == pytest.approx(kc, rel=1e-12)


def test_unloading_stiffness_deterioration_at_a_reversal(model):
    # At the reversal the unloading stiffness drops by 1 - beta_K,
    # beta_K = E / (2 Lamda_K My_Plus - E), E = work - f^2 / (2 K0).
    lam = 1.0
    path = list(np.arange(1, 11) * 0.0025) + [0.0225]
    rows = drive(model, args(lk=lam, lc=OFF), path)
    work = _work(path, rows[:, 0])
    E = work[9] - rows[9, 0] ** 2 / (2 * K0)
    beta = E / (2 * lam * MY_P - E)
    assert rows[10, 1] == pytest.approx(K0 * (1 - beta), rel=1e-12)
    assert rows[10, 0] == pytest.approx(rows[9, 0] - K0 * (1 - beta) * 0.0025, rel=1e-12)


def test_bad_arguments_are_named(model):
    name = "ModIMKPeakOriented"
    with pytest.raises(beamsolid.OpenSeesError, match=rf"{name}.*D_Neg"):
        model.uniaxialMaterial(name, 1, *args()[:-1])
    with pytest.raises(beamsolid.OpenSeesError, match=rf"{name}"):
        model.uniaxialMaterial(name, 1, *args(), 5.0)  # no nFactor here
    with pytest.raises(beamsolid.OpenSeesError, match=rf"{name}.*theta_p_Plus"):
        a = args()
        a[13] = "x"
        model.uniaxialMaterial(name, 1, *a)
    with pytest.raises(beamsolid.OpenSeesError, match=rf"{name}.*My_Neg"):
        a = args()
        a[4] = 8.0
        model.uniaxialMaterial(name, 1, *a)
    with pytest.raises(beamsolid.OpenSeesError, match=rf"{name}.*Lamda_K"):
        model.uniaxialMaterial(name, 1, *args(lk=-1.0))
    with pytest.raises(beamsolid.OpenSeesError, match=rf"{name}.*c_S"):
        model.uniaxialMaterial(name, 1, *args(c=(0.0, 1.0, 1.0, 1.0)))
    with pytest.raises(beamsolid.OpenSeesError, match=rf"{name}.*K0"):
        model.uniaxialMaterial(name, 1, 0.0, *args()[1:])
    with pytest.raises(beamsolid.OpenSeesError, match=rf"{name}.*matTag"):
        model.uniaxialMaterial(name, "a", *args())
    model.uniaxialMaterial(name, 1, *args())
    with pytest.raises(beamsolid.OpenSeesError, match="uniaxialMaterial"):
        model.uniaxialMaterial(name, 1, *args())  # duplicate tag
