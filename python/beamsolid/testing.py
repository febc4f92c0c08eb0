"""Helpers for people who write elements (C++ plugins or Python classes) and test them."""
import dataclasses

import numpy as np


@dataclasses.dataclass
class TangentCheck:
    """An element's tangent next to central differences of its resisting force."""
    element: int
    tangent: np.ndarray
    difference: np.ndarray
    h: float
    rtol: float

    @property
    def error(self):
        """Largest entry of |tangent - difference|, relative to the largest entry of either."""
        scale = max(np.abs(self.tangent).max(), np.abs(self.difference).max(), np.finfo(float).tiny)
        return float(np.abs(self.tangent - self.difference).max() / scale)

    @property
    def worst(self):
        """(row, column) of the entry that differs most."""
        return tuple(int(i) for i in np.unravel_index(np.abs(self.tangent - self.difference).argmax(),
                                                      self.tangent.shape))

    @property
    def ok(self):
        return self.error <= self.rtol

    def __str__(self):
        i, j = self.worst
        return (f"element {self.element}: tangent off its finite differences by {self.error:.3e} (relative; "
                f"tolerance {self.rtol:g}), worst at [{i}, {j}]: {self.tangent[i, j]:.9g} against "
                f"{self.difference[i, j]:.9g} (h = {self.h:g})")


def check_tangent(model, eleTag, h=1e-6, rtol=1e-6, raise_error=False):
    """Compare element eleTag's tangent with central differences of its resisting force.

    Each of the element's dofs is moved by +-h from the nodes' trial displacements (set them first,
    e.g. by an analysis step or ``setNodeDisp``, to check a state other than the start); the model
    is left as it was. Central differences err by O(h^2) against round-off O(eps/h): h = 1e-6 of
    the displacements' scale suits most elements. Returns a TangentCheck (``.ok``, ``.error``,
    ``.worst``); with raise_error=True a failed check raises AssertionError saying where.
    ``model`` is a beamsolid.Model or the beamsolid.opensees module.
    """
    if hasattr(model, "default_model"):
        model = model.default_model()
    tangent, difference = model._interp.tangent_check(int(eleTag), float(h))
    check = TangentCheck(int(eleTag), np.array(tangent), np.array(difference), float(h), float(rtol))
    if raise_error and not check.ok:
        raise AssertionError(str(check))
    return check
