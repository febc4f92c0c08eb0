"""C++ plugins: the tutorial's element, every kind of type a plugin may register, the
plugins loadPlugin must refuse (leaving the registry as it was), and the tangent check
offered to plugin authors.

The plugins are built by `make build` (examples/plugins with find_package(BeamSolid) and
beamsolid_add_plugin, as its users build it; tests/plugins for the refusals).
test_plugin_install.py builds the tutorial's plugin out of tree against a pip-installed package.
"""
import importlib.util
import json
import pathlib

import pytest

import beamsolid
from beamsolid import OpenSeesError
from beamsolid.testing import check_tangent
from conftest import PLUGIN_DIR

ROOT = pathlib.Path(__file__).resolve().parents[2]
# The plugins of the build the package came from (make build, or make sanitize's build-sanitize).
TUTORIAL = pathlib.Path(PLUGIN_DIR) / "libnonlinear_spring.so"
TEST_PLUGINS = pathlib.Path(PLUGIN_DIR).parent / "test-plugins"


def plugin_path(name):
    path = TEST_PLUGINS / f"lib{name}.so"
    assert path.exists(), f"{path} is built by `make build` (`make sanitize` for build-sanitize)"
    return str(path)


def spring_model(m, *element_args):
    """Two ndf-3 nodes 2 m apart along x, the first fixed, the second free along x only."""
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, 2.0, 0.0, 0.0)
    m.fix(1, 1, 1, 1)
    m.fix(2, 0, 1, 1)
    if element_args:
        m.element(*element_args)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)


def test_tutorial_spring_with_an_elastic_material_gives_P_over_k(model):
    model.loadPlugin(str(TUTORIAL))
    model.uniaxialMaterial("Elastic", 1, 250.0)
    spring_model(model, "NonlinearSpring3D", 1, 1, 2, 1)
    model.load(2, 5.0, 0.0, 0.0)
    model.analysis("Static")
    assert model.analyze(1) == 0
    assert model.nodeDisp(2, 1) == pytest.approx(5.0 / 250.0, rel=1e-14)
    assert model.eleResponse(1, "axialForce") == pytest.approx([5.0], rel=1e-14)
    assert model.eleResponse(1, "deformation") == pytest.approx([0.02], rel=1e-14)
    assert model.eleResponse(1, "force") == pytest.approx([-5.0, 0, 0, 5.0, 0, 0], abs=1e-12)


def test_tutorial_spring_yields_at_the_materials_strength(model):
    """ElasticPP (k = 1000 kN/m, yield at 0.01 m): pushed to 0.05 m the spring carries k * 0.01 = 10 kN.
    Its tangent agrees with finite differences in the elastic range. (At a converged plastic state the
    two one-sided slopes differ, 0 loading and k unloading: no tangent check belongs at a corner.)"""
    model.loadPlugin(str(TUTORIAL))
    model.uniaxialMaterial("ElasticPP", 1, 1000.0, 0.01)
    spring_model(model, "NonlinearSpring3D", 1, 1, 2, 1, "-orient", 1.0, 0.0, 0.0)
    model.sp(2, 1, 1.0)
    model.integrator("LoadControl", 0.005)
    model.analysis("Static")
    assert model.analyze(1) == 0
    assert model.eleResponse(1, "axialForce") == pytest.approx([5.0], rel=1e-12)
    assert check_tangent(model, 1).ok
    assert model.analyze(9) == 0
    assert model.nodeDisp(2, 1) == pytest.approx(0.05, rel=1e-12)
    assert model.eleResponse(1, "axialForce") == pytest.approx([10.0], rel=1e-12)
    assert model.eleResponse(1, "material", "stress") == pytest.approx([10.0], rel=1e-12)


