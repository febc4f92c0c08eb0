"""Static condensation of the constant-tangent equations against the plain solve.

With ``system(name, '-condense', 'on')`` the equations only constant-tangent
elements touch (elastic bricks, elastic beams with a Linear transformation,
elastic trusses and springs) are condensed out once (analysis/CondensedSolver):
every answer must equal the plain solve's (``'-condense', 'off'``) to 1e-9
relative - displacements, reactions, iteration counts - under LoadControl,
DisplacementControl and ArcLength, with Newton, ModifiedNewton and line search,
with equalDOF/rigidLink/sp constraints, with contact (Lagrange and penalty),
after element removal; and the condensation is redone exactly when the pattern
or a constant tangent changes.
"""
import dataclasses

import numpy as np
import pytest

import beamsolid
from beamsolid.scenes import donut_pullout, lateral_pile

RTOL = 1e-9


@pytest.fixture(autouse=True)
def _condense_every_model(monkeypatch):
    """Each test's models condense for themselves: the counts below are per model, and an identical
    model of an earlier test must not lend its condensation (test_a_rebuilt_model_... turns the
    process cache back on)."""
    monkeypatch.setenv("BEAMSOLID_CONDENSE_CACHE", "off")


def _close(a, b, rtol=RTOL):
    a, b = np.asarray(a, float), np.asarray(b, float)
    scale = max(np.abs(b).max(), 1e-300)
    return np.abs(a - b).max() <= rtol * scale


