#include "zip.hpp"

#include <zip.h>

#include <algorithm>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "pendulum/input_error.hpp"
#include "../text.hpp"
#include "stages.hpp"

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

/// The sets of an archive or an experiment file as they are parsed one by
/// one: those that read, in order, and a note for each that does not.
struct Sets {
  std::vector<Recording> read;
  std::vector<RecordingNote> unread;
  std::string refused;  ///< their errors, for a file of which none reads

  /// Parses the set `name` (its text), unless `wanted` names another; the
  /// set asked for throws its own error.
  void add(std::string_view text, const std::string& name, const std::string& file, RecordingFormat format,
           const std::string& wanted, const InputLimits& limits = kRecordingInput) {
    try {
      read.push_back(parse_recording(text, file + "/" + one_line(name, 80, true), format, {}, {}, limits));
      read.back().set = name;
    } catch (const InputError& bad) {
      if (!wanted.empty()) throw;
      if (refused.size() < 400) refused += std::string(refused.empty() ? "" : "; ") + bad.what();
      unread.push_back({0, "the set \"" + one_line(name, 80, true) + "\" is not used: " + one_line(bad.what(), 200)});
    }
  }

  /// The set with the best signal (rank), the others its candidates, handed
  /// on as parsed (analyse_candidates compares them without reading them
  /// again); a set's own columns cannot be declared.
  Recording best() {
    std::stable_sort(read.begin(), read.end(), [](const Recording& a, const Recording& b) { return rank(a.kind) < rank(b.kind); });
    const auto what = [](const Recording& r) { return "the set \"" + one_line(r.set, 80, true) + "\""; };
    Recording out = std::move(read.front());
    if (read.size() > 1) {
      out.candidates.push_back({what(out), "", out.set});
      for (auto r = read.begin() + 1; r != read.end(); ++r) {
        out.candidates.push_back({what(*r), "", r->set, std::make_shared<const Recording>(std::move(*r))});
      }
    }
    out.notes.insert(out.notes.end(), unread.begin(), unread.end());
    return out;
  }
};

struct Entry {
  zip_uint64_t index;
  std::string name;
  zip_uint64_t size;  ///< uncompressed, as the archive states it
};

/// A zip archive opened over bytes in memory; `whole` says what it should
/// have been ("phyphox's zip export"), for the message of a damaged one.
class Archive {
 public:
  Archive(std::string_view bytes, const std::string& file, std::string whole)
      : file_(file), whole_(std::move(whole)), archive_(nullptr, zip_discard) {
    zip_error_t error;
    zip_error_init(&error);
    zip_source_t* source = zip_source_buffer_create(bytes.data(), bytes.size(), 0, &error);
    if (source) {
      // The archive owns the source once it is open.
      archive_.reset(zip_open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error));
      if (!archive_) zip_source_free(source);
    }
    const std::string why = zip_error_strerror(&error);
    zip_error_fini(&error);
    if (!archive_) damaged(why);
  }

  /// Every entry, in the archive's order.
  std::vector<Entry> entries() const {
    std::vector<Entry> out;
    const zip_int64_t count = zip_get_num_entries(archive_.get(), 0);
    for (zip_int64_t i = 0; i < count; ++i) {
      zip_stat_t st;
      zip_stat_init(&st);
      if (zip_stat_index(archive_.get(), static_cast<zip_uint64_t>(i), 0, &st) != 0 ||
          !(st.valid & ZIP_STAT_NAME) || !(st.valid & ZIP_STAT_SIZE)) {
        damaged(zip_error_strerror(zip_get_error(archive_.get())));
      }
      out.push_back({static_cast<zip_uint64_t>(i), st.name, st.size});
    }
    return out;
  }

  /// The entry unpacked; one byte more than stated is damage too.
  std::string read(const Entry& e) const {
    std::string text(e.size, '\0');
    std::unique_ptr<zip_file_t, int (*)(zip_file_t*)> in(zip_fopen_index(archive_.get(), e.index, 0), zip_fclose);
    char extra;
    if (!in || zip_fread(in.get(), text.data(), e.size) != static_cast<zip_int64_t>(e.size) ||
        zip_fread(in.get(), &extra, 1) != 0) {
      const char* why = in ? zip_file_strerror(in.get()) : zip_error_strerror(zip_get_error(archive_.get()));
      damaged(one_line(e.name, 80, true) + ": " + why);
    }
    return text;
  }

  [[noreturn]] void fail(const std::string& message) const { throw InputError(file_, message); }

 private:
  [[noreturn]] void damaged(const std::string& why) const {
    fail("a damaged zip archive (" + why + "); expected " + whole_ + ", whole");
  }
  std::string file_, whole_;
  std::unique_ptr<zip_t, void (*)(zip_t*)> archive_;
};

}  // namespace

