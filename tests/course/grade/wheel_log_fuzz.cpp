// libFuzzer target for reading a wheel log (built with -DFROB_FUZZ=ON and clang). Any bytes are
// read or refused with a reason, never a crash, a hang or an exception; what is read writes back to
// a text that reads as the same log, whose records are exactly its lines (no value adds one).
#include "frob/grade/wheel_log.hpp"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>

namespace {

[[noreturn]] void fault(const char* what) {
  std::fprintf(stderr, "%s\n", what);
  std::abort();
}

bool same(const frob::course::WheelLog& a, const frob::course::WheelLog& b) {
  const auto bits = [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  if (a.wheels.size() != b.wheels.size()) return false;
  for (std::size_t k = 0; k < a.wheels.size(); ++k) {
    for (std::size_t i = 0; i < a.wheels[k].size(); ++i) {
      if (!bits(a.wheels[k][i].forward, b.wheels[k][i].forward) || !bits(a.wheels[k][i].turn, b.wheels[k][i].turn)) return false;
    }
  }
  return a.rubric == b.rubric && a.check == b.check && a.world == b.world && a.generated == b.generated && a.worldSeed == b.worldSeed &&
         a.seed == b.seed && a.submission == b.submission && a.submissionHash == b.submissionHash && a.student == b.student &&
         a.trajectory == b.trajectory && a.robots == b.robots && a.failures == b.failures && a.returned == b.returned &&
         a.returnedAt.size() == b.returnedAt.size();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view body(reinterpret_cast<const char*>(data), size);
  const frob::Result<frob::course::WheelLog> log = frob::course::parseWheelLog(body);
  if (!log) return 0;
  const std::string text = frob::course::wheelLogText(log.value(), "");
  const frob::Result<frob::course::WheelLog> again = frob::course::parseWheelLog(text);
  if (!again) fault(("a log written from one read does not read back: " + again.error()).c_str());
  if (!same(log.value(), again.value())) fault("a log written from one read reads back as another");
  // Its records: the header's lines, one per failure and result, then a line per step.
  const std::size_t records = 11 + (log.value().generated.empty() ? 0 : 1) + (log.value().student.empty() ? 0 : 1) + log.value().failures.size() +
                              log.value().returned.size() + log.value().returnedAt.size() + log.value().wheels.size();
  if (static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) != records) fault("a value added a record");
  return 0;
}
