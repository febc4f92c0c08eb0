"""The BLAS kernel: chosen at import from the CPU's own flags, never one the CPU cannot run,
a runnable setting kept, and the same answers on the chosen kernel as on a generic one.

/proc/cpuinfo is read here independently of the C++ (which asks CPUID).
"""
import json
import os
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import beamsolid
from beamsolid.blas import CHOICE, CORETYPE
from conftest import subprocess_env

HERE = os.path.dirname(os.path.abspath(__file__))
# Kernels and one flag each needs, to find a kernel this CPU cannot run. The tests below set
# OPENBLAS_CORETYPE in child processes only to such a kernel, which BeamSolid must replace before
# OpenBLAS loads, or to Prescott, which every x86-64 CPU since 2005 runs.
NEEDS = {"BULLDOZER": "fma4", "SAPPHIRERAPIDS": "amx_tile", "SKYLAKEX": "avx512f", "HASWELL": "avx2"}
# Prescott's SSE3 code runs on every x86-64 CPU made since 2005: the generic kernel.
GENERIC = "PRESCOTT"


def cpuinfo_flags():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("flags"):
                    return set(line.split(":", 1)[1].split())
    except OSError:
        pass
    return set()


def openblas():
    info = beamsolid.blas_info()
    if not info.kernel:
        pytest.skip("the BLAS in use is not OpenBLAS")
    return info


INFO_SCRIPT = textwrap.dedent(
    """
    import dataclasses, json, warnings
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        import beamsolid
    info = dataclasses.asdict(beamsolid.blas_info())
    info["warnings"] = [str(w.message) for w in caught]
    print(json.dumps(info))
    """
)


def child_info(**env):
    base = subprocess_env()
    for k in (CORETYPE, CHOICE):
        base.pop(k, None)
    base.update(env)
    done = subprocess.run([sys.executable, "-c", INFO_SCRIPT], env=base, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def test_the_kernel_in_use_runs_on_this_cpu():
    info = openblas()
    flags = cpuinfo_flags()
    if not flags:
        pytest.skip("no /proc/cpuinfo")
    assert info.kernel_requires, f"BeamSolid does not know the kernel {info.kernel}"
    assert set(info.kernel_requires) <= flags, set(info.kernel_requires) - flags
    assert set(info.cpu_flags) <= flags  # CPUID and the kernel agree
    assert info.reason and "no choice was recorded" not in info.reason
    assert f"kernel: {info.kernel}" in str(info) and info.library in str(info)


def test_a_setting_the_cpu_cannot_run_is_replaced_and_said():
    openblas()
    flags = cpuinfo_flags()
    bad = next((k for k, flag in NEEDS.items() if flag not in flags), None)
    if bad is None:
        pytest.skip("this CPU runs every kernel in NEEDS")
    info = child_info(**{CORETYPE: bad})
    assert set(info["kernel_requires"]) <= flags
    assert info["kernel"].upper() != bad
    assert f"{CORETYPE}={bad} needs {NEEDS[bad]}" in info["warning"]
    assert any("Illegal instruction" in w for w in info["warnings"])


def test_a_runnable_setting_is_kept():
    openblas()
    info = child_info(**{CORETYPE: GENERIC})
    assert info["kernel"].upper() == GENERIC
    assert info["coretype"] == GENERIC
    assert "was set before BeamSolid started" in info["reason"]
    assert not info["warning"]


def test_the_choice_is_made_once_per_process_tree():
    """A child takes the parent's choice from the environment instead of probing again."""
    info = child_info(**{CHOICE: "|made by the parent test process|"})
    assert info["reason"] == "made by the parent test process"
    assert info["coretype"] == ""


SOLVE_SCRIPT = textwrap.dedent(
    """
    import itertools, json, sys
    sys.path.insert(0, sys.argv[1])
    import beamsolid
    from beamsolid.scenes.donut_pullout import DonutPullout, run
    from test_equivalence import HANDLERS, NUMBERERS, SYSTEMS, solve

    out = {"kernel": beamsolid.blas_info().kernel, "cases": {}}
    for h, n, s in itertools.product(HANDLERS, NUMBERERS, SYSTEMS):
        disp, _ = solve(h, n, s)
        out["cases"][f"{h}/{n}/{s}"] = [float(v) for t in sorted(disp) for v in disp[t]]
    r = run(DonutPullout(n_theta=8, n_radial=2, n_z=5, mu=0.5))
    assert r.failed_step == 0
    out["donut"] = {"head_force": r.head_force, "friction_sum": r.friction_sum, "normal_sum": r.normal_sum,
                    "iterations": r.iterations}
    print(json.dumps(out))
    """
)


def solve_on(kernel):
    env = subprocess_env()
    for k in (CORETYPE, CHOICE):
        env.pop(k, None)
    if kernel:
        env[CORETYPE] = kernel
    done = subprocess.run([sys.executable, "-c", SOLVE_SCRIPT, HERE], env=env, capture_output=True, text=True,
                          timeout=600)
    assert done.returncode == 0, done.stderr[-3000:]
    return json.loads(done.stdout)


def test_solvers_give_the_same_answers_on_the_chosen_and_the_generic_kernel():
    """Handlers x numberers x systems (test_equivalence's model) and the coarse donut pullout, to 1e-12."""
    openblas()
    chosen, generic = solve_on(None), solve_on(GENERIC)
    assert generic["kernel"].upper() == GENERIC
    assert chosen["kernel"].upper() != GENERIC or beamsolid.blas_info().kernel.upper() == GENERIC
    assert chosen["cases"].keys() == generic["cases"].keys() and len(chosen["cases"]) == 81
    for case, u in chosen["cases"].items():
        a, b = np.array(u), np.array(generic["cases"][case])
        assert np.abs(a - b).max() <= 1e-12 * np.abs(a).max(), case
    for name in ("head_force", "friction_sum", "normal_sum"):
        a, b = np.array(chosen["donut"][name]), np.array(generic["donut"][name])
        assert a.shape == b.shape and a.size > 3
        assert np.abs(a - b).max() <= 1e-12 * np.abs(a).max(), name
    assert chosen["donut"]["iterations"] == generic["donut"]["iterations"]
