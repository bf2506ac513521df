// A preloaded library (LD_PRELOAD) that makes, at a chosen point, what
// otherwise happens only by bad luck, for tests/cli_safety.sh:
//  - PENDULUM_TEST_TRUNCATE=NAME: right after a file whose name ends in
//    "/NAME" is mapped for reading, the file is cut to half its size, as a
//    phone still syncing or an export being rewritten does. The pages past
//    the new end leave the mapping at once (the kernel unmaps a truncated
//    file's pages from every mapping), so the reader finds them gone during
//    its read, every time.
//  - PENDULUM_TEST_SIGNAL_ON_FSYNC=SIG: fsync raises signal SIG first, as a
//    Ctrl-C (2) or kill (15) while a report is being written would.
#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <climits>
#include <cstdlib>
#include <cstring>
#include <string>

extern "C" void* mmap(void* address, size_t length, int prot, int flags, int fd, off_t offset) {
  using Mmap = void* (*)(void*, size_t, int, int, int, off_t);
  static const Mmap real = reinterpret_cast<Mmap>(dlsym(RTLD_NEXT, "mmap"));
  void* map = real(address, length, prot, flags, fd, offset);
  const char* name = std::getenv("PENDULUM_TEST_TRUNCATE");
  if (!name || fd < 0 || map == MAP_FAILED) return map;
  char path[PATH_MAX] = {};
  const std::string link = "/proc/self/fd/" + std::to_string(fd);
  if (readlink(link.c_str(), path, sizeof path - 1) < 0) return map;
  const std::string file(path), suffix = std::string("/") + name;
  if (file.size() < suffix.size() || file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0) return map;
  struct stat st;
  if (fstat(fd, &st) == 0) {
    const int w = open(path, O_WRONLY | O_CLOEXEC);
    if (w >= 0) {
      if (ftruncate(w, st.st_size / 2) != 0) std::abort();
      close(w);
    }
  }
  return map;
}

extern "C" int fsync(int fd) {
  using Fsync = int (*)(int);
  static const Fsync real = reinterpret_cast<Fsync>(dlsym(RTLD_NEXT, "fsync"));
  if (const char* signal = std::getenv("PENDULUM_TEST_SIGNAL_ON_FSYNC")) raise(std::atoi(signal));
  return real(fd);
}
