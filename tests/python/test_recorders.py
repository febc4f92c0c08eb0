"""Recorder files read back equal the values the queries returned at every step.

Each test records nodeDisp/eleResponse in its own loop and compares the file
row by row: text and CSV to the printed precision (a value printed with %.Ng
is within 0.5e-(N-1) relative of the true one), binary exactly. It also checks
the JSON sidecar, -dT, -closeOnWrite, flushing after a failed step, closing
on wipe()/remove(), and that a script exiting without wipe() loses nothing.
"""
import json
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import beamsolid
from conftest import subprocess_env

PATH_VALUES = [0.0, 1.0, -0.5, 0.8, -1.2, 0.3]  # a Path series that changes sign
NODES, DOFS = [2, 3, 4], [1, 2, 6]
BEAMS = [1, 2, 3]
LOCAL_NAMES = ["N", "Vy", "Vz", "T", "My", "Mz"]


def cantilever(m):
    """A 3-element cantilever along x, a truss from the tip, tip load through a Path series."""
    m.model("basic", "-ndm", 3, "-ndf", 6)
    for k in range(4):
        m.node(k + 1, 1.0 * k, 0.0, 0.0)
    m.node(5, 3.0, 2.0, 0.0)
    m.fix(1, 1, 1, 1, 1, 1, 1)
    m.fix(5, 1, 1, 1, 1, 1, 1)
    m.geomTransf("Linear", 1, 0.0, 0.0, 1.0)
    for k in range(3):
        m.element("elasticBeamColumn", k + 1, k + 1, k + 2, 0.01, 2.0e8, 8.0e7, 2e-6, 1e-6, 3e-6, 1)
    m.uniaxialMaterial("Elastic", 1, 2.0e8)
    m.element("truss", 4, 4, 5, 1e-5, 1)
    m.timeSeries("Path", 1, "-dt", 1.0, "-values", *PATH_VALUES)
    m.pattern("Plain", 1, 1)
    m.load(4, 3.0, 10.0, -5.0, 0.4, 0.0, 2.0)
    m.constraints("Transformation")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-12, 10)
    m.algorithm("Newton")
    m.integrator("LoadControl", 0.5)
    m.analysis("Static")


def snapshot(m):
    """What the recorders should write now: time, node dofs, beam local forces, truss force."""
    nodes = [m.nodeDisp(n, d) for n in NODES for d in DOFS]
    beams = [v for e in BEAMS for v in m.eleResponse(e, "localForce")]
    return m.getTime(), nodes, beams, m.eleResponse(4, "axialForce")


def read_text(path, delimiter=None):
    with open(path) as f:
        text = f.read()
    assert text == "" or text.endswith("\n"), "a partial row on disk"
    return np.array([[float(v) for v in line.split(delimiter)] for line in text.splitlines()])


def read_xml(path):
    with open(path) as f:
        text = f.read()
    header, _, data = text.partition("<Data>")
    data = data.partition("</Data>")[0]
    rows = np.array([[float(v) for v in line.split()] for line in data.strip().splitlines()])
    return header, rows, "</OpenSees>" in text


def read_binary(path):
    with open(path + ".json") as f:
        columns = json.load(f)["columnCount"]
    raw = np.fromfile(path, dtype=np.uint8)
    row_bytes = 8 * columns + 1
    assert raw.size % row_bytes == 0, "a partial row on disk"
    raw = raw.reshape(-1, row_bytes)
    assert np.all(raw[:, -1] == ord("\n"))
    return raw[:, :-1].copy().view("<f8")


def read(path, fmt):
    if fmt == "text":
        return read_text(path)
    if fmt == "csv":
        return read_text(path, ",")
    if fmt == "xml":
        return read_xml(path)[1]
    return read_binary(path)


FLAGS = {"text": "-file", "csv": "-csv", "xml": "-xml", "binary": "-binary"}