def _mixed(m, condense, integrator=("LoadControl", 0.25), algorithm=("Newton",), handler=("Transformation",)):
    """An elastic brick block (4 x 4 x 3) carrying a yielding Steel01 truss
    brace and an elastic beam column on its top, tied by equalDOF and
    rigidLink; the base fixed, one top node pushed by an sp."""
    m.wipe()
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.nDMaterial("ElasticIsotropic", 1, 2.0e4, 0.3)
    nx, ny, nz = 4, 4, 3
    tag = lambda i, j, k: 1 + i + (nx + 1) * (j + (ny + 1) * k)
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                m.node(tag(i, j, k), float(i), float(j), float(k))
    e = 1
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                m.element("stdBrick", e, tag(i, j, k), tag(i + 1, j, k), tag(i + 1, j + 1, k), tag(i, j + 1, k),
                          tag(i, j, k + 1), tag(i + 1, j, k + 1), tag(i + 1, j + 1, k + 1), tag(i, j + 1, k + 1), 1)
                e += 1
    m.fixZ(0.0, 1, 1, 1)
    top = lambda i, j: tag(i, j, nz)
    # a yielding brace across the top (nonlinear: its dofs stay in the interface)
    m.uniaxialMaterial("Steel01", 1, 40.0, 2.0e4, 0.05)
    m.element("Truss", 1000, top(0, 0), top(4, 4), 0.5, 1)
    # a node tied by equalDOF to a soil node, sharing a Steel01 spring
    m.node(900, 2.0, 2.0, 3.0)
    m.equalDOF(top(2, 2), 900, 3)
    m.node(901, 2.0, 2.0, 3.0)
    m.fix(901, 1, 1, 1)
    m.element("zeroLength", 1001, 901, 900, "-mat", 1, 1, "-dir", 1, 2)
    # a beam column (6 dofs) on the top, rigidLinked to two soil nodes
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.node(800, 1.0, 1.0, 3.0)
    m.node(801, 1.0, 1.0, 5.0)
    m.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    m.element("elasticBeamColumn", 1002, 800, 801, 0.1, 3.0e4, 1.2e4, 1e-3, 1e-3, 1e-3, 1)
    m.rigidLink("bar", top(1, 1), 800)
    m.rigidLink("bar", top(3, 3), 801)
    m.fix(800, 0, 0, 0, 0, 0, 1)  # the beam's torsion would be free
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(top(4, 4), 30.0, 20.0, -10.0)
    m.load(801, 5.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    m.sp(top(0, 4), 1, 0.02)
    m.constraints(*handler)
    m.numberer("RCM")
    m.system("UmfPack", "-condense", "on" if condense else "off")
    m.test("NormDispIncr", 1e-10, 50)
    m.algorithm(*algorithm)
    m.integrator(*integrator)
    m.analysis("Static")


def _state(m):
    m.reactions()
    tags = m.getNodeTags()
    return np.concatenate([np.concatenate([m.nodeDisp(t), m.nodeReaction(t)]) for t in tags])


def _run_mixed(condense, steps=4, **kw):
    m = beamsolid.Model()
    _mixed(m, condense, **kw)
    states, iters = [], []
    for _ in range(steps):
        assert m.analyze(1) == 0, m.last_error()
        states.append(_state(m))
        iters.append(m.testIter())
    info = m.solver_info()
    m.wipe()
    return np.array(states), iters, info


@pytest.mark.parametrize("reuse", ["off", "always"])
@pytest.mark.parametrize("integrator, algorithm, handler", [
    (("LoadControl", 0.25), ("Newton",), ("Transformation",)),
    (("LoadControl", 0.25), ("ModifiedNewton",), ("Transformation",)),
    (("LoadControl", 0.25), ("NewtonLineSearch",), ("Plain",)),
    (("LoadControl", 0.25), ("KrylovNewton",), ("Penalty", 1e10, 1e10)),
    (("DisplacementControl", 100, 1, 0.01), ("Newton",), ("Transformation",)),
    (("ArcLength", 0.05, 1.0), ("Newton",), ("Transformation",)),
])
def test_mixed_model_condensed_equals_plain(monkeypatch, integrator, algorithm, handler, reuse):
    """reuse 'always': the interface is solved by GMRES with an earlier factorization of S
    wherever it can (CondensedSolver), 'off': S factored at every factorization."""
    monkeypatch.setenv("BEAMSOLID_INTERFACE_REUSE", reuse)
    plain, plain_iters, plain_info = _run_mixed(False, integrator=integrator, algorithm=algorithm, handler=handler)
    cond, cond_iters, info = _run_mixed(True, integrator=integrator, algorithm=algorithm, handler=handler)
    assert not plain_info["condensed"]
    assert info["condensed"] and info["interior"] > 3 * info["interface"] > 0
    assert cond_iters == plain_iters
    assert _close(cond, plain)
    # the bricks never change: condensed once for the whole run
    assert info["condensations"] == 1
    assert info["factorizations"] == plain_info["factorizations"]
    if reuse == "off":
        assert info["interface_factorizations"] == info["factorizations"] and info["krylov_iterations"] == 0
    else:  # an unchanged interface block is solved with the factors it has
        assert info["interface_factorizations"] < info["factorizations"]


def test_recondenses_exactly_when_a_constant_tangent_or_the_pattern_changes():
    m = beamsolid.Model()
    _mixed(m, True)
    for _ in range(2):
        assert m.analyze(1) == 0
    assert m.solver_info()["condensations"] == 1
    # a stiffer soil: the constant blocks differ, condensed again once
    m.setParameter("-val", 3.0e4, "-ele", *range(1, 49), "E")
    assert m.analyze(1) == 0
    assert m.solver_info()["condensations"] == 2
    assert m.analyze(1) == 0
    assert m.solver_info()["condensations"] == 2
    # an element removed: a new pattern, a new condensation of the new interior
    before = m.solver_info()["analyses"]
    m.remove("element", 1000)
    assert m.analyze(1) == 0
    info = m.solver_info()
    assert info["condensations"] == 1 and info["analyses"] == 1 and before == 1
    m.wipe()


def test_element_removed_between_steps_condensed_equals_plain():
    def go(condense):
        m = beamsolid.Model()
        _mixed(m, condense)
        out = []
        for step in range(4):
            if step == 2:
                m.remove("element", 1000)
            assert m.analyze(1) == 0
            out.append(_state(m))
        m.wipe()
        return np.array(out)

    assert _close(go(True), go(False))


def test_a_mechanism_fails_as_in_the_plain_solve():
    """Bricks with no support: the condensed block is singular, the whole
    system too; analyze returns -3 either way and the model stays at rest."""
    for mode in ("on", "off"):
        m = beamsolid.Model()
        m.model("basic", "-ndm", 3, "-ndf", 3)
        m.nDMaterial("ElasticIsotropic", 1, 100.0, 0.25)
        for i, (x, y, z) in enumerate([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1),
                                       (0, 1, 1)], start=1):
            m.node(i, float(x), float(y), float(z))
        m.element("stdBrick", 1, *range(1, 9), 1)
        m.timeSeries("Linear", 1)
        m.pattern("Plain", 1, 1)
        m.load(7, 1.0, 0.5, -2.0)
        m.system("UmfPack", "-condense", mode)
        m.integrator("LoadControl", 1.0)
        m.analysis("Static")
        assert m.analyze(1) == -3
        assert m.nodeDisp(7) == [0.0, 0.0, 0.0]
        m.wipe()


