#pragma once
/// What crosses the trust boundary between the grader and a controller host: typed messages, each
/// written and read here and nowhere else, as plain bytes in a fixed area of shared memory. Writing
/// stops at the area's end and cuts strings to their cap; reading checks every length and count
/// against the caps below, so bytes a hostile host wrote can fail a read (with the cap named) but
/// never read past the area or allocate without bound.

#include "frob/base/result.hpp"
#include "frob/debug.hpp"
#include "frob/picture.hpp"
#include "frob/robot_values.hpp"
#include "frob/sandbox/layers.hpp"

#include <cstddef>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <unordered_set>
#include <vector>

namespace frob::sandbox {

/// What the trusted side accepts from a host, per robot. A message past a cap fails its robot.
inline constexpr std::size_t kNameBytes = 256;            ///< a task's name or place, a plotted value's name, a label
inline constexpr std::size_t kMessageBytes = 4096;        ///< a failure, a task's result, a load error, a summary
inline constexpr std::uint32_t kRecordsPerStep = 4096;    ///< task starts and ends in one reply
inline constexpr std::uint32_t kShapesPerStep = 4096;     ///< shapes in one picture
inline constexpr std::uint32_t kPointsPerShape = 4096;    ///< points of one shape
inline constexpr std::uint32_t kOpenTasks = 4096;         ///< tasks running at once
inline constexpr std::uint32_t kPlotNames = 64;           ///< names of plotted values in one run
inline constexpr std::uint64_t kRunBytes = 256ULL << 20;  ///< task records and pictures of one run
inline constexpr std::uint32_t kSonars = 1024;            ///< sonars of one robot (a frame, a body)
inline constexpr std::uint32_t kModules = 1024;           ///< modules one host loads

/// Appends values to a byte area; once one does not fit, ok() is false and the rest is dropped.
class Writer {
 public:
  explicit Writer(std::span<std::byte> area) : area_(area) {}
  template <class T>
    requires std::is_trivially_copyable_v<T>
  void put(const T& v) {
    if (!fits(sizeof v)) return;
    std::memcpy(area_.data() + used_, &v, sizeof v);
    used_ += sizeof v;
  }
  /// `s`, cut to `cap` bytes.
  void put(std::string_view s, std::size_t cap);
  [[nodiscard]] bool ok() const { return ok_; }
  [[nodiscard]] std::size_t size() const { return used_; }

 private:
  bool fits(std::size_t n) {
    ok_ = ok_ && n <= area_.size() - used_;
    return ok_;
  }
  std::span<std::byte> area_;
  std::size_t used_ = 0;
  bool ok_ = true;
};

/// Reads values back; a read past the end, or a count or length past its cap, fails the read and
/// says why.
class Reader {
 public:
  explicit Reader(std::span<const std::byte> bytes) : bytes_(bytes) {}
  template <class T>
    requires std::is_trivially_copyable_v<T>
  bool get(T& v) {
    if (!ok_) return false;
    if (sizeof v > bytes_.size() - used_) return fail("it ends too soon");
    std::memcpy(&v, bytes_.data() + used_, sizeof v);
    used_ += sizeof v;
    return true;
  }
  /// A string of at most `cap` bytes; `what` names it in the failure.
  bool get(std::string& s, std::size_t cap, const char* what);
  /// A count of at most `cap` elements; `what` names them in the failure.
  bool count(std::uint32_t& n, std::uint32_t cap, const char* what);
  /// Fails the read from here on with `why` (the first failure is kept).
  bool fail(std::string why);
  [[nodiscard]] bool ok() const { return ok_; }
  [[nodiscard]] const std::string& why() const { return why_; }

 private:
  std::span<const std::byte> bytes_;
  std::size_t used_ = 0;
  bool ok_ = true;
  std::string why_;
};

/// The host's answer to Load: the filter it put on itself, then each module's declaration.
struct LoadReply {
  struct Module {
    bool loaded = false;
    std::string error;  ///< why it did not load; "" when it has no FROB_CONTROLLER line
    std::string name, world, summary;
    double seconds = 0.0;
  };
  Layer seccomp;
  std::vector<Module> modules;
};

/// The trusted side's Build request: each robot's module and body.
struct BuildRequest {
  struct Robot {
    std::uint32_t module = 0;
    RobotSpec spec;
  };
  std::vector<Robot> robots;
};

/// One robot's answer to a Step.
struct StepReply {
  /// Done: its task returned and every record has been sent; it stands still from now on, unasked.
  enum class State : std::uint8_t { Running, FailedNow, FailedBefore, Done };
  State state = State::Running;
  Wheels wheels;
  std::string failure;              ///< FailedNow: why
  std::vector<TaskRecord> records;  ///< task starts and ends since the last reply
  bool hasPicture = false;
  Picture picture;
};

void write(Writer& w, const SensorFrame& frame);
bool read(Reader& r, SensorFrame& frame);  ///< reuses frame's vectors, so a step allocates nothing
void write(Writer& w, const LoadReply& reply);
bool read(Reader& r, LoadReply& reply);
void write(Writer& w, const BuildRequest& request);
bool read(Reader& r, BuildRequest& request);
void write(Writer& w, const StepReply& reply);
bool read(Reader& r, StepReply& reply);

/// Writes `reply` in a robot's reply area (or the answer to loading in the setup area): its length,
/// then its bytes. False if it did not fit (the reader then fails it).
bool writeFramed(std::span<std::byte> area, const StepReply& reply);
bool writeFramed(std::span<std::byte> area, const LoadReply& reply);
/// Reads a reply from a copy of its `area` (`copy` is reused), so that the host cannot change it
/// while it is read; only as many bytes as it says it has are copied.
[[nodiscard]] Status readFramed(std::span<const std::byte> area, std::vector<std::byte>& copy, StepReply& reply);
[[nodiscard]] Status readFramed(std::span<const std::byte> area, std::vector<std::byte>& copy, LoadReply& reply);

/// What the trusted side keeps of one robot's replies over a run, against the caps per run: the
/// tasks running now (each start numbered in order, each end of a running task), the names of
/// plotted values, and the bytes of records and pictures.
class RunBudget {
 public:
  /// Takes `reply` into the budget; fails with the cap or rule it breaks.
  [[nodiscard]] Status take(const StepReply& reply);

 private:
  std::int64_t started_ = 0;
  std::unordered_set<std::int64_t> open_;
  std::unordered_set<std::string> plotNames_;
  std::uint64_t bytes_ = 0;
};

}  // namespace frob::sandbox
