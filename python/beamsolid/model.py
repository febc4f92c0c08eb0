"""The Model class: one Domain and its analysis, with every OpenSeesPy command as a method."""
import atexit
import sys
import weakref

from ._beamsolid import Interpreter, OpenSeesError, command_names

_live_models = weakref.WeakSet()


@atexit.register
def _close_all_models():
    # Recorded data is never lost: flush and close every recorder at exit,
    # and release Python elements while the interpreter is still whole.
    for model in list(_live_models):
        try:
            model._interp.close_recorders()
            model._interp.call("wipe")
        except OpenSeesError as e:  # too late to raise: say what was not written
            print(f"WARNING {e}", file=sys.stderr)


def _make_command(name):
    def command(self, *args):
        return self._interp.call(name, *args)

    command.__name__ = name
    command.__qualname__ = f"Model.{name}"
    command.__doc__ = f"OpenSeesPy command ``{name}``; see docs/commands.md."
    command._generic = True  # opensees.py binds such commands straight to the interpreter
    return command


class Model:
    """An independent model: its own nodes, elements, recorders and analysis.

    Methods have OpenSeesPy's names and positional arguments, e.g.
    ``m.node(1, 0.0, 0.0, 0.0)``; bad input raises OpenSeesError.
    """

    def __init__(self):
        self._interp = Interpreter()
        _live_models.add(self)

    def printModel(self, *args):
        """Print the model (readable, or '-JSON'); with '-file' write it there."""
        text = self._interp.call("printModel", *args)
        if text:
            sys.stdout.write(text)

    def last_error(self):
        """Why the most recent ``analyze`` returned a negative code ('' after one that succeeded).

        ``analyze`` never raises once it runs, as in OpenSees: a failed step (no
        convergence, a singular matrix, a system that cannot take the model, an
        element that threw) returns -1, -2 or -3, prints a WARNING and leaves the
        model at its last converged state; the reason is kept here.
        """
        return self._interp.last_error()

    def solver_info(self):
        """The linear system of the current analysis, as a dict.

        ``system`` (the name asked for), ``backend`` (what runs), ``equations``;
        ``condensed`` with ``interior`` and ``interface`` equation counts when the
        equations only constant-tangent elements touch are condensed out, and
        ``condensations`` (how often that was done), ``condensations_reused`` (how often the
        process had condensed the same constant part before, in a rebuilt model, and it was taken
        from there; BEAMSOLID_CONDENSE_CACHE=off stops that), ``factorizations`` and
        ``analyses`` (symbolic) so far, ``solver_seconds`` (wall time in factorizations and solves
        of this analysis); ``note`` says why or why not. Switch
        condensation with ``system(name, '-condense', 'auto'|'on'|'off')`` or the
        environment variable BEAMSOLID_CONDENSE=on|off.
        """
        return self._interp.solver_info()

    def close(self):
        """Flush and close this model's recorders."""
        self._interp.close_recorders()


for _name in command_names():
    if not hasattr(Model, _name):
        setattr(Model, _name, _make_command(_name))
del _name
