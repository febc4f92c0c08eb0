"""For each command: wrong argument count, wrong type, unknown tag and duplicate tag
raise OpenSeesError with a message that names the command and what is wrong."""
import pytest

import beamsolid
from beamsolid import OpenSeesError


def base(m):
    m.model("basic", "-ndm", 3, "-ndf", 6)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, 0.0, 0.0, 1.0)
    m.node(3, 0.0, 0.0, 2.0)
    m.model("basic", "-ndm", 3, "-ndf", 3)
    for i, (x, y, z) in enumerate([(0, 0, 0), (1, 0, 0), (1, 1, 0), (0, 1, 0),
                                   (0, 0, 1), (1, 0, 1), (1, 1, 1), (0, 1, 1)], start=11):
        m.node(i, float(x), float(y), float(z))
    m.node(20, 0.5, 0.0, 0.5)
    m.node(21, 0.0, 0.0, 0.0)
    m.uniaxialMaterial("Elastic", 1, 100.0)
    m.nDMaterial("ElasticIsotropic", 1, 1000.0, 0.3)
    m.nDMaterial("ContactMaterial3D", 2, 0.3, 1000.0, 0.0, 0.0)
    m.geomTransf("Linear", 1, 1.0, 0.0, 0.0)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.element("elasticBeamColumn", 1, 1, 2, 1.0, 100.0, 40.0, 1.0, 1.0, 1.0, 1)
    m.element("stdBrick", 2, 11, 12, 13, 14, 15, 16, 17, 18, 1)
    m.element("truss", 3, 11, 13, 1.0, 1)


