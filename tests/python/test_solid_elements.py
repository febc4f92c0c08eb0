"""bbarQuad, SSPquad, bbarBrick and SSPbrick against closed forms, next to
the standard quad and stdBrick (tests/python/solid_models.py builds the
models; benchmarks/solid_elements.py prints the full tables).

- Near-incompressible locking (nu = 0.4999): a quarter of a thick-walled
  cylinder under internal pressure in plane strain against Lame; the
  standard elements lock (their inner displacement is far too small and
  barely improves with refinement), the B-bar and SSP elements converge at
  second order.
- Bending: a cantilever in pure bending (linear end traction, roller root)
  against beam theory, exact for this case, with nu = 0.3 and 0.4999;
  second-order convergence for the new elements.
- Commands: the argument forms, errors naming command and argument, the
  responses, eleType names, the PVD recorder's cells and stresses.
"""
import math
import os
import xml.etree.ElementTree as ET

import numpy as np
import pytest

import solid_models as sm

import beamsolid
import beamsolid.opensees as ops


def _errors(model, fn, etype, meshes, *args):
    return [fn(model, etype, *mesh, *args) for mesh in meshes]


# --- locking -------------------------------------------------------------------------

CYLINDER_MESHES = [(2,), (4,), (8,)]


@pytest.mark.parametrize("etype", ["bbarQuad", "SSPquad", "bbarBrick", "SSPbrick"])
def test_thick_cylinder_nearly_incompressible_converges(model, etype):
    # Inner radial displacement against Lame, nu = 0.4999, meshes n x 2n
    # (n = 2, 4, 8 through the wall). Measured: bbarQuad and bbarBrick
    # -2.8 %, -0.74 %, -0.19 %; SSPquad -1.2 %, -0.32 %, -0.08 %; SSPbrick
    # -4.4 %, -1.2 %, -0.32 % (rates 1.8 to 2.0).
    errors = _errors(model, sm.cylinder_inner_error, etype, CYLINDER_MESHES, 0.4999)
    rates = sm.rate(errors, [1 / n for (n,) in CYLINDER_MESHES])
    assert abs(errors[-1]) < 0.01, errors
    assert all(r > 1.6 for r in rates), (errors, rates)


@pytest.mark.parametrize("etype", ["quad", "stdBrick"])
def test_thick_cylinder_standard_elements_lock(model, etype):
    # The same meshes with full integration: the volumetric constraints
    # stiffen the mesh and the inner displacement stays far too small.
    # Measured (quad and stdBrick alike): -98.3 %, -94.1 %, -80.2 %.
    errors = _errors(model, sm.cylinder_inner_error, etype, CYLINDER_MESHES, 0.4999)
    locked = _errors(model, sm.cylinder_inner_error, "bbarQuad" if etype == "quad" else "bbarBrick",
                     CYLINDER_MESHES, 0.4999)
    assert all(e < -0.3 for e in errors), errors
    # Ten times the B-bar error even on the finest mesh.
    assert abs(errors[-1]) > 10 * abs(locked[-1]), (errors, locked)


# --- bending -------------------------------------------------------------------------

BENDING_MESHES = [(16, 4), (32, 8), (64, 16)]


@pytest.mark.parametrize("nu", [0.3, 0.4999])
@pytest.mark.parametrize("etype", ["bbarQuad", "SSPquad", "bbarBrick"])
def test_cantilever_bending_converges_to_beam_theory(model, etype, nu):
    # Tip deflection of L/h = 10 in pure bending against M L^2 / (2 E' I),
    # meshes 16x4 to 64x16. Measured at nu = 0.3 / 0.4999: bbarQuad and
    # bbarBrick -9.4/-5.3 %, -2.5/-1.4 %, -0.64/-0.35 % (rates 1.9, 2.0);
    # SSPquad +4.2/+4.9 %, +1.0/+1.2 %, +0.26/+0.29 % (from above, rate 2.0).
    errors = _errors(model, sm.bending_tip_error, etype, BENDING_MESHES, nu)
    rates = sm.rate(errors, [1 / nx for nx, _ in BENDING_MESHES])
    assert abs(errors[-1]) < 0.008, errors
    assert all(r > 1.8 for r in rates), (errors, rates)


@pytest.mark.parametrize("nu", [0.3, 0.4999])
def test_sspbrick_is_exact_in_pure_bending(model, nu):
    # The enhanced strains give rectangular bricks the exact bending modes
    # (no parasitic shear, free lateral strain): the coarsest mesh already
    # gives beam theory to round-off (measured 1e-13 at nu = 0.3, 1.3e-9 at
    # 0.4999, where the bulk modulus is 5000 shear moduli).
    for mesh in BENDING_MESHES[:2]:
        assert abs(sm.bending_tip_error(model, "SSPbrick", *mesh, nu)) < 1e-7


