// beamsolid_blas: prints the BLAS kernel choice as "kernel|reason|warning".
//
// The Python package runs it before it loads the solvers, with
// OPENBLAS_CORETYPE removed and the user's setting (if any) as the argument:
// this process's OpenBLAS then shows its own pick, which the package itself
// cannot see without loading the library, and by then it is too late to choose.
#include <iostream>
#include <string>

#include "core/BlasKernel.h"

int main(int argc, char** argv) {
  using beamsolid::BlasKernel;
  const std::string setting = argc > 1 ? argv[1] : "";
  const auto loaded = BlasKernel::loaded();
  const auto choice = BlasKernel::choose(BlasKernel::thisCpu(), loaded ? loaded->core : "", setting,
                                         loaded ? loaded->config : "");
  std::cout << BlasKernel::encode(choice) << '\n';
  return 0;
}
