// libFuzzer target for the trusted side's reading of what a host sends (built with -DFROB_FUZZ=ON
// and clang). Any bytes a host may write are read within their caps or refused with a reason, never
// a crash, a hang or a leak; what is read is taken into a run's budget and timeline as the grader
// does, and writes back to the same bytes. The input is either the bytes themselves (a load reply,
// then a run of framed step replies), or a recipe for replies a host might write, some of whose
// bytes are then overwritten: the second reaches past the first fields that raw bytes rarely get
// right.
#include "frob/sandbox/wire.hpp"

#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <span>
#include <vector>

namespace {

using namespace frob;
using namespace frob::sandbox;

[[noreturn]] void fault(const char* what) {
  std::fprintf(stderr, "%s\n", what);
  std::abort();
}

// Written, read and written again, a message gives the same bytes twice.
template <class Message>
void checkRewrite(const Message& m) {
  static std::vector<std::byte> once(1 << 20), twice(1 << 20);
  Writer w1(once);
  write(w1, m);
  Message back;
  Reader r(std::span(once).first(w1.size()));
  if (!w1.ok() || !read(r, back)) fault("a message read from bytes did not read back once written");
  Writer w2(twice);
  write(w2, back);
  if (w2.size() != w1.size() || std::memcmp(once.data(), twice.data(), w1.size()) != 0) fault("a message wrote back to other bytes");
}

// A robot's run as the grader takes it: each reply read from its area, budgeted and mirrored.
class RobotRun {
 public:
  // False once the robot would fail.
  bool take(std::span<const std::byte> area) {
    if (const Status s = readFramed(area, copy_, reply_); !s) {
      if (s.error().empty()) fault("a step reply refused without a reason");
      return false;
    }
    checkRewrite(reply_);
    if (!budget_.take(reply_)) return false;
    for (TaskRecord& t : reply_.records) {
      if (t.how == TaskEnd::Running) {
        if (timeline_.start(t.parent, std::move(t.name), std::move(t.where), t.start) != t.id) fault("the budget let a task start out of order");
      } else {
        timeline_.end(t.id, t.end, t.how, std::move(t.detail));
      }
    }
    if (timeline_.running().size() > kOpenTasks) fault("more tasks running than the cap");
    return true;
  }
  [[nodiscard]] std::size_t lastLength() const { return copy_.size(); }

 private:
  RunBudget budget_;
  Timeline timeline_;
  std::vector<std::byte> copy_;
  StepReply reply_;
};

void rawBytes(std::span<const std::byte> bytes) {
  LoadReply load;
  Reader r(bytes);
  if (read(r, load)) {
    checkRewrite(load);
  } else if (r.why().empty()) {
    fault("a load reply refused without a reason");
  }
  std::vector<std::byte> copy;  // the same bytes as a setup area, framed as the grader reads it
  if (const Status s = bytes.size() >= sizeof(std::uint32_t) ? readFramed(bytes, copy, load) : Status{}; !s && s.error().empty()) {
    fault("a framed load reply refused without a reason");
  }
  RobotRun run;
  for (std::span<const std::byte> rest = bytes; rest.size() >= sizeof(std::uint32_t) && run.take(rest);) {
    rest = rest.subspan(sizeof(std::uint32_t) + run.lastLength());
  }
}

Picture recipePicture(FuzzedDataProvider& in) {
  std::vector<Shape> shapes(in.ConsumeIntegralInRange<std::size_t>(0, 8));
  for (Shape& s : shapes) {
    s.kind = static_cast<Shape::Kind>(in.ConsumeIntegralInRange<int>(0, static_cast<int>(Shape::Kind::Value)));
    s.points.resize(in.ConsumeIntegralInRange<std::size_t>(0, 6));
    for (Point2& p : s.points) p = {in.ConsumeFloatingPoint<double>(), in.ConsumeFloatingPoint<double>()};
    s.radius = in.ConsumeFloatingPoint<double>();
    s.text = in.ConsumeRandomLengthString(300);
    s.value = in.ConsumeFloatingPoint<double>();
    if (in.ConsumeBool()) s.color = Color{in.ConsumeFloatingPoint<float>(), 0.5f, 0.5f, 1.0f};
  }
  return Picture(std::move(shapes));
}

void recipes(FuzzedDataProvider& in) {
  static std::vector<std::byte> area(64 << 10);
  RobotRun run;
  std::int64_t next = 0;
  for (int step = 0; step < 64 && in.remaining_bytes() > 0; ++step) {
    StepReply reply{.state = static_cast<StepReply::State>(in.ConsumeIntegralInRange<int>(0, static_cast<int>(StepReply::State::Done))),
                    .wheels = {in.ConsumeFloatingPoint<double>(), in.ConsumeFloatingPoint<double>()}};
    if (reply.state == StepReply::State::FailedNow) reply.failure = in.ConsumeRandomLengthString(5000);
    reply.records.resize(in.ConsumeIntegralInRange<std::size_t>(0, 16));
    for (TaskRecord& t : reply.records) {
      const bool starts = in.ConsumeBool();
      t.id = starts ? (in.ConsumeBool() ? next++ : in.ConsumeIntegral<std::int64_t>()) : in.ConsumeIntegralInRange<std::int64_t>(-1, next);
      t.parent = in.ConsumeIntegralInRange<std::int64_t>(-1, next);
      t.name = in.ConsumeRandomLengthString(300);
      t.where = in.ConsumeRandomLengthString(300);
      t.how = starts ? TaskEnd::Running : static_cast<TaskEnd>(in.ConsumeIntegralInRange<int>(1, static_cast<int>(TaskEnd::Replaced)));
      t.detail = in.ConsumeRandomLengthString(5000);
    }
    reply.hasPicture = in.ConsumeBool();
    if (reply.hasPicture) reply.picture = recipePicture(in);
    std::fill(area.begin(), area.end(), std::byte{0});
    writeFramed(area, reply);
    for (int flips = in.ConsumeIntegralInRange<int>(0, 4); flips > 0; --flips) {  // what a hostile host overwrote
      area[in.ConsumeIntegralInRange<std::size_t>(0, 511)] = std::byte{in.ConsumeIntegral<std::uint8_t>()};
    }
    if (!run.take(area)) return;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  if (data[0] % 2 == 0) {
    rawBytes(std::span(reinterpret_cast<const std::byte*>(data) + 1, size - 1));
  } else {
    FuzzedDataProvider in(data + 1, size - 1);
    recipes(in);
  }
  return 0;
}
