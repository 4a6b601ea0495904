#pragma once
/// What crosses the trust boundary between the grader and a controller host, as plain bytes in a
/// fixed area of shared memory. Writing stops at the area's end; reading checks every length, so
/// bytes a hostile host wrote can fail a read but never read past the area or allocate without bound.

#include "frob/debug.hpp"
#include "frob/picture.hpp"
#include "frob/robot_values.hpp"

#include <cstddef>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>

namespace frob::sandbox {

/// Longest string that crosses (a task name, a failure message); longer ones are cut.
inline constexpr std::size_t kMaxString = 4096;
/// Most elements of any one list that crosses (sonars, shapes, points, records).
inline constexpr std::uint32_t kMaxCount = 1u << 20;

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
  /// `s`, cut to kMaxString bytes.
  void put(std::string_view s);
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

/// Reads values back; a read past the end, or a count or length out of bounds, makes ok() false.
class Reader {
 public:
  explicit Reader(std::span<const std::byte> bytes) : bytes_(bytes) {}
  template <class T>
    requires std::is_trivially_copyable_v<T>
  bool get(T& v) {
    if (!ok_ || sizeof v > bytes_.size() - used_) return ok_ = false;
    std::memcpy(&v, bytes_.data() + used_, sizeof v);
    used_ += sizeof v;
    return true;
  }
  bool get(std::string& s);
  /// A count of at most `max` elements.
  bool count(std::uint32_t& n, std::uint32_t max = kMaxCount);
  [[nodiscard]] bool ok() const { return ok_; }
  /// Fails the read from here on (a value that was read but cannot be).
  bool fail() { return ok_ = false; }

 private:
  std::span<const std::byte> bytes_;
  std::size_t used_ = 0;
  bool ok_ = true;
};

void write(Writer& w, const SensorFrame& frame);
bool read(Reader& r, SensorFrame& frame);  ///< reuses frame's vectors, so a step allocates nothing
void write(Writer& w, const RobotSpec& spec);
bool read(Reader& r, RobotSpec& spec);
void write(Writer& w, const Picture& picture);
bool read(Reader& r, Picture& picture);
void write(Writer& w, const TaskRecord& record);
bool read(Reader& r, TaskRecord& record);

}  // namespace frob::sandbox
