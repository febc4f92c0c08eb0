"""Ready-made models shared by the examples, the tests and the benchmarks."""
