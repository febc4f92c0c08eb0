"""The bridge bent scene (coarse): equilibrium, symmetry, where the gaps open, the geostatic
closed form, and the files it writes."""
import math
import os
import xml.etree.ElementTree as ET

import pytest

from beamsolid.scenes.bridge_bent import BridgeBent, main, run


@pytest.fixture(scope="module", params=[3, 2], ids=["3piles", "2piles"])
def bent(request, tmp_path_factory):
    out = str(tmp_path_factory.mktemp(f"bent{request.param}"))
    setup = BridgeBent(level="coarse", n_piles=request.param, steps=6)
    return run(setup, out=out)


def test_every_step_converged(bent):
    assert bent.failed_step == 0 and len(bent.cap_disp) == bent.setup.steps + 1
    assert bent.cap_disp[-1] == pytest.approx(bent.setup.push, rel=1e-12)


def test_global_equilibrium(bent):
    """Cap force = sum of the pile head shears = minus the x reactions on the soil's x faces
    (bricks only), 1e-8 of the cap force, at every step."""
    for k in range(1, len(bent.cap_disp)):
        P = bent.cap_force[k]
        assert P > 0.0
        assert sum(bent.head_shear[k]) == pytest.approx(P, rel=1e-8)
        assert -bent.soil_reaction_x[k] == pytest.approx(P, rel=1e-8)


def test_contact_forces_carry_the_push(bent):
    """Cap force = sum of the x contact forces on the soil nodes (= minus those on the piles,
    which rest on nothing else), per pile = its head shear, 1e-8 of the cap force, at every
    step. Status is decided at the commit (docs/beam_contact.md): a contact that starts sliding
    there has its friction returned to the cone (those steps are held to 1e-3; observed 1e-4).
    A contact released or handed over at a commit still answers with the step's converged
    state (until session 4 one released and handed over in the same commit answered with the
    next step's, and those steps were skipped here); the hand-overs do happen in this run."""
    for k in range(1, len(bent.cap_disp)):
        P = bent.cap_force[k]
        changes = [(a, b) for s0, s1 in zip(bent.status[k - 1], bent.status[k]) for a, b in zip(s0, s1)]
        tol = 1e-3 if any(a == 1 and b == 2 for a, b in changes) else 1e-8
        assert sum(bent.contact_x[k]) == pytest.approx(P, rel=tol)
        for p in range(bent.setup.n_piles):
            assert bent.contact_x[k][p] == pytest.approx(bent.head_shear[k][p], abs=tol * P)
    assert sum(sum(h) for h in bent.handovers[-1]) > 0


def test_symmetric_about_the_row(bent):
    """The push along the row (x) keeps every pile symmetric in y: contact forces in y sum to
    zero, and the contacts at (angle, z) and (-angle, z) have the same status and normal force."""
    fmax = max(max(c.normal) for c in bent.final)
    for c in bent.final:
        assert abs(sum(c.force_y)) <= 1e-9 * fmax * len(c.force_y)
        at = {(round(a, 6), round(z, 9)): (st, n) for a, z, st, n in zip(c.angle, c.z, c.status, c.normal)}
        for (a, z), (st, n) in at.items():
            mirror = (round(-a, 6), z) if abs(abs(a) - 180.0) > 1e-6 else (a, z)
            assert at[mirror][0] == st
            assert at[mirror][1] == pytest.approx(n, abs=1e-9 * fmax)
    for row in bent.contact_y:
        assert all(abs(v) <= 1e-9 * fmax * len(bent.final[0].z) for v in row)


