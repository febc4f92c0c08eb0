"""A recorder that cannot write its file raises OpenSeesError; it never ends the process,
and it never leaves wipe() half done.

Found by the command fuzzer under `make sanitize`: an EnvelopeNode recorder on /dev/null
made wipe() raise (resize_file on a device) before the model was wiped, and at exit the
Domain destructor let the same error escape: std::terminate, the interpreter aborted.
"""
import os
import shutil
import subprocess
import sys
import textwrap

import pytest

from beamsolid import OpenSeesError
from conftest import subprocess_env


def bar(m):
    m.model("basic", "-ndm", 3, "-ndf", 3)
    m.node(1, 0.0, 0.0, 0.0)
    m.node(2, 2.0, 0.0, 0.0)
    m.fix(1, 1, 1, 1)
    m.fix(2, 0, 1, 1)
    m.uniaxialMaterial("Elastic", 1, 100.0)
    m.element("truss", 1, 1, 2, 1.0, 1)
    m.timeSeries("Linear", 1)
    m.pattern("Plain", 1, 1)
    m.load(2, 5.0, 0.0, 0.0)
    m.integrator("LoadControl", 0.1)
    m.analysis("Static")


@pytest.mark.parametrize("kind", ["EnvelopeNode", "Node"])
def test_a_recorder_on_dev_null_records_and_wipes(model, kind):
    bar(model)
    model.recorder(kind, "-file", os.devnull, "-node", 2, "-dof", 1, "disp")
    assert model.analyze(3) == 0
    model.wipe()
    assert model.getNodeTags() == []


def test_a_failing_recorder_still_leaves_the_model_wiped(model, tmp_path):
    folder = tmp_path / "gone"
    folder.mkdir()
    bar(model)
    # an XML recorder that closes its file after each row reopens it to write its closing tags
    model.recorder("Node", "-xml", str(folder / "gone.xml"), "-closeOnWrite", "-node", 2, "-dof", 1, "disp")
    model.recorder("Node", "-file", str(tmp_path / "kept.out"), "-node", 2, "-dof", 1, "disp")
    assert model.analyze(2) == 0
    shutil.rmtree(folder)  # the file and its JSON sidecar
    with pytest.raises(OpenSeesError, match="recorder Node.*gone.xml"):
        model.wipe()
    assert model.getNodeTags() == []
    # the other recorder was closed too: all its rows are on disk
    assert len((tmp_path / "kept.out").read_text().splitlines()) == 2
    bar(model)  # and the model builds again from nothing
    assert model.analyze(1) == 0


def test_a_failing_recorder_at_exit_or_garbage_collection_is_a_warning_not_an_abort(tmp_path):
    script = tmp_path / "script.py"
    script.write_text(textwrap.dedent(f"""
        import gc, os, shutil, sys
        sys.path.insert(0, {os.path.dirname(__file__)!r})
        import beamsolid
        from test_recorder_failures import bar

        def failing_model(name):
            m = beamsolid.Model()
            bar(m)
            os.makedirs(name)
            m.recorder("Node", "-xml", os.path.join(name, name + ".xml"), "-closeOnWrite", "-node", 2, "-dof", 1,
                       "disp")
            assert m.analyze(2) == 0
            shutil.rmtree(name)
            return m

        collected = failing_model("collected")
        del collected  # the Domain's destructor closes the recorder: that failure once ended the process
        gc.collect()
        print("collected", flush=True)
        at_exit = failing_model("at_exit")
        print("done", flush=True)
        # no wipe(): closing at exit fails
    """))
    proc = subprocess.run([sys.executable, str(script)], env=subprocess_env(), cwd=tmp_path, capture_output=True,
                          text=True, timeout=120)
    assert proc.stdout.split() == ["collected", "done"], proc.stderr[-3000:]
    assert proc.returncode == 0, f"exit {proc.returncode}:\n{proc.stderr[-3000:]}"
    assert "terminate called" not in proc.stderr
    # both failures are reported on stderr, not lost silently
    assert "WARNING recorder Node" in proc.stderr and "collected.xml" in proc.stderr and "at_exit.xml" in proc.stderr
