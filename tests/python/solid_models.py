"""Small solid models shared by the locking and convergence tests and the
benchmarks: a quarter of a thick-walled cylinder under internal pressure
(Lame) and a cantilever in pure bending, meshed with any of the 4-node
quads (quad, bbarQuad, SSPquad) or 8-node bricks (stdBrick, bbarBrick,
SSPbrick), in plane strain. Each function builds the model through the
OpenSees commands of `m` (a beamsolid.Model, the beamsolid.opensees module
or openseespy.opensees), analyses it and returns what is compared.
"""
import math

import numpy as np

BRICKS = ("stdBrick", "bbarBrick", "SSPbrick")
QUADS = ("quad", "bbarQuad", "SSPquad")


def element(m, etype, tag, nodes, mat, thick=1.0):
    """One solid element of `etype` with its own argument form."""
    if etype == "quad":
        m.element("quad", tag, *nodes, thick, "PlaneStrain", mat)
    elif etype == "bbarQuad":
        m.element("bbarQuad", tag, *nodes, thick, mat)
    elif etype == "SSPquad":
        m.element("SSPquad", tag, *nodes, mat, "PlaneStrain", thick)
    else:
        m.element(etype, tag, *nodes, mat)


def _static_linear(m):
    m.constraints("Plain")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-12, 5)
    m.algorithm("Linear")
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")
    assert m.analyze(1) == 0


def plane_strain_grid(m, etype, point, ni, nj, fixed, depth=0.25):
    """Nodes point(i, j) = (x, y) for 0 <= i <= ni, 0 <= j <= nj and the
    (ni x nj) elements of `etype` on them, counterclockwise when i runs
    along x and j along y. Quads: a 2D model. Bricks: two layers of nodes
    (z = 0 and `depth`) with every z dof fixed: plane strain. fixed(i, j)
    gives the (x, y) fixity flags of a node. Returns tag(i, j, k) (k the
    layer; 0 for quads)."""
    brick = etype in BRICKS
    m.wipe()
    m.model("basic", "-ndm", 3 if brick else 2, "-ndf", 3 if brick else 2)

    def tag(i, j, k=0):
        return 1 + i + (ni + 1) * (j + (nj + 1) * k)

    for k in range(2 if brick else 1):
        for j in range(nj + 1):
            for i in range(ni + 1):
                fx, fy = fixed(i, j)
                if brick:
                    m.node(tag(i, j, k), *point(i, j), depth * k)
                    m.fix(tag(i, j, k), fx, fy, 1)
                else:
                    m.node(tag(i, j), *point(i, j))
                    if fx or fy:
                        m.fix(tag(i, j), fx, fy)
    return tag


def plane_strain_elements(m, etype, tag, ni, nj, mat=1):
    """The elements of plane_strain_grid (material `mat`)."""
    e = 0
    for j in range(nj):
        for i in range(ni):
            e += 1
            quad = [tag(i, j), tag(i + 1, j), tag(i + 1, j + 1), tag(i, j + 1)]
            if etype in BRICKS:
                element(m, etype, e, quad + [tag(i, j, 1), tag(i + 1, j, 1), tag(i + 1, j + 1, 1), tag(i, j + 1, 1)],
                        mat)
            else:
                element(m, etype, e, quad, mat)


def lame_displacement(r, a, b, p, E, nu):
    """Radial displacement of a thick cylinder (radii a < b) under internal
    pressure p in plane strain (Lame)."""
    return (1 + nu) * p * a * a / (E * (b * b - a * a)) * ((1 - 2 * nu) * r + b * b / r)


