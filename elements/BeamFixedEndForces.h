#pragma once

namespace beamsolid {

// Fixed-end forces of element loads in one bending plane of the basic system
// (simply supported, axially fixed at I), shared by the 2D and 3D elastic
// beams. Transverse loads act along the plane's local transverse axis; the
// moments are for the rotation that is +dv/dx in that plane (the 3D beam
// flips them for the x-z plane, where theta_y = -dw/dx).
struct BeamFixedEndForces {
  double axialReactionI = 0.0;  // added to the local axial force at I (p0)
  double basicAxial = 0.0;      // added to the basic axial force (q0)
  double shearI = 0.0, shearJ = 0.0;    // transverse reactions at I and J (p0)
  double momentI = 0.0, momentJ = 0.0;  // fixed-end moments (q0)

  // Uniform transverse w and axial wx per length on a span L: axial all at I,
  // transverse half at each end, moments -+ wL^2/12.
  static BeamFixedEndForces uniform(double w, double wx, double L) {
    BeamFixedEndForces f;
    f.axialReactionI = -wx * L;
    f.basicAxial = -0.5 * wx * L;
    f.shearI = f.shearJ = -0.5 * w * L;
    f.momentI = -w * L * L / 12.0;
    f.momentJ = w * L * L / 12.0;
    return f;
  }

  // Point loads P (transverse) and Px (axial) at a = xL*L: moments
  // -P a b^2/L^2 and +P a^2 b/L^2.
  static BeamFixedEndForces point(double P, double Px, double xL, double L) {
    const double a = xL * L;
    const double b = L - a;
    BeamFixedEndForces f;
    f.axialReactionI = -Px;
    f.basicAxial = -Px * a / L;
    f.shearI = -P * b / L;
    f.shearJ = -P * a / L;
    f.momentI = -P * a * b * b / (L * L);
    f.momentJ = P * a * a * b / (L * L);
    return f;
  }
};

}  // namespace beamsolid