def test_auto_condenses_large_models_and_can_be_switched_off(monkeypatch):
    m = beamsolid.Model()

    def block(n, *system):
        m.wipe()
        m.model("basic", "-ndm", 3, "-ndf", 3)
        m.nDMaterial("ElasticIsotropic", 1, 1.0e3, 0.3)
        tag = lambda i, j, k: 1 + i + (n + 1) * (j + (n + 1) * k)
        for k in range(n + 1):
            for j in range(n + 1):
                for i in range(n + 1):
                    m.node(tag(i, j, k), i / n, j / n, k / n)
        e = 1
        for k in range(n):
            for j in range(n):
                for i in range(n):
                    m.element("stdBrick", e, tag(i, j, k), tag(i + 1, j, k), tag(i + 1, j + 1, k), tag(i, j + 1, k),
                              tag(i, j, k + 1), tag(i + 1, j, k + 1), tag(i + 1, j + 1, k + 1),
                              tag(i, j + 1, k + 1), 1)
                    e += 1
        m.fixZ(0.0, 1, 1, 1)
        m.timeSeries("Linear", 1)
        m.pattern("Plain", 1, 1)
        m.load(tag(n, n, n), 0.0, 0.0, -1.0)
        m.system(*system)
        m.analysis("Static")
        assert m.analyze(1) == 0
        return m.nodeDisp(tag(n, n, n))

    assert block(4, "UmfPack") and not m.solver_info()["condensed"]  # small: plain
    u_auto = block(9, "UmfPack")
    assert m.solver_info()["condensed"] and m.solver_info()["interface"] == 0
    u_off = block(9, "UmfPack", "-condense", "off")
    assert not m.solver_info()["condensed"] and "switched off" in m.solver_info()["note"]
    assert _close(u_auto, u_off)
    monkeypatch.setenv("BEAMSOLID_CONDENSE", "off")
    block(9, "UmfPack")
    assert not m.solver_info()["condensed"]
    m.wipe()


def test_bad_condense_option_names_it():
    with pytest.raises(beamsolid.OpenSeesError, match="-condense"):
        m = beamsolid.Model()
        m.model("basic", "-ndm", 3, "-ndf", 3)
        m.system("UmfPack", "-condense", "sometimes")


@pytest.mark.parametrize("reuse", ["off", "on"])
@pytest.mark.parametrize("interface", ["contact", "penalty"])
def test_lateral_pile_condensed_equals_plain(monkeypatch, interface, reuse):
    numerics = lateral_pile.Numerics(level="coarse", interface=interface, steps=4)
    results = {}
    monkeypatch.setenv("BEAMSOLID_INTERFACE_REUSE", reuse)
    for mode in ("off", "on"):
        monkeypatch.setenv("BEAMSOLID_CONDENSE", mode)
        results[mode] = lateral_pile.run(lateral_pile.LateralPile(), numerics)
    on, off = results["on"], results["off"]
    assert on.converged and off.converged
    assert on.iterations == off.iterations
    assert _close(on.head_force, off.head_force)
    assert _close(on.head_disp, off.head_disp)
    # at geostatic rest the gaps are round-off (1e-16 m): open or not is noise there
    assert on.n_open[1:] == off.n_open[1:]


def test_donut_pullout_condensed_equals_plain(monkeypatch):
    setup = dataclasses.replace(donut_pullout.DonutPullout(), n_theta=8, n_radial=2, n_z=4, steps=4)
    results = {}
    for mode in ("off", "on"):
        monkeypatch.setenv("BEAMSOLID_CONDENSE", mode)
        results[mode] = donut_pullout.run(setup)
    on, off = results["on"], results["off"]
    assert _close(on.head_force, off.head_force)
    assert _close(on.head_disp, off.head_disp)