@pytest.mark.parametrize("fmt", list(FLAGS))
@pytest.mark.parametrize("precision", [None, 12])
def test_rows_equal_the_queried_values(model, tmp_path, fmt, precision):
    m = model
    cantilever(m)
    prec = [] if precision is None else ["-precision", precision]
    node_file, beam_file, truss_file = (str(tmp_path / f"{n}.{fmt}") for n in ("node", "beam", "truss"))
    m.recorder("Node", FLAGS[fmt], node_file, "-time", *prec, "-nodeRange", 2, 4, "-dof", *DOFS, "disp")
    m.recorder("Element", FLAGS[fmt], beam_file, "-time", *prec, "-eleRange", 1, 3, "localForce")
    m.recorder("Element", FLAGS[fmt], truss_file, *prec, "-ele", 4, "axialForce")
    expected = []
    m.record()  # the initial state
    expected.append(snapshot(m))
    for _ in range(10):
        assert m.analyze(1) == 0
        expected.append(snapshot(m))
    times = np.array([e[0] for e in expected])
    assert times[-1] == pytest.approx(5.0)
    assert np.ptp([e[1][1] for e in expected]) > 0 and min(e[1][1] for e in expected) < 0

    node_rows, beam_rows, truss_rows = (read(f, fmt) for f in (node_file, beam_file, truss_file))
    want_node = np.array([[t, *n] for t, n, _, _ in expected])
    want_beam = np.array([[t, *b] for t, _, b, _ in expected])
    want_truss = np.array([s for _, _, _, s in expected])
    if fmt == "binary":
        np.testing.assert_array_equal(node_rows, want_node)
        np.testing.assert_array_equal(beam_rows, want_beam)
        np.testing.assert_array_equal(truss_rows, want_truss)
    else:
        rtol = 0.5 * 10.0 ** (1 - (precision or 6)) * (1 + 1e-9)
        for got, want in ((node_rows, want_node), (beam_rows, want_beam), (truss_rows, want_truss)):
            assert got.shape == want.shape
            np.testing.assert_allclose(got, want, rtol=rtol, atol=0.0)

    if fmt == "xml":
        m.wipe()
        header, _, closed = read_xml(node_file)
        assert closed
        for n in NODES:
            assert f'nodeTag="{n}"' in header
        assert header.count("<ResponseType>") == 1 + len(NODES) * len(DOFS)
        assert "<ResponseType>D6</ResponseType>" in header
        header, _, _ = read_xml(beam_file)
        assert header.count("<ResponseType>Vy_2</ResponseType>") == 3
        assert not os.path.exists(node_file + ".json")
        return
    # The sidecar names every column in file order.
    with open(node_file + ".json") as f:
        side = json.load(f)
    assert side["format"] == fmt and side["columnCount"] == 1 + len(NODES) * len(DOFS)
    cols = side["columns"]
    assert cols[0]["name"] == "time"
    assert [(c["node"], c["dof"], c["response"]) for c in cols[1:]] == [(n, d, "disp") for n in NODES for d in DOFS]
    with open(beam_file + ".json") as f:
        cols = json.load(f)["columns"]
    assert [(c["element"], c["component"]) for c in cols[1:]] == [
        (e, f"{name}_{end}") for e in BEAMS for end in (1, 2) for name in LOCAL_NAMES]
    assert all(c["response"] == "localForce" for c in cols[1:])
    with open(truss_file + ".json") as f:
        cols = json.load(f)["columns"]
    assert [(c["element"], c["response"]) for c in cols] == [(4, "axialForce")]


def test_dT_records_only_when_due(model, tmp_path):
    m = model
    cantilever(m)
    m.integrator("LoadControl", 0.1)
    path = str(tmp_path / "dt.out")
    dT = 0.25
    m.recorder("Node", "-file", path, "-time", "-precision", 15, "-dT", dT, "-node", 4, "-dof", 2, "disp")
    expected, last = [], None
    for _ in range(12):
        assert m.analyze(1) == 0
        t = m.getTime()
        if last is None or t >= last + dT - 1e-5 * dT:  # the documented rule, with -rTolDt's default
            expected.append([t, m.nodeDisp(4, 2)])
            last = t
    assert [round(r[0], 10) for r in expected] == [0.1, 0.4, 0.7, 1.0]
    np.testing.assert_allclose(read_text(path), expected, rtol=1e-14, atol=0.0)


