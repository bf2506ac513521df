#include "zip.hpp"

#include <zip.h>

#include <algorithm>
#include <memory>
#include <vector>

#include "pendulum/input_error.hpp"
#include "../text.hpp"

namespace pendulum {

namespace {

bool ends_with_csv(const std::string& name) {
  return name.size() >= 4 && lower_case(name.substr(name.size() - 4)) == ".csv";
}

/// Lower rank, better pendulum signal: a rate turns with the pendulum.
int rank(SignalKind kind) {
  switch (kind) {
    case SignalKind::angular_rate: return 0;
    case SignalKind::linear_acceleration: return 1;
    case SignalKind::acceleration: return 2;
    default: return 3;
  }
}

struct Entry {
  zip_uint64_t index;
  std::string name;
  zip_uint64_t size;  ///< uncompressed, as the archive states it
};

}  // namespace

bool looks_like_zip(std::string_view bytes) {
  return bytes.substr(0, 4) == std::string_view("PK\x03\x04", 4) || bytes.substr(0, 4) == std::string_view("PK\x05\x06", 4);
}

Recording read_zip_recording(std::string_view bytes, const std::string& file, RecordingFormat format,
                             const std::string& set, const RecordingLimits& limits) {
  zip_error_t error;
  zip_error_init(&error);
  auto fail = [&](const std::string& message) {
    zip_error_fini(&error);
    throw InputError(file, message);
  };
  auto damaged = [&](const char* why) {
    fail(std::string("a damaged zip archive (") + why + "); expected phyphox's zip export, whole");
  };
  zip_source_t* source = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
  if (!source) damaged(zip_error_strerror(&error));
  // The archive owns the source once it is open.
  std::unique_ptr<zip_t, void (*)(zip_t*)> archive(zip_open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error),
                                                    zip_discard);
  if (!archive) {
    zip_source_free(source);
    damaged(zip_error_strerror(&error));
  }

  // The candidate sets: CSV files outside meta/ (phyphox's device and time tables).
  std::vector<Entry> sets;
  std::string names;  // every candidate's, for a set asked for that is not there
  const zip_int64_t count = zip_get_num_entries(archive.get(), 0);
  for (zip_int64_t i = 0; i < count; ++i) {
    zip_stat_t st;
    zip_stat_init(&st);
    if (zip_stat_index(archive.get(), static_cast<zip_uint64_t>(i), 0, &st) != 0 ||
        !(st.valid & ZIP_STAT_NAME) || !(st.valid & ZIP_STAT_SIZE)) {
      damaged(zip_error_strerror(zip_get_error(archive.get())));
    }
    const std::string name = st.name;
    if (name.rfind("meta/", 0) == 0 || !ends_with_csv(name)) continue;
    if (names.size() < 300) names += (names.empty() ? "\"" : ", \"") + one_line(name, 80, true) + "\"";
    // A set asked for in any case, with or without ".csv": "gyroscope" is Gyroscope.csv.
    if (!set.empty() && lower_case(name) != lower_case(set) && lower_case(name) != lower_case(set) + ".csv") continue;
    sets.push_back({static_cast<zip_uint64_t>(i), name, st.size});
  }
  if (sets.empty()) {
    fail(set.empty() ? "a zip archive with no CSV set outside meta/; expected phyphox's zip export "
                       "(Gyroscope.csv, Accelerometer.csv, ...)"
                     : "a zip archive with no set \"" + one_line(set, 80, true) + "\"; expected one of its CSV sets: " + names);
  }
  // Stated sizes first: a zip bomb is refused before anything is unpacked.
  zip_uint64_t total = 0;
  for (const Entry& e : sets) total += std::min<zip_uint64_t>(e.size, limits.max_bytes + 1);
  if (total > limits.max_bytes) {
    fail("a zip archive whose sets unpack to over " + std::to_string(limits.max_bytes) +
         " bytes (RecordingLimits::max_bytes; a zip bomb?); expected a recording that fits");
  }

  std::vector<Recording> read;  // the sets that read, in the archive's order
  std::vector<RecordingNote> unread;
  std::string refused;
  for (const Entry& e : sets) {
    const std::string name = file + "/" + one_line(e.name, 80, true);
    std::string text(e.size, '\0');
    std::unique_ptr<zip_file_t, int (*)(zip_file_t*)> in(zip_fopen_index(archive.get(), e.index, 0), zip_fclose);
    // One byte more than stated: a set longer than its header says is damaged too.
    char extra;
    if (!in || zip_fread(in.get(), text.data(), e.size) != static_cast<zip_int64_t>(e.size) ||
        zip_fread(in.get(), &extra, 1) != 0) {
      const char* why = in ? zip_file_strerror(in.get()) : zip_error_strerror(zip_get_error(archive.get()));
      fail("a damaged zip archive (" + one_line(e.name, 80, true) + ": " + why + "); expected phyphox's zip export, whole");
    }
    try {
      read.push_back(parse_recording(text, name, format));
      read.back().set = e.name;
    } catch (const InputError& bad) {
      if (!set.empty()) throw;  // the set asked for: its own error
      if (refused.size() < 400) refused += std::string(refused.empty() ? "" : "; ") + bad.what();
      unread.push_back({0, "the set \"" + one_line(e.name, 80, true) + "\" is not used: " + one_line(bad.what(), 200)});
    }
  }
  if (read.empty()) fail("a zip archive with no set that reads as a recording (" + refused + ")");
  zip_error_fini(&error);
  std::stable_sort(read.begin(), read.end(), [](const Recording& a, const Recording& b) { return rank(a.kind) < rank(b.kind); });
  // The sets are the candidates, the others handed on as parsed (analyse_candidates
  // compares them without unpacking them again); a set's own columns cannot be declared in a zip.
  const auto what = [](const Recording& r) { return "the set \"" + one_line(r.set, 80, true) + "\""; };
  Recording best = std::move(read.front());
  if (read.size() > 1) {
    best.candidates.push_back({what(best), "", best.set});
    for (auto r = read.begin() + 1; r != read.end(); ++r) {
      best.candidates.push_back({what(*r), "", r->set, std::make_shared<const Recording>(std::move(*r))});
    }
  }
  best.notes.insert(best.notes.end(), unread.begin(), unread.end());
  return best;
}

}  // namespace pendulum
