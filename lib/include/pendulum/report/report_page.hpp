#pragma once
/// \file report_page.hpp
/// \brief `pendulum-g report`'s page (docs/report.md): a scene or a recording
/// read, reduced and drawn as one HTML page or one SVG plot.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "pendulum/analysis.hpp"
#include "pendulum/files.hpp"
#include "pendulum/recordings/swings.hpp"

namespace pendulum::report {

/// What to report on, and how.
struct ReportRequest {
  std::string file;                 ///< a scene file, a recording, or "-" (standard input, or `text`)
  std::optional<std::string> text;  ///< the scene's text, read instead of `file`
  std::optional<std::string> directory;  ///< where a `text` scene's recordings are; default: file's folder
  bool allow_outside = false;            ///< --allow-outside
  GivenLimits limits;                    ///< --max-bytes, --max-rows, --max-columns
  std::optional<RecordingFormat> family;  ///< the input is a recording of this family (--format)
  std::string plot;                       ///< empty: the HTML page; else this one SVG plot (--plot)
  AnalysisOptions analysis;
  SwingOptions swing;   ///< a recording's analysis
  std::string set;      ///< --set
  std::string columns;  ///< --columns
};

/// The page and the warnings of the scene and of its analysis, in that order.
struct ReportPage {
  std::string text;
  std::vector<std::string> warnings;
};

/// A recording, not a scene: a regular file (a pipe is not read ahead) whose
/// text does not open a JSON object or array and has three lines or more (no
/// recording has fewer; a short or empty file gets the scene reader's
/// message, as from reduce) and is no table of settings and periods (the
/// scene reader's message says to import it).
bool looks_like_recording(const std::string& file);

/// The report of `request`: a recording's when request.family is set or the
/// file looks like one, else the scene's. `check_recordings` is called with
/// the files a scene names (recordings, tables; scene_file_names()) before
/// any of them is read (the CLI refuses an output that would replace one).
/// Throws InputError.
ReportPage make_report_page(const ReportRequest& request,
                            const std::function<void(const std::vector<std::string>&)>& check_recordings = {});

}  // namespace pendulum::report