def test_close_on_write_rows_are_on_disk_after_every_step(model, tmp_path):
    m = model
    cantilever(m)
    path = str(tmp_path / "cow.out")
    m.recorder("Element", "-file", path, "-closeOnWrite", "-precision", 14, "-ele", 2, "localForce")
    expected = []
    for _ in range(4):
        assert m.analyze(1) == 0
        expected.append(m.eleResponse(2, "localForce"))
        np.testing.assert_allclose(read_text(path), expected, rtol=1e-13, atol=0.0)


def test_exception_mid_script_leaves_complete_rows(model, tmp_path):
    """Three steps, then a bad command raises: every row is on disk, nothing closed."""
    m = model
    cantilever(m)
    text, binary, xml = (str(tmp_path / n) for n in ("d.out", "d.bin", "d.xml"))
    m.recorder("Node", "-file", text, "-precision", 16, "-node", 4, "disp")
    m.recorder("Node", "-binary", binary, "-node", 4, "disp")
    m.recorder("Node", "-xml", xml, "-precision", 16, "-node", 4, "disp")
    expected = []
    with pytest.raises(beamsolid.OpenSeesError):
        for step in range(10):
            if step == 3:
                m.element("elasticBeamColumn", 9, 1, 42, 0.01, 2e8, 8e7, 2e-6, 1e-6, 3e-6, 1)  # node 42: none
            assert m.analyze(1) == 0
            expected.append(m.nodeDisp(4))
    assert len(expected) == 3
    np.testing.assert_allclose(read_text(text), expected, rtol=1e-15, atol=0.0)
    np.testing.assert_array_equal(read_binary(binary), expected)
    _, rows, closed = read_xml(xml)
    np.testing.assert_allclose(rows, expected, rtol=1e-15, atol=0.0)
    assert not closed
    # The failed command left the model as it was: the script could go on.
    assert 9 not in m.getEleTags()
    assert m.analyze(1) == 0
    assert len(read_text(text)) == 4


def epp_bar(m):
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, 1.0, 0.0, 0.0)
    m.fix(1, 1, 1, 1)
    m.fix(2, 0, 1, 1)
    m.uniaxialMaterial("ElasticPP", 1, 1000.0, 0.01)
    m.element("truss", 1, 1, 2, 1.0, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, 10.0, 0.0, 0.0)  # capacity 10 reached at load factor 1
    m.constraints("Plain")
    m.system("UmfPack")
    m.test("NormUnbalance", 1e-10, 10)
    m.algorithm("Newton")
    m.integrator("LoadControl", 0.15)
    m.analysis("Static")


def test_rows_before_a_failed_step_are_flushed(model, tmp_path):
    m = model
    epp_bar(m)
    path = str(tmp_path / "epp.out")
    m.recorder("Element", "-file", path, "-time", "-precision", 16, "-ele", 1, "axialForce")
    assert m.analyze(10) < 0  # the 7th step (1.05) exceeds the capacity
    rows = read_text(path)
    assert len(rows) == 6
    np.testing.assert_allclose(rows[:, 0], 0.15 * np.arange(1, 7), rtol=1e-14)
    np.testing.assert_allclose(rows[:, 1], 10.0 * rows[:, 0], rtol=1e-14)
    assert rows[-1, 1] == m.eleResponse(1, "axialForce")[0]
    # Nothing was closed: the next converged step adds its row.
    m.integrator("LoadControl", 0.05)
    assert m.analyze(1) == 0
    assert len(read_text(path)) == 7


