#pragma once

namespace beamsolid {

// How many threads OpenBLAS runs, set where it pays.
//
// A threaded BLAS call leaves its worker threads spinning (sched_yield) for a
// while after it returns; between the many small calls of a Newton iteration
// (a triangular solve, a small factorization) that spinning costs a core and
// gains nothing (measured on the lateral pile: 2 threads 9.3 s CPU, 1 thread
// 6.8 s, same answers). So the solvers run one thread by default and ask for
// the machine's threads only around work large enough to share (a dense
// factorization of thousands of equations). A user's OPENBLAS_NUM_THREADS or
// OMP_NUM_THREADS is kept as it is: then nothing here changes the count.
class BlasThreads {
 public:
  // The threads OpenBLAS started with (its own default or the user's setting).
  static int available();
  // Whether the user fixed the count (then set() does nothing).
  static bool userSet();
  static void set(int threads);
  static int current();

  // Sets the count for a scope and restores it after.
  class Scope {
   public:
    explicit Scope(int threads);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    int previous_;
  };
};

}  // namespace beamsolid
