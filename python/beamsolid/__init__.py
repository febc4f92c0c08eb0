"""BeamSolid: OpenSees-style finite element analysis with beam-solid contact.

``import beamsolid.opensees as ops`` gives the OpenSeesPy command set on a
default model; ``beamsolid.Model()`` gives independent models in one process.
"""
from ._beamsolid import OpenSeesError, command_names, registered_types
from .element import Element, register_element
from .model import Model

__all__ = ["Element", "Model", "OpenSeesError", "command_names", "register_element", "registered_types"]
__version__ = "0.1.0"