@pytest.mark.parametrize("how", ["wipe", "remove recorders", "remove recorder"])
def test_wipe_and_remove_close_files(model, tmp_path, how):
    m = model
    cantilever(m)
    a, b = str(tmp_path / "a.xml"), str(tmp_path / "b.out")
    tag_a = m.recorder("Node", "-xml", a, "-node", 4, "disp")
    m.recorder("Node", "-file", b, "-node", 4, "disp")
    assert m.analyze(2) == 0
    assert not read_xml(a)[2]
    if how == "wipe":
        m.wipe()
    elif how == "remove recorders":
        m.remove("recorders")
    else:
        m.remove("recorder", tag_a)
    header, rows, closed = read_xml(a)
    assert closed and len(rows) == 2
    if how != "wipe":
        assert m.analyze(1) == 0
        assert len(read_xml(a)[1]) == 2                      # closed: no more rows
        assert len(read_text(b)) == (2 if how == "remove recorders" else 3)


SCRIPT = textwrap.dedent("""
    import sys
    import beamsolid
    import beamsolid.opensees as ops

    def build(m, out):
        m.model('basic', '-ndm', 3, '-ndf', 3)
        m.node(1, 0.0, 0.0, 0.0)
        m.node(2, 2.0, 0.0, 0.0)
        m.fix(1, 1, 1, 1)
        m.fix(2, 0, 1, 1)
        m.uniaxialMaterial('Elastic', 1, 100.0)
        m.element('truss', 1, 1, 2, 1.0, 1)
        m.timeSeries('Linear', 1)
        m.pattern('Plain', 1, 1)
        m.load(2, 5.0, 0.0, 0.0)
        for ext, flag in (('out', '-file'), ('xml', '-xml'), ('bin', '-binary')):
            m.recorder('Node', flag, out + '.' + ext, '-time', '-precision', 16, '-node', 2, '-dof', 1, 'disp')
        m.integrator('LoadControl', 0.1)
        m.analysis('Static')

    build(ops, sys.argv[1] + '_ops')
    extra = beamsolid.Model()
    build(extra, sys.argv[1] + '_model')
    for step in range(7):
        ops.analyze(1)
        extra.analyze(1)
        if sys.argv[2] == 'raise' and step == 4:
            raise RuntimeError('the script stops here')
    # no wipe(): the interpreter's exit must close everything
""")


@pytest.mark.parametrize("ending", ["exit", "raise"])
def test_script_exiting_without_wipe_keeps_every_row(tmp_path, ending):
    script = tmp_path / "script.py"
    script.write_text(SCRIPT)
    env = subprocess_env()
    base = str(tmp_path / "rec")
    proc = subprocess.run([sys.executable, str(script), base, ending], env=env, capture_output=True, text=True,
                          timeout=60)
    steps = 7 if ending == "exit" else 5
    if ending == "exit":
        assert proc.returncode == 0, proc.stderr
    else:
        assert proc.returncode != 0 and "the script stops here" in proc.stderr
    t = 0.1 * np.arange(1, steps + 1)
    want = np.column_stack([t, 5.0 * t * 2.0 / 100.0])  # u = P L / EA
    for who in ("_ops", "_model"):
        np.testing.assert_allclose(read_text(base + who + ".out"), want, rtol=1e-14)
        np.testing.assert_allclose(read_binary(base + who + ".bin"), want, rtol=1e-14)
        _, rows, closed = read_xml(base + who + ".xml")
        assert closed, "the XML recorder was not closed at exit"
        np.testing.assert_allclose(rows, want, rtol=1e-14)


def test_envelope_recorders_match_the_recorded_extremes(model, tmp_path):
    m = model
    cantilever(m)
    node_env, ele_env = str(tmp_path / "env_node.out"), str(tmp_path / "env_ele.out")
    m.recorder("EnvelopeNode", "-file", node_env, "-precision", 16, "-nodeRange", 2, 4, "-dof", *DOFS, "disp")
    m.recorder("EnvelopeElement", "-file", ele_env, "-precision", 16, "-eleRange", 1, 3, "localForce")
    history = []
    for _ in range(10):
        assert m.analyze(1) == 0
        _, nodes, beams, _ = snapshot(m)
        history.append(nodes + beams)
    m.wipe()
    h = np.array(history)
    n = len(NODES) * len(DOFS)
    for path, cols in ((node_env, h[:, :n]), (ele_env, h[:, n:])):
        rows = read_text(path)
        np.testing.assert_allclose(rows, [cols.min(0), cols.max(0), np.abs(cols).max(0)], rtol=1e-15, atol=1e-300)