def cylinder_inner_error(m, etype, n, nu, a=1.0, b=2.0, p=1.0, E=1000.0, depth=0.25):
    """Quarter annulus, n elements through the wall and 2n around, plane
    strain (bricks: one layer of thickness `depth`, every axial dof fixed),
    symmetry planes x = 0 and y = 0, pressure p on the inner face as
    consistent nodal forces. Returns the relative error of the radial
    displacement at the inner face (mean over its nodes) against Lame."""
    brick = etype in BRICKS
    nr, nt = n, 2 * n

    def point(i, j):
        r, th = a + (b - a) * i / nr, 0.5 * math.pi * j / nt
        return r * math.cos(th), r * math.sin(th)

    tag = plane_strain_grid(m, etype, point, nr, nt, lambda i, j: (int(j == nt), int(j == 0)), depth)
    m.nDMaterial("ElasticIsotropic", 1, E, nu)
    plane_strain_elements(m, etype, tag, nr, nt)
    layers = 2 if brick else 1
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    # Edge j -> j+1 of the inner face (chord d, counterclockwise) takes p (d_y, -d_x), split evenly.
    forces = np.zeros((nt + 1, 2))
    for j in range(nt):
        t0, t1 = 0.5 * math.pi * j / nt, 0.5 * math.pi * (j + 1) / nt
        d = a * np.array([math.cos(t1) - math.cos(t0), math.sin(t1) - math.sin(t0)])
        f = p * np.array([d[1], -d[0]]) * (depth if brick else 1.0)
        forces[j] += 0.5 * f
        forces[j + 1] += 0.5 * f
    for j in range(nt + 1):
        if brick:
            for k in range(layers):
                m.load(tag(0, j, k), *(0.5 * forces[j]), 0.0)
        else:
            m.load(tag(0, j), *forces[j])
    _static_linear(m)
    exact = lame_displacement(a, a, b, p, E, nu)
    radial = []
    for j in range(nt + 1):
        th = 0.5 * math.pi * j / nt
        u = m.nodeDisp(tag(0, j))
        radial.append(u[0] * math.cos(th) + u[1] * math.sin(th))
    return float(np.mean(radial)) / exact - 1.0


