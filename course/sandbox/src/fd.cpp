#include "frob/sandbox/fd.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

namespace frob::sandbox {

void Fd::reset(int fd) {
  if (fd_ >= 0 && fd_ != fd) ::close(fd_);
  fd_ = fd;
}

Result<Pipe> openPipe(const char* what) {
  int ends[2];
  if (::pipe2(ends, O_CLOEXEC) != 0) return Status::failure(std::string(what) + ": " + std::strerror(errno));
  return Pipe{Fd(ends[0]), Fd(ends[1])};
}

}  // namespace frob::sandbox
