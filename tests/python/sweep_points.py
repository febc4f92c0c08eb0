"""Point functions for tests/python/test_sweep.py: small models with closed forms.

A bar of length L, area A, elastic-perfectly-plastic (E, yield strain eps_y) pulled by a
force P in `steps` load steps. Below the yield force N_y = E A eps_y its end moves
u = P L / (E A); above it no equilibrium exists, Newton fails and analyze returns a
negative code. `material` names the uniaxial material (an unknown one makes the
interpreter raise); `pause` keeps a point busy for that long (the interrupted-sweep test).
"""
import time

import beamsolid
from beamsolid import sweep

E, AREA, EPS_Y = 1000.0, 2.0, 0.01  # N_y = 20


def bar(P, L, material="ElasticPP", steps=4, pause=0.0):
    m = beamsolid.Model()
    m.model("basic", "-ndm", 1)
    m.node(1, 0.0)
    m.node(2, L)
    m.fix(1, 1)
    m.uniaxialMaterial(material, 1, E, EPS_Y)
    m.element("Truss", 1, 1, 2, AREA, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, P)
    m.constraints("Plain")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-12, 10)
    m.algorithm("Newton")
    m.integrator("LoadControl", 1.0 / steps)
    m.analysis("Static")
    sweep.analyze(m, steps)
    if pause:
        time.sleep(pause)
    return {"u": m.nodeDisp(2, 1), "N": m.eleResponse(1, "axialForce")[0],
            "history": [m.nodeDisp(2, 1), m.getTime()]}


def bar_code(P, L):
    """The same bar, returning the analyze code among its results instead of raising."""
    m = beamsolid.Model()
    m.model("basic", "-ndm", 1)
    m.node(1, 0.0)
    m.node(2, L)
    m.fix(1, 1)
    m.uniaxialMaterial("ElasticPP", 1, E, EPS_Y)
    m.element("Truss", 1, 1, 2, AREA, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, P)
    m.constraints("Plain")
    m.numberer("RCM")
    m.system("UmfPack")
    m.test("NormDispIncr", 1e-12, 10)
    m.algorithm("Newton")
    m.integrator("LoadControl", 0.25)
    m.analysis("Static")
    code = m.analyze(4)
    return {"returncode": code, "error": m.last_error() or None, "u": m.nodeDisp(2, 1), "time": m.getTime()}


def blas(i):
    """What a worker runs with: its BLAS threads and OPENBLAS_NUM_THREADS."""
    import os

    return {"threads": beamsolid.blas_info().threads, "env": os.environ.get("OPENBLAS_NUM_THREADS"),
            "pid": os.getpid()}


def crash(i):
    """Point 2 ends its process at once, as a segmentation fault in a solver would."""
    import os

    if i == 2:
        os._exit(3)
    return {"square": i * i}
