#include "frob/detail/node.hpp"
#include "frob/event.hpp"
#include "frob/instant.hpp"

#include <cassert>
#include <algorithm>
#include <vector>

namespace frob {

namespace {
// Instant ids are unique in the process so that a node shared between clocks never reuses a stale value.
std::atomic<std::uint64_t> nextInstantId{1};
}  // namespace

namespace detail {
std::atomic<long> liveNodes{0};

std::optional<std::int64_t> TimerNode::compute(const Instant& now) {
  double local = start_.local(now);
  if (!repeat_ && fired_ > 0) return std::nullopt;
  // A tolerance far below any step keeps t = k × period from being missed by rounding.
  double due = static_cast<double>(fired_ + 1) * period_;
  if (local + 1e-9 * (1.0 + due) < due) return std::nullopt;
  return ++fired_;
}
}  // namespace detail

namespace detail {
namespace {
// Depth-first, inputs in the order the node reads them, each node listed after its inputs. Plans
// are small, so `seen` is searched linearly rather than hashed (a switch builds plans often).
void planCone(NodeBase* node, std::vector<PlanStep>& plan, std::vector<const NodeBase*>& seen) {
  if (std::find(seen.begin(), seen.end(), node) != seen.end()) return;
  seen.push_back(node);
  if (node->strict()) {
    std::vector<NodeBase*> inputs;
    node->strictInputs(inputs);
    for (NodeBase* input : inputs) planCone(input, plan, seen);
  }
  plan.push_back(PlanStep{node, node->refresher()});
}
}  // namespace

std::vector<PlanStep> planFor(const NodeBase& root) {
  std::vector<NodeBase*> inputs;
  root.strictInputs(inputs);
  std::vector<PlanStep> plan;
  if (inputs.empty()) return plan;
  std::vector<const NodeBase*> seen{&root};
  for (NodeBase* input : inputs) planCone(input, plan, seen);
  return plan;
}
}  // namespace detail

long liveNodeCount() { return detail::liveNodes.load(std::memory_order_relaxed); }

Clock::Clock(double dt) {
  assert(dt > 0 && "Clock: dt must be positive");
  now_ = Instant{.id = nextInstantId.fetch_add(1, std::memory_order_relaxed), .step = 0, .time = 0.0, .dt = dt};
}

const Instant& Clock::advance() {
  now_.id = nextInstantId.fetch_add(1, std::memory_order_relaxed);
  now_.step += 1;
  now_.time = static_cast<double>(now_.step) * now_.dt;
  return now_;
}

}  // namespace frob
