#pragma once
// Private to lib/src/recordings/.
#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace pendulum::detail {

/// Asks the kernel for 2 MiB pages under a large vector's storage before it
/// is first touched: a column of an hour at 500 Hz (14 MiB) then costs a few
/// page faults instead of 3500 (transparent huge pages, "madvise" mode).
/// Advice only: where the kernel declines, nothing changes.
inline void huge_pages(std::vector<double>& v) {
  constexpr std::uintptr_t kPage = 4096;
  const std::size_t bytes = v.capacity() * sizeof(double);
  if (bytes < (std::size_t{4} << 20)) return;
  const auto begin = (reinterpret_cast<std::uintptr_t>(v.data()) + kPage - 1) & ~(kPage - 1);
  const auto end = (reinterpret_cast<std::uintptr_t>(v.data()) + bytes) & ~(kPage - 1);
  ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

}  // namespace pendulum::detail
