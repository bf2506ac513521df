#pragma once
/// \file html_report.hpp
/// \brief One self-contained HTML page: inline CSS and SVG, no script, no
/// external resource, the same bytes for the same input (docs/report.md).
/// The markup is also well-formed XML, so that xmllint checks it.

#include <optional>
#include <string>
#include <vector>

#include "pendulum/report/scene_report.hpp"

namespace pendulum::report {

/// The report of one scene.
std::string scene_report_html(const SceneReport& r);

/// The report of one recording: what was read, the period, the signal with
/// its crossings, the amplitudes with the decay fit, and the period against
/// the amplitude.
std::string recording_report_html(const RecordingRecord& r);

/// One scene of a class: its report, or why it failed.
struct ClassEntry {
  std::string input;
  std::optional<SceneReport> report;
  std::string error;  ///< when report is empty
};

/// The class at a glance (every g against the expected g, sorted; z-scores;
/// the files that failed and why), then each scene's own section, linked
/// from its row.
std::string class_report_html(const std::vector<ClassEntry>& entries);

}  // namespace pendulum::report
