#pragma once
/// \file status.hpp
/// \brief The verdict on a result: "ok", "suspect" (g far from the expected
/// value, or an input that betrays a slip), or "failed" (no result). Each
/// suspicion comes with a reason that names the likely slip and the input to
/// fix (docs/output.md, "Status").

#include <optional>
#include <string>
#include <vector>

#include "pendulum/analysis.hpp"
#include "pendulum/parsed_scene.hpp"
#include "pendulum/slips.hpp"

namespace pendulum {

/// g more than this many combined standard uncertainties from the site's g is suspect...
inline constexpr double kSuspectSigmas = 3.0;
/// ...and, with no site, more than this fraction from standard gravity (or
/// kSuspectSigmas of its own standard uncertainties beyond the range of g
/// on the Earth's surface).
inline constexpr double kSuspectFraction = 0.05;

/// The verdict on one analysed scene: suspect when g is more than
/// kSuspectSigmas combined standard uncertainties from the site's expected
/// g (or, when that comparison has no uncertainty or there is no site, more
/// than kSuspectFraction from it, or from standard gravity; with no site,
/// also more than kSuspectSigmas of g's own standard uncertainties outside
/// the range of g on the Earth's surface), when the bob is
/// lighter than any solid ball (a mass unit slip) or than the air, when the
/// air pressure is a hundredth or a thousandth of an atmosphere (hPa or kPa
/// written as Pa), or when an amplitude in deg reads as an ordinary lab
/// amplitude only in radians, when a decay record starts 20 times above or
/// below the scene's amplitude (the other angular unit), or when the reader
/// found a trial far from the
/// others (ParsedScene::suspicions). Otherwise ok.
struct Verdict {
  ResultStatus status = ResultStatus::ok;
  std::vector<std::string> reasons;
};
Verdict judge(const ParsedScene& scene, const Analysis& analysis);

/// A status reason (or an error) in a few words, for a table's cell: the
/// comparison of g and the slip, or the JSON path and the slip guessed:
/// "g 4.01 times the expected g: half swings are counted as oscillations",
/// "g 17.3 sigma from the expected g", "air.pressure: a barometer's 1013 hPa
/// written as Pa?". At most
/// kBriefReasonLength characters (UTF-8 code points), cut at a word with
/// "...". The full reason stays in status_reasons.
inline constexpr std::size_t kBriefReasonLength = 96;
std::string brief_reason(const std::string& reason);

}  // namespace pendulum
