"""Bad input of every kind raises OpenSeesError naming the command and argument."""
import pytest

import beamsolid
from beamsolid import OpenSeesError


def base(m, ndf=3):
    m.model("basic", "-ndm", 3, "-ndf", ndf)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, 1.0, 0.0, 0.0)


# (command, args, fragment the message must contain)
CASES = [
    # wrong argument count
    ("node", (3, 0.0, 0.0), "node 3: expected 3 coordinates (x, y, z) in a model with -ndm 3, got 2"),
    ("node", (3, 0.0, 0.0, 0.0, 0.0), "node 3: expected 3 coordinates (x, y, z) in a model with -ndm 3, got 4"),
    ("fix", (1, 1, 1), "has 3 dofs but 2 flags"),
    ("mass", (1,), "argument 2 (mass): expected at least 1 number"),
    ("equalDOF", (1, 2), "argument 3 (dof): expected at least 1"),
    ("load", (1, 1.0, 0.0), "has 3 dofs but 2 load values"),
    ("model", ("basic", "-ndm", 4), "-ndm must be 1, 2 or 3, got 4"),
    ("model", ("basic", "-ndm", 2, "-ndf", 6), "-ndf must be 2 or 3 in 2D, got 6"),
    ("timeSeries", ("Linear",), "argument 2"),
    # wrong type
    ("node", ("a", 0.0, 0.0, 0.0), "argument 1 (nodeTag): expected an integer, got 'a'"),
    ("node", (3, "x", 0.0, 0.0), "argument 2 (x): expected a number, got 'x'"),
    ("fix", (1.5, 1, 1, 1), "argument 1 (nodeTag): expected an integer, got 1.5"),
    ("fix", (1, 1, 2, 1), "flags must be 0 or 1"),
    ("nodeDisp", ("one",), "nodeDisp: argument 1 (nodeTag)"),
    ("node", (3, [0.0], 0.0, 0.0), "expected a number or a string, got list (unpack it with *)"),
    # unknown tag
    ("fix", (9, 1, 1, 1), "fix 9: node 9 does not exist"),
    ("mass", (9, 1.0, 1.0, 1.0), "node 9 does not exist"),
    ("equalDOF", (1, 9, 1), "node 9 does not exist"),
    ("nodeDisp", (9,), "nodeDisp 9: node 9 does not exist"),
    ("nodeDisp", (1, 4), "dof 4 is out of range 1..3"),
    ("eleResponse", (5, "force"), "element 5 does not exist"),
    ("eleForce", (5,), "element 5 does not exist"),
    ("remove", ("node", 9), "node 9 does not exist"),
    ("remove", ("recorder", 3), "recorder 3 does not exist"),
    ("pattern", ("Plain", 1, 7), "timeSeries 7 does not exist"),
    ("load", (1, 1.0, 0.0, 0.0), "no load pattern"),
    ("rigidLink", ("beam", 1, 9), "node 9 does not exist"),
    ("rigidLink", ("hinge", 1, 2), "type must be 'beam' or 'bar'"),
    # unknown type / command options
    ("element", ("noSuchElement", 1, 1, 2), "type 'noSuchElement' is unknown"),
    ("uniaxialMaterial", ("NoSuch", 1), "type 'NoSuch' is unknown"),
    ("nDMaterial", ("NoSuch", 1), "type 'NoSuch' is unknown"),
    ("system", ("NoSolver",), "type 'NoSolver' is unknown"),
    ("algorithm", ("Newton", "-bogus"), "unknown option '-bogus'"),
    ("test", ("NormDispIncr", -1.0, 10), "tol must be positive"),
    ("analyze", (1,), "no analysis"),
    ("node", (3, 0.0, 0.0, 0.0, "-ndf", 4), "-ndf must be 3 or 6"),
]


@pytest.mark.parametrize("command,args,fragment", CASES, ids=[f"{c[0]}-{i}" for i, c in enumerate(CASES)])
def test_bad_input_raises_clear_error(model, command, args, fragment):
    base(model)
    with pytest.raises(OpenSeesError) as err:
        getattr(model, command)(*args)
    assert fragment in str(err.value), str(err.value)
    assert "See stderr" not in str(err.value)


DUPLICATES = [
    ("node", lambda m: m.node(1, 5.0, 0.0, 0.0), "node 1 already exists"),
    ("fix", lambda m: (m.fix(1, 1, 1, 1), m.fix(1, 1, 0, 0)), "already fixed"),
    ("timeSeries", lambda m: (m.timeSeries("Constant", 1), m.timeSeries("Linear", 1)), "timeSeries with tag 1 already exists"),
    ("pattern", lambda m: (m.timeSeries("Linear", 1), m.pattern("Plain", 1, 1), m.pattern("Plain", 1, 1)),
     "load pattern 1 already exists"),
    ("equalDOF", lambda m: (m.equalDOF(1, 2, 1), m.equalDOF(1, 2, 1)), "already constrained"),
]


@pytest.mark.parametrize("name,build,fragment", DUPLICATES, ids=[d[0] for d in DUPLICATES])
def test_duplicate_tag_raises(model, name, build, fragment):
    base(model)
    with pytest.raises(OpenSeesError) as err:
        build(model)
    assert fragment in str(err.value)


def test_error_is_a_runtime_error_and_reachable_from_ops(ops):
    assert issubclass(beamsolid.OpenSeesError, RuntimeError)
    assert ops.OpenSeesError is beamsolid.OpenSeesError
    with pytest.raises(RuntimeError):
        ops.nodeDisp(1)


def test_unknown_command_attribute_is_an_attribute_error(model):
    with pytest.raises(AttributeError):
        model.noSuchCommand(1)


def test_commands_before_model_are_refused(model):
    with pytest.raises(OpenSeesError, match="call model"):
        model.node(1, 0.0, 0.0, 0.0)


def test_huge_and_nonfinite_numbers_are_refused(model):
    base(model)
    with pytest.raises(OpenSeesError, match="32-bit"):
        model.node(2**40, 0.0, 0.0, 0.0)
    with pytest.raises(OpenSeesError, match="finite"):
        model.node(5, float("nan"), 0.0, 0.0)
    with pytest.raises(OpenSeesError, match="integer out of range"):
        model.node(2**80, 0.0, 0.0, 0.0)


def test_numpy_scalars_are_accepted(model):
    np = pytest.importorskip("numpy")
    base(model)
    model.node(np.int64(3), np.float64(1.5), np.float32(0.5), 0)
    assert model.nodeCoord(3) == [1.5, 0.5, 0.0]


def test_numpy_arrays_are_refused_by_name(model):
    # A one-element array (rayleigh(0, 0, 0, 2 * zeta / omega) with omega from
    # a NumPy computation) used to fail as "integer out of range".
    np = pytest.importorskip("numpy")
    base(model)
    with pytest.raises(OpenSeesError, match=r"node: argument 2: expected a number or a string, got an array \(1,\)"):
        model.node(3, np.array([1.5]), 0.0, 0.0)
    model.node(4, np.array(1.5), 0.0, 0.0)  # a 0-d array is a number
    assert model.nodeCoord(4, 1) == 1.5
