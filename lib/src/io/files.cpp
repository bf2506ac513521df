#include "pendulum/files.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

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

}  // namespace

std::optional<FileId> file_id(const std::string& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) return std::nullopt;
  return FileId{st.st_dev, st.st_ino};
}

InputFile::InputFile(const std::string& path, const std::string& expected) : path_(printable_name(path)) {
  // A device is refused before it is opened (opening some has effects),
  // and what is opened is checked again.
  struct stat st;
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    throw InputError(path_, kind_of(st.st_mode) + "; expected " + expected);
  }
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
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

std::string too_large(std::size_t max_bytes) {
  return "got more than " + std::to_string(max_bytes) + " bytes; expected at most " +
         std::to_string(max_bytes >> 20) + " MiB (the limit of a scene file, a list and standard input)";
}

std::string read_text(const std::string& path, std::size_t max_bytes, const std::string& expected) {
  std::optional<InputFile> file;
  if (path != "-") file.emplace(path, expected);
  const int fd = file ? file->fd() : STDIN_FILENO;
  const std::string name = file ? file->path() : "stdin";
  // One byte past the limit tells a file at the limit from a larger one.
  std::string text(file ? std::min(file->size(), max_bytes) + 1 : 65536, '\0');
  std::size_t used = 0;
  for (;;) {
    if (used == text.size()) {
      if (used > max_bytes) throw InputError(name, too_large(max_bytes));
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
  if (used > max_bytes) throw InputError(name, too_large(max_bytes));
  text.resize(used);
  return text;
}

std::string printable_name(const std::string& name) {
  static const char hex[] = "0123456789abcdef";
  std::string out;
  for (std::size_t i = 0; i < name.size();) {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    const std::size_t length = c < 0x20 || c == 0x7f || c == '\\' ? 0 : printable_utf8_length(name, i);
    if (c == '\\') {
      out += "\\\\";
    } else if (!length) {
      out += {'\\', 'x', hex[c >> 4], hex[c & 15]};
    }
    out.append(name, i, length);
    i += length ? length : 1;
  }
  return out;
}

}  // namespace pendulum