def test_trailing_sides_open_and_the_gap_deepens(bent):
    """Open contacts lie on the side away from the push (x <= pile axis) and start at the
    ground; the gap depth and the largest gap never decrease and end deeper than one layer."""
    s = bent.setup
    R = s.pile_radius
    top_layer = s.levels()[1]
    for p, c in enumerate(bent.final):
        opened = [k for k, st in enumerate(c.status) if st == 0]
        assert opened, f"pile {p} has no open contact"
        for k in opened:
            assert R * math.cos(math.radians(c.angle[k])) <= 1e-9 * R  # x - x_axis
        assert max(c.z[k] for k in opened) == pytest.approx(0.0, abs=1e-12)  # open at the ground
        assert bent.gap_depth[-1][p] > -top_layer  # below the first layer
        depth = [row[p] for row in bent.gap_depth]
        gap = [row[p] for row in bent.max_gap]
        assert all(b >= a for a, b in zip(depth, depth[1:]))
        assert all(b >= a - 1e-12 for a, b in zip(gap, gap[1:]))
        assert gap[-1] > 0.1 * s.push  # a visible opening: a fraction of the push


def test_geostatic_normal_sum_is_the_faceted_closed_form(bent):
    """Frictionless contacts, held piles, self weight: each pile's normal forces add up to
    n R sin(2 pi / n) integral_0^L K0 gamma z dz exactly (1e-8)."""
    s = bent.setup
    n = s.divisions["n_theta"]
    expected = n * s.pile_radius * math.sin(2 * math.pi / n) * s.K0 * s.gamma * s.embedded**2 / 2.0
    for v in bent.geostatic_normal_sum:
        assert v == pytest.approx(expected, rel=1e-8)


def test_vtu_files_hold_the_last_step(bent):
    """The last .vtu of the PVD collection, read with meshio, has the normal forces and
    statuses eleResponse gave at the last step (10 significant digits written)."""
    meshio = pytest.importorskip("meshio")
    pvd = bent.files["pvd"]
    sets = ET.parse(pvd).getroot().findall("./Collection/DataSet")
    assert len(sets) == bent.setup.steps + 1  # the geostatic state, then each step
    assert float(sets[-1].get("timestep")) == pytest.approx(bent.cap_force[-1], rel=1e-12)
    mesh = meshio.read(os.path.join(os.path.dirname(pvd), sets[-1].get("file")))
    block = [i for i, b in enumerate(mesh.cells) if b.type == "vertex"][0]
    tags = mesh.cell_data["elementTag"][block].ravel()
    normal = dict(zip(tags, mesh.cell_data["contactNormalForce"][block].ravel()))
    status = dict(zip(tags, mesh.cell_data["contactStatus"][block].ravel()))
    fmax = max(max(c.normal) for c in bent.final)
    count = 0
    for c in bent.final:
        for e, n, st in zip(c.elements, c.normal, c.status):
            assert normal[e] == pytest.approx(n, rel=1e-9, abs=1e-12 * fmax)
            assert status[e] == st
            count += 1
    assert count == len(tags) == bent.n_contacts


def test_recorder_files(bent):
    """Node recorder: time (cap force) then 6 dofs per pile head; Element recorder: 12 local
    forces per pile element. Last rows against the result."""
    s = bent.setup
    with open(bent.files["heads"]) as f:
        rows = [list(map(float, line.split())) for line in f if line.strip()]
    assert len(rows) == s.steps + 1 and len(rows[-1]) == 1 + 6 * s.n_piles
    assert rows[-1][0] == pytest.approx(bent.cap_force[-1], rel=1e-9)
    assert rows[-1][1 + 6 * s.loaded_pile] == pytest.approx(s.push, rel=1e-9)
    with open(bent.files["pile_forces"]) as f:
        rows = [list(map(float, line.split())) for line in f if line.strip()]
    assert len(rows) == s.steps + 1 and (len(rows[-1]) - 1) % 12 == 0


def test_cli_rejects_a_bad_level(capsys):
    with pytest.raises(SystemExit):
        main(["--level", "huge"])
    assert "huge" in capsys.readouterr().err


def test_bad_parameters():
    with pytest.raises(ValueError, match="level"):
        BridgeBent(level="huge")
    with pytest.raises(ValueError, match="n_piles"):
        BridgeBent(n_piles=0)
