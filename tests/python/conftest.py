import os
import sys

import pytest

REPO = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))

# `make test` sets PYTHONPATH=python and `make sanitize` PYTHONPATH=build-sanitize/python;
# without PYTHONPATH, `pytest` alone imports the working tree's package. With it,
# the caller's choice stands (inserting python/ first would hide the sanitizer build).
if not os.environ.get("PYTHONPATH"):
    sys.path.insert(0, os.path.join(REPO, "python"))

import beamsolid  # noqa: E402

# The folder the beamsolid package was imported from: a child Python process
# must run the same build (the in-place one, an installed one, or the
# sanitizer build), so it goes first on the child's path.
PACKAGE_PARENT = os.path.dirname(os.path.dirname(os.path.abspath(beamsolid.__file__)))

# The example C++ plugin (CMakeLists.txt: <build>/plugins) must come from the same
# build as the package, since it links that build's libbeamsolid.so: `make sanitize`
# names build-sanitize/plugins; otherwise it is the normal build's.
PLUGIN_DIR = os.environ.get("BEAMSOLID_PLUGIN_DIR") or os.path.join(REPO, "build", "plugins")


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
