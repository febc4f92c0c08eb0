"""CircularPile: section properties of a solid circular pile, shared by the pile scenes' problems."""
import math


class CircularPile:
    """Mixin for a problem dataclass with pile_radius, pile_E and pile_nu (a solid, elastic,
    isotropic circular section)."""

    @property
    def pile_G(self):
        return self.pile_E / (2.0 * (1.0 + self.pile_nu))

    @property
    def area(self):
        return math.pi * self.pile_radius**2

    @property
    def inertia(self):
        return math.pi * self.pile_radius**4 / 4.0