def test_multiplier_nodes_inert_dofs_are_condensed(monkeypatch):
    """A BeamContact3D multiplier node's two inert dofs (unit stiffness, coupled to nothing) go
    with the constant part: the dense interface holds each contact's soil node (3 dofs, less the
    fixed base) and its normal-force dof, not the inert ones (2 of the 4 equations per contact
    that would otherwise be dense)."""
    monkeypatch.setenv("BEAMSOLID_CONDENSE", "on")
    setup = dataclasses.replace(donut_pullout.DonutPullout(), n_theta=8, n_radial=2, n_z=4, steps=4)
    model = donut_pullout.DonutModel(setup).build()
    model.geostatic()
    model.release()  # the pile free along its axis, the head's motion imposed
    assert model.m.analyze(1) == 0
    info = model.m.solver_info()
    contacts = setup.n_theta * (setup.n_z + 1)
    base = setup.n_theta  # soil nodes of the deepest level: z fixed
    pile = len(model.pile_nodes) - 1  # the axial dof of each pile node but the head's
    assert info["condensed"]
    assert info["interface"] == 3 * contacts - base + contacts + pile
    assert info["interior"] + info["interface"] == info["equations"]
    model.m.wipe()


def _donut_push(setup):
    """Both stages of a small donut pullout; the pull's head forces and displacements and the
    push stage's solver_info."""
    model = donut_pullout.DonutModel(setup).build()
    model.geostatic()
    model.release()
    r = donut_pullout.PulloutResult(setup=setup, n_contacts=len(model.contacts))
    model.record(r)
    model.pull(r, None)
    info = model.m.solver_info()
    model.m.wipe()
    return np.array(r.head_force), np.array(r.head_disp), info


def test_a_rebuilt_model_reuses_its_condensation_exactly(monkeypatch):
    """A sweep that wipes and rebuilds the same soil (here: another friction coefficient) gets the
    condensation of the first build back (CondensationCache): the same answers, bit for bit, as
    condensing again; a changed soil is condensed afresh; BEAMSOLID_CONDENSE_CACHE=off stops it."""
    monkeypatch.delenv("BEAMSOLID_CONDENSE_CACHE")
    monkeypatch.setenv("BEAMSOLID_CONDENSE", "on")
    # A soil modulus no other test uses: the first build cannot find an earlier condensation.
    first = dataclasses.replace(donut_pullout.DonutPullout(), n_theta=8, n_radial=2, n_z=4, steps=4,
                                soil_E=20e3 * 1.000123, mu=0.5)
    f1, d1, info1 = _donut_push(first)
    assert info1["condensations"] == 1 and info1["condensations_reused"] == 0
    other_mu = dataclasses.replace(first, mu=0.3)
    f2, d2, info2 = _donut_push(other_mu)
    assert info2["condensations"] == 0 and info2["condensations_reused"] == 1
    monkeypatch.setenv("BEAMSOLID_CONDENSE_CACHE", "off")
    f3, d3, info3 = _donut_push(other_mu)
    assert info3["condensations"] == 1 and info3["condensations_reused"] == 0
    assert np.array_equal(f2, f3) and np.array_equal(d2, d3)
    monkeypatch.delenv("BEAMSOLID_CONDENSE_CACHE")
    # The plain solve agrees (to the tolerance of any two solvers).
    monkeypatch.setenv("BEAMSOLID_CONDENSE", "off")
    f4, d4, _ = _donut_push(other_mu)
    assert _close(f2, f4) and _close(d2, d4)
    # Another soil: condensed afresh.
    monkeypatch.setenv("BEAMSOLID_CONDENSE", "on")
    f5, _, info5 = _donut_push(dataclasses.replace(other_mu, soil_E=other_mu.soil_E * 2))
    assert info5["condensations"] == 1 and info5["condensations_reused"] == 0
    assert not np.allclose(f5, f2, rtol=1e-3)


def _pullout(m):
    """test_pile_interface's chained pullout: a pile pulled 1.1 through a confined soil donut, every
    soil node handed over to the next segment on the way."""
    import test_pile_interface as tpi
    from beamsolid import contact

    m.wipe()
    pile, donut, iface = tpi.build_pullout(m, levels=(1.8, 0.2), n_z=4, n_theta=8)
    tpi.confine(m, donut)
    tpi.start_pull(m, pile[-1], 1.1)
    tpi.analysis(m, 1.0 / 22)
    # Converged far below the comparison's 1e-9: a steady slide converges in one iteration,
    # which leaves each run within the default test's 1e-6 but not within 1e-9 of the other.
    m.test("NormDispIncr", 1e-12, 30)
    states = []
    for step in range(22):
        assert m.analyze(1) == 0, m.last_error()
        states.append(_state(m))
    f = contact.interface_forces(m, iface)
    info = m.solver_info()
    m.wipe()
    return np.array(states), f.hand_overs, info