# (id, command, args, fragments that must all appear in the message)
CASES = [
    # elasticBeamColumn
    ("beam count", "element", ("elasticBeamColumn", 5, 2, 3, 1.0, 100.0, 3.0), ["element elasticBeamColumn 5", "transfTag"]),
    ("beam section form", "element", ("elasticBeamColumn", 5, 2, 3, 9, 1), ["element elasticBeamColumn 5", "section 9 does not exist"]),
    ("beam type", "element", ("elasticBeamColumn", 5, 2, 3, "A", 100.0, 40.0, 1.0, 1.0, 1.0, 1), ["element elasticBeamColumn 5", "A, E, G, J, Iy, Iz"]),
    ("beam node", "element", ("elasticBeamColumn", 5, 2, 99, 1.0, 100.0, 40.0, 1.0, 1.0, 1.0, 1), ["node 99 does not exist"]),
    ("beam transf", "element", ("elasticBeamColumn", 5, 2, 3, 1.0, 100.0, 40.0, 1.0, 1.0, 1.0, 7), ["geomTransf 7 does not exist"]),
    ("beam dup", "element", ("elasticBeamColumn", 1, 2, 3, 1.0, 100.0, 40.0, 1.0, 1.0, 1.0, 1), ["element 1 already exists"]),
    ("beam ndf", "element", ("elasticBeamColumn", 5, 11, 12, 1.0, 100.0, 40.0, 1.0, 1.0, 1.0, 1), ["element elasticBeamColumn 5", "6"]),
    # stdBrick
    ("brick count", "element", ("stdBrick", 5, 11, 12, 13, 14, 15, 16, 17), ["element stdBrick 5", "argument"]),
    ("brick type", "element", ("stdBrick", 5, 11, 12, 13, 14, 15, 16, 17, "x", 1), ["element stdBrick 5", "expected an integer, got 'x'"]),
    ("brick node", "element", ("stdBrick", 5, 11, 12, 13, 14, 15, 16, 17, 42, 1), ["element stdBrick 5: node 42 does not exist"]),
    ("brick material", "element", ("stdBrick", 5, 11, 12, 13, 14, 15, 16, 17, 18, 9), ["nDMaterial 9 does not exist"]),
    ("brick dup", "element", ("stdBrick", 2, 11, 12, 13, 14, 15, 16, 17, 18, 1), ["element 2 already exists"]),
    # truss / corotTruss / zeroLength
    ("truss count", "element", ("truss", 5, 11, 12, 1.0), ["element truss 5", "argument"]),
    ("truss type", "element", ("truss", 5, 11, 12, "A", 1), ["element truss 5", "expected a number"]),
    ("truss material", "element", ("truss", 5, 11, 12, 1.0, 8), ["uniaxialMaterial 8 does not exist"]),
    ("corotTruss node", "element", ("corotTruss", 5, 11, 77, 1.0, 1), ["node 77 does not exist"]),
    ("zeroLength dirs", "element", ("zeroLength", 5, 11, 21, "-mat", 1, "-dir"), ["element zeroLength 5"]),
    ("zeroLength material", "element", ("zeroLength", 5, 11, 21, "-mat", 4, "-dir", 1), ["uniaxialMaterial 4 does not exist"]),
    ("zeroLength dup", "element", ("zeroLength", 3, 11, 21, "-mat", 1, "-dir", 1), ["element 3 already exists"]),
    # contact
    ("contact count", "element", ("BeamContact3D", 5, 2, 3, 20), ["element BeamContact3D 5", "argument"]),
    ("contact material", "element", ("BeamContact3D", 5, 2, 3, 20, 21, 0.5, 1, 1, 1e-8, 1e-8), ["ContactMaterial3D"]),
    ("contact node", "element", ("BeamContact3D", 5, 2, 3, 20, 99, 0.5, 1, 2, 1e-8, 1e-8), ["node 99 does not exist"]),
    # materials, transforms, series
    ("uniaxial count", "uniaxialMaterial", ("Elastic", 2), ["uniaxialMaterial Elastic 2", "argument"]),
    ("uniaxial type", "uniaxialMaterial", ("Elastic", "two", 1.0), ["expected an integer, got 'two'"]),
    ("uniaxial dup", "uniaxialMaterial", ("Elastic", 1, 5.0), ["uniaxialMaterial with tag 1 already exists"]),
    ("nD count", "nDMaterial", ("ElasticIsotropic", 3, 1000.0), ["nDMaterial ElasticIsotropic 3", "argument"]),
    ("nD dup", "nDMaterial", ("ElasticIsotropic", 1, 1000.0, 0.3), ["nDMaterial with tag 1 already exists"]),
    ("contact material count", "nDMaterial", ("ContactMaterial3D", 3, 0.3), ["nDMaterial ContactMaterial3D 3", "argument"]),
    ("transf count", "geomTransf", ("Linear", 2, 1.0, 0.0), ["geomTransf Linear 2"]),
    ("transf type", "geomTransf", ("PDelta", 2, "x", 0.0, 0.0), ["geomTransf PDelta 2", "expected a number", "got 'x'"]),
    ("transf dup", "geomTransf", ("Linear", 1, 0.0, 1.0, 0.0), ["geomTransf with tag 1 already exists"]),
    ("series type", "timeSeries", ("Path", 2, "-dt", "a", "-values", 1.0), ["timeSeries Path 2"]),
    ("series dup", "timeSeries", ("Constant", 1), ["timeSeries with tag 1 already exists"]),
    # loads and constraints
    ("pattern count", "pattern", ("Plain", 2), ["pattern Plain 2", "argument 3 (tsTag)"]),
    ("pattern series", "pattern", ("Plain", 2, 9), ["timeSeries 9 does not exist"]),
    ("pattern dup", "pattern", ("Plain", 1, 1), ["load pattern 1 already exists"]),
    ("load count", "load", (2, 1.0, 0.0, 0.0), ["load 2", "has 6 dofs but 3 load values"]),
    ("load type", "load", (2, "x", 0.0, 0.0, 0.0, 0.0, 0.0), ["load 2", "expected"]),
    ("load node", "load", (99, 1.0, 0.0, 0.0), ["node 99 does not exist"]),
    ("sp count", "sp", (2, 1), ["sp 2", "argument 3 (value)"]),
    ("sp node", "sp", (99, 1, 0.1), ["sp 99: node 99 does not exist"]),
    ("sp dof", "sp", (12, 4, 0.1), ["dof 4 is out of range 1..3"]),
    ("eleLoad type", "eleLoad", ("-ele", 1, "-type", "-beamUniform", "w"), ["eleLoad", "Wy, Wz"]),
    ("eleLoad element", "eleLoad", ("-ele", 42, "-type", "-beamUniform", 1.0, 0.0), ["element 42 does not exist"]),
    ("eleLoad kind", "eleLoad", ("-ele", 3, "-type", "-beamUniform", 1.0, 0.0), ["does not accept -beamUniform"]),
    ("equalDOF dof", "equalDOF", (11, 12, 5), ["dof 5 is out of range"]),
    # dof - 1 overflowed for the most negative int (UBSan, found by the command fuzzer)
    ("equalDOF dof int min", "equalDOF", (11, 12, 1, -2**31), ["equalDOF 11 12", "argument 4 (dof)", ">= 1"]),
    ("equalDOF dof zero", "equalDOF", (11, 12, 0), ["equalDOF 11 12", "argument 3 (dof)", ">= 1"]),
    ("remove sp dof int min", "remove", ("sp", 12, -2**31), ["remove", "argument 3 (dof)", ">= 1"]),
    ("rigidLink count", "rigidLink", ("beam", 1), ["rigidLink", "argument 3 (constrainedNode)"]),
    ("fixZ flags", "fixZ", (0.0,), ["fixZ", "no constraint flags"]),
    # analysis objects
    ("test count", "test", ("NormDispIncr", 1e-6), ["test NormDispIncr", "argument 3 (maxIter)"]),
    ("test type", "test", ("EnergyIncr", 1e-6, "many"), ["expected an integer, got 'many'"]),
    ("integrator count", "integrator", ("DisplacementControl", 2, 1), ["integrator DisplacementControl"]),
    ("integrator node", "integrator", ("LoadControl", "x"), ["integrator LoadControl", "expected a number"]),
    ("constraints penalty", "constraints", ("Penalty", 1e10), ["constraints Penalty", "argument 3 (alphaM)"]),
    # queries
    ("eleResponse unknown", "eleResponse", (1, "noSuchResponse"), ["eleResponse 1", "has no response 'noSuchResponse'"]),
    ("eleResponse element", "eleResponse", (42, "force"), ["element 42 does not exist"]),
    ("nodeEigenvector mode", "nodeEigenvector", (2, 1), ["mode 1 is not available"]),
    ("nodeReaction type", "nodeReaction", ("2",), ["nodeReaction", "expected an integer, got '2'"]),
    ("recorder node", "recorder", ("Node", "-file", "/dev/null", "-node", 99, "-dof", 1, "disp"), ["recorder Node", "99"]),
    ("recorder element", "recorder", ("Element", "-file", "/dev/null", "-ele", 99, "force"), ["recorder Element", "element 99"]),
    ("setParameter none", "setParameter", ("-val", 1.0, "-ele", 1, "friction"), ["setParameter", "no element recognizes parameter 'friction'"]),
    ("updateMaterialStage", "updateMaterialStage", ("-material", 9, "-stage", 1), ["nDMaterial 9 does not exist"]),
    ("region element", "region", (1, "-ele", 99, "-rayleigh", 0.1, 0.0, 0.0, 0.0), ["region 1: element 99 does not exist"]),
    ("region node", "region", (1, "-node", 1, 98, "-rayleigh", 0.1, 0.0, 0.0, 0.0), ["region 1: node 98 does not exist"]),
    ("region option", "region", (1, "-ele", 1, "-damp", 1), ["region", "unknown option '-damp'"]),
    ("region factors", "region", (1, "-ele", 1, "-rayleigh", 0.1, 0.0), ["region", "betaKinit"]),
    ("modalDamping none", "modalDamping", (), ["modalDamping", "damping factor"]),
    ("modalDamping eigen", "modalDamping", (0.05,), ["modalDamping", "call eigen(n) before modalDamping"]),
]


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_command_errors_name_command_and_problem(model, case):
    _, command, args, fragments = case
    base(model)
    with pytest.raises(OpenSeesError) as err:
        getattr(model, command)(*args)
    message = str(err.value)
    for fragment in fragments:
        assert fragment in message, message
    # The model is untouched by the failed command and still solves.
    assert model.getEleTags() == [1, 2, 3]


def test_every_registered_element_type_rejects_an_empty_argument_list(model):
    base(model)
    for kind in beamsolid.registered_types("element"):
        with pytest.raises(OpenSeesError) as err:
            model.element(kind)
        assert "element " + kind in str(err.value) or "argument" in str(err.value), str(err.value)


def test_region_tag_used_twice_is_an_error(model):
    base(model)
    model.region(1, "-ele", 1, "-rayleigh", 0.1, 0.0, 0.0, 0.0)
    with pytest.raises(OpenSeesError, match="region with tag 1 already exists"):
        model.region(1, "-ele", 2)
