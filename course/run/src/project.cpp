#include "frob/run/project.hpp"

#include "frob/base/layout.hpp"
#include "frob/render/output_file.hpp"
#include "frob/run/controller_file.hpp"

#include <algorithm>
#include <fstream>

namespace frob::course {

namespace fs = std::filesystem;

std::vector<std::string> editorFlags() {
  const std::vector<std::string> compiled = compilerSetup().flags;
  std::vector<std::string> flags;
  for (std::size_t i = 0; i < compiled.size(); ++i) {
    if (compiled[i] == "-ivfsoverlay") {
      ++i;  // its overlay file: clangd reads the real folder instead
    } else if (compiled[i] != std::string("-I") + kSdkIncludeDir) {
      flags.push_back(compiled[i]);
    }
  }
  flags.push_back("-I" + layout().includeDir.string());
  flags.emplace_back("-I.");  // the project's headers, from the folder of compile_flags.txt (tests/ includes them)
  return flags;
}

Result<std::vector<ProjectFile>> initProject(const fs::path& folder) {
  std::error_code ec;
  fs::create_directories(folder, ec);
  if (ec) return Status::failure("cannot create the folder '" + folder.string() + "': " + ec.message());
  std::vector<ProjectFile> files;
  const fs::path from = layout().studentTemplate;
  std::vector<fs::path> sources;  // in a stable order, for the command's report
  for (const fs::directory_entry& e : fs::recursive_directory_iterator(from, ec)) {
    if (e.is_regular_file()) sources.push_back(fs::relative(e.path(), from));
  }
  if (ec) return Status::failure("cannot read the student template '" + from.string() + "': " + ec.message());
  std::sort(sources.begin(), sources.end());
  for (const fs::path& source : sources) {
    const fs::path to = folder / source;
    const bool absent = !fs::exists(to);
    if (absent) {
      fs::create_directories(to.parent_path(), ec);
      if (!ec) fs::copy_file(from / source, to, ec);
      if (ec) return Status::failure("cannot write '" + to.string() + "': " + ec.message());
    }
    files.push_back({to, absent});
  }

  const fs::path flagsFile = folder / "compile_flags.txt";
  {
    std::ofstream out(render::partialPath(flagsFile.string()));
    for (const std::string& f : editorFlags()) out << f << "\n";
    if (!out.flush()) return render::discardPartial(flagsFile.string()), Status::failure("cannot write '" + flagsFile.string() + "'");
  }
  if (Status s = render::commitPartial(flagsFile.string(), "the editor's flags"); !s) return s;
  files.push_back({flagsFile, true});
  return files;
}

}  // namespace frob::course
