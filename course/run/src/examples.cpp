#include "frob/run/examples.hpp"

#include "frob/base/layout.hpp"

#include <algorithm>
#include <cctype>

namespace frob::course {

namespace fs = std::filesystem;

std::vector<Example> examples() {
  std::vector<Example> list;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(layout().examples, ec)) {
    const std::string stem = e.path().stem().string();
    if (e.path().extension() != ".cpp" || stem.size() < 4 || !std::isdigit(static_cast<unsigned char>(stem[0])) ||
        !std::isdigit(static_cast<unsigned char>(stem[1])))
      continue;
    list.push_back({stem, e.path(), layout().exampleModules / (stem + ".so")});
  }
  std::sort(list.begin(), list.end(), [](const Example& a, const Example& b) { return a.name < b.name; });
  return list;
}

std::optional<Example> findExample(std::string_view name) {
  for (Example& e : examples()) {
    if (e.name == name || std::string_view(e.name).substr(3) == name) return std::move(e);
  }
  return std::nullopt;
}

Result<CompiledController> compileExample(const Example& example, const CompilerSetup& setup) {
  // Named as people would type it from where they are (course/examples/06_bug.cpp from the
  // repository's root), or in full from elsewhere.
  std::error_code ec;
  fs::path source = fs::proximate(example.source, ec);
  if (ec || source.empty() || *source.begin() == "..") source = example.source;
  // A module older than its source (edited since the build) is compiled afresh, like a student's file.
  if (!setup.checked && fs::exists(example.module) && fs::last_write_time(example.module, ec) >= fs::last_write_time(example.source, ec)) {
    return CompiledController{.module = example.module, .source = source.string()};
  }
  return compileControllerFile(source, setup);
}

}  // namespace frob::course
