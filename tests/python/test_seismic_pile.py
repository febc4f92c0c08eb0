"""The seismic pile scene (issue 16): equilibrium, the free field, contact against tied.

Coarse meshes and short windows of the shipped record keep every test to seconds.
"""
import math
import re

import numpy as np
import pytest

from beamsolid.scenes import seismic_pile as sp


def test_soil_box_alone_moves_like_the_1d_shear_column():
    # Periodic sides make every soil column of a homogeneous box move alike: the box's surface
    # motion is the column's of one brick per layer with the same levels, mass per area and
    # Rayleigh damping (a brick's nodal forces under a stress uniform in plan cancel between plan
    # neighbours, and the tied sides cancel each other). Equal to round-off and the Newton tolerance.
    problem = sp.SeismicPile(duration=1.5, scale=1.0)
    numerics = sp.Numerics(level="coarse", interface="none")
    box = sp.run(problem, numerics)
    times, column = sp.run_column(problem, numerics)
    assert box.converged and len(box.surface_disp) == len(column)
    peak = max(abs(u) for u in column)
    assert peak > 1e-3  # the motion is not trivial (PGA 0.3 g)
    worst = max(abs(a - b) for a, b in zip(box.surface_disp, column))
    assert worst <= 1e-8 * peak, worst / peak


def _fixed_row_coupling(m, elements, rho, fixed):
    """{free node b: sum over fixed nodes f of the consistent mass M_fb = rho int N_f N_b dV}
    (2 x 2 x 2 Gauss quadrature, exact for trilinear bricks)."""
    g = 1.0 / math.sqrt(3.0)
    signs = [(-1, -1, -1), (1, -1, -1), (1, 1, -1), (-1, 1, -1), (-1, -1, 1), (1, -1, 1), (1, 1, 1), (-1, 1, 1)]
    coupling = {}
    for e in elements:
        nodes = m.eleNodes(e)
        if not fixed.intersection(nodes):
            continue
        X = np.array([m.nodeCoord(t) for t in nodes])
        for gp in signs:
            xi = np.array(gp, dtype=float) * g
            N = np.array([(1 + s[0] * xi[0]) * (1 + s[1] * xi[1]) * (1 + s[2] * xi[2]) / 8.0 for s in signs])
            dN = np.array([[s[0] * (1 + s[1] * xi[1]) * (1 + s[2] * xi[2]) / 8.0,
                            s[1] * (1 + s[0] * xi[0]) * (1 + s[2] * xi[2]) / 8.0,
                            s[2] * (1 + s[0] * xi[0]) * (1 + s[1] * xi[1]) / 8.0] for s in signs])
            detJ = abs(np.linalg.det(dN.T @ X))
            for a, f in enumerate(nodes):
                if f not in fixed:
                    continue
                for b, t in enumerate(nodes):
                    if t not in fixed:
                        coupling[t] = coupling.get(t, 0.0) + rho * N[a] * N[b] * detJ
    return coupling


@pytest.fixture(scope="module")
def recorded_equilibrium():
    """A contact run with the base reactions and the motion of every node after each step."""
    problem = sp.SeismicPile(duration=1.0, scale=0.1, head_mass=5.0)
    states = []

    def on_step(model, t):
        m = model.m
        if not hasattr(model, "_masses"):
            masses = sp.lumped_masses(m, model.mesh.elements, problem.soil_rho)
            half = 0.5 * problem.pile_density * problem.area
            for e in model.beams:
                i, j = m.eleNodes(e)
                length = abs(m.nodeCoord(i, 3) - m.nodeCoord(j, 3))
                for n in (i, j):
                    masses[n] = masses.get(n, 0.0) + half * length
            masses[model.pile_nodes[0]] += problem.head_mass  # nodal mass (ops.mass)
            model._masses = masses
        fixed = model.base_nodes + [model.pile_nodes[-1]]
        if not hasattr(model, "_coupling"):
            model._coupling = _fixed_row_coupling(m, model.mesh.elements, problem.soil_rho, set(fixed))
        m.reactions()
        static = sum(m.nodeReaction(n, 1) for n in fixed)
        m.reactions("-rayleigh")
        damping_at_base = sum(m.nodeReaction(n, 1) for n in fixed)
        ag = model.ground_accel(t)
        # stdBrick's mass is consistent: the fixed nodes' rows couple them to the free nodes'
        # accelerations, which the static reactions do not hold
        inertia = sum(mass * (m.nodeAccel(n, 1) + ag) for n, mass in model._masses.items())
        inertia -= sum(c * m.nodeAccel(n, 1) for n, c in model._coupling.items())
        momentum = sum(mass * m.nodeVel(n, 1) for n, mass in model._masses.items())
        states.append((t, static, damping_at_base, inertia, momentum, model))

    result = sp.run(problem, sp.Numerics(level="coarse", interface="contact"), on_step=on_step)
    return problem, result, states


