// Tries every way to see or change which pages of a library the kernel caches, or to watch files:
// two hosts (robots, runs or students) would pass notes through them.
// Drives at 0.1 m/s, turning 0.001 rad/s times the bits of the calls the kernel carried out rather
// than refused as not implemented (bit k: the k-th call below).
#include "misbehave.hpp"

#include <fcntl.h>
#include <linux/aio_abi.h>
#include <sys/inotify.h>
#include <sys/mman.h>
#include <sys/syscall.h>
#include <sys/uio.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>

namespace {

// Bit k set when attempt k was not refused with ENOSYS.
int notRefused() {
  const int fd = ::open("/etc/ld.so.cache", O_RDONLY);
  void* page = fd >= 0 ? ::mmap(nullptr, 4096, PROT_READ, MAP_SHARED, fd, 0) : MAP_FAILED;
  unsigned char resident = 0;
  char byte = 0;
  iovec io{&byte, 1};
  struct {
    std::uint64_t offset, length;
  } range{0, 4096};
  std::uint64_t stats[8] = {};
  aio_context_t aio = 0;
  int bits = 0, k = 0;
  const auto attempt = [&](long result) {  // errno read at once, before the next call
    if (!(result == -1 && errno == ENOSYS)) bits |= 1 << k;
    ++k;
  };
  if (page == MAP_FAILED) {  // the library could not be mapped: nothing was tried
    if (fd >= 0) ::close(fd);
    return 1 << 15;
  }
  attempt(::syscall(SYS_mincore, page, 4096, &resident));
  attempt(::syscall(SYS_fadvise64, fd, 0, 4096, POSIX_FADV_DONTNEED));
  attempt(::syscall(SYS_readahead, fd, 0, 4096));
  attempt(::syscall(451 /* cachestat */, fd, &range, stats, 0));
  attempt(::syscall(SYS_preadv2, fd, &io, 1, 0, 0, RWF_NOWAIT));
  attempt(::syscall(SYS_io_setup, 1, &aio));
  attempt(::syscall(SYS_inotify_init1, 0));
  attempt(::syscall(SYS_fanotify_init, 0, 0));
  attempt(::syscall(SYS_madvise, page, 4096, MADV_PAGEOUT));
  attempt(::syscall(SYS_madvise, page, 4096, MADV_COLD));
  ::munmap(page, 4096);
  ::close(fd);
  return bits;
}

}  // namespace

Behavior<Wheels> seesThePageCache(const Robot&) {
  return toBehavior(lift([](double) { return Wheels{0.1, 0.001 * notRefused()}; }, time()));
}
FROB_CONTROLLER(seesThePageCache)
