"""BeamSolid: OpenSees-style finite element analysis with beam-solid contact.

``import beamsolid.opensees as ops`` gives the OpenSeesPy command set on a
default model; ``beamsolid.Model()`` gives independent models in one process.
"""
import os as _os

from .blas import blas_info, choose_kernel

choose_kernel()  # before the solvers load: OpenBLAS reads its kernel only then

from ._beamsolid import OpenSeesError, __version__, command_names, plugin_abi, registered_types  # noqa: E402
from .element import Element, register_element  # noqa: E402
from .model import Model  # noqa: E402

__all__ = ["Element", "Model", "OpenSeesError", "__version__", "blas_info", "cmake_dir", "command_names", "get_include", "last_error", "solver_info",
           "plugin_abi", "register_element", "registered_types"]


def get_include():
    """The folder of BeamSolid's C++ headers, for building plugins (docs/plugins.md)."""
    return _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), "include")


def cmake_dir():
    """The folder of BeamSolidConfig.cmake: find_package(BeamSolid) with BeamSolid_DIR set to it."""
    return _os.path.join(_os.path.dirname(_os.path.abspath(__file__)), "cmake")


def last_error():
    """Why the last ``analyze`` of the ``beamsolid.opensees`` commands failed ('' if it succeeded).

    For a ``beamsolid.Model`` of your own, use its ``last_error()`` method.
    """
    from .opensees import default_model

    return default_model().last_error()


def solver_info():
    """The linear system of the ``beamsolid.opensees`` analysis (see ``Model.solver_info``)."""
    from .opensees import default_model

    return default_model().solver_info()