def test_base_reaction_balances_inertia_and_damping(recorded_equilibrium):
    # Horizontal equilibrium of the whole model, relative formulation (UniformExcitation):
    #   R_base = sum_i m_i (a_i + a_g) + alphaM sum_i m_i v_i - R_rayleigh,base.
    # R_base: reactions() at the fixed base nodes and the pinned tip (they include m a_g of the
    # base nodes' own mass, which UniformExcitation loads). The mass-proportional damping acts on
    # the relative velocity of every node, so it is held by the bedrock's frame, not the base;
    # the stiffness-proportional part C v = betaK K v sums to zero over all dofs (K 1 = 0), so
    # what the free dofs lose reaches the base: reactions('-rayleigh') there (with the fixed rows'
    # share of alphaM M v, which the consistent brick mass couples to the free nodes). Masses: the
    # bricks' row sums rho * int N_a dV (own Gauss quadrature; stdBrick's mass is consistent, so
    # sum_b M_ab a_b over all rows is that), less the fixed rows' coupling M_fb a_b that the static
    # reactions do not hold; half of each pile element's m L; the head mass.
    problem, result, states = recorded_equilibrium
    assert result.converged and len(states) == 100
    alpha_m, _ = problem.rayleigh
    total_mass = sum(states[0][5]._masses.values())
    volume = (2 * problem.half_width) ** 2 * problem.depth - problem.area * problem.depth
    # The O-grid's pile surface is a polygon: its hole is smaller than the circle.
    assert total_mass == pytest.approx(problem.soil_rho * volume + problem.pile_density * problem.area
                                       * problem.depth + problem.head_mass, rel=2e-3)
    scale = max(abs(s[3]) for s in states)
    assert scale > 50.0  # kN: the motion is not trivial (82 kN)
    worst = max(abs(static + damping - inertia - alpha_m * momentum) for _, static, damping, inertia, momentum, _
                in states)
    assert worst <= 1e-6 * scale, worst / scale
    # The damping terms matter: leaving them out breaks the balance by far more.
    without = max(abs(static - inertia) for _, static, _, inertia, _, _ in states)
    assert without > 1e3 * worst


def test_contact_and_tied_agree_while_the_interface_stays_closed():
    # At PGA 0.015 g the geostatic contact forces exceed every dynamic change: no contact opens,
    # and the Lagrange-multiplier interface is the tied one but for ContactMaterial3D's finite
    # stick stiffness (1e5 kN/m per node against the rigidLinks): within 2 % at the head and
    # 6 % on the largest moment.
    problem = sp.SeismicPile(duration=1.0, scale=0.05)
    contact = sp.run(problem, sp.Numerics(level="coarse", interface="contact"))
    tied = sp.run(problem, sp.Numerics(level="coarse", interface="tied"))
    assert contact.converged and tied.converged
    assert max(contact.n_open) == 0 and max(contact.max_gap) == 0.0
    assert contact.peak_head_disp == pytest.approx(tied.peak_head_disp, rel=0.02)
    assert max(contact.moment_envelope) == pytest.approx(max(tied.moment_envelope), rel=0.06)
    history = max(abs(a - b) for a, b in zip(contact.head_disp, tied.head_disp))
    assert history <= 0.05 * tied.peak_head_disp