@pytest.mark.parametrize("etype", ["bbarQuad", "SSPquad", "bbarBrick", "SSPbrick"])
def test_cantilever_bending_on_a_skewed_mesh_converges(model, etype):
    # Interior node columns lean by +-1/4 element width over the depth
    # (trapezoids, as distorted at every refinement), nu = 0.4999. Measured
    # at 32x8 / 64x16: bbarQuad/bbarBrick -2.3 / -0.52 %, SSPquad +0.58 /
    # +0.26 %, SSPbrick -0.55 / -0.035 %.
    errors = [sm.bending_tip_error(model, etype, nx, ny, 0.4999, skew=0.25) for nx, ny in BENDING_MESHES[1:]]
    assert abs(errors[-1]) < 0.006, errors
    assert abs(errors[-1]) < 0.5 * abs(errors[0]), errors


@pytest.mark.parametrize("etype", ["quad", "stdBrick"])
def test_cantilever_bending_standard_elements_lock_when_nearly_incompressible(model, etype):
    # Measured: -98.7 %, -95.1 %, -83.0 % at nu = 0.4999 (and -13 %, -3.6 %,
    # -0.93 % at nu = 0.3, converging).
    errors = _errors(model, sm.bending_tip_error, etype, BENDING_MESHES, 0.4999)
    assert all(e < -0.8 for e in errors), errors
    converging = _errors(model, sm.bending_tip_error, etype, BENDING_MESHES, 0.3)
    assert abs(converging[-1]) < 0.01, converging


# --- commands ------------------------------------------------------------------------

def _unit_quad(m):
    m.wipe()
    m.model("basic", "-ndm", 2, "-ndf", 2)
    for i, (x, y) in enumerate([(0, 0), (2, 0.2), (2.3, 1.7), (-0.2, 1.2)]):
        m.node(i + 1, x, y)
    m.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.3, 2.0)


def _unit_brick(m):
    m.wipe()
    m.model("basic", "-ndm", 3, "-ndf", 3)
    for i, x in enumerate([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]):
        m.node(i + 1, *x)
    m.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.3, 2.0)


@pytest.mark.parametrize(
    "setup, args, words",
    [
        (_unit_quad, ("bbarQuad", 1, 1, 2, 3, 4, -1.0, 1), ["element bbarQuad 1", "(thick)"]),
        (_unit_quad, ("bbarQuad", 1, 1, 2, 3, 4, 1.0), ["element bbarQuad 1", "(matTag)"]),
        (_unit_quad, ("bbarQuad", 1, 1, 2, 3, 4, 1.0, 1, 0.0, -9.8), ["element bbarQuad 1", "after matTag"]),
        (_unit_quad, ("bbarQuad", 1, 1, 2, 3, 4, 1.0, 7), ["element bbarQuad 1", "nDMaterial 7"]),
        (_unit_quad, ("SSPquad", 1, 1, 2, 3, 4, 1, "Plane", 1.0), ["element SSPquad 1", "(type)"]),
        (_unit_quad, ("SSPquad", 1, 1, 2, 3, 4, 1, "PlaneStrain"), ["element SSPquad 1", "(thick)"]),
        (_unit_quad, ("SSPquad", 1, 1, 2, 3, 4, 1, "PlaneStrain", 1.0, 2.0), ["element SSPquad 1", "body force"]),
        (_unit_quad, ("SSPquad", 1, 1, 2, 3, "PlaneStrain", 1.0), ["element SSPquad 1"]),
        (_unit_quad, ("SSPquad", 1, 1, 2, 3, 9, 1, "PlaneStrain", 1.0), ["element SSPquad 1", "node 9"]),
        (_unit_brick, ("SSPbrick", 1, 1, 2, 3, 4, 5, 6, 7, 8), ["element SSPbrick 1", "(matTag)"]),
        (_unit_brick, ("bbarBrick", 1, 1, 2, 3, 4, 5, 6, 7, 8, 1, 0.0), ["element bbarBrick 1", "body force"]),
        (_unit_brick, ("bbarBrick", 1, 5, 6, 7, 8, 1, 2, 3, 4, 1), ["element bbarBrick 1", "Jacobian"]),
        (_unit_brick, ("SSPbrick", 1, 1, 2, 3, 4, 5, 6, 7, 8, "one"), ["element SSPbrick 1", "matTag"]),
        (_unit_brick, ("SSPquad", 1, 1, 2, 3, 4, 1, "PlaneStrain", 1.0), ["element SSPquad 1", "2D"]),
    ],
)
def test_bad_arguments_name_the_command_and_the_argument(model, setup, args, words):
    setup(model)
    with pytest.raises(beamsolid.OpenSeesError) as err:
        model.element(*args)
    for w in words:
        assert w in str(err.value), str(err.value)


