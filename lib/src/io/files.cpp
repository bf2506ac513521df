#include "pendulum/files.hpp"

#include <fcntl.h>
#include <linux/openat2.h>
#include <poll.h>
#include <sys/syscall.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>

#include "pendulum/input_error.hpp"
#include "../text.hpp"

namespace pendulum {

namespace {

std::string reason(int error) { return std::strerror(error); }

/// What a file that is not regular is, for the message refusing it.
std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "not a regular file (a named pipe)";
  if (S_ISSOCK(mode)) return "not a regular file (a socket)";
  return "not a regular file (a device)";
}

constexpr int kReadFlags = O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY;

/// `path` opened beneath the folder `within` (see InputFile); -1 with errno
/// EXDEV when it leads out. Where openat2 is missing (Linux before 5.6), the
/// file is opened and what was opened is checked: its resolved name, from
/// /proc/self/fd, must lie in the folder's.
int open_beneath(const std::string& path, const std::string& within) {
  namespace fs = std::filesystem;
  const fs::path inside = fs::path(path).lexically_normal().lexically_relative(fs::path(within).lexically_normal());
  if (inside.empty() || *inside.begin() == "..") return errno = EXDEV, -1;
  const int folder = ::open(within.c_str(), O_PATH | O_DIRECTORY | O_CLOEXEC);
  if (folder < 0) return -1;
  open_how how{};
  how.flags = kReadFlags;
  how.resolve = RESOLVE_BENEATH;
  int fd = static_cast<int>(::syscall(SYS_openat2, folder, inside.c_str(), &how, sizeof how));
  if (fd < 0 && errno == ENOSYS) {
    fd = ::openat(folder, inside.c_str(), kReadFlags);
    std::error_code ec;
    const fs::path root = fs::canonical("/proc/self/fd/" + std::to_string(folder), ec);
    const fs::path opened = fs::canonical("/proc/self/fd/" + std::to_string(fd), ec);
    const fs::path below = opened.lexically_relative(root);
    if (fd >= 0 && (ec || below.empty() || *below.begin() == "..")) ::close(fd), fd = -1, errno = EXDEV;
  }
  const int error = errno;
  ::close(folder);
  errno = error;
  return fd;
}

}  // namespace

std::optional<FileId> file_id(const std::string& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  return FileId{st.st_dev, st.st_ino};
}

InputFile::InputFile(const std::string& path, const std::string& expected, const std::optional<std::string>& within)
    : path_(printable_name(path)) {
  // A device is refused before it is opened (opening some has effects),
  // and what is opened is checked again.
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    throw InputError(path_, kind_of(st.st_mode) + "; expected " + expected);
  }
  fd_ = within ? open_beneath(path, *within) : ::open(path.c_str(), kReadFlags);
  if (fd_ < 0 && within && errno == EXDEV) {
    throw InputError(path_, "a symbolic link (or a name) leads out of the folder " + printable_name(*within) +
                                "; expected a file in it or below: a scene's files are read from elsewhere only "
                                "with --allow-outside");
  }
  if (fd_ < 0) throw InputError(path_, "cannot open the file: " + reason(errno));
  if (::fstat(fd_, &st) != 0) {
    const int error = errno;
    ::close(fd_);
    throw InputError(path_, "cannot read the file: " + reason(error));
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd_);
    throw InputError(path_, kind_of(st.st_mode) + "; expected " + expected);
  }
  size_ = static_cast<std::size_t>(st.st_size);
  mtime_ = st.st_mtim;
}

InputFile::~InputFile() { ::close(fd_); }

bool InputFile::changed() const {
  struct stat st;
  if (::fstat(fd_, &st) != 0) return true;
  return static_cast<std::size_t>(st.st_size) != size_ || st.st_mtim.tv_sec != mtime_.tv_sec ||
         st.st_mtim.tv_nsec != mtime_.tv_nsec;
}

std::string over_limit(const InputLimits& limits, Limit which) {
  static const char* const kUnits[] = {"bytes", "rows", "columns"};
  const std::size_t limit = which == Limit::bytes ? limits.bytes : which == Limit::rows ? limits.rows : limits.columns;
  const char* unit = kUnits[static_cast<int>(which)];
  return "got more than " + std::to_string(limit) + " " + unit + "; expected at most " + std::to_string(limit) + " in " +
         limits.of + " (--max-" + unit + " raises the limit)";
}

InputLimits GivenLimits::applied_to(InputLimits defaults) const {
  defaults.bytes = std::max(defaults.bytes, bytes);
  defaults.rows = std::max(defaults.rows, rows);
  defaults.columns = std::max(defaults.columns, columns);
  return defaults;
}

std::string read_text(const std::string& path, const InputLimits& limits, const std::string& expected,
                      const std::optional<std::string>& within) {
  std::optional<InputFile> file;
  if (path != "-") file.emplace(path, expected, within);
  const int fd = file ? file->fd() : STDIN_FILENO;
  const std::string name = file ? file->path() : "stdin";
  const std::size_t max_bytes = limits.bytes;
  // One byte past the limit tells a file at the limit from a larger one.
  std::string text(file ? std::min(file->size(), max_bytes) + 1 : std::min<std::size_t>(65536, max_bytes + 1), '\0');
  std::size_t used = 0;
  for (;;) {
    if (used == text.size()) {
      if (used > max_bytes) throw InputError(name, over_limit(limits, Limit::bytes));
      text.resize(std::min(2 * text.size(), max_bytes + 1));
    }
    const ssize_t n = ::read(fd, text.data() + used, text.size() - used);
    if (n > 0) {
      used += static_cast<std::size_t>(n);
    } else if (n == 0) {
      break;
    } else if (errno == EAGAIN || errno == EWOULDBLOCK) {
      pollfd p{fd, POLLIN, 0};  // standard input left non-blocking by whoever opened it
      ::poll(&p, 1, -1);
    } else if (errno != EINTR) {
      throw InputError(name, std::string(file ? "cannot read the file: " : "cannot read standard input: ") +
                                 reason(errno));
    }
  }
  if (used > max_bytes) throw InputError(name, over_limit(limits, Limit::bytes));
  text.resize(used);
  return text;
}

std::string printable_name(const std::string& name) {
  // The backslash doubled first, so that a name holding "\\x1b" and one
  // holding the escape byte stay two. Not cut: a path is at most PATH_MAX
  // (4096) bytes, and two names cut alike would be one.
  std::string doubled;
  for (const char c : name) doubled += c == '\\' ? "\\\\" : std::string(1, c);
  return one_line(doubled, std::string::npos, true);
}

}  // namespace pendulum
