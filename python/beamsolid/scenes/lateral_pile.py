"""A single pile in elastic soil pushed laterally at its head (issue 5).

This module holds the physical problem shared by the scene, the accuracy-versus-cost
benchmark and the stability map: the parameters, the mesh levels and the closed forms.
Units: kN, m, kPa.

Problem: a solid circular concrete pile of radius R and length L, head at the ground
surface (z = 0), tip at z = -L on the base of a cylindrical soil domain of radius
R_out. The soil is elastic (E, nu) and confined by its own weight (unit weight gamma):
sigma_v = gamma d, sigma_h = K0 sigma_v at depth d with K0 = nu / (1 - nu) (the elastic
geostatic stage under uniaxial strain). The head is pushed along +x.

Randolph (1981), "The response of flexible piles to lateral loading", Geotechnique
31(2), 247-259 (also Fleming et al., Piling Engineering, 3rd ed., section 6.3), for a
flexible pile (L > lc) in homogeneous elastic soil (rho_c = 1), load H at ground level:
    G*  = G (1 + 3 nu / 4),         Ep = E_pile I_pile / (pi R^4 / 4)
    lc  = 2 R (Ep / G*)^(2/7)       (critical length)
    u   = (Ep / G*)^(1/7) / G* * (0.27 H / (lc / 2) + 0.3 M / (lc / 2)^2)
    theta = (Ep / G*)^(1/7) / G* * (0.3 H / (lc / 2)^2 + 0.8 M / (lc / 2)^3)
"""
import math
from dataclasses import dataclass

# Mesh levels: (n_theta, n_radial, n_z) of the soil O-grid; every level keeps the
# same geometry and grading so that the levels converge to one answer.
LEVELS = {
    "coarse": (12, 6, 12),
    "medium": (16, 9, 18),
    "fine": (24, 12, 27),
}


@dataclass(frozen=True)
class LateralPile:
    """The physical problem (kN, m, kPa). Numerical choices live with the models that use it."""

    pile_radius: float = 0.5
    length: float = 20.0  # pile length = soil depth (the pile is flexible: L = 2 lc)
    outer_radius: float = 12.0  # soil domain radius (24 pile diameters)
    pile_E: float = 30e6
    pile_nu: float = 0.2
    soil_E: float = 20e3
    soil_nu: float = 0.3
    gamma: float = 20.0  # soil unit weight (kN/m^3)
    mu: float = 0.5  # pile-soil friction coefficient
    head_disp: float = 0.02  # largest head displacement (m), 2% of the diameter

    @property
    def pile_G(self):
        return self.pile_E / (2.0 * (1.0 + self.pile_nu))

    @property
    def area(self):
        return math.pi * self.pile_radius**2

    @property
    def inertia(self):
        return math.pi * self.pile_radius**4 / 4.0

    @property
    def soil_G(self):
        return self.soil_E / (2.0 * (1.0 + self.soil_nu))

    @property
    def K0(self):
        """At-rest earth pressure coefficient of the elastic geostatic stage (uniaxial strain)."""
        return self.soil_nu / (1.0 - self.soil_nu)

    @property
    def stiffness_scale(self):
        """Soil stiffness scale per contact node, E_soil R (kN/m): penalties are quoted as multiples."""
        return self.soil_E * self.pile_radius

    # --- Randolph (1981) --------------------------------------------------------
    @property
    def G_star(self):
        return self.soil_G * (1.0 + 0.75 * self.soil_nu)

    @property
    def Ep(self):
        """Equivalent modulus of a solid pile of radius R with the pile's bending stiffness."""
        return self.pile_E * self.inertia / (math.pi * self.pile_radius**4 / 4.0)

    @property
    def critical_length(self):
        return 2.0 * self.pile_radius * (self.Ep / self.G_star) ** (2.0 / 7.0)

    def randolph_head(self, H, M=0.0):
        """(u, theta) at ground level of a flexible pile in homogeneous elastic soil."""
        half = 0.5 * self.critical_length
        scale = (self.Ep / self.G_star) ** (1.0 / 7.0) / self.G_star
        u = scale * (0.27 * H / half + 0.3 * M / half**2)
        theta = scale * (0.3 * H / half**2 + 0.8 * M / half**3)
        return u, theta

    @property
    def randolph_compliance(self):
        """u / H at ground level for a lateral load alone (m/kN)."""
        return self.randolph_head(1.0)[0]
