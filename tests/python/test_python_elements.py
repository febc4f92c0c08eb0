"""Elements written in Python solve like C++ ones and fail cleanly."""
import re

import numpy as np
import pytest

import beamsolid
from beamsolid import OpenSeesError


class Bar(beamsolid.Element):
    """A small-displacement axial bar with N = k e + c e^3, ndf-3 nodes."""

    def __init__(self, tag, i, j, k, c=0.0):
        super().__init__(tag, [i, j])
        self.k, self.c = k, c
        self.commits = 0

    def setup(self):
        if self.ndf != [3, 3]:
            raise ValueError("Bar needs ndf-3 nodes")
        d = self.coords[1] - self.coords[0]
        self.axis = d / np.linalg.norm(d)

    def elongation(self):
        return float(self.axis @ (self.disps[1] - self.disps[0]))

    def tangent(self):
        e = self.elongation()
        kk = (self.k + 3 * self.c * e * e) * np.outer(self.axis, self.axis)
        return np.block([[kk, -kk], [-kk, kk]])

    def force(self):
        e = self.elongation()
        n = self.k * e + self.c * e**3
        return np.concatenate([-n * self.axis, n * self.axis])

    def commit(self):
        self.commits += 1

    def response(self, args):
        if args == ["axialForce"]:
            e = self.elongation()
            return [self.k * e + self.c * e**3]
        return super().response(args)


beamsolid.register_element("PyBar", Bar)


def bar_model(m, c=0.0):
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, 3.0, 4.0, 0.0)
    m.fix(1, 1, 1, 1)
    m.fix(2, 0, 0, 1)
    m.element("PyBar", 1, 1, 2, 100.0, c)
    # A transverse C++ truss keeps node 2 stable in the other direction.
    m.node(3, 3.0 + 4.0, 4.0 - 3.0, 0.0)
    m.fix(3, 1, 1, 1)
    m.uniaxialMaterial("Elastic", 1, 1000.0)
    m.element("truss", 2, 2, 3, 1.0, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)


def test_python_element_matches_closed_form(model):
    bar_model(model)
    # Load along the bar axis (0.6, 0.8): only the bar carries it.
    model.load(2, 6.0, 8.0, 0.0)
    model.system("UmfPack")
    model.test("NormDispIncr", 1e-12, 10)
    model.integrator("LoadControl", 0.5)
    model.analysis("Static")
    assert model.analyze(2) == 0
    u = np.array(model.nodeDisp(2))
    assert u[:2] == pytest.approx(np.array([0.6, 0.8]) * 10.0 / 100.0, rel=1e-12)
    assert model.eleResponse(1, "axialForce") == pytest.approx([10.0], rel=1e-12)


def test_nonlinear_python_element_converges_quadratically(model):
    bar_model(model, c=1e4)
    model.load(2, 6.0, 8.0, 0.0)
    model.test("NormUnbalance", 1e-10, 20)
    model.analysis("Static")
    assert model.analyze(1) == 0
    e = np.linalg.norm(model.nodeDisp(2)[:2])
    assert 100 * e + 1e4 * e**3 == pytest.approx(10.0, rel=1e-9)
    # Observed order from the last three residuals above round-off.
    r = [x for x in model.testNorm() if x > 1e-12]
    assert len(r) >= 3
    assert np.log(r[-1] / r[-2]) / np.log(r[-2] / r[-3]) > 1.8


def test_python_errors_become_opensees_errors(model):
    class Broken(Bar):
        def tangent(self):
            raise ZeroDivisionError("boom")

    beamsolid.register_element("PyBroken", Broken)
    model.model("basic", "-ndm", 3, "-ndf", 3)
    model.node(1, 0.0, 0.0, 0.0)
    model.node(2, 1.0, 0.0, 0.0)
    model.fix(1, 1, 1, 1)
    model.fix(2, 0, 1, 1)
    model.element("PyBroken", 1, 1, 2, 1.0)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, 1.0, 0.0, 0.0)
    model.analysis("Static")
    # analyze never raises: a Python element's exception fails the step (-3), with its reason kept.
    assert model.analyze(1) == -3
    assert re.search(r"element PyBroken 1: Python tangent\(\) raised ZeroDivisionError", model.last_error())
    assert model.nodeDisp(2) == [0.0, 0.0, 0.0]
    assert model.getTime() == 0.0


def test_wrong_shapes_and_setup_errors(model):
    class WrongShape(Bar):
        def force(self):
            return np.zeros(3)

    beamsolid.register_element("PyWrongShape", WrongShape)
    model.model("basic", "-ndm", 3, "-ndf", 6)
    model.node(1, 0.0, 0.0, 0.0)
    model.node(2, 1.0, 0.0, 0.0)
    with pytest.raises(OpenSeesError, match="Bar needs ndf-3 nodes"):
        model.element("PyBar", 1, 1, 2, 1.0)
    model.model("basic", "-ndm", 3, "-ndf", 3)
    model.node(3, 0.0, 0.0, 0.0)
    model.node(4, 1.0, 0.0, 0.0)
    model.element("PyWrongShape", 2, 3, 4, 1.0)
    with pytest.raises(OpenSeesError, match=r"force\(\) returned 3 values, expected 6"):
        model.eleForce(2)
    with pytest.raises(OpenSeesError, match="already registered"):
        beamsolid.register_element("PyBar", Bar)
    with pytest.raises(OpenSeesError, match="Python constructor raised TypeError"):
        model.element("PyBar", 3, 3)
