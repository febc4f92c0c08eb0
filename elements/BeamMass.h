#pragma once
#include "elements/transforms/CrdTransf.h"

namespace beamsolid {

// Global 12x12 mass of a straight 3D beam with mass m per length and length L.
// Lumped: half the translational mass at each end, no rotary inertia.
// Consistent: linear axial (and torsional, with polar mass per length
// `torsionalInertia`, 0 for none) fields and cubic Hermite bending in both
// planes (theta_z = v', theta_y = -w'), rotated by the local axes (rows x, y, z);
// with shear flexibility phiY (x-y plane) or phiZ (x-z plane) > 0, the shear-flexible
// beam's shape functions instead of Hermite's, and with rotaryY = Iz / A (x-y plane) or
// rotaryZ = Iy / A > 0 the sections' rotary inertia (ElasticTimoshenkoBeam).
CrdTransf::Matrix12 beamMass(double m, double L, bool consistent, double torsionalInertia, const Matrix3& axes,
                             double phiY = 0.0, double phiZ = 0.0, double rotaryY = 0.0, double rotaryZ = 0.0);

}  // namespace beamsolid