def test_tutorial_spring_is_recorded_like_a_builtin(model, tmp_path):
    """An Element recorder of the plugin's responses writes what eleResponse answers, step by step,
    and its sidecar names the columns the element gave."""
    model.loadPlugin(str(TUTORIAL))
    model.uniaxialMaterial("ElasticPP", 1, 1000.0, 0.01)
    spring_model(model, "NonlinearSpring3D", 1, 1, 2, 1)
    model.sp(2, 1, 1.0)
    out = tmp_path / "spring.out"
    model.recorder("Element", "-file", str(out), "-time", "-precision", 16, "-ele", 1, "axialForce")
    model.integrator("LoadControl", 0.004)
    model.analysis("Static")
    expected = []
    for _ in range(5):
        assert model.analyze(1) == 0
        expected.append([model.getTime(), *model.eleResponse(1, "axialForce")])
    model.wipe()
    rows = [[float(v) for v in line.split()] for line in out.read_text().splitlines()]
    # k = 1000 up to the yield force 10 kN at 10 mm: 4, 8, 10, 10, 10 kN.
    assert len(rows) == 5
    for row, want in zip(rows, expected):
        assert row == pytest.approx(want, rel=1e-15)
    assert [r[1] for r in rows] == pytest.approx([4.0, 8.0, 10.0, 10.0, 10.0], rel=1e-12)
    sidecar = json.loads((tmp_path / "spring.out.json").read_text())
    assert [c["name"] for c in sidecar["columns"]] == ["time", "e1_N"]
    assert sidecar["columns"][1]["component"] == "N" and sidecar["columns"][1]["response"] == "axialForce"


def test_tutorial_spring_refuses_bad_input(model):
    model.loadPlugin(str(TUTORIAL))
    model.uniaxialMaterial("Elastic", 1, 250.0)
    spring_model(model)
    model.node(3, 0.0, 0.0, 0.0)
    with pytest.raises(OpenSeesError, match="NonlinearSpring3D 1.*uniaxialMaterial 9"):
        model.element("NonlinearSpring3D", 1, 1, 2, 9)
    with pytest.raises(OpenSeesError, match="the nodes coincide; give the axis with -orient"):
        model.element("NonlinearSpring3D", 2, 1, 3, 1)
    with pytest.raises(OpenSeesError, match="NonlinearSpring3D 3.*z"):
        model.element("NonlinearSpring3D", 3, 1, 3, 1, "-orient", 1.0, 0.0)


