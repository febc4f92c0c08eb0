"""Recorder files compared as text: Node disp and reaction recorders with
-time and -precision, Element force recorders (global and local), a row
written by record() before the analysis, and values that span magnitudes
(1e-05 and smaller, exact zeros, thousands, negative numbers).
"""

FILES = {
    "disp_default.out": ("Node", "-file", "disp_default.out", "-time", "-node", 2, 3, "-dof", 1, 2, 3, 4, 5, 6, "disp"),
    "disp_p10.out": ("Node", "-file", "disp_p10.out", "-time", "-precision", 10, "-node", 3, "-dof", 1, 3, 5, "disp"),
    "disp_p3.out": ("Node", "-file", "disp_p3.out", "-precision", 3, "-node", 3, "-dof", 2, 6, "disp"),
    "reaction.out": ("Node", "-file", "reaction.out", "-time", "-node", 1, "-dof", 1, 2, 3, 4, 5, 6, "reaction"),
    "reaction_p12.out": ("Node", "-file", "reaction_p12.out", "-time", "-precision", 12, "-node", 1, "-dof", 3, 5, "reaction"),
    "ele_force.out": ("Element", "-file", "ele_force.out", "-time", "-ele", 1, 2, "force"),
    "ele_local.out": ("Element", "-file", "ele_local.out", "-ele", 2, "localForce"),
    "ele_basic.out": ("Element", "-file", "ele_basic.out", "-time", "-precision", 8, "-ele", 1, "basicForce"),
    "disp.csv": ("Node", "-csv", "disp.csv", "-time", "-node", 3, "-dof", 1, 2, "disp"),
    "disp_sci.out": ("Node", "-file", "disp_sci.out", "-scientific", "-time", "-node", 3, "-dof", 1, 2, "disp"),
    "disp_sci3.out": ("Node", "-file", "disp_sci3.out", "-precision", 3, "-scientific", "-node", 3, "-dof", 2, "disp"),
    "disp_dT.out": ("Node", "-file", "disp_dT.out", "-time", "-dT", 0.25, "-node", 3, "-dof", 2, "disp"),
    "disp_close.out": ("Node", "-file", "disp_close.out", "-closeOnWrite", "-time", "-node", 3, "-dof", 2, "disp"),
    "disp_range.out": ("Node", "-file", "disp_range.out", "-time", "-nodeRange", 2, 3, "-dof", 2, 7, "disp"),
    "env_disp.out": ("EnvelopeNode", "-file", "env_disp.out", "-time", "-node", 2, 3, "-dof", 2, 3, "disp"),
    "env_disp_notime.out": ("EnvelopeNode", "-file", "env_disp_notime.out", "-node", 3, "-dof", 2, "disp"),
    # Without -time: the time of a round-off extremum (a zero component) is arbitrary.
    "env_force.out": ("EnvelopeElement", "-file", "env_force.out", "-ele", 1, "basicForce"),
    "disp.bin": ("Node", "-binary", "disp.bin", "-time", "-node", 3, "-dof", 1, 2, "disp"),
    "disp.xml": ("Node", "-xml", "disp.xml", "-time", "-node", 2, 3, "-dof", 1, 2, "disp"),
    # -precision 7, not 4 or 5: the reactions (multiples of 1234.5 x 0.05) would be rounding ties
    # there (123.45, -1111.05), which round-off decides either way.
    "reaction.xml": ("Node", "-xml", "reaction.xml", "-precision", 7, "-node", 1, "-dof", 3, 4, "reaction"),
    "ele_basic.xml": ("Element", "-xml", "ele_basic.xml", "-time", "-ele", 1, "basicForce"),
    "ele_force.xml": ("Element", "-xml", "ele_force.xml", "-ele", 1, 2, "force"),
    "env_disp.xml": ("EnvelopeNode", "-xml", "env_disp.xml", "-time", "-node", 3, "-dof", 2, 3, "disp"),
    "env_force.xml": ("EnvelopeElement", "-xml", "env_force.xml", "-ele", 1, "basicForce"),
}
BINARY_COLUMNS = {"disp.bin": 3}


# Values that show the number format: %g switches to exponents below 1e-4
# and from 10**precision on; exact zeros, negative numbers, round-off noise.
VALUES = [(1e-05, 100000.0, 1234567.0, -0.000123456789, 0.1, 2.5e-300)]
TIMES = (0.0, 1e-05, 0.30000000000000004, 123456.5, 1e7)


def _read_binary(name, columns):
    """Rows of native doubles, each followed by one byte (returned as such)."""
    import struct

    with open(name, "rb") as f:
        data = f.read()
    width = 8 * columns + 1
    if len(data) % width:
        return {"bytes": len(data), "error": "not a whole number of rows"}
    rows = [data[i:i + width] for i in range(0, len(data), width)]
    return {"rows": [list(struct.unpack(f"={columns}d", r[:-1])) for r in rows],
            "terminators": [r[-1] for r in rows]}


def run(ops):
    ops.wipe()
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 0.0, 0.0, 2.0)
    ops.node(3, 1.5, 0.0, 2.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    ops.geomTransf("Linear", 2, 0.0, 0.0, 1.0)
    ops.element("elasticBeamColumn", 1, 1, 2, 0.02, 210e6, 81e6, 3e-5, 2e-5, 4e-5, 1)
    ops.element("elasticBeamColumn", 2, 2, 3, 0.02, 210e6, 81e6, 3e-5, 2e-5, 4e-5, 2)
    tags = []
    for args in FILES.values():
        tags.append(ops.recorder(*args))
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(3, 0.0, 1234.5, -20.0, 0.0, 0.0, 0.0)
    ops.system("UmfPack")
    ops.constraints("Plain")
    ops.numberer("Plain")
    ops.test("NormDispIncr", 1e-12, 10)
    ops.algorithm("Linear")
    ops.integrator("LoadControl", 0.1)
    ops.analysis("Static")
    ops.record()
    codes = [ops.analyze(1) for _ in range(3)]
    # Unloading past zero, so that envelopes have distinct min and max.
    ops.integrator("LoadControl", -0.25)
    codes += [ops.analyze(1) for _ in range(3)]
    ops.wipe()
    # Tags count up from the first one; OpenSees does not restart the count
    # at wipe, so only the differences are comparable.
    out = {"codes": codes, "recorderTagSteps": [t - tags[0] for t in tags]}
    for name in FILES:
        if name in BINARY_COLUMNS:
            out["binary:" + name] = _read_binary(name, BINARY_COLUMNS[name])
            continue
        with open(name) as f:
            out["file:" + name] = f.read()

    # Number formats: a node holding chosen values (-disp), recorded at
    # chosen times with the default precision and with -precision 3 and 12.
    ops.model("basic", "-ndm", 3, "-ndf", 6)
    ops.node(1, 0.0, 0.0, 0.0, "-disp", *VALUES[0])
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    for precision in (None, 3, 12):
        name = f"formats_{precision or 'default'}.out"
        options = () if precision is None else ("-precision", precision)
        ops.recorder("Node", "-file", name, "-time", *options, "-node", 1, "-dof", 1, 2, 3, 4, 5, 6, "disp")
    for t in TIMES:
        ops.setTime(t)
        ops.record()
    ops.wipe()
    for precision in (None, 3, 12):
        name = f"formats_{precision or 'default'}.out"
        with open(name) as f:
            out["file:" + name] = f.read()
    return out
