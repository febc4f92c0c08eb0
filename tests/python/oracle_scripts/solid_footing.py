"""The strip footing of tests/python/solid_models.py on weightless J2 soil
(nDMaterial J2Plasticity, perfectly plastic) with quad, bbarQuad and
SSPquad on the 12 x 8 mesh: 25 fixed steps of imposed settlement,
NewtonLineSearch; the bearing pressure after every step and the footing
elements' stresses at the end. The mesh is of rectangles, where SSPquad is
OpenSees' to round-off. The answers agree to the accuracy of OpenSeesPy's
J2 return (its local tolerance leaves ~5e-9 of the exact stress, which the
25 plastic steps carry to ~1e-7 in the displacements): compare.py's
tolerance for footing.* is 2e-7.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
import solid_models as sm  # noqa: E402


def run(ops):
    out = {}
    for etype in ("quad", "bbarQuad", "SSPquad"):
        q = sm.strip_footing(ops, etype, 12, 8, algorithm=("NewtonLineSearch",), adaptive=False)
        out[f"footing.{etype}.q"] = q
        # The element under the footing edge (top row, 4th column) and the
        # surface node just beyond the edge (columns i = 0..12, rows j = 0..8).
        edge = 1 + 3 + 12 * 7
        out[f"footing.{etype}.edge.stresses"] = ops.eleResponse(edge, "stresses")
        if etype != "SSPquad":  # OpenSees' SSPquad answers no 'material' query
            out[f"footing.{etype}.edge.material2.stress"] = ops.eleResponse(edge, "material", 2, "stress")
        out[f"footing.{etype}.edge.disp"] = ops.nodeDisp(1 + 5 + 13 * 8)
    ops.wipe()
    return out
