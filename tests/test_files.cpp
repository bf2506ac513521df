// Opening and reading the files pendulum-g is given (pendulum/files.hpp,
// docs/robustness.md "Files and processes"): names escaped and kept apart,
// the read limit at its exact edge, pipes refused without waiting.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "pendulum/files.hpp"
#include "pendulum/input_error.hpp"

using Catch::Matchers::Contains;

namespace {

std::string temporary_name() {
  char name[] = "/tmp/pendulum-g-files-XXXXXX";
  const int fd = mkstemp(name);
  REQUIRE(fd >= 0);
  close(fd);
  return name;
}

}  // namespace

TEST_CASE("printable_name escapes what is not printable UTF-8 and keeps names apart", "[files]") {
  using pendulum::printable_name;
  CHECK(printable_name("class/a.json") == "class/a.json");
  CHECK(printable_name("\xce\xb8.csv") == "\xce\xb8.csv");  // θ stays θ
  CHECK(printable_name("new\nline") == "new\\x0aline");
  CHECK(printable_name("\x1b[2J") == "\\x1b[2J");
  CHECK(printable_name("del\x7f") == "del\\x7f");
  // C1 controls, valid UTF-8 but read by a terminal as ESC [ is (U+009B CSI).
  CHECK(printable_name("\xc2\x9b" "2J") == "\\xc2\\x9b" "2J");
  CHECK(printable_name("\xc2\x80") == "\\xc2\\x80");
  CHECK(printable_name("\xc2\xa0") == "\xc2\xa0");  // U+00A0, the first after them, kept
  // RFC 3629's ill-formed sequences: a lone continuation byte, an overlong
  // "/" (C0 AF), a surrogate (ED A0 80), beyond U+10FFFF (F4 90 80 80), a
  // sequence cut short (E2 82).
  CHECK(printable_name("\x80") == "\\x80");
  CHECK(printable_name("\xc0\xaf") == "\\xc0\\xaf");
  CHECK(printable_name("\xed\xa0\x80") == "\\xed\\xa0\\x80");
  CHECK(printable_name("\xf4\x90\x80\x80") == "\\xf4\\x90\\x80\\x80");
  CHECK(printable_name("\xe2\x82") == "\\xe2\\x82");
  CHECK(printable_name("\xf4\x8f\xbf\xbf") == "\xf4\x8f\xbf\xbf");  // U+10FFFF, the last code point
  // Two names stay two: the backslash is escaped too, so the four bytes
  // "\xff" and the byte 0xff differ.
  CHECK(printable_name("\xff") != printable_name("\xfe"));
  CHECK(printable_name("\\xff") == "\\\\xff");
  CHECK(printable_name("\\xff") != printable_name("\xff"));
}

TEST_CASE("read_text takes a file of exactly the limit and refuses one byte more", "[files]") {
  const std::string file = temporary_name();
  constexpr pendulum::InputLimits kLimit{1024, 0, 0, "a test"};
  std::ofstream(file, std::ios::binary) << std::string(kLimit.bytes, 'x');
  CHECK(pendulum::read_text(file, kLimit, "a scene file").size() == kLimit.bytes);
  std::ofstream(file, std::ios::binary) << std::string(kLimit.bytes + 1, 'x');
  CHECK_THROWS_WITH(pendulum::read_text(file, kLimit, "a scene file"),
                    file + ": got more than 1024 bytes; expected at most 1024 in a test (--max-bytes raises the limit)");
  std::remove(file.c_str());
  CHECK_THROWS_WITH(pendulum::read_text(file, kLimit, "a scene file"),
                    Contains("cannot open the file: No such file or directory"));
}

TEST_CASE("A named pipe, a device or a folder is refused without being read", "[files]") {
  const std::string fifo = temporary_name();
  std::remove(fifo.c_str());
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  // No writer: a blocking open would never return.
  CHECK_THROWS_WITH(pendulum::InputFile(fifo, "a scene file"),
                    fifo + ": not a regular file (a named pipe); expected a scene file");
  std::remove(fifo.c_str());
  CHECK_THROWS_WITH(pendulum::InputFile("/dev/zero", "a recording file"),
                    "/dev/zero: not a regular file (a device); expected a recording file");
  CHECK_THROWS_WITH(pendulum::InputFile("/tmp", "a scene file"), "/tmp: a directory; expected a scene file");
}

TEST_CASE("file_id is one file's through every link", "[files]") {
  const std::string file = temporary_name();
  const std::string hard = file + "-hard", soft = file + "-soft";
  REQUIRE(link(file.c_str(), hard.c_str()) == 0);
  REQUIRE(symlink(file.c_str(), soft.c_str()) == 0);
  const auto id = pendulum::file_id(file);
  REQUIRE(id);
  CHECK(pendulum::file_id(hard) == id);
  CHECK(pendulum::file_id(soft) == id);
  CHECK_FALSE(pendulum::file_id("/tmp") == id);
  for (const auto& f : {file, hard, soft}) std::remove(f.c_str());
  CHECK_FALSE(pendulum::file_id(file));
}

TEST_CASE("A file opened within a folder cannot be led out of it at the open", "[files]") {
  // What a scene's recording check sees by name can change before the open
  // (a link swapped in): the open itself must stay beneath the folder.
  char made[] = "/tmp/pendulum-g-within-XXXXXX";
  REQUIRE(mkdtemp(made));
  const std::string folder = made, outside = folder + "-outside.tsv";
  std::ofstream(outside) << "t\n";
  std::ofstream(folder + "/inside.tsv") << "t\n";
  REQUIRE(mkdir((folder + "/sub").c_str(), 0700) == 0);
  REQUIRE(symlink("../inside.tsv", (folder + "/sub/up.tsv").c_str()) == 0);  // leads up, stays inside
  REQUIRE(symlink(outside.c_str(), (folder + "/absolute.tsv").c_str()) == 0);
  REQUIRE(symlink(("../" + outside.substr(outside.rfind('/') + 1)).c_str(), (folder + "/relative.tsv").c_str()) == 0);
  CHECK(pendulum::InputFile(folder + "/inside.tsv", "a recording file", folder).size() == 2);
  CHECK(pendulum::InputFile(folder + "/sub/up.tsv", "a recording file", folder).size() == 2);
  for (const char* link : {"/absolute.tsv", "/relative.tsv"}) {
    CHECK_THROWS_WITH(pendulum::InputFile(folder + link, "a recording file", folder),
                      folder + link + ": a symbolic link (or a name) leads out of the folder " + folder +
                          "; expected a file in it or below: a scene's files are read from elsewhere only with "
                          "--allow-outside");
    CHECK(pendulum::InputFile(folder + link, "a recording file").size() == 2);  // unconfined, it opens
  }
  CHECK_THROWS_WITH(pendulum::InputFile(folder + "/../x.tsv", "a recording file", folder),
                    Contains("leads out of the folder"));
  for (const char* name : {"/sub/up.tsv", "/absolute.tsv", "/relative.tsv", "/inside.tsv"}) std::remove((folder + name).c_str());
  rmdir((folder + "/sub").c_str());
  rmdir(folder.c_str());
  std::remove(outside.c_str());
}
