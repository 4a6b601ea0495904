#pragma once
// How many times a benchmark with a fixed count runs: `figures` when run by hand, once when ctest runs
// it as a smoke test (which sets FROB_BENCH_SMOKE), whose only question is whether it still works.
#include <cstdlib>

namespace bench {

inline int iterations(int figures) { return std::getenv("FROB_BENCH_SMOKE") != nullptr ? 1 : figures; }

}  // namespace bench
