#pragma once

// The one place BeamSolid's version is written: CMake's project() and the
// Python package's metadata read it from here.
#define BEAMSOLID_VERSION "0.1.0"
