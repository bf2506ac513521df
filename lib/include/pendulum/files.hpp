#pragma once
/// \file files.hpp
/// \brief Opening and reading the files pendulum-g is given (docs/robustness.md,
/// "Files"): without waiting (a named pipe or a device named is refused at
/// once, not read), within one limit, every error naming the file and why.

#include <sys/types.h>

#include <cstddef>
#include <optional>
#include <string>

namespace pendulum {

/// A file's device and inode: one file, whatever link or hard link names it.
struct FileId {
  dev_t device = 0;
  ino_t inode = 0;
  friend bool operator==(const FileId& a, const FileId& b) { return a.device == b.device && a.inode == b.inode; }
};

/// The file `path` names, links followed; none where nothing is there (or
/// it cannot be looked at).
std::optional<FileId> file_id(const std::string& path);

/// A regular file open for reading. Opened with O_NONBLOCK, so that a named
/// pipe without a writer cannot block, then refused unless regular (what is
/// opened is what is checked: a pipe swapped in for the file is refused too).
class InputFile {
 public:
  /// Throws InputError(path, "cannot open the file: <reason>"), or (path,
  /// "a directory; expected <expected>"), (path, "not a regular file (a
  /// named pipe ...); expected <expected>") for a pipe, device or socket.
  /// `path` in the errors as printable_name() writes it. With `within` (a
  /// folder), `path` must name a file in it or below, and the open itself
  /// stays beneath it (openat2's RESOLVE_BENEATH: no "..", no absolute
  /// name, no symbolic link leading out, at the moment of opening), so that
  /// a link swapped in after a scene's names were checked cannot lead the
  /// read elsewhere; InputError(path, "a symbolic link leads out of ...") then.
  InputFile(const std::string& path, const std::string& expected, const std::optional<std::string>& within = {});
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  int fd() const { return fd_; }
  const std::string& path() const { return path_; }
  /// Size (bytes) when opened.
  std::size_t size() const { return size_; }
  /// True when the file's size or modification time differs from when it
  /// was opened: it changed while it was read.
  bool changed() const;

 private:
  std::string path_;
  int fd_ = -1;
  std::size_t size_ = 0;
  struct timespec mtime_ {};
};

/// The most of one input read (docs/robustness.md, "Limits"): its bytes,
/// and for a recording or a table its rows and columns, each refused as
/// soon as it is passed (no more is kept than the limit), with one message
/// (over_limit()). `of` names the input in that message.
struct InputLimits {
  std::size_t bytes;
  std::size_t rows;
  std::size_t columns;
  const char* of;
};

/// A scene file, a list of scenes and standard input: a scene is a few kB,
/// and its JSON takes about 16 times its text in memory; rows and columns
/// are a table's or a recording's.
inline constexpr InputLimits kSceneInput{std::size_t{1} << 20, 0, 0, "a scene file, a list or standard input"};
/// A table of settings and periods: each of its settings is an observation
/// of a series, reduced and printed with its own budget (about 50 kB of
/// memory each), and no laboratory times 10^4 settings.
inline constexpr InputLimits kTableInput{std::size_t{1} << 28, 10000, 256, "a table"};
/// A recording: 8 hours at 500 Hz (1 GiB of text, 14.4 million rows), and
/// a PASCO or Tracker export of many runs or tracks side by side.
inline constexpr InputLimits kRecordingInput{std::size_t{1} << 30, std::size_t{1} << 24, 1024, "a recording"};

/// Which of an input's limits.
enum class Limit { bytes, rows, columns };

/// The message of an input past one of its limits: "got more than 10000
/// rows; expected at most 10000 in a table (--max-rows raises the limit)".
std::string over_limit(const InputLimits& limits, Limit which);

/// --max-bytes, --max-rows and --max-columns as a command was given them (0:
/// not given). Each raises the limit of every input the command reads to
/// it, and lowers none: a scene's 1 MiB raised to 4 MiB leaves its
/// recordings their 1 GiB (docs/robustness.md, "Limits").
struct GivenLimits {
  std::size_t bytes = 0, rows = 0, columns = 0;
  InputLimits applied_to(InputLimits defaults) const;
};

/// The text of the file `path`, or of standard input for "-", at most
/// limits.bytes: more is refused as soon as it is read, with the same
/// message whatever is read (over_limit()). Throws InputError naming `path`
/// ("stdin" for "-") and the read's error; `expected` as for InputFile.
/// `within` as for InputFile.
std::string read_text(const std::string& path, const InputLimits& limits, const std::string& expected,
                      const std::optional<std::string>& within = {});

/// A file name fit for a message or an `input` key: control characters,
/// bytes that are not UTF-8 and the backslash itself escaped (\n, \x1b,
/// \xff, \\), so that a name cannot move the terminal's cursor and two
/// names stay two.
std::string printable_name(const std::string& name);

}  // namespace pendulum
