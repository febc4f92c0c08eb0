"""The tutorial's plugin built as a user builds it: BeamSolid installed by `pip install` into a
fresh virtual environment, examples/plugins configured and built out of the source tree against
that installation, loaded from a script run by that environment's Python, and an analysis with its
element giving the closed-form answer.

Slow (pip builds the whole package: a few minutes on 2 cores), and needs PyPI for the build
requirements; it skips only when no C++ compiler or CMake is on the machine.
"""
import json
import os
import pathlib
import shutil
import subprocess
import sys
import textwrap

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]

SCRIPT = textwrap.dedent(
    """
    import json, sys
    import beamsolid
    import beamsolid.opensees as ops
    from beamsolid.testing import check_tangent

    ops.loadPlugin(sys.argv[1])
    ops.model('basic', '-ndm', 3, '-ndf', 3)
    # A node held by three springs to anchors along x, y and z.
    ops.node(1, 0.0, 0.0, 0.0)
    for tag, xyz, k in ((2, (-2.0, 0.0, 0.0), 100.0), (3, (0.0, -3.0, 0.0), 200.0), (4, (0.0, 0.0, -4.0), 400.0)):
        ops.node(tag, *xyz)
        ops.fix(tag, 1, 1, 1)
        ops.uniaxialMaterial('Elastic', tag, k)
        ops.element('NonlinearSpring3D', tag, tag, 1, tag)
    ops.timeSeries('Linear', 1)
    ops.pattern('Plain', 1, 1)
    ops.load(1, 5.0, 8.0, -12.0)
    ops.analysis('Static')
    ok = ops.analyze(1)
    print(json.dumps({"ok": ok, "disp": ops.nodeDisp(1), "N": [ops.eleResponse(t, 'axialForce')[0] for t in (2, 3, 4)],
                      "version": beamsolid.__version__, "file": beamsolid.__file__,
                      "tangent_ok": all(check_tangent(ops, t).ok for t in (2, 3, 4)),
                      "origin": beamsolid.registered_types()["element"]["NonlinearSpring3D"]}))
    """
)


def run(cmd, **kw):
    done = subprocess.run(cmd, capture_output=True, text=True, **kw)
    assert done.returncode == 0, f"{' '.join(map(str, cmd))}\n{done.stdout[-3000:]}\n{done.stderr[-5000:]}"
    return done.stdout


def source_tree(dest):
    """The files git knows (tracked, and new ones not ignored): what a clone or an sdist holds,
    without the development build's in-place libraries."""
    files = run(["git", "ls-files", "--cached", "--others", "--exclude-standard", "-z"], cwd=ROOT).split("\0")
    for f in filter(None, files):
        src = ROOT / f
        if src.is_file():
            (dest / f).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(src, dest / f)
    return dest


@pytest.mark.skipif(shutil.which("c++") is None, reason="no C++ compiler")
def test_tutorial_plugin_builds_out_of_tree_against_the_pip_installed_package(tmp_path):
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "LD_PRELOAD")}
    venv = tmp_path / "venv"
    run([sys.executable, "-m", "venv", str(venv)], env=env)
    python = venv / "bin" / "python"
    src = source_tree(tmp_path / "src")
    run([str(python), "-m", "pip", "install", "-q", str(src)], env=env, timeout=3000)

    cmake_dir = run([str(python), "-m", "beamsolid", "--cmake-dir"], env=env, cwd=tmp_path).strip()
    assert pathlib.Path(cmake_dir).is_relative_to(venv)
    assert (pathlib.Path(run([str(python), "-m", "beamsolid", "--include"], env=env, cwd=tmp_path).strip())
            / "elements" / "Element.h").exists()

    # The tutorial's project, copied away from the source tree, configured with the CMake the
    # package's build used (any CMake >= 3.20 does).
    project = tmp_path / "my_plugin"
    shutil.copytree(ROOT / "examples" / "plugins", project)
    cmake = shutil.which("cmake") or str(pathlib.Path(sys.executable).parent / "cmake")
    build = tmp_path / "build"
    run([cmake, "-S", str(project), "-B", str(build), f"-DBeamSolid_DIR={cmake_dir}",
         "-DCMAKE_BUILD_TYPE=Release"], env=env)
    run([cmake, "--build", str(build)], env=env)
    plugin = build / "libnonlinear_spring.so"
    assert plugin.exists()

    out = run([str(python), "-c", SCRIPT, str(plugin)], env=env, cwd=tmp_path)
    result = json.loads(out)
    assert result["ok"] == 0
    assert pathlib.Path(result["file"]).is_relative_to(venv)  # the installed package, not the tree
    assert pathlib.Path(result["origin"]) == plugin.resolve()
    # Each spring takes the load along its axis: u = (5/100, 8/200, -12/400).
    assert result["N"] == pytest.approx([5.0, 8.0, -12.0], rel=1e-12)
    assert result["disp"] == pytest.approx([0.05, 0.04, -0.03], rel=1e-12)
    assert result["tangent_ok"]