def test_responses_and_class_names():
    _unit_quad(ops)
    ops.element("SSPquad", 1, 1, 2, 3, 4, 1, "PlaneStress", 0.5, 0.0, -10.0)
    ops.element("bbarQuad", 2, 1, 2, 3, 4, 0.5, 1)
    assert ops.eleType(1) == "SSPquad" and ops.eleType(2) == "ConstantPressureVolumeQuad"
    assert len(ops.eleResponse(1, "stresses")) == 3 and len(ops.eleResponse(2, "stresses")) == 16
    assert len(ops.eleResponse(2, "material", 4, "stress")) == 4
    assert len(ops.eleResponse(1, "forces")) == 8
    _unit_brick(ops)
    ops.element("SSPbrick", 1, *range(1, 9), 1)
    ops.element("bbarBrick", 2, *range(1, 9), 1)
    assert ops.eleType(1) == "SSPbrick" and ops.eleType(2) == "BbarBrick"
    assert len(ops.eleResponse(1, "strains")) == 6 and len(ops.eleResponse(2, "strains")) == 48
    ops.wipe()


def _one_element_under_imposed_strain(path, etype, mat, strain, steps, increment, algorithm):
    """One element (material `mat`: 1 elastic, 2 J2) whose nodes follow u_d =
    e x_d for strain = (d, e) (0-based), in `steps` LoadControl steps, with
    a PVD recorder at `path`; returns the recorder's folder."""
    brick = etype in sm.BRICKS
    (_unit_brick if brick else _unit_quad)(ops)
    ops.nDMaterial("J2Plasticity", 2, 800.0, 300.0, 1.0, 1.0, 0.0, 0.0)
    sm.element(ops, etype, 1, list(range(1, 9 if brick else 5)), mat, 0.5)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    direction, e = strain
    for n in range(1, (9 if brick else 5)):
        x = ops.nodeCoord(n)
        for d in range(3 if brick else 2):
            ops.sp(n, d + 1, e * x[d] if d == direction else 0.0)
    ops.constraints("Transformation")
    ops.system("UmfPack")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 20)
    ops.algorithm(algorithm)
    ops.integrator("LoadControl", increment)
    ops.analysis("Static")
    name = str(path)
    ops.recorder("PVD", name)
    assert ops.analyze(steps) == 0
    return name


@pytest.mark.parametrize("etype", ["bbarQuad", "SSPquad", "bbarBrick", "SSPbrick"])
def test_pvd_recorder_writes_the_cells_and_their_mean_stress(tmp_path, etype):
    # A uniform strain: every cell's stress is the material point stress.
    brick = etype in sm.BRICKS
    name = _one_element_under_imposed_strain(tmp_path / "solid", etype, 1, (0, 1e-3), 1, 1.0, "Linear")
    ops.wipe()
    vtu = sorted(os.listdir(name))[-1]
    grid = ET.parse(os.path.join(name, vtu)).getroot()
    types = [int(v) for v in grid.find(".//Cells/DataArray[@Name='types']").text.split()]
    assert types == [12 if brick else 9]
    stress = [float(v) for v in grid.find(".//CellData/DataArray[@Name='stress']").text.split()]
    # e_xx = 1e-3 with every other strain 0 (plane strain in 2D): s_xx = (lambda + 2G) e, s_yy = s_zz = lambda e.
    E, nu = 1000.0, 0.3
    lam, G = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
    expected = [(lam + 2 * G) * 1e-3, lam * 1e-3, lam * 1e-3 if (brick or etype == "bbarQuad") else 0.0, 0, 0, 0]
    assert np.allclose(stress, expected, atol=1e-12), stress


