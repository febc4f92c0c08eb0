// The C++ test runner's main: the BLAS kernel is chosen (and the runner
// re-executed with it) before any test factors a matrix, as for every other
// entry point.
#include <gtest/gtest.h>

#include "core/BlasKernel.h"

int main(int argc, char** argv) {
  beamsolid::BlasKernel::applyOrReexec(argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
