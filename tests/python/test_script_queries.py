"""Errors of the query commands scripts and post-processors call (their values
are compared with OpenSeesPy in oracle_scripts/script_queries.py), and
parameters against a closed form."""
import pytest

import beamsolid


def _spring():
    ops = beamsolid.Model()
    ops.model("basic", "-ndm", 1, "-ndf", 1)
    ops.node(1, 0.0)
    ops.node(2, 0.0)
    ops.fix(1, 1)
    ops.uniaxialMaterial("Elastic", 1, 100.0)
    ops.element("zeroLength", 1, 1, 2, "-mat", 1, "-dir", 1)
    ops.timeSeries("Linear", 1)
    ops.pattern("Plain", 1, 1)
    ops.load(2, 1.0)
    return ops


def test_updated_parameter_changes_the_stiffness():
    ops = _spring()
    assert ops.parameter(1, "element", 1, "E") == 1
    assert ops.updateParameter(1, 400.0) == 1
    ops.integrator("LoadControl", 1.0)
    ops.analysis("Static")
    assert ops.analyze(1) == 0
    assert ops.nodeDisp(2, 1) == pytest.approx(1.0 / 400.0, rel=1e-14)
    assert ops.getParamValue(1) == 400.0
    ops.reset()
    assert ops.nodeDisp(2, 1) == 0.0 and ops.getTime() == 0.0


def test_errors_name_the_command_and_argument():
    ops = _spring()
    cases = [
        (("getNDM", 9), "getNDM 9.*node 9"),
        (("getNodeLoadTags", 5), "getNodeLoadTags 5.*pattern"),
        (("getEleLoadData", "x"), "getEleLoadData.*patternTag"),
        (("getEleClassTags", 7), "getEleClassTags 7.*element 7"),
        (("classType", "uniaxialMaterial", 3), "classType uniaxialMaterial 3.*uniaxialMaterial 3"),
        (("classType", "foo", 1), "classType foo 1: unknown type 'foo'"),
        (("getConstrainedDOFs",), "getConstrainedDOFs.*cNode"),
        (("getRetainedDOFs", 8), "getRetainedDOFs 8.*node 8"),
        (("setNumThreads", 0), "setNumThreads.*at least 1"),
        (("setPrecision", "a"), "setPrecision.*precision"),
        (("numFact",), "numFact.*no algorithm"),
        (("updateParameter", 4, 1.0), "updateParameter 4.*parameter 4 does not exist"),
        (("getParamValue", 4), "getParamValue 4.*does not exist"),
        (("addToParameter", 4, "element", 1, "E"), "addToParameter 4.*does not exist"),
        (("parameter", 2, "element", 9, "E"), "parameter 2.*element 9"),
        (("parameter", 2, "load", 1), "parameter 2: unknown object type 'load'"),
        (("setElementRayleighDampingFactors", 1, 0.1, 0.2), "setElementRayleighDampingFactors 1.*betaK0"),
        (("imposedSupportMotion", 2, 1, 7), "imposedMotion 2.*MultipleSupport"),
    ]
    for args, message in cases:
        with pytest.raises(beamsolid.OpenSeesError, match=message):
            getattr(ops, args[0])(*args[1:])
    ops.parameter(3, "element", 1, "nonsense")
    with pytest.raises(beamsolid.OpenSeesError, match="updateParameter 3.*no parameter 'nonsense'"):
        ops.updateParameter(3, 1.0)
    with pytest.raises(beamsolid.OpenSeesError, match="parameter 3 already exists"):
        ops.parameter(3)
