#include "frob/render/output_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace frob::render {

Status checkWritable(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  if (path.empty()) return Status::failure(what + ": no output path given");
  const fs::path dir = fs::path(path).parent_path().empty() ? fs::path(".") : fs::path(path).parent_path();
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) {
    const bool exists = fs::exists(dir, ec);
    return Status::failure(what + ": cannot write '" + path + "': " + (exists ? "'" : "directory '") + dir.string() +
                           (exists ? "' is not a directory" : "' does not exist"));
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0) {
    return Status::failure(what + ": cannot write '" + path + "': directory '" + dir.string() + "' is not writable (" + std::strerror(errno) + ")");
  }
  if (fs::is_directory(path, ec)) return Status::failure(what + ": cannot write '" + path + "': it is a directory");
  return {};
}

Status commitPartial(const std::string& path, const std::string& what) {
  std::error_code ec;
  std::filesystem::rename(partialPath(path), path, ec);
  if (ec) {
    discardPartial(path);
    return Status::failure(what + ": cannot move the finished file into place at '" + path + "': " + ec.message());
  }
  return {};
}

void discardPartial(const std::string& path) {
  std::error_code ec;
  std::filesystem::remove(partialPath(path), ec);
}

}  // namespace frob::render
