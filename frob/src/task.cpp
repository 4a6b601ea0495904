#include "frob/task.hpp"

#include <cstring>
#include <string_view>

namespace frob {

namespace detail {

std::atomic<long> liveFrames{0};

std::string taskName(const char* functionName) {
  // GCC gives e.g. "frob::Task<frob::Wheels, bool> driveTo(frob::Point2)": keep "driveTo".
  std::string_view s(functionName);
  int depth = 0;
  std::size_t open = std::string_view::npos;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '<') ++depth;
    if (s[i] == '>') --depth;
    if (s[i] == '(' && depth == 0) {
      open = i;
      break;
    }
  }
  std::string_view head = s.substr(0, open);
  std::size_t start = head.find_last_of(" :");
  std::string_view name = start == std::string_view::npos ? head : head.substr(start + 1);
  if (name.empty()) return std::string(s);
  // A lambda's call operator appears as "f()::<lambda(...)>": name it after its enclosing function.
  if (s.find("::<lambda", open) != std::string_view::npos) return "lambda in " + std::string(name);
  return std::string(name);
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

}  // namespace detail

long liveTaskFrames() { return detail::liveFrames.load(std::memory_order_relaxed); }

}  // namespace frob