# One writer per file: a recorder on a file another recorder writes is refused
# before it opens (and so truncates) it.

def _spellings(tmp_path, path):
    """The same file as other strings: relative, with '.' and '..', through a symlinked folder."""
    link = tmp_path / "link"
    if not link.exists():
        link.symlink_to(tmp_path, target_is_directory=True)
    name = os.path.basename(path)
    return [os.path.relpath(path), os.path.join(str(tmp_path), ".", name),
            os.path.join(str(tmp_path), "nowhere", "..", name), os.path.join(str(link), name)]


def test_second_recorder_on_a_file_is_refused_and_the_first_keeps_its_rows(model, tmp_path):
    m = model
    cantilever(m)
    m.recorder("Node", "-file", str(tmp_path / "other.out"), "-node", 2, "disp")  # tag 0
    path = str(tmp_path / "disp.out")
    assert m.recorder("Node", "-file", path, "-time", "-precision", 16, "-node", 3, 4, "-dof", 1, 2, "disp") == 1
    expected = []
    assert m.analyze(1) == 0
    expected.append([m.getTime(), m.nodeDisp(3, 1), m.nodeDisp(3, 2), m.nodeDisp(4, 1), m.nodeDisp(4, 2)])

    refused = [("Node", flag, spelling, "-node", 2, "disp")
               for spelling in [path, *_spellings(tmp_path, path)]
               for flag in ("-file", "-fileAdd", "-csv", "-xml", "-binary")]
    refused += [("Element", "-file", path, "-ele", 1, "localForce"),
                ("EnvelopeNode", "-csv", path, "-node", 2, "disp"),
                ("EnvelopeElement", "-xml", path, "-ele", 2, "localForce")]
    for args in refused:
        with pytest.raises(beamsolid.OpenSeesError) as info:
            m.recorder(*args)
        message = str(info.value)
        assert message.startswith(f"recorder {args[0]}: file '{args[2]}' is already written by recorder 1 (Node)")
        assert message.endswith("; remove that recorder first or choose another file")
        assert "another model" not in message
        assert (f"which opened it as '{path}'" in message) == (args[2] != path)

    # The refused commands took no tag, and the holder's file is intact.
    assert m.recorder("Node", "-file", str(tmp_path / "third.out"), "-node", 2, "disp") == 2
    for _ in range(3):
        assert m.analyze(1) == 0
        expected.append([m.getTime(), m.nodeDisp(3, 1), m.nodeDisp(3, 2), m.nodeDisp(4, 1), m.nodeDisp(4, 2)])
    m.remove("recorders")
    np.testing.assert_allclose(read_text(path), expected, rtol=1e-15, atol=0.0)
    with open(path + ".json") as f:
        assert json.load(f)["columnCount"] == 5


def elastic_bar(m, load):
    """A truss of length 2 and EA = 100 pulled by `load`: u = 0.02 load lambda."""
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, 2.0, 0.0, 0.0)
    m.fix(1, 1, 1, 1)
    m.fix(2, 0, 1, 1)
    m.uniaxialMaterial("Elastic", 1, 100.0)
    m.element("truss", 1, 1, 2, 1.0, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, load, 0.0, 0.0)
    m.constraints("Plain")
    m.system("UmfPack")
    m.test("NormUnbalance", 1e-10, 10)
    m.algorithm("Newton")
    m.integrator("LoadControl", 0.1)
    m.analysis("Static")


