#pragma once
// Which cores a run's controller hosts run on. A host and the grader wait for each other by spinning;
// on a machine with fewer cores than they are, hosts that share the grader's core take turns with it
// at every step. Kept off its core, they take turns among themselves while it simulates.

#include <sched.h>

#include <cstddef>
#include <optional>
#include <span>

namespace frob::course {

/// The cores for `hosts` hosts, of the `allowed` ones, when the grader runs on `graderCore`: every
/// allowed core but the grader's when they cannot have one each; nothing when no placement is needed
/// (enough cores) or possible (one core, or the grader on none of the allowed ones).
[[nodiscard]] std::optional<cpu_set_t> hostCores(const cpu_set_t& allowed, int graderCore, std::size_t hosts);

/// Places the processes `hosts` (0: one that has ended) as hostCores() says for the calling thread
/// (best effort: a refusal leaves them where they are, slower but correct).
void keepGraderCore(std::span<const int> hosts);

}  // namespace frob::course