def test_contact_opens_a_gap_at_large_amplitude():
    # The full record (PGA 0.3 g): the pile lags the soil near the surface and contacts open.
    problem = sp.SeismicPile(duration=1.1, scale=1.0)
    r = sp.run(problem, sp.Numerics(level="coarse", interface="contact"))
    assert r.converged
    assert max(r.n_open) >= 1
    assert r.peak_gap > 1e-6
    small = sp.run(sp.SeismicPile(duration=1.1, scale=0.05), sp.Numerics(level="coarse", interface="contact"))
    assert max(small.n_open) == 0


def test_pvd_holds_displacements_velocities_and_accelerations(tmp_path):
    problem = sp.SeismicPile(duration=0.1, scale=1.0)
    r = sp.run(problem, sp.Numerics(level="coarse", interface="tied", pvd_dt=0.05), out=tmp_path, record=True)
    assert r.converged
    pvd = (tmp_path / "seismic_pile.pvd").read_text()
    # -dT 0.05: the first commit (t = 0.01), then once 0.05 has passed (0.06); 0.11 is beyond the run.
    assert [float(t) for t in re.findall(r'timestep="([^"]+)"', pvd)] == pytest.approx([0.01, 0.06])
    last = (tmp_path / re.findall(r'file="([^"]+)"', pvd)[-1]).read_text()
    for name in ("displacement", "velocity", "acceleration"):
        assert f'Name="{name}"' in last
    # The head's absolute acceleration recorder (-timeSeries: relative + ground) against nodeAccel + a_g.
    rows = [list(map(float, line.split())) for line in (tmp_path / "head_accel_abs.out").read_text().split("\n")
            if line.strip()]
    assert rows[-1][0] == pytest.approx(0.1)
    assert rows[-1][1] == pytest.approx(r.head_accel[-1], rel=1e-5)  # 6 digits in the file
    assert math.isfinite(rows[-1][1])


def test_contact_takes_no_rayleigh_damping_and_recloses_under_it():
    # A soil node on a spring (zeroLength: no Rayleigh damping by default) pressed onto a fixed pile
    # segment, pulled off, then slowly pressed again, under rayleigh(alphaM, betaK, 0, 0) with
    # betaK / dt as in the scene (alphaM damps the node's free vibration so that it comes back
    # slowly). The contact element gives no damping force (reactions('-rayleigh') at the node holds
    # alphaM m v only), and the node closes at the first commit after it touches the pile. With
    # betaK on the multiplier row, lambda + betaK dlambda/dt = 0 under Newmark made a released
    # node's lambda alternate in sign, decaying by (betaK - dt/2) / (betaK + dt/2) = -0.67 a step,
    # and the node sank into the pile for some 50 steps before it could close.
    from beamsolid import Model

    m = Model()
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, 0.0, 0.0, 2.0)
    for n in (1, 2):
        m.fix(n, 1, 1, 1, 1, 1, 1)
    m.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    m.element("elasticBeamColumn", 10, 1, 2, 0.28, 3e7, 1.2e7, 0.0127, 0.0064, 0.0064, 1)
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(3, 0.3, 0.0, 1.0, "-mass", 1.0, 1.0, 1.0)
    m.node(4, 0.3, 0.0, 1.0)
    m.node(8, 0.3, 0.0, 1.0)
    m.fix(8, 1, 1, 1)
    m.uniaxialMaterial("Elastic", 3, 1e3)
    m.element("zeroLength", 30, 3, 8, "-mat", 3, 3, 3, "-dir", 1, 2, 3)
    m.nDMaterial("ContactMaterial3D", 1, 0.3, 1e5, 0.0, 0.0)
    m.element("BeamContact3D", 21, 1, 2, 3, 4, 0.3, 1, 1, 1e-8, 1e-8)
    # x: pressed (-10 kN) until 0.3 s, pulled (+10) until 0.8 s, back to pressing by 1.6 s; z: a small shear.
    m.timeSeries("Path", 1, "-time", 0.0, 0.3, 0.31, 0.8, 1.6, 2.5, "-values", -1.0, -1.0, 1.0, 1.0, -1.0, -1.0)
    m.timeSeries("Trig", 2, 0.0, 2.0, 0.25)
    m.pattern("Plain", 1, 1)
    m.load(3, 10.0, 0.0, 0.0)
    m.pattern("Plain", 2, 2)
    m.load(3, 0.0, 0.0, 1.0)
    alpha_m = 40.0
    m.rayleigh(alpha_m, 1e-3, 0.0, 0.0)
    m.constraints("Transformation")
    m.numberer("Plain")
    m.system("UmfPack")
    m.test("NormUnbalance", 1e-8, 25)
    m.algorithm("Newton")
    m.integrator("Newmark", 0.5, 0.25)
    m.analysis("Transient")
    status, damping, speed, gap = [], [], [], []
    while len(status) < 200 and not (len(status) > 80 and gap[-2] < 0.0):  # one step past the touch
        assert m.analyze(1, 0.01) == 0
        status.append(m.eleResponse(21, "status")[0])
        gap.append(m.eleResponse(21, "gap")[0])
        m.reactions("-rayleigh")
        damping.append(max(abs(m.nodeReaction(3, d) - alpha_m * m.nodeVel(3, d)) for d in (1, 3)))
        speed.append(abs(m.nodeVel(3, 3)))
    assert max(speed[:30]) > 1e-6  # it sticks elastically while pressed: K_contact v != 0
    assert max(damping) <= 1e-12
    assert status[25] != 0.0 and all(s == 0.0 for s in status[40:80])  # pressed, then released
    assert len(status) < 200 and status[-1] != 0.0  # in contact at the commit after the touch
    assert gap[-2] > -1e-6  # it touched, it did not sink in