def bending_tip_error(m, etype, nx, ny, nu, L=10.0, h=1.0, E=1000.0, M=1.0, depth=0.5, skew=0.0):
    """Cantilever of length L and depth h in plane strain, pure bending:
    the tip carries the linear traction -M y / I (consistent nodal forces),
    the root x = 0 is on rollers (u = 0) with v = 0 at its middle node, which
    the exact 2D solution satisfies (u = -k x y, v = k (x^2 + nu' y^2) / 2,
    k = M / (E' I), E' = E / (1 - nu^2)). Returns the relative error of the
    tip deflection v(L, 0) against beam theory, M L^2 / (2 E' I), which is
    here exact. ny must be even. skew > 0 distorts the mesh: the interior
    columns of nodes lean alternately by +-skew element widths over the
    depth (trapezoids)."""
    brick = etype in BRICKS
    thick = depth if brick else 1.0
    def point(i, j):
        y = -h / 2 + h * j / ny
        lean = skew * (L / nx) * (2 * y / h) * (-1) ** i if 0 < i < nx else 0.0
        return L * i / nx + lean, y

    tag = plane_strain_grid(m, etype, point, nx, ny,
                            lambda i, j: (int(i == 0), int(i == 0 and 2 * j == ny)), depth)
    m.nDMaterial("ElasticIsotropic", 1, E, nu)
    plane_strain_elements(m, etype, tag, nx, ny)
    layers = 2 if brick else 1
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    inertia = thick * h ** 3 / 12.0
    traction = lambda y: -M * y / inertia * thick  # noqa: E731  (force per unit length of the tip edge)
    loads = np.zeros(ny + 1)
    for j in range(ny):
        y0, y1 = -h / 2 + h * j / ny, -h / 2 + h * (j + 1) / ny
        loads[j] += (y1 - y0) / 6.0 * (2 * traction(y0) + traction(y1))
        loads[j + 1] += (y1 - y0) / 6.0 * (traction(y0) + 2 * traction(y1))
    for j in range(ny + 1):
        if brick:
            for k in range(layers):
                m.load(tag(nx, j, k), 0.5 * loads[j], 0.0, 0.0)
        else:
            m.load(tag(nx, j), loads[j], 0.0)
    _static_linear(m)
    exact = M * L * L / (2.0 * E / (1 - nu * nu) * inertia)
    return m.nodeDisp(tag(nx, ny // 2), 2) / exact - 1.0


def rate(errors, sizes):
    """Observed convergence rates log(e_i / e_i+1) / log(h_i / h_i+1)."""
    return [math.log(abs(errors[k] / errors[k + 1])) / math.log(sizes[k] / sizes[k + 1])
            for k in range(len(errors) - 1)]


def footing_mesh(nx, ny, half_width=1.0, width=5.0, depth=4.0, grading=1.6):
    """Node coordinates of the half-space under a strip footing (half model,
    symmetry plane x = 0, footing on 0 <= x <= half_width at y = 0, soil
    down to y = -depth and out to x = width): `nx` columns, a third of them
    under the footing, and `ny` rows, graded geometrically (ratio `grading`
    overall) towards the footing edge and the surface. Returns (xs, ys)."""
    under = max(2, nx // 3)
    beyond = nx - under
    # Under the footing: finer towards the edge x = half_width.
    s = np.linspace(0.0, 1.0, under + 1)
    xs_under = half_width * (1.0 - (1.0 - s) ** grading)
    t = np.linspace(0.0, 1.0, beyond + 1)[1:]
    xs_beyond = half_width + (width - half_width) * t ** grading
    ys = -depth * np.linspace(0.0, 1.0, ny + 1) ** grading
    return np.concatenate([xs_under, xs_beyond]), ys


def strip_footing(m, etype, nx, ny, su=1.0, E=1000.0, nu=0.49, settlement=0.05, steps=25, algorithm=("Newton",),
                  adaptive=True, **mesh):
    """A rigid smooth strip footing (half width 1) pushed into weightless
    von Mises soil (nDMaterial J2Plasticity, perfectly plastic, yield stress
    sqrt(3) su so that the plane-strain shear strength is su) by imposed
    vertical displacement of its nodes, horizontal displacement free. The
    mesh is footing_mesh(nx, ny); the far side and the bottom are on rollers.
    Returns the bearing pressures q / su (the footing reaction over the half
    width) after each converged step (beamsolid.stepping.adaptive_analyze:
    nominal steps of settlement / steps, cut where Newton fails; with
    adaptive=False fixed steps until the first failure, for OpenSeesPy)."""
    xs, ys = footing_mesh(nx, ny, **mesh)
    ys = ys[::-1]  # bottom (j = 0) to surface (j = ny)
    brick = etype in BRICKS
    ni, nj = len(xs) - 1, len(ys) - 1
    tag = plane_strain_grid(m, etype, lambda i, j: (xs[i], ys[j]), ni, nj,
                            lambda i, j: (int(i in (0, ni)), int(j == 0)))
    K, G = E / (3 * (1 - 2 * nu)), E / (2 * (1 + nu))
    sy = math.sqrt(3.0) * su
    m.nDMaterial("J2Plasticity", 1, K, G, sy, sy, 0.0, 0.0)
    plane_strain_elements(m, etype, tag, ni, nj)
    layers = 2 if brick else 1
    footing = [i for i, x in enumerate(xs) if x <= 1.0 + 1e-12]
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    for i in footing:
        for k in range(layers):
            m.sp(tag(i, nj, k), 2, -settlement)
    m.constraints("Transformation")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-8 * settlement, 50)
    m.algorithm(*algorithm)
    m.integrator("LoadControl", 1.0 / steps)
    m.analysis("Static")
    q = []

    def record(progress, iterations):
        m.reactions()
        total = sum(m.nodeReaction(tag(i, nj, k), 2) for i in footing for k in range(layers))
        q.append(abs(total) / (0.25 if brick else 1.0) / su)

    if not adaptive:
        for k in range(steps):
            if m.analyze(1) != 0:
                break
            record((k + 1) / steps, m.testIter())
        return q
    # Steps of settlement / steps, halved (down to 1/64) where Newton fails:
    # the first plastic steps at the footing edge need them on fine meshes.
    from beamsolid.stepping import adaptive_analyze

    adaptive_analyze(m, 1.0, steps, on_step=record)
    return q
