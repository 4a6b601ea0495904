#include "frob/instant.hpp"

#include "frob/detail/node.hpp"
#include "frob/errors.hpp"
#include "frob/event.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace frob {

namespace {
// Instant ids are unique in the process so that a node shared between clocks never reuses a stale value.
std::atomic<std::uint64_t> nextInstantId{1};
}  // namespace

namespace detail {
std::atomic<long> liveNodes{0};
std::atomic<std::uint64_t> planCutShort{0};

std::optional<std::int64_t> TimerNode::compute(const Instant& now) {
  if (!repeat_ && fired_ > 0) return std::nullopt;
  double local = start_.local(now);
  // The occurrence's lag: how long ago the due time `due` passed. Below a nanosecond it is rounding
  // (the due time is this sample), so that a task started then counts whole steps from it.
  auto occurAfter = [this, local](double due) {
    double lag = local - due;
    origin_.lag = lag < 1e-9 ? 0.0 : lag;
    return fired_;
  };
  if (!repeat_) {
    // Exactly when time() >= period first holds for a behavior started with this timer.
    if (local < period_) return std::nullopt;
    fired_ = 1;
    return occurAfter(period_);
  }
  // A tolerance far below any step keeps t = k × period from being missed by rounding.
  auto due = [this](std::int64_t k) { return static_cast<double>(k) * period_; };
  auto reached = [&](std::int64_t k) { return local + 1e-9 * (1.0 + due(k)) >= due(k); };
  if (!reached(fired_ + 1)) return std::nullopt;
  // Every period elapsed since the last occurrence counts, however many fit in one step.
  std::int64_t k = std::max(fired_ + 1, static_cast<std::int64_t>(std::floor(local / period_)));
  if (reached(k + 1)) ++k;
  fired_ = k;
  return occurAfter(due(k));
}
}  // namespace detail

Event<Unit> after(double seconds) {
  FROB_ASSERT(seconds >= 0, "after: the delay must be zero or more seconds");
  return Event<std::int64_t>(detail::makeNode<detail::TimerNode>(seconds, false)).map([] { return Unit{}; });
}

Event<std::int64_t> every(double seconds) {
  FROB_ASSERT(seconds > 0, "every: the period must be more than zero seconds");
  return Event<std::int64_t>(detail::makeNode<detail::TimerNode>(seconds, true));
}

namespace detail {
namespace {
// A node of a plan's cone: what it reads, its owners, and how many of those are the plan's root and
// its own nodes.
struct ConeNode {
  NodeBase* node;
  long owners;
  std::vector<Input> inputs;
  long ownedByPlan = 0;
};

std::vector<ConeNode>::iterator find(std::vector<ConeNode>& cone, const NodeBase* node) {
  return std::find_if(cone.begin(), cone.end(), [node](const ConeNode& c) { return c.node == node; });
}

// Depth-first, inputs in the order the node reads them, each node listed after its inputs. Plans
// are small, so the cone is searched linearly rather than hashed (a switch builds plans often).
void planCone(const Input& input, std::vector<ConeNode>& cone) {
  if (input.node->constant() || find(cone, input.node) != cone.end()) return;
  ConeNode c{.node = input.node, .owners = input.owners, .inputs = {}};
  if (c.node->strict()) {
    c.node->strictInputs(c.inputs);
    for (const Input& i : c.inputs) planCone(i, cone);
  }
  cone.push_back(std::move(c));
}
}  // namespace

std::vector<PlanStep> planFor(const NodeBase& root) {
  std::vector<Input> inputs;
  root.strictInputs(inputs);
  if (inputs.empty()) return {};
  std::vector<ConeNode> cone;
  cone.push_back({.node = const_cast<NodeBase*>(&root), .owners = 0, .inputs = std::move(inputs)});
  // By index and by copy: the cone grows as it is walked.
  for (std::size_t i = 0; i < cone[0].inputs.size(); ++i) planCone(Input(cone[0].inputs[i]), cone);
  // Readers come after what they read, so going backwards all the handles the plan holds on a node
  // are counted when it is reached: it is the plan's own if they are all its owners.
  auto countHandles = [&cone](const ConeNode& reader) {
    for (const Input& i : reader.inputs) {
      if (auto it = find(cone, i.node); it != cone.end()) ++it->ownedByPlan;  // constants are not in it
    }
  };
  countHandles(cone[0]);
  std::vector<PlanStep> plan(cone.size(), PlanStep{nullptr, &PlanStep::last});
  for (std::size_t k = cone.size() - 1; k > 0; --k) {
    bool own = cone[k].ownedByPlan == cone[k].owners;
    if (own) countHandles(cone[k]);
    plan[k - 1] = PlanStep{cone[k].node, cone[k].node->planStep(!own)};
  }
  return plan;
}
}  // namespace detail

long liveNodeCount() { return detail::liveNodes.load(std::memory_order_relaxed); }

Clock::Clock(double dt) {
  FROB_ASSERT(dt > 0, "Clock: dt must be positive");
  now_ = Instant{.id = nextInstantId.fetch_add(1, std::memory_order_relaxed), .step = 0, .time = 0.0, .dt = dt};
}

const Instant& Clock::advance() {
  now_.id = nextInstantId.fetch_add(1, std::memory_order_relaxed);
  now_.step += 1;
  now_.time = static_cast<double>(now_.step) * now_.dt;
  return now_;
}

}  // namespace frob