@pytest.mark.parametrize("how", ["remove recorder", "remove recorders", "wipe"])
def test_the_file_is_free_after_remove_or_wipe(model, tmp_path, how):
    """OpenSees scripts often wipe and rebuild in a loop with the same recorder: each run rewrites the file."""
    m = model
    path = str(tmp_path / "disp.out")
    for run, load in enumerate((1.0, 2.0, 3.0)):
        if how == "wipe" or run == 0:
            elastic_bar(m, load)  # each run writes other values
        tag = m.recorder("Node", "-file", path, "-precision", 16, "-node", 2, "-dof", 1, "disp")
        with pytest.raises(beamsolid.OpenSeesError, match=f"already written by recorder {tag} \\(Node\\)"):
            m.recorder("Node", "-file", path, "-node", 2, "-dof", 1, "disp")
        rows = []
        for _ in range(2):
            assert m.analyze(1) == 0
            rows.append([m.nodeDisp(2, 1)])
        if how == "remove recorder":
            m.remove("recorder", tag)
        elif how == "remove recorders":
            m.remove("recorders")
        else:
            m.wipe()
        np.testing.assert_allclose(read_text(path), rows, rtol=1e-15, atol=0.0)


def test_two_models_cannot_share_a_file(ops, tmp_path):
    path = str(tmp_path / "disp.out")
    first, second = beamsolid.Model(), beamsolid.Model()
    for m in (first, second, ops):
        epp_bar(m)
    first.recorder("Node", "-file", path, "-precision", 16, "-node", 2, "-dof", 1, "disp")
    with pytest.raises(beamsolid.OpenSeesError) as info:
        second.recorder("Node", "-csv", path, "-node", 2, "disp")
    assert str(info.value) == (f"recorder Node: file '{path}' is already written by recorder 0 (Node) in another "
                               "model; remove that recorder first or choose another file")
    relative = os.path.relpath(path)
    with pytest.raises(beamsolid.OpenSeesError) as info:
        second.recorder("Node", "-xml", relative, "-node", 2, "disp")
    assert str(info.value).startswith(f"recorder Node: file '{relative}' is already written by recorder 0 (Node) "
                                      f"in another model, which opened it as '{path}'")
    with pytest.raises(beamsolid.OpenSeesError, match=r"recorder 0 \(Node\) in another model"):
        ops.recorder("Node", "-file", path, "-node", 2, "disp")
    assert first.analyze(2) == 0
    want = [[0.15 * 10.0 / 1000.0], [0.30 * 10.0 / 1000.0]]  # u = lambda P L / EA
    np.testing.assert_allclose(read_text(path), want, rtol=1e-14)

    # Destroying the holder's model frees the file.
    del first
    import gc
    gc.collect()
    second.recorder("Node", "-file", path, "-node", 2, "disp")
    second.wipe()


def test_a_failed_recorder_command_leaves_no_claim(model, tmp_path):
    m = model
    cantilever(m)
    path = str(tmp_path / "x.out")
    later = tmp_path / "later"
    failing = [
        ("Element", "-file", path, "-ele", 99, "force"),           # no element 99
        ("Node", "-file", path, "-node", 42, "disp"),               # no node 42
        ("Node", "-file", path, "-node", 2, "disp", 3),             # an extra argument
        ("Node", "-file", str(later / "x.out"), "-node", 2, "disp"),  # claimed, then cannot open: no folder
    ]
    for args in failing:
        with pytest.raises(beamsolid.OpenSeesError):
            m.recorder(*args)
    later.mkdir()
    assert m.recorder("Node", "-file", path, "-node", 2, "disp") == 0
    assert m.recorder("Node", "-file", str(later / "x.out"), "-node", 2, "disp") == 1


def test_pvd_recorders_on_one_name_are_refused(model, tmp_path):
    m = model
    cantilever(m)
    name = str(tmp_path / "model")
    assert m.recorder("PVD", name) == 0
    for args in (("PVD", name), ("vtk", name + ".pvd"), ("PVD", os.path.relpath(name))):
        with pytest.raises(beamsolid.OpenSeesError, match=r"is already written by recorder 0 \(PVD\)"):
            m.recorder(*args)
    with pytest.raises(beamsolid.OpenSeesError, match=r"recorder Node: file '.*model\.pvd' .* recorder 0 \(PVD\)"):
        m.recorder("Node", "-file", name + ".pvd", "-node", 2, "disp")
    assert m.analyze(2) == 0
    m.remove("recorder", 0)
    with open(name + ".pvd") as f:
        assert f.read().count("<DataSet") == 2
    assert m.recorder("PVD", name) == 1  # the refused commands took no tag