@pytest.mark.parametrize("etype, args", [("bbarQuad", (0.5, 1)), ("SSPquad", (1, "PlaneStrain", 0.5))])
def test_block2d_meshes_the_new_quads(model, etype, args):
    # block2D passes OpenSees' eleArgs counts (bbarQuad 2, SSPquad 3) through
    # the element command; the mesh's area is the block's.
    model.wipe()
    model.model("basic", "-ndm", 2, "-ndf", 2)
    model.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.3, 2.0)
    model.block2D(3, 2, 1, 1, etype, *args, 1, 0.0, 0.0, 2, 3.0, 0.0, 3, 3.0, 2.0, 4, 0.0, 2.0)
    assert model.getEleTags() == list(range(1, 7))
    assert all(model.eleType(e) in ("SSPquad", "ConstantPressureVolumeQuad") for e in range(1, 7))
    assert model.eleNodes(6) == [7, 8, 12, 11]
    assert model.nodeCoord(12) == pytest.approx([3.0, 2.0])


@pytest.mark.parametrize("etype", ["bbarBrick", "SSPbrick"])
def test_block3d_meshes_the_new_bricks(model, etype):
    model.wipe()
    model.model("basic", "-ndm", 3, "-ndf", 3)
    model.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.3)
    corners = [(0, 0, 0), (2, 0, 0), (2, 1, 0), (0, 1, 0), (0, 0, 1), (2, 0, 1), (2, 1, 1), (0, 1, 1)]
    points = [v for k, c in enumerate(corners, start=1) for v in (k, *c)]
    model.block3D(2, 1, 1, 1, 1, etype, 1, *points)
    assert model.getEleTags() == [1, 2]
    assert len(model.eleResponse(1, "forces")) == 24


# --- plasticity (nDMaterial J2Plasticity) ----------------------------------------------

PRANDTL = 2.0 + math.pi


def test_strip_footing_reaches_the_prandtl_load_with_bbar_quads(model):
    # Rigid smooth strip footing (imposed settlement, half model) on weightless
    # von Mises soil, E = 1000 s_u, nu = 0.49, meshes 12x8 and 24x16 graded
    # to the footing edge, NewtonLineSearch. Measured q / s_u at the end
    # (plateau): 5.4744 (+6.47 %) and 5.2628 (+2.36 %): within 3 % and
    # converging from above (48x32: 5.1852, +0.85 %, benchmarks/solid_elements.py).
    coarse = sm.strip_footing(model, "bbarQuad", 12, 8, algorithm=("NewtonLineSearch",))
    fine = sm.strip_footing(model, "bbarQuad", 24, 16, algorithm=("NewtonLineSearch",))
    assert len(fine) == 25, "the settlement was not reached"
    assert PRANDTL < fine[-1] < 1.03 * PRANDTL, fine[-1]
    assert fine[-1] < coarse[-1], (coarse[-1], fine[-1])
    # A limit load: the last fifth of the settlement adds less than 0.1 %.
    assert fine[-1] - fine[-6] < 1e-3 * PRANDTL, fine[-6:]


def test_strip_footing_standard_quads_overshoot(model):
    # The same 24x16 mesh with quad (full integration) locks: +32.8 % at the
    # same settlement and still rising (SSPquad, stabilized from the elastic
    # tangent, +8.4 %, also still rising: its limit load converges from
    # above at about first order, docs/solid_elements.md).
    q = sm.strip_footing(model, "quad", 24, 16, algorithm=("NewtonLineSearch",))
    assert q[-1] > 1.3 * PRANDTL, q[-1]
    assert q[-1] - q[-6] > 1e-2 * PRANDTL, q[-6:]


@pytest.mark.parametrize("etype", ["bbarQuad", "SSPquad", "bbarBrick", "SSPbrick"])
def test_plastic_strains_reach_the_responses_and_the_pvd_recorder(tmp_path, etype):
    # A column in uniaxial compression past yield (J2, no hardening): every
    # material point has the same plastic strain, reported per point and as
    # the cells' mean by the PVD recorder.
    brick = etype in sm.BRICKS
    name = _one_element_under_imposed_strain(tmp_path / "plastic", etype, 2, (1, -1e-2), 4, 0.25, "Newton")
    eq = ops.eleResponse(1, "equivalentPlasticStrains")
    points = 1 if etype.startswith("SSP") else (8 if brick else 4)
    assert len(eq) == points and min(eq) > 1e-3 and max(eq) - min(eq) < 1e-9
    assert len(ops.eleResponse(1, "plasticStrains")) == 6 * points
    ops.wipe()
    vtu = sorted(os.listdir(name))[-1]
    grid = ET.parse(os.path.join(name, vtu)).getroot()
    cell = [float(v) for v in grid.find(".//CellData/DataArray[@Name='equivalentPlasticStrain']").text.split()]
    assert cell == pytest.approx([eq[0]], rel=1e-9)
