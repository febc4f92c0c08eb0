import os
import sys

import pytest

# `make test` sets PYTHONPATH=python; this keeps `pytest` alone working too.
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "python"))

import beamsolid  # noqa: E402

# The folder the beamsolid package was imported from: a child Python process
# must run the same build (the in-place one, an installed one, or the
# sanitizer build), so it goes first on the child's path.
PACKAGE_PARENT = os.path.dirname(os.path.dirname(os.path.abspath(beamsolid.__file__)))


def subprocess_env(**extra):
    """This process's environment (BLAS choice, sanitizer runtime and all) for a child
    Python that imports the same beamsolid build, with `extra` variables set."""
    env = dict(os.environ, **extra)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [PACKAGE_PARENT, os.environ.get("PYTHONPATH", "")]))
    return env


@pytest.fixture
def model():
    """A fresh independent model."""
    m = beamsolid.Model()
    yield m
    m.wipe()


@pytest.fixture
def ops():
    """The module-level OpenSeesPy-style commands, wiped before and after."""
    import beamsolid.opensees as o

    o.wipe()
    yield o
    o.wipe()