bool looks_like_zip(std::string_view bytes) {
  return bytes.substr(0, 4) == std::string_view("PK\x03\x04", 4) || bytes.substr(0, 4) == std::string_view("PK\x05\x06", 4);
}

Recording read_zip_recording(std::string_view bytes, const std::string& file, RecordingFormat format,
                             const std::string& set, const RecordingLimits& limits) {
  const Archive archive(bytes, file, "phyphox's zip export");
  // The candidate sets: CSV files outside meta/ (phyphox's device and time tables).
  std::vector<Entry> sets;
  std::string names;  // every candidate's, for a set asked for that is not there
  for (const Entry& e : archive.entries()) {
    if (e.name.rfind("meta/", 0) == 0 || !ends_with_csv(e.name)) continue;
    if (names.size() < 300) names += (names.empty() ? "\"" : ", \"") + one_line(e.name, 80, true) + "\"";
    // A set asked for in any case, with or without ".csv": "gyroscope" is Gyroscope.csv.
    if (!set.empty() && lower_case(e.name) != lower_case(set) && lower_case(e.name) != lower_case(set) + ".csv") continue;
    sets.push_back(e);
  }
  if (sets.empty()) {
    archive.fail(set.empty() ? "a zip archive with no CSV set outside meta/; expected phyphox's zip export "
                               "(Gyroscope.csv, Accelerometer.csv, ...) or a spreadsheet (.xlsx)"
                             : "a zip archive with no set \"" + one_line(set, 80, true) + "\"; expected one of its CSV sets: " + names);
  }
  // Stated sizes first: a zip bomb is refused before anything is unpacked.
  zip_uint64_t total = 0;
  for (const Entry& e : sets) total += std::min<zip_uint64_t>(e.size, limits.input.bytes + 1);
  if (total > limits.input.bytes) archive.fail("a zip archive whose sets unpack (a zip bomb?): " + over_limit(limits.input, Limit::bytes));
  Sets read;  // in the archive's order
  for (const Entry& e : sets) read.add(archive.read(e), e.name, file, format, set, limits.input);
  if (read.read.empty()) archive.fail("a zip archive with no set that reads as a recording (" + read.refused + ")");
  return read.best();
}

namespace {

/// A code point as UTF-8 (U+FFFD for none: a surrogate or beyond U+10FFFF).
std::string utf8(unsigned long c) {
  if (c >= 0xD800 && (c < 0xE000 || c > 0x10FFFF)) c = 0xFFFD;
  std::string out;
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6)), out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12)), out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18)), out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F)), out += static_cast<char>(0x80 | (c & 0x3F));
  }
  return out;
}

