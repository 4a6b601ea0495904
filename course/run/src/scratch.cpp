#include "frob/run/scratch.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <utility>

namespace frob::course {

namespace fs = std::filesystem;

Result<Scratch> Scratch::make(const fs::path& parent, const std::string& prefix) {
  // Made and locked under another name, then renamed: removeStale() never sees it unlocked.
  std::string making = (parent / ("frob-making-XXXXXX")).string();
  if (::mkdtemp(making.data()) == nullptr) return Status::failure("cannot make a scratch folder in " + parent.string());
  Scratch s;
  s.lock_.reset(::open(making.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  const fs::path name = parent / (prefix + making.substr(making.size() - 7));  // "-" and the six random letters
  std::error_code ec;
  if (!s.lock_.valid() || ::flock(s.lock_.get(), LOCK_EX | LOCK_NB) != 0 || (fs::rename(making, name, ec), ec)) {
    fs::remove_all(making, ec);
    return Status::failure("cannot make a scratch folder in " + parent.string());
  }
  s.path_ = name;
  return s;
}

Scratch::~Scratch() {
  std::error_code ec;
  if (!path_.empty()) fs::remove_all(path_, ec);
}

Scratch::Scratch(Scratch&& o) noexcept { *this = std::move(o); }

Scratch& Scratch::operator=(Scratch&& o) noexcept {
  std::swap(path_, o.path_);
  std::swap(lock_, o.lock_);
  return *this;
}

void removeStale(const fs::path& parent, const std::string& prefix) {
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(parent, ec)) {
    if (!e.path().filename().string().starts_with(prefix + "-") || !e.is_directory(ec) || e.is_symlink(ec)) continue;
    const sandbox::Fd dir(::open(e.path().c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC));
    if (dir.valid() && ::flock(dir.get(), LOCK_EX | LOCK_NB) == 0) fs::remove_all(e.path(), ec);
  }
}

}  // namespace frob::course