def test_an_element_recorder_leaves_out_elements_without_the_response(tmp_path, capfd):
    """As OpenSees: a section response asked of a mix of force-based and elastic members records the
    force-based ones only (the elastic beam is named in a warning); a name no element has gives
    rows of the time alone with -time (nothing without it, and nothing in an envelope) instead of
    stopping the script, and each element's XML block stays, empty (OpenSeesPy 3.7.1 does all
    this: public example 1b records 'deformations' of elastic beams)."""
    m = beamsolid.Model()
    m.model("basic", "-ndm", 2, "-ndf", 3)
    for tag, y in ((1, 0.0), (2, 3.0), (3, 6.0)):
        m.node(tag, 0.0, y)
    m.fix(1, 1, 1, 1)
    m.geomTransf("Linear", 1)
    m.section("Elastic", 1, 200.0, 10.0, 30.0)
    m.beamIntegration("Lobatto", 1, 1, 3)
    m.element("forceBeamColumn", 1, 1, 2, 1, 1)
    m.element("elasticBeamColumn", 2, 2, 3, 10.0, 200.0, 30.0, 1)
    mixed, unknown = tmp_path / "mixed.out", tmp_path / "unknown.out"
    m.recorder("Element", "-file", str(mixed), "-time", "-ele", 1, 2, "section", 1, "force")
    m.recorder("Element", "-file", str(unknown), "-time", "-ele", 1, 2, "noSuchResponse")
    untimed, envelope = tmp_path / "untimed.out", tmp_path / "envelope.out"
    xml = tmp_path / "unknown.xml"
    m.recorder("Element", "-file", str(untimed), "-ele", 1, 2, "noSuchResponse")
    m.recorder("EnvelopeElement", "-file", str(envelope), "-time", "-ele", 1, 2, "noSuchResponse")
    m.recorder("Element", "-xml", str(xml), "-time", "-ele", 2, "noSuchResponse")
    assert "element 2 (elasticBeamColumn) has no response 'section 1 force'" in capfd.readouterr().err
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(3, 1.0, 0.0, 0.0)
    m.integrator("LoadControl", 0.5)
    m.analysis("Static")
    assert m.analyze(2) == 0
    m.wipe()
    rows = [[float(x) for x in line.split()] for line in mixed.read_text().splitlines()]
    # time, then the force-based member's first section: N and M = 1 x 6 at the base (factor 0.5, 1).
    assert [len(r) for r in rows] == [3, 3]
    assert rows[1][0] == pytest.approx(1.0)
    assert abs(rows[1][2]) == pytest.approx(6.0, rel=1e-10)
    assert unknown.read_text().split() == ["0.5", "1"]
    assert untimed.read_text() == "" and envelope.read_text() == ""
    text = xml.read_text()
    assert '<ElementOutput eleType="ElasticBeam2d" eleTag="2" node1="2" node2="3"/>' in text
    assert text.split("<Data>")[1].split() == ["0.5", "1", "</Data>", "</OpenSees>"]


def test_ele_dynamical_force_balances_the_load(model):
    """eleDynamicalForce(tag): the resisting force with inertia and Rayleigh damping (OpenSees'
    getResistingForceIncInertia). A cantilever of one element with consistent mass: at the free
    node it equals the applied load after each converged step (the equation of motion); it is the
    static eleForce plus M a + C v, with M a from the element's own mass matrix in closed form."""
    L, m = 3.0, 2.0
    model.model("basic", "-ndm", 2, "-ndf", 3)
    model.node(1, 0.0, 0.0)
    model.node(2, L, 0.0)
    model.fix(1, 1, 1, 1)
    model.geomTransf("Linear", 1)
    model.element("elasticBeamColumn", 1, 1, 2, 1.0, 100.0, 1.0, 1, "-mass", m, "-cMass")
    model.timeSeries("Linear", 1)
    model.pattern("Plain", 1, 1)
    model.load(2, 0.0, 1.0, 0.0)
    model.integrator("Newmark", 0.5, 0.25)
    model.analysis("Transient")
    for step in range(1, 4):
        assert model.analyze(1, 0.1) == 0
        f = model.eleDynamicalForce(1)
        assert f[3:] == pytest.approx([0.0, 0.1 * step, 0.0], abs=1e-12)
        # Transverse: the consistent mass of an Euler-Bernoulli beam at the free end
        # (156, 22 L; 22 L, 4 L^2) m L / 420 times (a_y, a_rz), added to eleForce.
        ay, arz = model.nodeAccel(2, 2), model.nodeAccel(2, 3)
        inertia_y = m * L / 420 * (156 * ay - 22 * L * arz)
        assert f[4] == pytest.approx(model.eleForce(1, 5) + inertia_y, rel=1e-10)
    assert model.eleDynamicalForce(1, 5) == [pytest.approx(f[4])]


