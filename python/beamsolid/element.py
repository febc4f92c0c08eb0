"""Elements written in Python, for prototyping a formulation before writing it in C++.

Subclass :class:`Element`, implement ``tangent()`` and ``force()`` (and
whatever else the formulation needs), register the class, then use it like
any element type::

    class Spring(beamsolid.Element):
        def __init__(self, tag, i, j, k):
            super().__init__(tag, [i, j])
            self.k = k
        def tangent(self): ...
        def force(self): ...

    beamsolid.register_element("PySpring", Spring)
    ops.element("PySpring", 1, 1, 2, 100.0)

Matrices and vectors are in the element's dof order: node by node, all dofs
of each node. Python runs in the Newton loop, so such elements are for
prototypes and tests, not production models.
"""
from ._beamsolid import register_element as _register


def _np():
    # NumPy on first use: `import beamsolid` alone (every OpenSeesPy script)
    # then neither pays its import nor starts its BLAS threads.
    import numpy

    return numpy


class Element:
    """Base class of Python elements.

    After the element is added to a model, ``coords`` (n_nodes x 3) and
    ``ndf`` (dofs per node) are set and ``setup()`` is called; before every
    use ``update(disps)`` receives the nodes' trial displacements (a list of
    arrays, one per node).
    """

    #: True if the tangent is unsymmetric or has zero diagonal entries.
    general_solver = False

    def __init__(self, tag, nodes):
        self.tag = int(tag)
        self.nodes = [int(n) for n in nodes]
        self.coords = None
        self.ndf = None
        self.disps = None

    def _connect(self, coords, ndf):
        self.coords = _np().asarray(coords, dtype=float)
        self.ndf = list(ndf)
        self.setup()

    @property
    def num_dof(self):
        return sum(self.ndf)

    def setup(self):
        """Called once the nodes are known; raise to refuse the model."""

    def update(self, disps):
        """Trial displacements of the nodes (list of arrays)."""
        np = _np()
        self.disps = [np.asarray(d, dtype=float) for d in disps]

    def tangent(self):
        raise NotImplementedError("a Python element must implement tangent()")

    def initial_tangent(self):
        return self.tangent()

    def force(self):
        raise NotImplementedError("a Python element must implement force()")

    def mass(self):
        return None

    def commit(self):
        pass

    def revert_to_last_commit(self):
        pass

    def revert_to_start(self):
        pass

    def response(self, args):
        """Array for eleResponse/recorders, or None if `args` names nothing."""
        if args and args[0] in ("force", "forces", "globalForce"):
            return self.force()
        return None


def register_element(name, cls):
    """Make `cls` (an Element subclass or a callable returning one) element type `name`."""
    _register(name, cls)
