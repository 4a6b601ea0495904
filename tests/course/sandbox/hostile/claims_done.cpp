// Takes the protocol over half a second into the run: says once that its task returned (a reply
// Done, which the grader then stops asking for), and then drives on at 30 cm/s in every reply.
#include "misbehave.hpp"
#include "takes_over.hpp"

namespace {

[[noreturn]] void serve() {
  bool claimed = false;
  answerEveryStep([&](std::byte* at, std::size_t) {
    at = put(at, static_cast<std::uint8_t>(claimed ? 0 : 3)), at = put(at, 0.3), at = put(at, 0.0);  // Running, or Done
    claimed = true;
    at = put(at, std::uint32_t{0});   // no task records
    return put(at, std::uint8_t{0});  // no picture
  });
}

}  // namespace

Behavior<Wheels> claimsDone(const Robot&) { return misbehaveFrom(0.5, serve); }
FROB_CONTROLLER(claimsDone)
