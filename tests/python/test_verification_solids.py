"""stdBrick through the Python commands: oedometer, patch test, body forces, beam-on-block.

Trilinear bricks reproduce linear displacement fields exactly on any mesh,
and a laterally confined column is a 1D bar whose nodal values are exact
with consistent body forces; these checks use a relative tolerance of 1e-10.
"""
import numpy as np
import pytest

import beamsolid

E_SOIL, NU = 25.0e3, 0.3
M_OED = E_SOIL * (1 - NU) / ((1 + NU) * (1 - 2 * NU))  # constrained modulus


def assert_close(actual, expected, rtol=1e-10, scale=None):
    actual, expected = np.asarray(actual, float), np.asarray(expected, float)
    scale = np.max(np.abs(expected)) if scale is None else scale
    assert scale > 0.0
    err = np.max(np.abs(actual - expected)) / scale
    assert err <= rtol, f"relative error {err:.3e} > {rtol:.0e}"


class BrickGrid:
    """A structured nx x ny x nz brick mesh on a box, node tags from `first`."""

    def __init__(self, m, size, counts, origin=(0.0, 0.0, 0.0), first_node=1, first_ele=1, mat=1,
                 body=(0.0, 0.0, 0.0), jitter=0.0, seed=0):
        self.counts = nx, ny, nz = counts
        self.first = first_node
        rng = np.random.default_rng(seed)
        self.coords = {}
        for k in range(nz + 1):
            for j in range(ny + 1):
                for i in range(nx + 1):
                    x = np.array(origin) + np.array(size) * np.array([i / nx, j / ny, k / nz])
                    if jitter:
                        h = np.array(size) / np.array(counts)
                        x = x + jitter * h * rng.uniform(-1.0, 1.0, 3)
                    tag = self.tag(i, j, k)
                    self.coords[tag] = x
                    m.node(tag, *x, "-ndf", 3)
        self.elements = []
        e = first_ele
        for k in range(nz):
            for j in range(ny):
                for i in range(nx):
                    nodes = [self.tag(i, j, k), self.tag(i + 1, j, k), self.tag(i + 1, j + 1, k), self.tag(i, j + 1, k),
                             self.tag(i, j, k + 1), self.tag(i + 1, j, k + 1), self.tag(i + 1, j + 1, k + 1),
                             self.tag(i, j + 1, k + 1)]
                    m.element("stdBrick", e, *nodes, mat, *body)
                    self.elements.append(e)
                    e += 1

    def tag(self, i, j, k):
        nx, ny, _ = self.counts
        return self.first + i + (nx + 1) * (j + (ny + 1) * k)

    def face(self, axis, index):
        nx, ny, nz = self.counts
        out = []
        for k in range(nz + 1):
            for j in range(ny + 1):
                for i in range(nx + 1):
                    if (i, j, k)[axis] == index:
                        out.append(self.tag(i, j, k))
        return out

    def boundary(self):
        nx, ny, nz = self.counts
        return sorted({t for a, n in enumerate((nx, ny, nz)) for idx in (0, n) for t in self.face(a, idx)})


def static(m, system="UmfPack", steps=1):
    m.constraints("Transformation")
    m.numberer("RCM")
    m.system(system)
    m.test("NormDispIncr", 1e-12, 10)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0 / steps)
    m.analysis("Static")
    assert m.analyze(steps) == 0


def confine_laterally(m, size):
    """Rollers on the four side faces, fixed base: a 1D (oedometric) column."""
    m.fixX(0.0, 1, 0, 0)
    m.fixX(size[0], 1, 0, 0)
    m.fixY(0.0, 0, 1, 0)
    m.fixY(size[1], 0, 1, 0)
    m.fixZ(0.0, 0, 0, 1)


def gauss_stresses(m, elements):
    return np.array([np.reshape(m.eleResponse(e, "stresses"), (8, 6)) for e in elements])


