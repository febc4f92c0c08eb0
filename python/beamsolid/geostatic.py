"""The geostatic (gravity) stage before a pile is loaded, as OpenSees users run it.

A laterally restrained soil column under its own weight is in uniaxial strain:
sigma_v = gamma d and sigma_h = K0 sigma_v at depth d, with K0 = nu / (1 - nu) for
elastic soil. OpenSees users reach this state with an elastic stage: soil weight
as brick body forces, side boundaries on rollers, the base fixed, contact
interfaces frictionless (``updateMaterialStage`` stage 0) and the pile held; then
``loadConst('-time', 0)`` freezes the weight, the contacts get their friction back
(stage 1) and the pile is loaded.

``geostatic_stage`` runs that stage with the given command module
(``beamsolid.opensees`` or a ``beamsolid.Model``) and checks the stresses it
produced against the closed form.

Stress signs are those of stdBrick: tension positive, so sigma_zz = -gamma d.
Eight-node bricks under a linearly varying body force reproduce the column's
stress at each element's mid-depth exactly (the strain is constant through an
element's height, equal to the exact mean), so the check compares every Gauss
point's stress with the closed form at its element's centroid depth.
"""
import math
from dataclasses import dataclass

__all__ = ["GeostaticState", "geostatic_stage", "geostatic_stress_error", "element_centroid"]


@dataclass
class GeostaticState:
    """What the gravity stage gave: Newton iterations and the stress errors."""

    iterations: int
    error_v: float  # max |sigma_zz - (-gamma d)| / (gamma * deepest centroid depth)
    error_h: float  # max |sigma_xx, sigma_yy - (-K0 gamma d)| / (same scale)
    K0: float  # measured mean sigma_h / sigma_v over the elements below the surface layer
    elements: int


def element_centroid(ops, element):
    """Mean of an element's node coordinates."""
    nodes = ops.eleNodes(element)
    xyz = [ops.nodeCoord(n) for n in nodes]
    return [sum(p[i] for p in xyz) / len(xyz) for i in range(3)]


def geostatic_stress_error(ops, elements, gamma, K0, z_surface=0.0):
    """(error_v, error_h, measured K0) of stdBrick elements against uniaxial-strain gravity."""
    worst_v = worst_h = 0.0
    deepest = 0.0
    ratio_sum, ratio_count = 0.0, 0
    for e in elements:
        depth = z_surface - element_centroid(ops, e)[2]
        deepest = max(deepest, depth)
        s = ops.eleResponse(e, "stresses")
        if len(s) % 6 != 0 or not s:
            raise ValueError(f"geostatic: element {e} gives no stresses (is it a stdBrick?)")
        sv, sh = -gamma * depth, -K0 * gamma * depth
        for g in range(len(s) // 6):
            xx, yy, zz = s[6 * g], s[6 * g + 1], s[6 * g + 2]
            worst_v = max(worst_v, abs(zz - sv))
            worst_h = max(worst_h, abs(xx - sh), abs(yy - sh))
            if zz < 0.0:
                ratio_sum += 0.5 * (xx + yy) / zz
                ratio_count += 1
    scale = gamma * deepest if deepest > 0 else 1.0
    return worst_v / scale, worst_h / scale, (ratio_sum / ratio_count if ratio_count else math.nan)


def geostatic_stage(ops, *, soil_elements, gamma, K0, z_surface=0.0, contact_materials=(), steps=1,
                    tol=1e-8, max_iter=25, system="UmfPack", check_tol=None, initial_state=False):
    """Run the elastic gravity stage, check it, then ``loadConst('-time', 0)``.

    The soil elements must carry their weight as body forces (stdBrick b3 = -gamma)
    and the boundary conditions must be in place (mesh.fix_soil_boundary or your own);
    a pile in the hole should be fixed for this stage. ``contact_materials`` (tags of
    ContactMaterial3D) are frictionless during the stage and get their friction back
    after it. ``check_tol``: raise RuntimeError when a stress error exceeds it (None:
    only report). Returns a GeostaticState; the analysis objects are wiped afterwards
    so the next stage defines its own.

    ``initial_state=True`` runs the stage inside ``InitialStateAnalysis('on')`` /
    ``('off')``: afterwards every displacement is zero again (the settlement of
    switching gravity on is an artifact, not part of the problem), the stresses
    stay, and contact elements see the reference geometry. The soil materials
    must then be ``InitialStateAnalysisWrapper`` s; the stresses are checked
    again after ``'off'`` and a RuntimeError says so if they were lost.
    """
    if initial_state:
        ops.InitialStateAnalysis("on")
    for mat in contact_materials:
        ops.updateMaterialStage("-material", mat, "-stage", 0)
    ops.constraints("Transformation")
    ops.numberer("RCM")
    ops.system(system)
    ops.test("NormUnbalance", tol, max_iter)
    ops.algorithm("Newton")
    ops.integrator("LoadControl", 1.0 / steps)
    ops.analysis("Static")
    iterations = 0
    for _ in range(steps):
        if ops.analyze(1) != 0:
            raise RuntimeError(f"geostatic stage: step {_ + 1} of {steps} did not converge "
                               f"(NormUnbalance {tol}, {max_iter} iterations)")
        iterations += ops.testIter()
    error_v, error_h, k0 = geostatic_stress_error(ops, soil_elements, gamma, K0, z_surface)
    if check_tol is not None and max(error_v, error_h) > check_tol:
        raise RuntimeError(f"geostatic stage: stresses off the closed form by {max(error_v, error_h):.3e} "
                           f"(relative to gamma * depth), more than check_tol {check_tol:.1e}")
    if initial_state:
        ops.InitialStateAnalysis("off")
        kept_v, kept_h, _ = geostatic_stress_error(ops, soil_elements, gamma, K0, z_surface)
        lost = max(kept_v - error_v, kept_h - error_h)
        if lost > max(1e-6, 10.0 * max(error_v, error_h)):
            raise RuntimeError("geostatic stage: InitialStateAnalysis('off') lost the gravity stresses (error "
                               f"{max(kept_v, kept_h):.3e} after it); wrap the soil materials in "
                               "nDMaterial('InitialStateAnalysisWrapper', tag, innerTag, 3)")
    ops.loadConst("-time", 0.0)
    ops.wipeAnalysis()
    for mat in contact_materials:
        ops.updateMaterialStage("-material", mat, "-stage", 1)
    return GeostaticState(iterations=iterations, error_v=error_v, error_h=error_h, K0=k0,
                          elements=len(soil_elements))