/// The text of the XML element or attribute value [p, e) with its five
/// predefined entities and numeric character references (&#76;, &#x4C;) decoded.
std::string xml_text(std::string_view s) {
  static const std::pair<std::string_view, char> kEntities[] = {
      {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&apos;", '\''}};
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto entity = std::find_if(std::begin(kEntities), std::end(kEntities),
                                     [&](const auto& en) { return s.substr(i, en.first.size()) == en.first; });
    const std::size_t end = s.substr(i, 2) == "&#" ? s.find(';', i) : std::string_view::npos;
    if (entity != std::end(kEntities)) {
      out += entity->second;
      i += entity->first.size() - 1;
    } else if (end != std::string_view::npos && end - i <= 10) {
      const bool hex = s.substr(i + 2, 1) == "x" || s.substr(i + 2, 1) == "X";
      const std::string digits(s.substr(i + (hex ? 3 : 2), end - i - (hex ? 3 : 2)));
      char* stop = nullptr;
      const unsigned long c = std::strtoul(digits.c_str(), &stop, hex ? 16 : 10);
      out += !digits.empty() && *stop == '\0' ? utf8(c) : std::string(s.substr(i, end + 1 - i));
      i = end;
    } else {
      out += s[i];
    }
  }
  return out;
}

/// The value of attribute `name` in the start tag `tag` ("<set name=...>"), or nullopt.
std::optional<std::string> attribute(std::string_view tag, std::string_view name) {
  for (std::size_t at = tag.find(name); at != std::string_view::npos; at = tag.find(name, at + 1)) {
    const std::size_t quote = at + name.size() + 2;  // after name="
    if (at > 0 && tag[at - 1] == ' ' && tag.substr(at + name.size(), 2) == "=\"") {
      const std::size_t end = tag.find('"', quote);
      if (end != std::string_view::npos) return xml_text(tag.substr(quote, end - quote));
    }
  }
  return std::nullopt;
}

/// Each element `<element ...>text</element>` of `xml` in order: its start
/// tag and its text, decoded unless `raw` (which keeps the elements inside
/// it for a search of their own).
std::vector<std::pair<std::string_view, std::string>> elements(std::string_view xml, std::string_view element,
                                                               bool raw = false) {
  std::vector<std::pair<std::string_view, std::string>> out;
  const std::string open = "<" + std::string(element), close = "</" + std::string(element) + ">";
  for (std::size_t at = xml.find(open); at != std::string_view::npos; at = xml.find(open, at + 1)) {
    const std::size_t tag_end = xml.find('>', at);
    if (tag_end == std::string_view::npos) break;
    const char after = xml[at + open.size()];
    if (after != ' ' && after != '>' && after != '/') continue;  // <data-containers> is no <data>
    const std::string_view tag = xml.substr(at, tag_end + 1 - at);
    const std::size_t end = xml[tag_end - 1] == '/' ? tag_end : xml.find(close, tag_end);  // <x/> holds no text
    if (end == std::string_view::npos) break;
    const std::string_view inner = end == tag_end ? std::string_view() : xml.substr(tag_end + 1, end - tag_end - 1);
    out.emplace_back(tag, raw ? std::string(inner) : xml_text(recording_text::trim_cell(inner)));
  }
  return out;
}

}  // namespace

bool looks_like_phyphox_experiment(std::string_view bytes) {
  const std::string_view head = bytes.substr(0, 1024);
  return head.find("<phyphox") != std::string_view::npos;
}

Recording read_phyphox_experiment(std::string_view xml, const std::string& file, RecordingFormat format,
                                  const std::string& set) {
  // The buffers: <container ... init="v1,v2,...">name</container>.
  std::vector<std::pair<std::string, std::string_view>> buffers;
  std::vector<std::string> inits;
  for (const auto& [tag, name] : elements(xml, "container")) {
    if (auto init = attribute(tag, "init")) inits.push_back(std::move(*init)), buffers.emplace_back(name, std::string_view());
  }
  for (std::size_t k = 0; k < buffers.size(); ++k) buffers[k].second = inits[k];
  const auto buffer = [&](const std::string& name) {
    const auto b = std::find_if(buffers.begin(), buffers.end(), [&](const auto& x) { return x.first == name; });
    return b == buffers.end() ? std::optional<std::string_view>() : b->second;
  };
  // The sets of its export, each a CSV of its buffers side by side, as phyphox's own export writes them.
  const std::size_t export_at = xml.find("<export");
  if (export_at == std::string_view::npos) {
    throw InputError(file, "a phyphox experiment file without an <export> of its data; expected one saved after a "
                           "measurement (phyphox: save the experiment state)");
  }
  Sets read;
  std::string names;
  const std::string_view exported = xml.substr(export_at);
  const auto sets = elements(exported, "set");
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const std::string name = attribute(sets[k].first, "name").value_or("set " + std::to_string(k + 1));
    if (names.size() < 300) names += (names.empty() ? "\"" : ", \"") + one_line(name, 80, true) + "\"";
    if (!set.empty() && lower_case(name) != lower_case(set)) continue;
    const std::size_t from = static_cast<std::size_t>(sets[k].first.data() - exported.data());  // its own tag's place
    const std::string_view body = exported.substr(from, exported.find("</set>", from) - from);
    std::vector<std::string> header;
    std::vector<std::vector<std::string_view>> columns;
    for (const auto& [tag, buffer_name] : elements(body, "data")) {
      const auto values = buffer(buffer_name);
      if (!values) continue;
      header.push_back("\"" + attribute(tag, "name").value_or(buffer_name) + "\"");
      columns.push_back(recording_text::split_cells(*values, recording_text::Dialect{',', false}));
    }
    std::size_t rows = columns.empty() ? 0 : columns[0].size();
    for (const auto& c : columns) rows = std::min(rows, c.size());
    std::string text;
    for (std::size_t j = 0; j < header.size(); ++j) text += (j ? "," : "") + header[j];
    text += '\n';
    for (std::size_t i = 0; i < rows; ++i) {
      for (std::size_t j = 0; j < columns.size(); ++j) (text += j ? "," : "") += columns[j][i];
      text += '\n';
    }
    read.add(text, name, file, format, set);
  }
  if (read.read.empty()) {
    throw InputError(file, set.empty() || names.empty()
                               ? "a phyphox experiment file with no exported set that reads as a recording (" +
                                     (read.refused.empty() ? std::string("no sets") : read.refused) + ")"
                               : "a phyphox experiment file with no set \"" + one_line(set, 80, true) +
                                     "\"; expected one of its sets: " + names);
  }
  return read.best();
}

