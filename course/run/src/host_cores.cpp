#include "host_cores.hpp"

namespace frob::course {

std::optional<cpu_set_t> hostCores(const cpu_set_t& allowed, int graderCore, std::size_t hosts) {
  const auto cores = static_cast<std::size_t>(CPU_COUNT(&allowed));
  if (cores < 2 || cores > hosts || graderCore < 0 || graderCore >= CPU_SETSIZE || !CPU_ISSET(graderCore, &allowed)) return std::nullopt;
  cpu_set_t placed = allowed;
  CPU_CLR(graderCore, &placed);
  return placed;
}

void keepGraderCore(std::span<const int> hosts) {
  cpu_set_t allowed;
  CPU_ZERO(&allowed);
  if (::sched_getaffinity(0, sizeof allowed, &allowed) != 0) return;
  const std::optional<cpu_set_t> placed = hostCores(allowed, ::sched_getcpu(), hosts.size());
  if (!placed) return;
  for (const int pid : hosts) {
    if (pid > 0) ::sched_setaffinity(pid, sizeof *placed, &*placed);  // 0 would be this thread
  }
}

}  // namespace frob::course
