// Takes the protocol over half a second into the run and answers every step itself, each reply as
// full as its area holds of task starts that never end, with 4000-byte names. Kept without bound,
// they would grow the trusted side by a gigabyte in a few thousand steps.
#include "misbehave.hpp"
#include "takes_over.hpp"

namespace {

[[noreturn]] void serve() {
  const std::string name(4000, 'x');
  std::int64_t id = 0;
  answerEveryStep([&](std::byte* at, std::size_t room) {
    at = put(at, std::uint8_t{0}), at = put(at, 0.1), at = put(at, 0.0);
    const auto records = static_cast<std::uint32_t>((room - 60) / (name.size() + 64));
    at = put(at, records);
    for (std::uint32_t k = 0; k < records; ++k) {
      at = put(at, id++), at = put(at, std::int64_t{-1}), at = put(at, 0), at = put(at, name), at = put(at, std::string("here")), at = put(at, 0.5),
      at = put(at, 0.0), at = put(at, std::uint8_t{0}), at = put(at, std::string());
    }
    return put(at, std::uint8_t{0});
  });
}

}  // namespace

Behavior<Wheels> forgesRecords(const Robot&) { return misbehaveFrom(0.5, serve); }
FROB_CONTROLLER(forgesRecords)
