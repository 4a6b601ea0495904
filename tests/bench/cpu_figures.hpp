#pragma once
// A console reporter that also keeps each benchmark's CPU seconds per iteration (the median when
// repetitions are asked for), for a summary printed at Finalize. CPU time: the benchmarks here are
// single-threaded, and on a shared machine the wall clock also counts time spent waiting for a core.

#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

namespace bench {

class CpuFiguresReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median") continue;
      if (r.error_occurred || r.iterations == 0) continue;
      seconds_[r.run_name.str()] = r.GetAdjustedCPUTime() / benchmark::GetTimeUnitMultiplier(r.time_unit);
    }
  }

 protected:
  // CPU seconds per iteration of the benchmark `name`, or -1 when it did not run.
  [[nodiscard]] double seconds(const std::string& name) const {
    const auto it = seconds_.find(name);
    return it == seconds_.end() ? -1.0 : it->second;
  }

 private:
  std::map<std::string, double> seconds_;
};

}  // namespace bench
