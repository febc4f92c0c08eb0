"""Independent models, the OpenSees-compatible module, and node queries."""
import pytest

import beamsolid


def test_two_models_are_independent():
    a, b = beamsolid.Model(), beamsolid.Model()
    for m in (a, b):
        m.model("basic", "-ndm", 3, "-ndf", 3)
    a.node(1, 0.0, 0.0, 0.0)
    b.node(1, 5.0, 6.0, 7.0)
    b.node(2, 1.0, 1.0, 1.0)
    assert a.nodeCoord(1) == [0.0, 0.0, 0.0]
    assert b.nodeCoord(1) == [5.0, 6.0, 7.0]
    assert a.getNodeTags() == [1]
    assert b.getNodeTags() == [1, 2]


def test_wipe_clears_the_default_model(ops):
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(1, 1.0, 2.0, 3.0)
    assert ops.getNodeTags() == [1]
    assert ops.nodeCoord(1, 3) == 3.0


def test_mixed_ndf_nodes_and_return_types(ops):
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(2, 0.0, 0.0, 1.0)
    ops.node(3, 0.0, 0.0, 2.0, "-ndf", 6, "-mass", 1, 2, 3, 4, 5, 6)
    assert len(ops.nodeDisp(1)) == 6
    assert len(ops.nodeDisp(2)) == 3
    assert isinstance(ops.nodeDisp(3, 1), float)
    assert ops.nodeMass(3) == [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]
    assert ops.getTime() == 0.0


def test_fixz_serves_mixed_ndf_nodes(ops):
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 1.0, 0.0, 0.0, "-ndf", 3)
    ops.node(3, 1.0, 0.0, 1.0, "-ndf", 3)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.fixZ(0.0, 1, 1, 1)
    ops.printModel("-JSON", "-file", "/dev/null")
    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    # node 2 fixed by fixZ, node 3 not: a second fix on node 2 collides.
    try:
        ops.fix(2, 1, 0, 0)
        raise AssertionError("fix on a fixed dof must raise")
    except ops.OpenSeesError as err:
        assert "already fixed" in str(err)
    ops.fix(3, 1, 0, 0)


def test_printmodel_json_is_valid(ops, tmp_path):
    import json

    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 1.0, 0.0, 0.0)
    ops.fix(1, 1, 1, 1)
    out = tmp_path / "model.json"
    ops.printModel("-JSON", "-file", str(out))
    data = json.loads(out.read_text())
    nodes = data["StructuralAnalysisModel"]["geometry"]["nodes"]
    assert [n["name"] for n in nodes] == [1, 2]
    assert nodes[1]["crd"] == [1.0, 0.0, 0.0]


def test_printmodel_prints_through_python_stdout(ops, capsys):
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    ops.node(7, 0.0, 0.0, 0.0)
    ops.printModel()
    assert "Node 7" in capsys.readouterr().out


def test_constraint_bookkeeping_after_removal(ops):
    """The fixed and equalDOF-constrained dofs are looked up in sets kept with the constraints: a dof
    fixed twice or tied twice is refused; after remove('sp'), remove('node') or a re-tie the dof is
    free again; fixZ skips dofs fixed already."""
    ops.model("basic", "-ndm", 3, "-ndf", 3)
    for tag in range(1, 5):
        ops.node(tag, float(tag), 0.0, 0.0)
    ops.fix(1, 1, 0, 1)
    with pytest.raises(ops.OpenSeesError, match="node 1 dof 3 is already fixed"):
        ops.fix(1, 0, 0, 1)
    ops.remove("sp", 1, 3)
    ops.fix(1, 0, 0, 1)  # free again after the removal
    ops.fixX(1.0, 1, 1, 1)  # dofs 1 and 3 of node 1 are fixed already: only dof 2 is added
    with pytest.raises(ops.OpenSeesError, match="already fixed"):
        ops.fix(1, 0, 1, 0)
    ops.equalDOF(2, 3, 1, 2)
    with pytest.raises(ops.OpenSeesError, match="dof 2 of node 3 is already constrained"):
        ops.equalDOF(4, 3, 2)
    ops.equalDOF(4, 3, 3)  # another dof of node 3 may be tied
    ops.fix(4, 1, 1, 1)
    ops.remove("node", 4)  # takes its fix and the tie 4-3 with it
    ops.node(4, 4.0, 0.0, 0.0)
    ops.fix(4, 1, 1, 1)
    ops.equalDOF(4, 3, 3)


def test_remove_sp_of_one_load_pattern(ops):
    """remove('sp', node, dof, patternTag) removes that pattern's sp only (OpenSees' optional
    pattern tag); the same sp of another pattern stays, and a missing one is an error."""
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    ops.node(2, 1.0)
    ops.fix(1, 1)
    ops.uniaxialMaterial("Elastic", 1, 10.0)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    ops.timeSeries("Constant", 1)
    ops.pattern("Plain", 1, 1)
    ops.sp(2, 1, 0.5)
    ops.pattern("Plain", 2, 1)
    ops.load(2, 3.0)
    with pytest.raises(ops.OpenSeesError, match=r"remove sp: load pattern 2 has no sp on node 2 dof 1"):
        ops.remove("sp", 2, 1, 2)
    with pytest.raises(ops.OpenSeesError, match=r"remove sp: load pattern 9 does not exist"):
        ops.remove("sp", 2, 1, 9)
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    assert ops.analyze(1) == 0
    assert ops.nodeDisp(2, 1) == pytest.approx(0.5)
    ops.remove("sp", 2, 1, 1)
    assert ops.analyze(1) == 0
    assert ops.nodeDisp(2, 1) == pytest.approx(0.3)  # now the load alone: 3 / 10