def test_oedometric_compression(model):
    """Imposed top settlement: sigma_zz = M eps_zz, sigma_xx = sigma_yy = nu/(1-nu) sigma_zz."""
    m = model
    size = (1.0, 1.0, 2.0)
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.nDMaterial("ElasticIsotropic", 1, E_SOIL, NU)
    g = BrickGrid(m, size, (2, 2, 2))
    confine_laterally(m, size)
    settlement = -0.004
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    top = g.face(2, 2)
    for t in top:
        m.sp(t, 3, settlement)
    static(m, steps=2)

    eps = settlement / size[2]
    s = gauss_stresses(m, g.elements)
    sz = M_OED * eps
    assert_close(s[:, :, 2], np.full((8, 8), sz))
    assert_close(s[:, :, 0], np.full((8, 8), NU / (1 - NU) * sz))
    assert_close(s[:, :, 1], np.full((8, 8), NU / (1 - NU) * sz))
    assert_close(s[:, :, 3:], 0.0, scale=abs(sz))
    for t, x in g.coords.items():
        assert_close(m.nodeDisp(t), [0.0, 0.0, eps * x[2]], scale=abs(settlement))
    m.reactions()
    assert_close(sum(m.nodeReaction(t, 3) for t in top), sz * size[0] * size[1])
    assert_close(sum(m.nodeReaction(t, 3) for t in g.face(2, 0)), -sz * size[0] * size[1])