def test_recorder_tags_go_on_after_wipe(tmp_path):
    # OpenSees numbers recorders on across wipe() (OpenSeesPy 3.7.1: 0, 1, wipe, 2).
    import beamsolid.opensees as ops

    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    first = ops.recorder("Node", "-file", str(tmp_path / "a.out"), "-node", 1, "-dof", 1, "disp")
    second = ops.recorder("Node", "-file", str(tmp_path / "b.out"), "-node", 1, "-dof", 1, "disp")
    ops.wipe()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    third = ops.recorder("Node", "-file", str(tmp_path / "c.out"), "-node", 1, "-dof", 1, "disp")
    assert (second - first, third - second) == (1, 1)
    ops.wipe()


def test_recorders_take_regions(tmp_path):
    # recorder(..., '-region', regTag): a region of elements records those elements and their
    # nodes, one of nodes those nodes (OpenSeesPy 3.7.1 writes the same columns). Three unit bars in
    # series pulled by 1: nodes 2, 3, 4 move 0.01, 0.02, 0.03 per step, every bar carries 1.
    import beamsolid.opensees as ops

    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 2)
    for i in range(1, 5):
        ops.node(i, float(i), 0.0)
    ops.fix(1, 1, 1)
    for i in range(2, 5):
        ops.fix(i, 0, 1)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    for i in range(1, 4):
        ops.element("Truss", i, i, i + 1, 1.0, 1)
    ops.region(1, "-ele", 2, 3)
    ops.region(2, "-node", 2, 4)
    ops.region(3, "-eleOnly", 1)
    files = {k: str(tmp_path / f"{k}.out") for k in ("e1", "n1", "n2", "e3")}
    ops.recorder("Element", "-file", files["e1"], "-region", 1, "axialForce")
    ops.recorder("Node", "-file", files["n1"], "-time", "-region", 1, "-dof", 1, "disp")
    ops.recorder("Node", "-file", files["n2"], "-region", 2, "-dof", 1, "disp")
    ops.recorder("Element", "-file", files["e3"], "-region", 3, "axialForce")
    with pytest.raises(beamsolid.OpenSeesError, match="region 3 holds no nodes"):
        ops.recorder("Node", "-file", str(tmp_path / "x.out"), "-region", 3, "-dof", 1, "disp")
    with pytest.raises(beamsolid.OpenSeesError, match="recorder Element.*region 9 does not exist"):
        ops.recorder("Element", "-file", str(tmp_path / "x.out"), "-region", 9, "axialForce")
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(4, 1.0, 0.0)
    ops.analysis("Static")
    assert ops.analyze(2) == 0
    ops.wipe()
    rows = {k: np.loadtxt(f, ndmin=2) for k, f in files.items()}
    np.testing.assert_allclose(rows["e1"], [[1, 1], [2, 2]], rtol=1e-12)
    np.testing.assert_allclose(rows["n1"], [[1, 0.01, 0.02, 0.03], [2, 0.02, 0.04, 0.06]], rtol=1e-12)
    np.testing.assert_allclose(rows["n2"], [[0.01, 0.03], [0.02, 0.06]], rtol=1e-12)
    np.testing.assert_allclose(rows["e3"], [[1], [2]], rtol=1e-12)
