#include "frob/course/examples.hpp"

#include "controller_setup.inc"

#include <algorithm>

namespace frob::course {

namespace fs = std::filesystem;

std::vector<Example> examples() {
  std::vector<Example> list;
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(FROB_EXAMPLES_SOURCE_DIR, ec)) {
    const std::string stem = e.path().stem().string();
    if (e.path().extension() != ".cpp" || stem.size() < 4 || !std::isdigit(stem[0]) || !std::isdigit(stem[1])) continue;
    list.push_back({stem, e.path(), fs::path(FROB_EXAMPLES_MODULE_DIR) / (stem + ".so")});
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

Result<LoadedController> loadExample(const Example& example) {
  if (fs::exists(example.module)) return loadControllerModule(example.module, example.source.string());
  return loadControllerFile(example.source);
}

}  // namespace frob::course
