"""A C++ plugin loaded at run time registers its element type as a command."""
import pathlib

import pytest

from beamsolid import OpenSeesError
from conftest import PLUGIN_DIR

PLUGIN = pathlib.Path(PLUGIN_DIR) / "liblinear_spring_plugin.so"


def test_plugin_element_solves_like_a_builtin(model):
    assert PLUGIN.exists(), f"{PLUGIN} is built by `make build` (`make sanitize` for build-sanitize)"
    model.loadPlugin(str(PLUGIN))
    model.model("basic", "-ndm", 3, "-ndf", 3)
    model.node(1, 0.0, 0.0, 0.0)
    model.node(2, 2.0, 0.0, 0.0)
    model.fix(1, 1, 1, 1)
    model.fix(2, 0, 1, 1)
    model.element("PluginSpring", 1, 1, 2, 250.0)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, 5.0, 0.0, 0.0)
    model.analysis("Static")
    assert model.analyze(1) == 0
    assert model.nodeDisp(2, 1) == pytest.approx(5.0 / 250.0, rel=1e-14)
    assert model.eleResponse(1, "axialForce") == pytest.approx([5.0], rel=1e-14)
    with pytest.raises(OpenSeesError, match="k must be positive"):
        model.element("PluginSpring", 2, 1, 2, -1.0)


def test_missing_plugin_is_a_clear_error(model):
    with pytest.raises(OpenSeesError, match="cannot load"):
        model.loadPlugin("/nonexistent/libnothing.so")
