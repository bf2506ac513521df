#include "mapped_file.hpp"

#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <mutex>

#include "pendulum/input_error.hpp"

namespace pendulum::detail {

namespace {

/// The guarded mappings: one per thread reading a recording at once (batch
/// --jobs is at most 256). The handler reads them; lock-free atomics only,
/// as a signal handler may use.
struct Guard {
  std::atomic<std::uintptr_t> begin{0}, end{0};
  std::atomic<bool> shrank{false};
};
constexpr int kGuards = 512;
Guard guards[kGuards];
struct sigaction previous;
std::uintptr_t page_size;  ///< read before the handler is installed: sysconf is not async-signal-safe

void on_sigbus(int signal, siginfo_t* info, void* context) {
  const auto address = reinterpret_cast<std::uintptr_t>(info->si_addr);
  for (Guard& g : guards) {
    const std::uintptr_t begin = g.begin.load(), end = g.end.load();
    if (address < begin || address >= end) continue;
    // Zero pages from the missing one to the mapping's end (the file is gone
    // past it too): the read that faulted is retried and finds zeros.
    const std::uintptr_t page = address & ~(page_size - 1);
    const int saved = errno;
    void* zeros = ::mmap(reinterpret_cast<void*>(page), end - page, PROT_READ,
                         MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0);
    errno = saved;
    if (zeros == MAP_FAILED) break;
    g.shrank.store(true);
    return;
  }
  // Not a recording's page: what would have happened without this handler.
  if (previous.sa_flags & SA_SIGINFO) {
    previous.sa_sigaction(signal, info, context);
  } else if (previous.sa_handler != SIG_DFL && previous.sa_handler != SIG_IGN) {
    previous.sa_handler(signal);
  } else {
    ::signal(SIGBUS, SIG_DFL);  // the fault repeats on return and ends the process
  }
}

void install_handler() {
  page_size = static_cast<std::uintptr_t>(::sysconf(_SC_PAGESIZE));
  struct sigaction action {};
  action.sa_sigaction = on_sigbus;
  action.sa_flags = SA_SIGINFO | SA_NODEFER;
  sigemptyset(&action.sa_mask);
  ::sigaction(SIGBUS, &action, &previous);
}

}  // namespace

MappedFile::MappedFile(const InputFile& file) : size_(file.size()) {
  if (!size_) return;
  static std::once_flag installed;
  std::call_once(installed, install_handler);
  for (int k = 0; k < kGuards && slot_ < 0; ++k) {
    std::uintptr_t free = 0;
    if (guards[k].begin.compare_exchange_strong(free, 1)) slot_ = k;  // 1: taken, no address yet
  }
  if (slot_ < 0) throw std::runtime_error("more than 512 recordings mapped at once");
  map_ = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, file.fd(), 0);
  if (map_ == MAP_FAILED) {
    map_ = nullptr;
    guards[slot_].begin.store(0);
    throw InputError(file.path(), std::string("cannot read the file: ") + std::strerror(errno));
  }
  // begin before end: while begin is the placeholder 1, an end already set
  // would make [1, end) a guarded range, and a fault anywhere below this
  // mapping (another thread's recording) would get zero pages mapped over
  // whatever lies between it and this mapping's end.
  Guard& g = guards[slot_];
  g.shrank.store(false);
  g.begin.store(reinterpret_cast<std::uintptr_t>(map_));
  g.end.store(reinterpret_cast<std::uintptr_t>(map_) + size_);
}

MappedFile::~MappedFile() {
  if (slot_ < 0) return;
  Guard& g = guards[slot_];
  g.end.store(0);
  if (map_) ::munmap(map_, size_);
  g.begin.store(0);
}

bool MappedFile::shrank() const { return slot_ >= 0 && guards[slot_].shrank.load(); }

}  // namespace pendulum::detail
