#pragma once
// Private to lib/src: a regular file's text mapped into memory, read without
// a copy, and safe against the file shrinking underneath (docs/robustness.md,
// "A file that changes while it is read").

#include <cstddef>
#include <string_view>

#include "pendulum/files.hpp"

namespace pendulum::detail {

/// The whole text of an open file, mapped (MAP_POPULATE: read ahead in one
/// go). A page that the file no longer holds when it is touched (the file was
/// truncated after it was opened) would raise SIGBUS and kill the process;
/// here a handler maps zero bytes over the missing pages of this mapping
/// instead, and shrank() says so, so that the caller throws an error for
/// this file alone. Faults outside every such mapping go to the handler that
/// was there before (or kill the process as they did).
class MappedFile {
 public:
  explicit MappedFile(const InputFile& file);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::string_view text() const { return {static_cast<const char*>(map_), size_}; }
  /// True once a page past the file's end was touched.
  bool shrank() const;

 private:
  void* map_ = nullptr;
  std::size_t size_ = 0;
  int slot_ = -1;  ///< this mapping's place among the guarded ones
};

}  // namespace pendulum::detail
