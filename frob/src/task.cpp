#include "frob/task.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <string_view>

namespace frob {

namespace detail {

std::atomic<long> liveFrames{0};

namespace {

// The identifier a function's signature names, e.g. "frob::Task<Wheels> f(int)" -> "f".
std::string identifierIn(std::string_view signature) {
  int depth = 0;
  std::size_t open = signature.size();
  for (std::size_t i = 0; i < signature.size(); ++i) {
    char c = signature[i];
    if (c == '<') ++depth;
    if (c == '>') --depth;
    if (c == '(' && depth == 0) {
      open = i;
      break;
    }
  }
  std::string_view head = signature.substr(0, open);
  std::size_t start = head.find_last_of(" :");
  return std::string(start == std::string_view::npos ? head : head.substr(start + 1));
}

void eraseAll(std::string& s, std::string_view what) {
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what)) s.erase(at, what.size());
}

}  // namespace

std::string taskName(const char* functionName) {
  // GCC: "frob::Task<frob::Wheels, bool> driveTo(frob::Point2)", "main()::<lambda(...)>";
  // clang: "Task<Wheels> frob::(anonymous namespace)::goAhead()", "f()::(anonymous class)::operator()() const".
  std::string s(functionName);
  eraseAll(s, "(anonymous namespace)");
  std::size_t lambda = s.find("::<lambda");
  if (lambda == std::string::npos) lambda = s.find("::(anonymous class)");
  if (lambda != std::string::npos) return "lambda in " + identifierIn(s.substr(0, lambda));
  std::string name = identifierIn(s);
  return name.empty() ? std::string(functionName) : name;
}

std::string taskWhere(const std::source_location& loc) {
  const char* file = loc.file_name();
  const char* slash = std::strrchr(file, '/');
  return std::string(slash ? slash + 1 : file) + ":" + std::to_string(loc.line());
}

std::string describe(const std::exception_ptr& e, TaskEnd* why) {
  if (why) *why = TaskEnd::Failed;
  try {
    std::rethrow_exception(e);
  } catch (const RoboErr& err) {
    return std::string("error: ") + err.what();
  } catch (const ScopeSignal& s) {
    if (why) *why = TaskEnd::Aborted;
    return s.reason;
  } catch (const std::exception& x) {
    return std::string("exception: ") + x.what();
  } catch (...) {
    return "an exception of unknown type";
  }
}

namespace print {
std::string joined(const std::vector<std::string>& items) {
  constexpr std::size_t kShown = 8;
  std::string out;
  for (std::size_t k = 0; k < items.size() && k < kShown; ++k) out += (k == 0 ? "" : ", ") + items[k];
  return items.size() > kShown ? out + ", ..." : out;
}
}  // namespace print

std::string typeNameIn(std::string_view signature) {
  // clang: "std::string frob::detail::typeName() [T = Wall]"; GCC: "... [with T = Wall; ...]".
  std::size_t from = signature.find("T = ");
  if (from == std::string_view::npos) return "(value)";
  from += 4;
  std::size_t to = signature.find_first_of(";]", from);
  std::string name(signature.substr(from, to - from));
  eraseAll(name, "(anonymous namespace)::");
  return name;
}

std::string tooDeepMessage(const std::vector<std::pair<std::string, std::string>>& chain, int limit) {
  std::map<std::string, int> count;
  std::map<std::string, std::string> where;
  for (const auto& [name, at] : chain) ++count[name], where.emplace(name, at);
  std::string self = chain.empty() ? std::string("the task") : chain.front().first;
  for (const auto& [name, n] : count) {
    if (n > count[self]) self = name;
  }
  std::string nested =
      "is running inside itself " + std::to_string(count[self]) + " times over (tasks nested more than " + std::to_string(limit) + " deep)";
  if (self.starts_with("taskCatch(")) {
    return "the " + self + " made at " + where[self] + " " + nested +
           ": each round's taskCatch runs inside the one before, since its handler differs from that one's, so an error that its "
           "handler's task raises would reach the one before too. A taskCatch whose task becomes one with the same handler (the "
           "same lambda, capturing equal values) folds into it instead: capture only what stays the same from round to round, "
           "as in [g](const RoboErr&) { return bug(g); }, and no counter or container.";
  }
  std::string call = "co_await " + self + "();";
  return "task '" + self + "' " + nested + ": a task that ends with " + call +
         " waits for that call, so every earlier call stays in memory for as long as the robot runs. End it with "
         "co_await become(" +
         self + "()); instead: the new call then takes the old one's place.";
}

bool UsedOccurrences::fresh(const NodeBase* source, const Instant& at) const {
  return instant_ != at.id || std::none_of(used_.begin(), used_.end(), [source](const auto& u) { return u.first == source; });
}

void UsedOccurrences::use(const NodeBase* source, std::shared_ptr<NodeBase> carrier, const Instant& at) {
  if (instant_ != at.id) used_.clear(), instant_ = at.id;
  used_.emplace_back(source, std::move(carrier));
}

std::string endedOutputMessage(const std::string& task, double endedAt, double readAt) {
  char times[96];
  std::snprintf(times, sizeof times, "ended at t = %.3f s, and its output was read at t = %.3f s", endedAt, readAt);
  return "withTask: task '" + task + "' " + times + ": a task's output exists only while it runs (stop reading it when its end event occurs)";
}

std::optional<RoboErr> roboErrIn(const std::exception_ptr& e) {
  try {
    std::rethrow_exception(e);
  } catch (const RoboErr& err) {
    return err;
  } catch (...) {
    return std::nullopt;
  }
}

}  // namespace detail

long liveTaskFrames() { return detail::liveFrames.load(std::memory_order_relaxed); }

}  // namespace frob