def test_distorted_mesh_patch_test(model):
    """Linear field imposed through fix and sp on every boundary node of a distorted 3x3x3 mesh."""
    m = model
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.nDMaterial("ElasticIsotropic", 1, E_SOIL, NU)
    g = BrickGrid(m, (2.0, 1.5, 1.0), (3, 3, 3), jitter=0.2, seed=11)
    grad = np.array([[1.0, 0.4, -0.3], [0.2, -0.5, 0.6], [-0.7, 0.1, 0.8]]) * 1e-3
    anchor = g.tag(0, 0, 0)
    shift = -grad @ g.coords[anchor]  # the anchor node stays put: it is fixed

    def field(x):
        return grad @ x + shift

    m.fix(anchor, 1, 1, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    boundary = g.boundary()
    for t in boundary:
        if t != anchor:
            for d in range(3):
                m.sp(t, d + 1, field(g.coords[t])[d])
    static(m)

    interior = [t for t in g.coords if t not in boundary]
    assert len(interior) == 8
    for t in interior:
        assert_close(m.nodeDisp(t), field(g.coords[t]), scale=np.abs(grad).max())
    eps = 0.5 * (grad + grad.T)
    strain = np.array([eps[0, 0], eps[1, 1], eps[2, 2], 2 * eps[0, 1], 2 * eps[1, 2], 2 * eps[0, 2]])
    lam = E_SOIL * NU / ((1 + NU) * (1 - 2 * NU))
    mu = E_SOIL / (2 * (1 + NU))
    sig = lam * np.trace(eps) * np.eye(3) + 2 * mu * eps
    stress = np.array([sig[0, 0], sig[1, 1], sig[2, 2], sig[0, 1], sig[1, 2], sig[0, 2]])
    for e in g.elements:
        assert_close(np.reshape(m.eleResponse(e, "strains"), (8, 6)), np.tile(strain, (8, 1)))
        assert_close(np.reshape(m.eleResponse(e, "stresses"), (8, 6)), np.tile(stress, (8, 1)))
    # Interior nodes carry no load: the unbalance there is zero.
    m.reactions()
    for t in interior:
        assert_close(m.nodeReaction(t), [0.0] * 3, scale=abs(stress).max())


@pytest.mark.parametrize("how", ["element body force", "eleLoad -selfWeight"])
def test_body_force_column(model, how):
    """Confined column under its weight: base reaction gamma V, u(z) = -gamma (H z - z^2/2) / M."""
    m = model
    size, nz = (1.0, 0.5, 4.0), 4
    gamma = 18.0
    m.model("basic", "-ndm", 3, "-ndf", 3)
    if how == "element body force":
        m.nDMaterial("ElasticIsotropic", 1, E_SOIL, NU)
        g = BrickGrid(m, size, (1, 1, nz), body=(0.0, 0.0, -gamma))
    else:
        # OpenSees' -selfWeight fx fy fz on a stdBrick scales the element's own
        # body-force arguments (lambda * (fx b1, fy b2, fz b3)); density is not used.
        m.nDMaterial("ElasticIsotropic", 1, E_SOIL, NU)
        g = BrickGrid(m, size, (1, 1, nz), body=(0.0, 0.0, -gamma))
    confine_laterally(m, size)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    if how == "eleLoad -selfWeight":
        m.eleLoad("-ele", *g.elements, "-type", "-selfWeight", 0.0, 0.0, 1.0)
    static(m)

    H = size[2]
    for t, x in g.coords.items():
        z = x[2]
        assert_close(m.nodeDisp(t), [0.0, 0.0, -gamma * (H * z - z * z / 2) / M_OED], scale=gamma * H * H / M_OED)
    m.reactions()
    volume = np.prod(size)
    assert_close(sum(m.nodeReaction(t, 3) for t in g.face(2, 0)), gamma * volume)
    # Element strain is the chord of the exact (linear) strain: exact at mid-height.
    for k, e in enumerate(g.elements):
        z_mid = (k + 0.5) * H / nz
        s = np.reshape(m.eleResponse(e, "stresses"), (8, 6))
        assert_close(s[:, 2], np.full(8, -gamma * (H - z_mid)), scale=gamma * H)


def beam_on_block(m, tie):
    """A 2-element beam column standing on a 2x2x2 brick block; returns the tip and base node tags."""
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.nDMaterial("ElasticIsotropic", 1, E_SOIL, NU)
    g = BrickGrid(m, (1.0, 1.0, 1.0), (2, 2, 2))
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    base, mid, tip = 101, 102, 103
    for t, z in ((base, 1.0), (mid, 2.0), (tip, 3.0)):
        m.node(t, 0.5, 0.5, z)
    m.element("elasticBeamColumn", 101, base, mid, BEAM_A, BEAM_E, BEAM_E / 2.5, 1e-3, BEAM_I, BEAM_I, 1)
    m.element("elasticBeamColumn", 102, mid, tip, BEAM_A, BEAM_E, BEAM_E / 2.5, 1e-3, BEAM_I, BEAM_I, 1)
    tie(m, g, base)
    return g, base, tip


BEAM_A, BEAM_E, BEAM_I = 0.01, 2.0e8, 1e-5


def test_beam_column_on_confined_block_tied_by_equaldof(model):
    """Axial load through equalDOF(base, every top node, 3): u = -P Lc/EA - P Hb/(M A)."""
    def tie(m, g, base):
        confine_laterally(m, (1.0, 1.0, 1.0))
        m.fix(base, 1, 1, 0, 1, 1, 1)
        for t in g.face(2, 2):
            m.equalDOF(base, t, 3)

    m = model
    g, base, tip = beam_on_block(m, tie)
    P = 30.0
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(tip, 0.0, 0.0, -P, 0.0, 0.0, 0.0)
    static(m)
    block = -P * 1.0 / (M_OED * 1.0)
    assert_close(m.nodeDisp(base, 3), block)
    assert_close(m.nodeDisp(tip, 3), block - P * 2.0 / (BEAM_E * BEAM_A))
    s = gauss_stresses(m, g.elements)
    assert_close(s[:, :, 2], np.full((8, 8), -P))
    assert_close(s[:, :, 0], np.full((8, 8), -P * NU / (1 - NU)))
    assert_close(m.eleResponse(102, "localForce")[6], -P)


def test_beam_column_on_block_matches_block_alone(model):
    """equalDOF(base, block top centre, 1 2 3): tip = beam cantilever + block under the same point force."""
    def tie(m, g, base):
        m.fixZ(0.0, 1, 1, 1)
        m.fix(base, 0, 0, 0, 1, 1, 1)
        m.equalDOF(base, g.tag(1, 1, 2), 1, 2, 3)

    F = np.array([4.0, -2.5, -30.0])
    m = model
    g, base, tip = beam_on_block(m, tie)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(tip, *F, 0.0, 0.0, 0.0)
    static(m)

    # The independent solution: the block alone under F at its top centre node.
    b = beamsolid.Model()
    b.model("basic", "-ndm", 3, "-ndf", 3)
    b.nDMaterial("ElasticIsotropic", 1, E_SOIL, NU)
    gb = BrickGrid(b, (1.0, 1.0, 1.0), (2, 2, 2))
    b.fixZ(0.0, 1, 1, 1)
    b.timeSeries("Linear", 1)
    b.pattern("Plain", 1, 1)
    b.load(gb.tag(1, 1, 2), *F)
    static(b)
    block = np.array(b.nodeDisp(gb.tag(1, 1, 2)))
    block_nodes = {t: b.nodeDisp(t) for t in gb.coords}
    b.wipe()

    Lc = 2.0
    beam = np.array([F[0] * Lc**3 / (3 * BEAM_E * BEAM_I), F[1] * Lc**3 / (3 * BEAM_E * BEAM_I),
                     F[2] * Lc / (BEAM_E * BEAM_A)])
    assert_close(m.nodeDisp(base)[:3], block)
    assert_close(m.nodeDisp(tip)[:3], block + beam)
    scale = np.abs(block).max()
    for t in g.coords:
        assert_close(m.nodeDisp(t), block_nodes[t], scale=scale)
