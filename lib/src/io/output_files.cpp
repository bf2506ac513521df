// Writing what pendulum-g writes (docs/robustness.md, "Files"): outputs
// written whole or not at all, never over an input.
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <optional>

#include "pendulum/files.hpp"
#include "pendulum/output_files.hpp"

namespace pendulum {

void refuse_output_over_inputs(const std::string& output, const std::vector<std::string>& inputs) {
  if (output.empty() || output == "-") return;
  const std::optional<FileId> out = file_id(output);
  if (!out) return;  // a new file is no input
  // "-" is standard input, which may be the output's file too
  // (`report - -o x.json < x.json`); a pipe or device is no file to lose.
  const auto input_id = [](const std::string& input) -> std::optional<FileId> {
    struct stat st;
    if (input != "-") return file_id(input);
    if (::fstat(STDIN_FILENO, &st) != 0 || !S_ISREG(st.st_mode)) return std::nullopt;
    return FileId{st.st_dev, st.st_ino};
  };
  for (const auto& input : inputs) {
    if (!(input_id(input) == out)) continue;
    const std::string shown = input == "-" ? "standard input" : printable_name(input);
    throw UsageError("the output " + printable_name(output) + " is the input " + shown +
                     (output == input || input == "-" ? "" : " (the same file, through a link)") +
                     "; expected another file: writing it would replace the input");
  }
}

namespace {

/// The temporary file of the report being written, removed if the process
/// is interrupted (SIGINT, SIGTERM, SIGHUP) before it is renamed.
char temporary_name[PATH_MAX + 8];
volatile sig_atomic_t temporary_exists = 0;
constexpr int kCleanupSignals[] = {SIGINT, SIGTERM, SIGHUP};

void remove_temporary(int signal) {
  if (temporary_exists) ::unlink(temporary_name);
  ::signal(signal, SIG_DFL);
  ::raise(signal);  // the exit status says which signal ended it, as without the handler
}

/// The cleanup handlers, for the temporary file's lifetime.
struct CleanupOnSignal {
  struct sigaction previous[3];
  explicit CleanupOnSignal(const std::string& name) {
    std::snprintf(temporary_name, sizeof temporary_name, "%s", name.c_str());
    struct sigaction action {};
    action.sa_handler = remove_temporary;
    sigemptyset(&action.sa_mask);
    for (const int s : kCleanupSignals) sigaddset(&action.sa_mask, s);
    // A signal ignored (nohup's SIGHUP, SIGINT of a background job) stays
    // ignored: the handler would end the process it was meant to spare.
    for (int k = 0; k < 3; ++k) {
      ::sigaction(kCleanupSignals[k], nullptr, &previous[k]);
      const bool ignored = !(previous[k].sa_flags & SA_SIGINFO) && previous[k].sa_handler == SIG_IGN;
      if (!ignored) ::sigaction(kCleanupSignals[k], &action, nullptr);
    }
    temporary_exists = 1;
  }
  ~CleanupOnSignal() {
    temporary_exists = 0;
    for (int k = 0; k < 3; ++k) ::sigaction(kCleanupSignals[k], &previous[k], nullptr);
  }
};

}  // namespace

void write_output(const std::string& path, const std::string& text) {
  if (path == "-") {
    std::cout << text;
    return;
  }
  const std::string shown = printable_name(path);
  auto fail = [&](int error) { return OutputError("cannot write " + shown + ": " + std::strerror(error)); };
  struct stat existing;
  const bool exists = ::stat(path.c_str(), &existing) == 0;
  if (exists && S_ISDIR(existing.st_mode)) throw fail(EISDIR);
  if (exists && !S_ISREG(existing.st_mode)) {
    // A device or a pipe (/dev/stdout): written in place, never replaced;
    // without waiting for a reader of a named pipe.
    const int fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
    if (fd < 0 && errno == ENXIO) throw OutputError("cannot write " + shown + ": a named pipe that no process reads");
    if (fd < 0) throw fail(errno);
    ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);  // opened: now wait for the reader to take it
    int error = 0;
    for (std::size_t written = 0; written < text.size() && !error;) {
      const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
      if (n > 0) written += static_cast<std::size_t>(n);
      else if (n < 0 && errno != EINTR) error = errno;
      else if (n == 0) error = EIO;
    }
    if (::close(fd) != 0 && !error) error = errno;
    if (error) throw fail(error);
    return;
  }
  // A regular file: a temporary file beside it (beside the link's target for
  // a symbolic link), renamed over it once whole, so that a failure leaves no
  // partial file and an old report stays as it was.
  std::string target = path;
  if (exists) {
    if (char* resolved = ::realpath(path.c_str(), nullptr)) {
      target = resolved;
      std::free(resolved);
    }
  }
  std::string temporary = target + ".XXXXXX";
  if (temporary.size() >= PATH_MAX) throw fail(ENAMETOOLONG);
  // Signals held while the file and its cleanup come to be, so that no
  // interruption falls between the two.
  sigset_t hold, before;
  sigemptyset(&hold);
  for (const int s : kCleanupSignals) sigaddset(&hold, s);
  ::pthread_sigmask(SIG_BLOCK, &hold, &before);
  const int fd = mkstemp(temporary.data());
  const int open_error = errno;
  std::optional<CleanupOnSignal> cleanup;
  if (fd >= 0) cleanup.emplace(temporary);
  ::pthread_sigmask(SIG_SETMASK, &before, nullptr);
  if (fd < 0) throw fail(open_error);
  int error = 0;  // the first failure's errno
  for (std::size_t written = 0; written < text.size();) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error = n < 0 ? errno : EIO;
      break;
    }
    written += static_cast<std::size_t>(n);
  }
  // mkstemp makes the file 0600: a new report gets the mode the umask
  // gives (it is for others to read), a report written over keeps its own.
  // umask is read by setting it, and no other thread runs here.
  const mode_t mask = umask(0);
  umask(mask);
  const mode_t mode = exists ? existing.st_mode & 07777 : 0666 & ~mask;
  if (!error && fchmod(fd, mode) != 0) error = errno;
  if (!error && fsync(fd) != 0) error = errno;
  if (::close(fd) != 0 && !error) error = errno;
  if (!error && std::rename(temporary.c_str(), target.c_str()) != 0) error = errno;
  if (error) {
    std::remove(temporary.c_str());
    throw fail(error);
  }
}

}  // namespace pendulum
