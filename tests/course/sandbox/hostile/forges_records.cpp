// Takes the protocol over half a second into the run: maps the channel (fd 3) and answers every
// step itself, each reply as full as its area holds of task starts that never end, with 4000-byte
// names. Kept without bound, they would grow the trusted side by a gigabyte in a few thousand steps.
// (Built with the sandbox's headers for the channel's layout; a student would copy it.)
#include "misbehave.hpp"

#include <frob/sandbox/channel.hpp>

#include <sched.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstring>
#include <string>

namespace {

using namespace frob::sandbox;

template <class T>
std::byte* put(std::byte* at, const T& v) {
  std::memcpy(at, &v, sizeof v);
  return at + sizeof v;
}

std::byte* put(std::byte* at, const std::string& s) {
  at = put(at, static_cast<std::uint32_t>(s.size()));
  std::memcpy(at, s.data(), s.size());
  return at + s.size();
}

[[noreturn]] void serve() {
  auto* first = static_cast<Header*>(::mmap(nullptr, Channel::kHeaderBytes, PROT_READ | PROT_WRITE, MAP_SHARED, kChannelFd, 0));
  const std::size_t reply = Channel::kHeaderBytes + first->setupBytes + first->inBytes;  // robot 0's reply area
  auto* base = static_cast<std::byte*>(::mmap(nullptr, reply + first->outBytes, PROT_READ | PROT_WRITE, MAP_SHARED, kChannelFd, 0));
  Header& h = *reinterpret_cast<Header*>(base);
  const std::string name(4000, 'x');
  std::int64_t id = 0;
  for (std::uint32_t sequence = h.request.sequence.load();; ++sequence) {
    while (h.request.sequence.load() != sequence) ::sched_yield();
    std::byte* at = base + reply + sizeof(std::uint32_t);
    at = put(at, std::uint8_t{0}), at = put(at, 0.1), at = put(at, 0.0);
    const std::uint32_t records = static_cast<std::uint32_t>((h.outBytes - 64) / (name.size() + 64));
    at = put(at, records);
    for (std::uint32_t k = 0; k < records; ++k) {
      at = put(at, id++), at = put(at, std::int64_t{-1}), at = put(at, 0), at = put(at, name), at = put(at, std::string("here")), at = put(at, 0.5),
      at = put(at, 0.0), at = put(at, std::uint8_t{0}), at = put(at, std::string());
    }
    at = put(at, std::uint8_t{0});
    put(base + reply, static_cast<std::uint32_t>(at - (base + reply) - sizeof(std::uint32_t)));
    h.reply.sequence.store(sequence + 1);
    const std::uint64_t one = 1;
    if (h.reply.sleeping.load() != 0) (void)::write(kWakeFd, &one, sizeof one);
  }
}

}  // namespace

Behavior<Wheels> forgesRecords(const Robot&) { return misbehaveFrom(0.5, serve); }
FROB_CONTROLLER(forgesRecords)