def test_a_plugin_registers_every_kind_and_the_registry_says_where_each_came_from(model, tmp_path):
    path = plugin_path("every_kind_plugin")
    model.loadPlugin(path)
    model.loadPlugin(path)  # loading it again does nothing
    origins = beamsolid.registered_types()
    added = {"element": ["PluginCubicSpring", "PluginWrongSpring"], "uniaxialMaterial": ["PluginElastic"],
             "nDMaterial": ["PluginElasticIsotropic"], "section": ["PluginElastic"], "timeSeries": ["PluginRamp"],
             "recorder": ["PluginCounter"]}
    for kind, types in added.items():
        for t in types:
            assert pathlib.Path(origins[kind][t]) == pathlib.Path(path).resolve(), (kind, t)
        assert t in beamsolid.registered_types(kind)
    assert origins["element"]["stdBrick"] == "built-in"

    # A truss of the plugin's material under the plugin's ramp: u = rate t P L / (E A).
    model.uniaxialMaterial("PluginElastic", 1, 2.0e5)
    spring_model(model, "Truss", 1, 1, 2, 0.01, 1)
    model.timeSeries("PluginRamp", 2, 0.5)
    model.pattern("Plain", 2, 2)
    model.load(2, 100.0, 0.0, 0.0)
    counts = tmp_path / "counts.txt"
    model.recorder("PluginCounter", str(counts))
    model.integrator("LoadControl", 1.0)
    model.analysis("Static")
    assert model.analyze(4) == 0
    assert model.nodeDisp(2, 1) == pytest.approx(0.5 * 4 * 100.0 * 2.0 / (2.0e5 * 0.01), rel=1e-13)
    model.wipe()
    assert [line.split() for line in counts.read_text().splitlines()] == [["1", "1"], ["2", "2"], ["3", "3"],
                                                                          ["4", "4"]]

    # The plugin's section carries a cantilever; its nD material fills a brick.
    model.section("PluginElastic", 1, 3.0e7, 0.2, 1e-3, 2e-3, 1.2e7, 3e-3)
    model.model("basic", "-ndm", 3, "-ndf", 6)
    model.node(1, 0.0, 0.0, 0.0)
    model.node(2, 0.0, 0.0, 3.0)
    model.fix(1, 1, 1, 1, 1, 1, 1)
    model.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    model.beamIntegration("Legendre", 1, 1, 3)
    model.element("forceBeamColumn", 1, 1, 2, 1, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, 0.0, 10.0, 0.0, 0.0, 0.0, 0.0)
    model.analysis("Static")
    assert model.analyze(1) == 0
    # Cantilever along z, vecxz = x: local y is -Y and local z is X, so a load along Y bends it about
    # local z: tip deflection P L^3 / (3 E Iz), exact for a force-based element.
    assert model.nodeDisp(2, 2) == pytest.approx(10.0 * 3.0**3 / (3.0 * 3.0e7 * 1e-3), rel=1e-10)
    model.wipe()
    model.nDMaterial("PluginElasticIsotropic", 1, 2.0e4, 0.25)
    model.model("basic", "-ndm", 3, "-ndf", 3)
    corners = [(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0), (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)]
    for tag, xyz in enumerate(corners, start=1):
        model.node(tag, *map(float, xyz))
    model.element("stdBrick", 1, *range(1, 9), 1)
    model.nDMaterial("PluginElasticIsotropic", 2, 2.0e4, 0.25)  # a second tag: the type stays usable
    # Uniaxial stress along z: the base rolls, the top is pulled by sigma = 10: u_z = sigma / E.
    for tag in range(1, 5):
        model.fix(tag, 1 if tag == 1 else 0, 1 if tag in (1, 2) else 0, 1)
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    for tag in range(5, 9):
        model.load(tag, 0.0, 0.0, 10.0 / 4)
    model.analysis("Static")
    assert model.analyze(1) == 0
    assert [model.nodeDisp(t, 3) for t in range(5, 9)] == pytest.approx([10.0 / 2.0e4] * 4, rel=1e-12)


def test_a_library_that_is_no_plugin_is_refused(model):
    with pytest.raises(OpenSeesError, match="not a BeamSolid plugin: it does not export beamsolid_register"):
        model.loadPlugin(plugin_path("plain_library"))


def test_a_plugin_without_a_stamp_is_refused(model):
    with pytest.raises(OpenSeesError, match="carries no ABI stamp; build it with beamsolid_add_plugin"):
        model.loadPlugin(plugin_path("unstamped_plugin"))


def test_a_plugin_stamped_with_another_version_is_refused_naming_both(model):
    with pytest.raises(OpenSeesError) as err:
        model.loadPlugin(plugin_path("wrong_stamp_plugin"))
    message = str(err.value)
    assert "was built for BeamSolid 0.0.1; gcc 9" in message
    assert f"but this is {beamsolid.plugin_abi()}" in message
    assert f"BeamSolid {beamsolid.__version__};" in beamsolid.plugin_abi()


def test_a_plugin_that_throws_while_registering_leaves_the_registry_as_it_was(model):
    before = beamsolid.registered_types()
    with pytest.raises(OpenSeesError, match="beamsolid_register threw: the plugin's licence file is missing; "
                                            "nothing was registered"):
        model.loadPlugin(plugin_path("throwing_plugin"))
    assert beamsolid.registered_types() == before
    with pytest.raises(OpenSeesError, match="HalfRegistered"):
        model.uniaxialMaterial("HalfRegistered", 1)


def test_a_plugin_naming_a_built_in_type_is_refused_whole(model):
    before = beamsolid.registered_types()
    with pytest.raises(OpenSeesError, match=r"types that exist already: uniaxialMaterial 'Elastic' \(built-in\); "
                                            "nothing was registered"):
        model.loadPlugin(plugin_path("clashing_plugin"))
    assert beamsolid.registered_types() == before  # BrandNew was not taken either


