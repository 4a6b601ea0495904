// Not a benchmark: it always skips with an error, and its smoke test is registered WILL_FAIL, so
// ctest goes red if a benchmark that calls SkipWithError ever passes its smoke test again.
#include <benchmark/benchmark.h>

namespace {

void SkipsWithError(benchmark::State& state) {
  state.SkipWithError("this benchmark always fails, to check that smoke tests see it");
  for (auto _ : state) {
  }
}
BENCHMARK(SkipsWithError);

}  // namespace
