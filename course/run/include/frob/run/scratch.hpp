#pragma once
// A folder of its own for one host or one compile, removed when it goes. It holds a lock for as long
// as it lives, so that removeStale() tells a live one from one that a killed frob left behind.

#include "frob/base/result.hpp"
#include "frob/sandbox/fd.hpp"

#include <filesystem>
#include <string>

namespace frob::course {

class Scratch {
 public:
  /// A new folder `prefix`-XXXXXX in `parent`, mode 0700, locked.
  [[nodiscard]] static Result<Scratch> make(const std::filesystem::path& parent, const std::string& prefix);
  Scratch() = default;
  ~Scratch();
  Scratch(Scratch&& o) noexcept;
  Scratch& operator=(Scratch&& o) noexcept;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
  sandbox::Fd lock_;  // the folder itself, flock()ed
};

/// Removes the folders `prefix`-* in `parent` whose lock nobody holds.
void removeStale(const std::filesystem::path& parent, const std::string& prefix);

}  // namespace frob::course
