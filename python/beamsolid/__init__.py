"""BeamSolid: OpenSees-style finite element analysis with beam-solid contact.

``import beamsolid.opensees as ops`` gives the OpenSeesPy command set on a
default model; ``beamsolid.Model()`` gives independent models in one process.
"""
from .blas import blas_info, choose_kernel

choose_kernel()  # before the solvers load: OpenBLAS reads its kernel only then

from ._beamsolid import OpenSeesError, command_names, registered_types  # noqa: E402
from .element import Element, register_element  # noqa: E402
from .model import Model  # noqa: E402

__all__ = ["Element", "Model", "OpenSeesError", "blas_info", "command_names", "register_element", "registered_types"]
__version__ = "0.1.0"