def test_missing_plugin_is_a_clear_error(model):
    with pytest.raises(OpenSeesError, match="cannot load it"):
        model.loadPlugin("/nonexistent/libnothing.so")


@pytest.mark.parametrize("wrong", [False, True])
def test_the_tangent_check_catches_a_wrong_tangent(model, wrong):
    """N = k d + c d^3 at d = 0.1: the right tangent k + 3 c d^2 agrees with central differences to
    round-off; the one that leaves out 3 c d^2 = 30 % of it is caught."""
    model.loadPlugin(plugin_path("every_kind_plugin"))
    spring_model(model, "PluginWrongSpring" if wrong else "PluginCubicSpring", 1, 1, 2, 100.0, 1.0e4)
    model.sp(2, 1, 1.0)
    model.integrator("LoadControl", 0.1)
    model.analysis("Static")
    model.algorithm("Newton")
    model.test("NormDispIncr", 1e-12, 50)
    assert model.analyze(1) == 0
    check = check_tangent(model, 1)
    assert check.tangent.shape == check.difference.shape == (6, 6)
    kt = 100.0 + 3 * 1.0e4 * 0.1**2
    assert check.difference[3, 3] == pytest.approx(kt, rel=1e-8)
    assert model.nodeDisp(2, 1) == pytest.approx(0.1, rel=1e-14)  # the check moved nothing
    if wrong:
        assert not check.ok and check.error == pytest.approx(300.0 / kt, rel=1e-6)
        assert check.worst[0] in (0, 3) and check.worst[1] in (0, 3)
        with pytest.raises(AssertionError, match="element 1: tangent off its finite differences"):
            check_tangent(model, 1, raise_error=True)
    else:
        assert check.ok and check.error < 1e-8


def test_the_tangent_check_works_through_the_opensees_module_and_names_a_missing_element(ops):
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 2.0, 0.0, 0.0)
    ops.uniaxialMaterial("Elastic", 1, 2.0e5)
    ops.element("Truss", 1, 1, 2, 0.01, 1)
    check = check_tangent(ops, 1)
    assert check.ok
    assert check.tangent[0, 0] == pytest.approx(2.0e5 * 0.01 / 2.0, rel=1e-12)
    with pytest.raises(OpenSeesError, match="element 7"):
        check_tangent(ops, 7)


def test_the_package_tells_cmake_and_compilers_where_it_is():
    cmake_dir = pathlib.Path(beamsolid.cmake_dir())
    assert (cmake_dir / "BeamSolidConfig.cmake").exists()
    assert (cmake_dir / "BeamSolidPlugin.cmake").exists()
    assert (pathlib.Path(beamsolid.get_include()) / "core" / "PluginAbi.h").exists()


def test_the_tutorial_scene_matches_zero_length_springs_and_the_closed_form():
    """examples/plugins/spring_pile.py: the lateral pile on the plugin's springs equals the same pile on
    built-in zeroLength springs to 1e-10 (elastic and elastic-plastic, 20 steps), and is within 0.5 % of
    Hetenyi's finite beam (measured -0.34 %: the springs are lumped at 40 beam nodes)."""
    spec = importlib.util.spec_from_file_location("spring_pile", ROOT / "examples" / "plugins" / "spring_pile.py")
    scene = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(scene)
    mine, builtin, closed = scene.elastic(str(TUTORIAL))
    assert mine.head_disp == pytest.approx(builtin.head_disp, rel=1e-10)
    assert mine.deflection == pytest.approx(builtin.deflection, rel=1e-10, abs=1e-15)
    assert mine.head_disp == pytest.approx(closed, rel=5e-3)
    mine, builtin = scene.plastic(str(TUTORIAL))
    assert len(mine.curve) == 20
    assert [f for _, f in mine.curve] == pytest.approx([f for _, f in builtin.curve], rel=1e-10)
    forces = [f for _, f in mine.curve]
    assert all(b > a for a, b in zip(forces, forces[1:]))  # springs yield, none breaks: the force still grows
    assert forces[-1] < 0.3 * 20 * forces[0]  # far below the elastic line (20 x the first step; measured 0.27)
