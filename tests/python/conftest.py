import os
import sys

import pytest

# `make test` sets PYTHONPATH=python; this keeps `pytest` alone working too.
sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "..", "python"))

import beamsolid  # noqa: E402


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
