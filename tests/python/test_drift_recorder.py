"""recorder('Drift') and recorder('EnvelopeDrift') against the closed-form
cantilever: a prismatic column of height H under a tip load P has
u(y) = P y^2 (3H - y) / (6 E I), so the drift of a storey between y1 and y2
is (u(y2) - u(y1)) / (y2 - y1). Two elastic elements per storey are exact
for this cubic, so the recorded values equal the closed form to the printed
digits (6 by default: 5e-6 relative; 12 with -precision 12: 5e-12).
"""
import numpy as np
import pytest

import beamsolid

E, I, A = 2.0e8, 3.0e-4, 0.01
LEVELS = [0.0, 1.5, 3.0, 4.2, 5.4]  # nodes 1..5 up the column, storeys 1-3 and 3-5
LOADS = [1.0, 2.0, -1.5]  # load factor after each step (the load reverses)
P = 40.0


def column(m):
    m.model("basic", "-ndm", 2, "-ndf", 3)
    for k, y in enumerate(LEVELS):
        m.node(k + 1, 0.25, y)
    m.fix(1, 1, 1, 1)
    m.geomTransf("Linear", 1)
    for k in range(len(LEVELS) - 1):
        m.element("elasticBeamColumn", k + 1, k + 1, k + 2, A, E, I, 1)


def exact_u(y, factor):
    H = LEVELS[-1]
    return factor * P * y * y * (3 * H - y) / (6 * E * I)


def exact_drift(i, j, factor):
    yi, yj = LEVELS[i - 1], LEVELS[j - 1]
    return (exact_u(yj, factor) - exact_u(yi, factor)) / abs(yj - yi)


def run(m):
    m.timeSeries("Path", 1, "-time", 0.0, 1.0, 2.0, 3.0, "-values", 0.0, *LOADS)
    m.pattern("Plain", 1, 1)
    m.load(5, P, 0.0, 0.0)  # +x at the top: the x-dof of the column moves
    m.system("UmfPack")
    m.constraints("Plain")
    m.numberer("Plain")
    m.test("NormDispIncr", 1e-12, 10)
    m.algorithm("Linear")
    m.integrator("LoadControl", 1.0)
    m.analysis("Static")
    assert m.analyze(len(LOADS)) == 0
    m.wipe()


def rows(path):
    """The file's rows as a 2D array (one row per line, also for one column)."""
    return np.array([[float(v) for v in line.split()] for line in open(path) if line.strip()])


def test_drift_columns_equal_the_closed_form(model, tmp_path):
    column(model)
    f = str(tmp_path / "drift.out")
    g = str(tmp_path / "drift12.out")
    model.recorder("Drift", "-file", f, "-time", "-iNode", 1, 3, "-jNode", 3, 5, "-dof", 1, "-perpDirn", 2)
    # j below i: the length is a distance (positive), the sign that of u_j - u_i.
    model.recorder("Drift", "-file", g, "-precision", 12, "-iNode", 5, "-jNode", 2, "-dof", 1, "-perpDirn", 2)
    run(model)
    r = rows(f)
    assert r.shape == (3, 3)
    np.testing.assert_allclose(r[:, 0], [1.0, 2.0, 3.0], rtol=0, atol=0)
    for step, factor in enumerate(LOADS):
        np.testing.assert_allclose(r[step, 1:], [exact_drift(1, 3, factor), exact_drift(3, 5, factor)], rtol=5e-6)
    r12 = rows(g)
    assert r12.shape == (3, 1)
    np.testing.assert_allclose(r12[:, 0], [exact_drift(5, 2, f) for f in LOADS], rtol=5e-12)


def test_rotation_dof_and_x_direction(model, tmp_path):
    """-dof 2 over -perpDirn 1: an unloaded arm at the top turns rigidly with the
    column's tip, whose rotation is theta_z = -u'(H) = -P H^2 / (2 E I) (the
    column bends towards +x), so the arm's end moves theta_z * 2 m vertically
    relative to the tip and the drift over the 2 m arm is theta_z."""
    column(model)
    model.node(6, 2.25, LEVELS[-1])
    model.element("elasticBeamColumn", 10, 5, 6, A, E, I, 1)  # an unloaded arm: rotates rigidly with the top
    f = str(tmp_path / "rot.out")
    model.recorder("Drift", "-file", f, "-precision", 12, "-iNode", 5, "-jNode", 6, "-dof", 2, "-perpDirn", 1)
    run(model)
    H = LEVELS[-1]
    for step, factor in enumerate(LOADS):
        theta_z = -factor * P * H * H / (2 * E * I)
        np.testing.assert_allclose(rows(f)[step, 0], theta_z * 2.0 / 2.0, rtol=5e-12)