def test_scene_command_line_writes_its_files(tmp_path, capsys):
    from beamsolid.scenes.__main__ import main

    assert main(["seismic_pile", "--interface", "tied", "--steps", "10", "--head-mass", "5", "--scale", "1",
                 "--out", str(tmp_path)]) == 0
    printed = capsys.readouterr().out
    assert "head mass 5 t" in printed and "x 1, first 3 s, dt = 0.3" in printed
    for name in ("head_accel_abs.out", "pile_forces.out", "seismic_pile.pvd", "head_response.png",
                 "moment_envelope.png"):
        assert (tmp_path / name).stat().st_size > 0


def test_py_springs_carry_a_pile_without_stiffness_along_the_free_field():
    # A pile with (almost) no bending stiffness and mass loads its p-y springs with nothing: every
    # pile node then moves with its spring's far end, which the scene drives with the 1D column's
    # displacement at that node's level. Checks the drive (sign, level, time) against the column
    # run on its own, to the springs' deflection under the pile's residual forces (~1e-9 relative).
    problem = sp.SeismicPile(duration=1.0, scale=1.0, pile_E=1e-3, pile_density=1e-9)
    numerics = sp.Numerics(level="coarse", interface="py", dt=0.01)
    r = sp.run(problem, numerics)
    times, disp, _ = sp.run_column(problem, sp.Numerics(level="coarse", interface="none", dt=0.01), all_levels=True)
    assert r.converged and r.n_springs == len(r.z)  # one element (x and y springs) per pile node
    peak = max(abs(u) for u in disp[0])
    assert peak > 5e-4  # 1.3 mm in the first second
    worst = max(abs(a - b) for a, b in zip(r.head_disp, disp[0]))
    assert worst <= 1e-6 * peak, worst / peak
    assert r.surface_disp == pytest.approx(disp[0], abs=1e-15)


def test_py_springs_scene_runs_beside_contact_and_tied():
    # The default motion (PGA 0.015 g): the three models agree on the head displacement within the
    # spread of their soil reactions (p-y springs are calibrated to strength, Matlock's initial
    # stiffness, not to the elastic box): within 25 % of the tied model's peak (measured 7 % over 3 s).
    problem = sp.SeismicPile(duration=1.5)
    tied = sp.run(problem, sp.Numerics(level="coarse", interface="tied"))
    py = sp.run(problem, sp.Numerics(level="coarse", interface="py"))
    assert tied.converged and py.converged
    assert py.peak_head_disp == pytest.approx(tied.peak_head_disp, rel=0.25)
    assert max(py.moment_envelope) > 0.0