namespace {

/// The column of a cell reference ("AB12" -> 27), from 0.
std::size_t column_of(std::string_view reference) {
  std::size_t column = 0;
  for (char c : reference) {
    if (c < 'A' || c > 'Z') break;
    column = column * 26 + static_cast<std::size_t>(c - 'A' + 1);
  }
  return column == 0 ? 0 : column - 1;
}

/// A cell as CSV writes it: a line break, a tab or a semicolon as a space
/// (the CSV's delimiter is sniffed again: a header cell "t10<LF>(s)" is one
/// header's words), quoted where it holds a comma or a quote.
std::string csv_cell(std::string text) {
  for (char& c : text) {
    if (c == '\r' || c == '\n' || c == '\t' || c == ';') c = ' ';
  }
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

/// The text of a shared string or an inline one: its <t> runs together as
/// written (spaces kept), without the phonetic runs (<rPh>) beside them.
std::string runs_of(std::string_view raw) {
  std::string text(raw);
  for (std::size_t at = text.find("<rPh"); at != std::string::npos; at = text.find("<rPh", at)) {
    const std::size_t end = text.find("</rPh>", at);
    text.erase(at, end == std::string::npos ? std::string::npos : end + 6 - at);
  }
  std::string out;
  for (const auto& [tag, inner] : elements(text, "t", true)) out += xml_text(inner);
  return out;
}

}  // namespace

bool looks_like_xlsx(std::string_view bytes) {
  // Entry names stand uncompressed in the local headers.
  return looks_like_zip(bytes) && bytes.find("xl/workbook.xml") != std::string_view::npos;
}

std::string xlsx_sheet_csv(std::string_view bytes, const std::string& file, const std::string& sheet,
                           std::size_t max_bytes) {
  const Archive archive(bytes, file, "a spreadsheet (.xlsx)");
  const std::vector<Entry> entries = archive.entries();
  auto part = [&](const std::string& name, bool required) -> std::string {
    const auto e = std::find_if(entries.begin(), entries.end(), [&](const Entry& x) { return x.name == name; });
    if (e == entries.end()) {
      if (required) archive.fail("a spreadsheet without " + name + "; expected an .xlsx file as Excel or LibreOffice saves it");
      return {};
    }
    if (e->size > max_bytes) {
      archive.fail("a spreadsheet whose " + name + " unpacks to " + std::to_string(e->size) + " bytes, over " +
                   std::to_string(max_bytes) + " (a zip bomb?); expected a table that fits");
    }
    return archive.read(*e);
  };
  // The sheets in the workbook's order, and where each is stored.
  const std::string workbook = part("xl/workbook.xml", true), rels = part("xl/_rels/workbook.xml.rels", true);
  struct Sheet {
    std::string name, target;
  };
  std::vector<Sheet> sheets;
  std::string names;
  for (const auto& [tag, text] : elements(workbook, "sheet")) {
    const auto name = attribute(tag, "name"), id = attribute(tag, "r:id");
    if (!name || !id) continue;
    std::string target;
    for (const auto& [rel, unused] : elements(rels, "Relationship")) {
      if (attribute(rel, "Id") == id) target = attribute(rel, "Target").value_or("");
    }
    target = target.rfind('/', 0) == 0 ? target.substr(1) : "xl/" + target;
    sheets.push_back({*name, target});
    names += (names.empty() ? "\"" : ", \"") + one_line(*name, 40, true) + "\"";
  }
  if (sheets.empty()) archive.fail("a spreadsheet with no sheet; expected one holding the table");
  // The sheet asked for by its name (any case) or its number from 1; the first by default.
  auto chosen = sheets.begin();
  if (!sheet.empty()) {
    chosen = std::find_if(sheets.begin(), sheets.end(), [&](const Sheet& x) { return lower_case(x.name) == lower_case(sheet); });
    const std::size_t number = sheet.find_first_not_of("0123456789") == std::string::npos && sheet.size() < 4 ? std::stoul(sheet) : 0;
    if (chosen == sheets.end() && number >= 1 && number <= sheets.size()) chosen = sheets.begin() + static_cast<long>(number - 1);
    if (chosen == sheets.end()) {
      archive.fail("a spreadsheet with no sheet \"" + one_line(sheet, 40, true) + "\"; expected one of " + names +
                   " (or its number from 1)");
    }
  }
  // Each part held while its elements' views into it are read.
  const std::string strings = part("xl/sharedStrings.xml", false), sheet_xml = part(chosen->target, true);
  std::vector<std::string> shared;
  for (const auto& [tag, raw] : elements(strings, "si", true)) shared.push_back(runs_of(raw));
  // Its cells by row and column: a formula's cached value, a shared or inline string, a number.
  std::vector<std::vector<std::string>> rows;
  std::vector<bool> used;
  std::size_t first_row = 0;  // the sheet's number of the first row that holds a cell
  for (const auto& [row_tag, row] : elements(sheet_xml, "row", true)) {
    std::vector<std::string> cells;
    std::size_t next = 0;  // a cell without its reference (optional) follows the one before
    for (const auto& [tag, raw] : elements(row, "c", true)) {
      const auto reference = attribute(tag, "r");
      const std::size_t column = reference ? column_of(*reference) : next;
      next = column + 1;
      if (column >= 16384) continue;  // beyond Excel's XFD
      const std::string type = attribute(tag, "t").value_or("n");
      const auto v = elements(raw, "v");
      std::string text = type == "inlineStr" ? runs_of(raw) : v.empty() ? std::string() : v.front().second;
      if (type == "s") {
        const bool index = !text.empty() && text.size() <= 9 && text.find_first_not_of("0123456789") == std::string::npos;
        const std::size_t k = index ? std::stoul(text) : shared.size();
        text = k < shared.size() ? shared[k] : std::string();
      } else if (type == "e") {
        text.clear();  // #DIV/0! and the like: no value
      }
      if (text.empty()) continue;
      if (cells.size() <= column) cells.resize(column + 1);
      if (used.size() <= column) used.resize(column + 1);
      cells[column] = text;
      used[column] = true;
    }
    if (cells.empty()) continue;  // an empty row stands for nothing
    if (rows.empty()) {
      const std::string r = attribute(row_tag, "r").value_or("1");
      first_row = r.find_first_not_of("0123456789") == std::string::npos && r.size() < 8 ? std::stoul(r) : 1;
    }
    rows.push_back(std::move(cells));
  }
  if (rows.empty()) archive.fail("a spreadsheet whose sheet \"" + one_line(chosen->name, 40, true) + "\" is empty; expected the table on it (choose another: " + names + ")");
  // As CSV, the columns no row uses left out; the empty rows above the
  // first as empty lines, so that a message's line is the sheet's row.
  std::string out(first_row > 1 ? std::min<std::size_t>(first_row - 1, 1000) : 0, '\n');
  for (const auto& cells : rows) {
    bool first = true;
    for (std::size_t j = 0; j < used.size(); ++j) {
      if (!used[j]) continue;
      if (!first) out += ',';
      first = false;
      if (j < cells.size()) out += csv_cell(cells[j]);
    }
    out += '\n';
  }
  return out;
}

}  // namespace pendulum