def test_envelope_drift_min_max_absmax_with_times(model, tmp_path):
    column(model)
    f = str(tmp_path / "env.out")
    h = str(tmp_path / "env_notime.out")
    model.recorder("EnvelopeDrift", "-file", f, "-time", "-iNode", 1, 3, "-jNode", 3, 5, "-dof", 1, "-perpDirn", 2)
    model.recorder("EnvelopeDrift", "-file", h, "-iNode", 3, "-jNode", 5, "-dof", 1, "-perpDirn", 2)
    run(model)
    r = rows(f)
    assert r.shape == (3, 4)  # min, max, absmax; (time, value) per pair
    for pair, (i, j) in enumerate([(1, 3), (3, 5)]):
        d = [exact_drift(i, j, f) for f in LOADS]
        k_min, k_max = int(np.argmin(d)), int(np.argmax(d))
        k_abs = int(np.argmax(np.abs(d)))
        np.testing.assert_allclose(r[:, 2 * pair], [k_min + 1, k_max + 1, k_abs + 1], rtol=0, atol=0)
        np.testing.assert_allclose(r[:, 2 * pair + 1], [d[k_min], d[k_max], abs(d[k_abs])], rtol=5e-6)
    d = [exact_drift(3, 5, f) for f in LOADS]
    np.testing.assert_allclose(rows(h)[:, 0], [min(d), max(d), max(abs(x) for x in d)], rtol=5e-6)


def test_dT_and_xml(model, tmp_path):
    column(model)
    f = str(tmp_path / "dt.out")
    x = str(tmp_path / "drift.xml")
    model.recorder("Drift", "-file", f, "-time", "-dT", 1.5, "-iNode", 1, "-jNode", 5, "-dof", 1, "-perpDirn", 2)
    model.recorder("Drift", "-xml", x, "-iNode", 1, "-jNode", 5, "-dof", 1, "-perpDirn", 2)
    run(model)
    r = rows(f)
    np.testing.assert_allclose(r[:, 0], [1.0, 3.0])  # 2.0 is less than dT after 1.0
    np.testing.assert_allclose(r[:, 1], [exact_drift(1, 5, 1.0), exact_drift(1, 5, -1.5)], rtol=5e-6)
    text = open(x).read()
    assert '<DriftOutput node1="1" node2="5" dof="1" perpDirn="2">' in text
    data = text.split("<Data>")[1].split("</Data>")[0].split()
    np.testing.assert_allclose([float(v) for v in data], [exact_drift(1, 5, f) for f in LOADS], rtol=5e-6)


@pytest.mark.parametrize("args, words", [
    (("-iNode", 1, "-jNode", 3, "-dof", 1), "'-perpDirn' is missing"),
    (("-iNode", 1, "-jNode", 3, "-perpDirn", 2), "'-dof' is missing"),
    (("-iNode", 1, 2, "-jNode", 3, "-dof", 1, "-perpDirn", 2), "the same number of nodes"),
    (("-iNode", 1, 2, "-jNode", 3, 4, "-dof", 1, 1, 1, "-perpDirn", 2), "'-dof' needs one value, or one per node pair"),
    (("-iNode", 1, "-jNode", 9, "-dof", 1, "-perpDirn", 2), "node 9 does not exist"),
    (("-iNode", 1, "-jNode", 3, "-dof", 4, "-perpDirn", 2), "'-dof' 4"),
    (("-iNode", 1, "-jNode", 3, "-dof", 0, "-perpDirn", 2), "dof"),
    (("-iNode", 1, "-jNode", 3, "-dof", 1, "-perpDirn", 3), "'-perpDirn' 3"),
    (("-iNode", 1, "-jNode", 3, "-dof", 1, "-perpDirn", 1), "zero length"),
    (("-iNode", 1, "-jNode", 3, "-dof", 1, "-perpDirn", 2, "-bogus"), "option"),
    (("-jNode", 3, "-dof", 1, "-perpDirn", 2), "no iNodes"),
])
def test_bad_input_names_the_argument(model, tmp_path, args, words):
    column(model)
    with pytest.raises(beamsolid.OpenSeesError) as info:
        model.recorder("Drift", "-file", str(tmp_path / "bad.out"), *args)
    assert "recorder Drift" in str(info.value) and words in str(info.value)
    with pytest.raises(beamsolid.OpenSeesError):
        model.recorder("Drift", "-iNode", 1, "-jNode", 3, "-dof", 1, "-perpDirn", 2)  # no file
