"""OpenSeesPy-compatible commands on a default model.

An OpenSeesPy script runs after changing only its import line to
``import beamsolid.opensees as ops``.
"""
from . import model as _model
from ._beamsolid import OpenSeesError, command_names as _command_names

_default = _model.Model()


def _bind(name):
    method = getattr(_default, name)
    if getattr(getattr(_model.Model, name, None), "_generic", False):
        # A plain command: straight into the interpreter (a script calls node
        # and element hundreds of thousands of times; each Python frame counts).
        return _default._interp.command(name)

    def command(*args):
        return method(*args)

    command.__name__ = name
    command.__doc__ = method.__doc__
    return command


__all__ = ["OpenSeesError"]
for _name in list(_command_names()) + ["printModel"]:
    globals()[_name] = _bind(_name)
    __all__.append(_name)
del _name


def default_model():
    """The Model behind the module-level commands."""
    return _default