@pytest.mark.parametrize("reuse", ["off", "always"])
def test_hand_overs_condensed_equal_plain(monkeypatch, reuse):
    monkeypatch.setenv("BEAMSOLID_INTERFACE_REUSE", reuse)
    m = beamsolid.Model()
    monkeypatch.setenv("BEAMSOLID_CONDENSE", "off")
    plain, plain_handed, _ = _pullout(m)
    monkeypatch.setenv("BEAMSOLID_CONDENSE", "on")
    cond, handed, info = _pullout(m)
    assert info["condensed"] and info["interior"] > 0
    assert plain_handed == handed > 0
    assert _close(cond, plain)
    if reuse == "always":  # the contacts' rows change: GMRES with an earlier factorization of S
        assert info["krylov_iterations"] > 0 and info["interface_factorizations"] < info["factorizations"]


def _fiber_pile(m, condense, algorithm="Newton"):
    """A fiber pile (forceBeamColumn, Steel01 fibers of a circular section that yield) in an elastic
    stdBrick O-grid, tied to the soil's surface nodes by rigidLink 'beam' (the tip pinned on the fixed
    base); the head pushed sideways."""
    from beamsolid import mesh

    m.wipe()
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.nDMaterial("ElasticIsotropic", 1, 2.0e4, 0.3)
    levels = [0.0, -1.0, -2.0, -3.0, -4.0]
    soil = mesh.ogrid(m, pile_radius=0.4, outer_size=4.0, outer="circle", n_theta=8, n_radial=3, radial_ratio=1.8,
                      levels=levels, material_tag=1, first_node=1001, first_element=1001)
    mesh.fix_soil_boundary(m, soil)
    m.model("basic", "-ndm", 3, "-ndf", 6)
    pile = list(range(1, len(levels) + 1))
    for tag, z in zip(pile, levels):
        m.node(tag, 0.0, 0.0, z)
    m.uniaxialMaterial("Steel01", 1, 2.0e3, 2.0e6, 0.02)
    m.section("Fiber", 1, "-GJ", 1.0e5)
    m.patch("circ", 1, 8, 2, 0.0, 0.0, 0.2, 0.4, 0.0, 360.0)
    m.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    m.beamIntegration("Lobatto", 1, 1, 3)
    for e in range(len(levels) - 1):
        m.element("forceBeamColumn", e + 1, pile[e], pile[e + 1], 1, 1)
    for k in range(len(levels) - 1):  # the base ring is fixed
        for s in soil.surfaces[0][k]:
            m.rigidLink("beam", pile[k], s)
    m.fix(pile[-1], 1, 1, 1, 0, 0, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(pile[0], 400.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    m.constraints("Transformation")
    m.numberer("RCM")
    m.system("UmfPack", "-condense", "on" if condense else "off")
    m.test("NormDispIncr", 1e-10, 50)
    m.algorithm(algorithm)
    m.integrator("LoadControl", 0.25)
    m.analysis("Static")
    states, iters = [], []
    for _ in range(4):
        assert m.analyze(1) == 0, m.last_error()
        states.append(_state(m))
        iters.append(m.testIter())
    info = m.solver_info()
    m.wipe()
    return np.array(states), iters, info


@pytest.mark.parametrize("reuse", ["off", "always"])
@pytest.mark.parametrize("algorithm", ["Newton", "NewtonLineSearch"])
def test_fiber_pile_in_elastic_soil_condensed_equals_plain(monkeypatch, reuse, algorithm):
    monkeypatch.setenv("BEAMSOLID_INTERFACE_REUSE", reuse)
    m = beamsolid.Model()
    plain, plain_iters, _ = _fiber_pile(m, False, algorithm)
    cond, iters, info = _fiber_pile(m, True, algorithm)
    assert info["condensed"] and info["interior"] > info["interface"] > 0
    assert info["condensations"] == 1
    assert iters == plain_iters and max(iters) > 2  # the fibers yield: a nonlinear pile
    assert _close(cond, plain)
    if reuse == "always":
        assert info["krylov_iterations"] > 0 and info["interface_factorizations"] < info["factorizations"]
