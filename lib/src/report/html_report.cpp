#include "pendulum/report/html_report.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "pendulum/numeric.hpp"
#include "pendulum/json/output.hpp"
#include "pendulum/status.hpp"
#include "pendulum/report/plots.hpp"
#include "pendulum/report/svg_plot.hpp"
#include "../grouping.hpp"
#include "../text.hpp"

namespace pendulum::report {

namespace {

std::string esc(const std::string& s) { return xml_escape(s); }

/// A file or JSON path, escaped, with a break opportunity after each of
/// `after` ("/" for files): a table column then needs only its longest part.
std::string breakable(const std::string& path, const std::string& after = "/") {
  std::string s;
  for (std::size_t i = 0; i < path.size(); ++i) {
    s += esc(path.substr(i, 1));
    if (after.find(path[i]) != std::string::npos && i + 1 < path.size()) s += "<wbr/>";
  }
  return s;
}

// No url(), no @import, no font file: the page loads nothing.
constexpr const char* kStyle = R"(body { font-family: "DejaVu Sans", Verdana, Arial, sans-serif; color: #111111;
  max-width: 52rem; margin: 1.5rem auto; padding: 0 1rem; line-height: 1.45; }
h1 { font-size: 1.6rem; margin-bottom: 0.3rem; }
h2 { font-size: 1.35rem; border-bottom: 2px solid #0072B2; padding-bottom: 0.2rem; margin-top: 2.2rem; }
h3 { font-size: 1.1rem; margin-top: 1.6rem; }
p.meta { color: #333333; font-size: 0.92rem; }
p.g { font-size: 1.35rem; font-weight: bold; margin: 0.6rem 0; }
table { border-collapse: collapse; font-size: 0.88rem; margin: 0.5rem 0 1rem; }
th, td { border-bottom: 1px solid #CCCCCC; padding: 0.22rem 0.5rem; text-align: left; vertical-align: baseline; }
th { background: #F0F0F0; }
td.method { overflow-wrap: anywhere; font-size: 0.8rem; }
td.num, th.num { text-align: right; font-variant-numeric: tabular-nums; }
td.num { white-space: nowrap; }
tr.negligible td { color: #444444; }
tr.skipped td { color: #666666; font-style: italic; }
tr.failed td { color: #8B2500; }
figure { margin: 1rem 0 1.5rem; }
svg { max-width: 100%; height: auto; display: block; }
figcaption { font-size: 0.85rem; color: #333333; margin-top: 0.3rem; }
ul.warnings li { color: #8B2500; }
div.verdict { border: 2px solid #767676; border-left-width: 0.6rem; padding: 0.3rem 0.8rem; margin: 0.8rem 0; }
div.verdict.suspect { border-color: #D55E00; background: #FFF4EC; }
div.verdict.failed { border-color: #8B2500; background: #FBECE8; }
div.verdict p { margin: 0.3rem 0; }
div.verdict li { margin: 0.2rem 0; }
code { font-size: 0.9em; overflow-wrap: anywhere; }
td code { overflow-wrap: break-word; }
td.file code { display: inline-block; min-width: 8rem; overflow-wrap: anywhere; }
tr.suspect td { background: #FFF4EC; }
@media print { body { max-width: none; } section.scene { break-before: page; } h1 + section.scene { break-before: auto; }
  h2, h3 { break-after: avoid; } figure, table { break-inside: avoid; } }
)";

/// Decimals that show `u` to two significant digits (5 for none, at most 9).
int decimals_for(double u) { return decimals_for_uncertainty(u, 9); }

/// An estimate rounded to its uncertainty, as a lab report writes it:
/// "9.693 ± 0.020 m/s²"; `decimals` fixed digits where it is unknown.
std::string rounded_estimate(const Estimate& e, int decimals, const std::string& unit) {
  if (!e.uncertainty || !(*e.uncertainty > 0.0) || !std::isfinite(*e.uncertainty)) return estimate_text(e, decimals, unit);
  return value_with_uncertainty(e.value, *e.uncertainty, false) + (unit.empty() ? "" : " " + unit);
}

/// "+1.20", "−1.20", and "0.00" for what rounds to zero from either side.
std::string signed_fixed(double v, int decimals) {
  const std::string text = format_fixed(v, decimals);
  return (v > 0.0 && text.find_first_not_of("0.") != std::string::npos ? "+" : "") + text;
}

std::string optional_fixed(const std::optional<double>& v, double scale, int decimals, bool sign) {
  if (!v) return "\u2014";
  return sign ? signed_fixed(*v * scale, decimals) : format_fixed(*v * scale, decimals);
}

std::string figure_html(const std::string& svg, const std::string& caption) {
  return "<figure>\n" + svg + "<figcaption>" + esc(caption) + "</figcaption>\n</figure>\n";
}

std::string page(const std::string& title, const std::string& body) {
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n"
         "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>\n"
         "<meta name=\"generator\" content=\"pendulum-g report\"/>\n<title>" +
         esc(title) + "</title>\n<style>\n" + kStyle + "</style>\n</head>\n<body>\n" + body +
         "<footer><p class=\"meta\">Made by pendulum-g report from the numbers of pendulum-g reduce. "
         "This page is one file: it needs no network, no other file and no script.</p></footer>\n"
         "</body>\n</html>\n";
}

/// The verdict in words, first on a scene's page: the status, each reason
/// (the likely slip and the input to fix), or why the result is ok.
std::string verdict_html(const SceneReport& r) {
  std::string s = "<div class=\"verdict " + esc(r.status) + "\" role=\"status\">\n<p><strong>Status: " + esc(r.status) +
                  "</strong> \u2014 ";
  if (r.status_reasons.empty()) {
    s += r.z ? "g agrees with the expected g (z = " + signed_fixed(*r.z, 2) + ") and no input looks like a slip."
             : "no input looks like a slip (the scene gives no site to compare g with).";
    if (!r.warnings.empty()) s += " " + std::to_string(r.warnings.size()) + (r.warnings.size() == 1 ? " warning" : " warnings") + " below.";
    return s + "</p>\n</div>\n";
  }
  s += r.status_reasons.size() == 1 ? "the result below is printed, but it looks like a slip. Reason and fix:"
                                    : "the result below is printed, but it looks like a slip. Reasons and fixes:";
  s += "</p>\n<ul>\n";
  for (const auto& reason : r.status_reasons) s += "<li>" + esc(reason) + "</li>\n";
  return s + "</ul>\n</div>\n";
}

std::string g_comparison(const SceneReport& r) {
  std::string s = "<table class=\"summary\">\n";
  auto row = [&](const std::string& name, const std::string& value) {
    s += "<tr><th scope=\"row\">" + esc(name) + "</th><td>" + esc(value) + "</td></tr>\n";
  };
  if (r.expected_g) {
    std::string source = r.expected_source;
    if (!r.expected_note.empty()) source += ": " + r.expected_note;
    row("expected g", format_fixed(r.expected_g->value, 5) + " \u00B1 " + format_fixed(r.expected_g->uncertainty, 5) +
                          " m/s\u00B2 (" + source + ")");
    std::string difference = signed_fixed(r.g.value - r.expected_g->value, 5) + " m/s\u00B2";
    if (r.z) difference += " = " + signed_fixed(*r.z, 2) + " combined standard uncertainties (z)";
    row("difference", difference);
  } else {
    row("expected g", "the scene gives no site to compare with");
  }
  if (r.birge_ratio && r.g_uncertainty_unscaled) {
    row("uncertainty of g", "scaled by the Birge ratio S = " + format_fixed(*r.birge_ratio, 2) +
                                " to what the scatter supports (the observations scatter more than their stated "
                                "uncertainties allow); from the stated uncertainties alone \u00B1 " +
                                format_fixed(*r.g_uncertainty_unscaled, 5) + " m/s\u00B2");
  }
  if (r.pivot_scan) {
    row("g of the textbook curve (no corrections)",
        rounded_estimate({r.pivot_scan->textbook_g, r.pivot_scan->textbook_g_uncertainty}, 5, "m/s\u00B2"));
  } else {
    row(r.series ? "g of the textbook line (no corrections)" : "g uncorrected (Eq. 5)",
        r.g_uncorrected ? rounded_estimate(*r.g_uncorrected, 5, "m/s\u00B2")
                        : "undefined: the lengths do not determine a line");
  }
  if (r.series) return s + "</table>\n";  // the periods are in the series' table
  auto counted = [](long n, const char* one) { return std::to_string(n) + " " + one + (n == 1 ? "" : "s"); };
  row("measured period T", rounded_estimate({r.period_measured.value, r.period_measured.uncertainty}, 6, "s") + " (" +
                               counted(r.trials, "trial") + " of " +
                               counted(r.oscillations_per_trial, "oscillation") + ")");
  row("ideal period T\u2080", rounded_estimate(r.period_ideal, 6, "s"));
  return s + "</table>\n";
}

// The equations are Nelson & Olsson's unless a row names another source.
std::string short_equation(const std::string& equation) {
  const std::string prefix = "Nelson & Olsson (1986) ";
  return equation.compare(0, prefix.size(), prefix) == 0 ? equation.substr(prefix.size()) : equation;
}

std::string corrections_table(const SceneReport& r) {
  std::string s = "<p>A correction smaller than " + duration_text(r.negligible_below, 3) +
                  " (a tenth of the period's uncertainty) is negligible; it is still applied.</p>\n"
                  "<table class=\"corrections\">\n<thead><tr><th scope=\"col\">correction</th>"
                  "<th scope=\"col\" class=\"num\">\u0394T (\u00B5s)</th><th scope=\"col\" class=\"num\">u(\u0394T) (\u00B5s)</th>"
                  "<th scope=\"col\" class=\"num\">\u0394g (10\u207B\u2075 m/s\u00B2)</th><th scope=\"col\">status</th>"
                  "<th scope=\"col\">method</th><th scope=\"col\">equation (Nelson &amp; Olsson 1986)</th></tr></thead>\n"
                  "<tbody>\n";
  // Each row rounded to its uncertainty, as a lab report writes it.
  for (const auto& c : r.corrections) {
    const std::string status = c.status == "skipped" && !c.reason.empty() ? c.status + ": " + c.reason : c.status;
    const CorrectionDecimals decimals = correction_decimals(c.delta_T.value_or(0.0), c.delta_T_uncertainty, c.delta_g.value_or(0.0));
    s += "<tr class=\"" + esc(c.status) + "\"><td>" + esc(c.title) + "</td><td class=\"num\">" +
         optional_fixed(c.delta_T, 1e6, decimals.delta_T, true) + "</td><td class=\"num\">" +
         (c.delta_T && !c.delta_T_uncertainty ? std::string(kUncertaintyUnknown)
                                              : optional_fixed(c.delta_T_uncertainty, 1e6, decimals.delta_T, false)) +
         "</td><td class=\"num\">" +
         optional_fixed(c.delta_g, 1e5, decimals.delta_g, true) + "</td><td>" + esc(status) + "</td><td class=\"method\">" +
         (c.method.empty() ? "\u2014" : esc(c.method)) + "</td><td>" + esc(short_equation(c.equation)) + "</td></tr>\n";
  }
  return s + "</tbody>\n</table>\n";
}

std::string budget_table(const SceneReport& r) {
  std::string s =
      "<table class=\"budget\">\n<thead><tr><th scope=\"col\">input</th><th scope=\"col\" class=\"num\">value</th>"
      "<th scope=\"col\" class=\"num\">uncertainty</th><th scope=\"col\">unit</th>"
      "<th scope=\"col\" class=\"num\">contribution to u(g) (mm/s\u00B2)</th><th scope=\"col\" class=\"num\">share "
      "of u(g)\u00B2</th><th scope=\"col\">GUM</th></tr></thead>\n<tbody>\n";
  bool grouped = false;
  for (const auto& b : r.budget) {
    grouped = grouped || b.rows > 1;
    // Type and distribution, and the degrees of freedom where finite.
    const std::string gum = b.type + ", " + b.distribution + (b.dof == "\u221E" ? "" : ", \u03BD = " + b.dof);
    s += "<tr><td><code>" + breakable(b.input, ".[") + "</code></td><td class=\"num\">" + format_significant(b.value, 6) +
         "</td><td class=\"num\">" + format_significant(b.uncertainty, 3) + "</td><td>" + esc(b.unit) +
         "</td><td class=\"num\">" + format_fixed(b.contribution * 1e3, 6) + "</td><td class=\"num\">" +
         format_fixed(100.0 * b.variance_share, 1) + " %</td><td>" + esc(gum) + "</td></tr>\n";
  }
  s += "</tbody>\n</table>\n";
  if (grouped) {
    s += "<p class=\"meta\">A row of several observations adds their contributions in quadrature and shows the "
         "largest one's value and uncertainty (JSON: every row in g.budget).</p>\n";
  }
  if (r.budget_correlation_variance) {
    const bool over = std::any_of(r.budget.begin(), r.budget.end(), [](const auto& b) { return b.variance_share > 1.0; });
    s += "<p>The fitted \u03B1 and \u03B2 are correlated; their cross term adds " +
         format_significant(*r.budget_correlation_variance * 1e6, 3) + " (mm/s\u00B2)\u00B2 to u(g)\u00B2" +
         (over ? ": the shares above count each input alone, and this term takes back what they add beyond 100 %."
               : ".") +
         "</p>\n";
  }
  if (!r.inputs_without_uncertainty.empty()) {
    std::string list;
    for (const auto& i : r.inputs_without_uncertainty) list += (list.empty() ? "" : ", ") + i;
    s += "<p class=\"meta\">Stated without an uncertainty, so not in the budget: " + esc(list) + ".</p>\n";
  }
  return s;
}

/// A fitted parameter's value: with its uncertainty, held fixed, or with
/// its uncertainty unknown (a singular covariance).
std::string parameter_value(const FitParameterText& p) {
  if (p.uncertainty) return value_with_uncertainty(p.value, *p.uncertainty, false);
  return format_significant(p.value, 6) + (p.fitted ? std::string(" (") + kUncertaintyUnknown + ")" : " (held fixed)");
}

std::string parameters_table(const char* css_class, const std::vector<FitParameterText>& parameters) {
  std::string s = std::string("<table class=\"") + css_class +
                  "\">\n<thead><tr><th scope=\"col\">parameter</th><th scope=\"col\" class=\"num\">value</th>"
                  "<th scope=\"col\">unit</th></tr></thead>\n<tbody>\n";
  for (const auto& p : parameters) {
    s += "<tr><td>" + esc(p.name) + "</td><td class=\"num\">" + parameter_value(p) + "</td><td>" + esc(p.unit) +
         "</td></tr>\n";
  }
  return s + "</tbody>\n</table>\n";
}

std::string decay_table(const DecayRecord& d) {
  std::string s = parameters_table("decay", d.parameters);
  s += "<p class=\"meta\">Model: " + esc(d.model) + ". \u03C7\u00B2 = " +
       format_significant(d.chi2, 4) + " for " + std::to_string(d.dof) + " degrees of freedom; uncertainties " +
       esc(d.uncertainty_scaling) + ".</p>\n";
  return s;
}

/// `setting` heads the settings' column: "L (m)", "pivot position x (m)".
/// Residuals as the plots draw them, measured - model, over the effective
/// uncertainty that reduce weighs them with and warns by.
/// An amplitude sweep's T0 and law test in words (docs/series.md).
std::string sweep_paragraph(const AmplitudeSweep& w) {
  std::string s = "<p>Small-amplitude period T₀ = " + esc(rounded_estimate(w.t0, 5, "s")) +
                  " from the exact law T = T₀ 2K(sin²(θ₀/2))/π fitted to the periods";
  if (w.coefficient) {
    s += "; the law tested: T = a (1 + c θ₀²) gives c = " +
         esc(estimate_text(*w.coefficient, 4, "/rad²")) + " against the law's " +
         format_significant(w.coefficient_law, 4) + " at these amplitudes (1/16 at small ones): " +
         (sweep_law_refuted(w) ? "<strong>refuted</strong>" : "agrees") + " (probability " +
         format_significant(w.coefficient_probability.value_or(1.0), 3) + ")";
  }
  return s + ".</p>\n";
}

std::string series_table(const SeriesRecord& d, const std::string& setting) {
  std::string s = parameters_table("series", d.parameters);
  s += "<table class=\"observations\">\n<thead><tr><th scope=\"col\" class=\"num\">" + esc(setting) + "</th>"
       "<th scope=\"col\" class=\"num\">T measured (s)</th><th scope=\"col\" class=\"num\">u(T) (s)</th>"
       "<th scope=\"col\" class=\"num\">T model (s)</th><th scope=\"col\" class=\"num\">\u03C3<sub>eff</sub> (s)</th>"
       "<th scope=\"col\" class=\"num\">residual (\u03C3<sub>eff</sub>)</th></tr></thead>\n<tbody>\n";
  for (std::size_t k = 0; k < d.lengths.size(); ++k) {
    const double u = d.period_uncertainties[k], sigma = d.effective_uncertainties[k];
    const int decimals = decimals_for(std::min(u, sigma));
    s += "<tr><td class=\"num\">" + format_fixed(d.lengths[k], 4) + "</td><td class=\"num\">" +
         format_fixed(d.periods[k], decimals) + "</td><td class=\"num\">" + format_significant(u, 2) +
         "</td><td class=\"num\">" + format_fixed(d.periods_model[k], decimals) + "</td><td class=\"num\">" +
         format_significant(sigma, 2) + "</td><td class=\"num\">" +
         (sigma > 0.0 ? signed_fixed((d.periods[k] - d.periods_model[k]) / sigma, 2) : "\u2014") + "</td></tr>\n";
  }
  s += "</tbody>\n</table>\n<p class=\"meta\">Residual: (T measured \u2212 T model) / \u03C3<sub>eff</sub>, as the "
       "plot draws it; \u03C3<sub>eff</sub> is u(T) with the setting's and the amplitude's uncertainties carried to "
       "the period, the weight of the fit and of reduce's warnings (reduce's <code>residual_sigma</code> is the same "
       "with the opposite sign, model \u2212 measured). \u03C7\u00B2 = " + format_significant(d.chi2, 4) + " for " +
       std::to_string(d.dof) + " degrees of freedom" +
       (d.probability ? ", P(\u03C7\u00B2 \u2265 this) = " + format_significant(*d.probability, 3) : "") +
       ". The corrections above are those of the first observation.</p>\n";
  return s;
}

/// A recording's findings and plots under a heading of `level` (2 or 3),
/// their own headings one level below; `anchor` prefixes the plots' ids.
std::string recording_part(const RecordingRecord& r, const std::string& anchor, int level) {
  const std::string h = "h" + std::to_string(level), sub = "h" + std::to_string(level + 1);
  auto heading = [](const std::string& tag, const std::string& text) {
    return "<" + tag + ">" + text + "</" + tag + ">\n";
  };
  std::string s = heading(h, "Recording <code>" + esc(r.input) + "</code>") +
                  "<p class=\"meta\">Recording file: <code>" + breakable(r.input) + "</code><br/>Format: " + esc(r.format) +
                  ", " + esc(r.signal) + "; " + std::to_string(r.rows) + " rows read, " +
                  std::to_string(r.dropped) + " skipped (a cell empty or not a number).</p>\n";
  const bool below_resolution = r.period.uncertainty < r.period_resolution;
  s += "<p class=\"g\">T = " +
       value_with_uncertainty(r.period.value, std::max(r.period.uncertainty, r.period_resolution), false) + " s</p>\n";
  if (below_resolution) {
    s += "<p class=\"meta\">The period's standard uncertainty, " + format_significant(r.period.uncertainty, 2) +
         " s, is below the clock's resolution spread over the " + std::to_string(r.period.periods) +
         " periods; the period is rounded to that, " + format_significant(r.period_resolution, 2) + " s.</p>\n";
  }
  s += "<table class=\"summary\">\n";
  auto row = [&](const std::string& name, const std::string& value) {
    s += "<tr><th scope=\"row\">" + esc(name) + "</th><td>" + esc(value) + "</td></tr>\n";
  };
  row("full periods", std::to_string(r.period.periods) + " (" + std::to_string(r.crossings.size()) + " crossings, " +
                          std::to_string(r.crossings_per_period) + " per period)");
  row("crossing residuals", format_significant(r.period.residual_rms, 3) + " s rms, lag-1 correlation " +
                                format_fixed(r.period.lag1_correlation, 2));
  if (r.analysed) {
    row("stretch analysed", format_number(r.analysed->first, 6) + " to " + format_number(r.analysed->second, 6) + " s" +
                                (r.cuts.empty() ? " (a typed range)" : " (the clean stretch, by default: --range all keeps the whole record)"));
  }
  for (const Cut& k : r.cuts) {
    row(k.periods_carried > 0.0 ? "bridged" : "cut",
        format_number(k.start, 6) + " to " + format_number(k.end, 6) + " s: " + k.why +
            (k.periods_carried > 0.0 ? " (" + format_number(k.periods_carried, 4) + (k.periods_carried == 1.0 ? " period)" : " periods)") : "") + ", " +
            format_number(k.worst, 3) + " robust sigmas");
  }
  if (r.whole_record_period) {
    row("whole record's period", rounded_estimate({r.whole_record_period->value, r.whole_record_period->uncertainty}, 6, "s"));
  }
  if (std::isfinite(r.small_amplitude_period)) {
    row("small-amplitude period T\u2080", format_fixed(r.small_amplitude_period, 7) + " s");
  }
  if (std::isfinite(r.start_amplitude)) {
    row("amplitude", format_fixed(degrees(r.start_amplitude), 3) + "\u00B0 at the first crossing, " +
                         format_fixed(degrees(r.end_amplitude), 3) + "\u00B0 at the last");
  }
  s += "</table>\n";
  if (auto f = signal_figure(r, anchor + "-signal")) {
    s += heading(sub, "Signal and crossings") + figure_html(to_svg(*f, false), f->description);
  }
  if (auto f = amplitude_figure(r, anchor + "-amplitude")) {
    s += heading(sub, "Amplitude against time") + figure_html(to_svg(*f, false), f->description);
    s += r.decay ? decay_table(*r.decay) : "<p class=\"meta\">" + esc(r.decay_note) + ".</p>\n";
  }
  if (auto f = period_amplitude_figure(r, anchor + "-period-amplitude")) {
    s += heading(sub, "Period against amplitude") + figure_html(to_svg(*f, false), f->description);
  }
  return s + "<p class=\"meta\"><code>pendulum-g import " + esc(r.input) +
         "</code> prints the scene's <code>timing</code> and <code>decay</code> parts from this recording.</p>\n";
}

/// One scene's section; `anchor` is its id in the page, and prefixes the ids
/// of its plots.
std::string scene_section(const SceneReport& r, const std::string& anchor) {
  std::string s = "<section class=\"scene\" id=\"" + esc(anchor) + "\">\n<h2>" +
                  esc(r.title.empty() ? r.input : r.title) + "</h2>\n<p class=\"meta\">Scene file: <code>" +
                  esc(r.input) + "</code>";
  if (!r.source.empty()) s += "<br/>Source: " + esc(r.source);
  s += "</p>\n" + verdict_html(r) + "<p class=\"g\">g = " + esc(rounded_estimate(r.g, 5, "m/s\u00B2")) + "</p>\n";
  if (!r.g_expanded.empty()) s += "<p class=\"meta\">Expanded: g = " + esc(r.g_expanded) + "</p>\n";
  s += g_comparison(r);
  if (!r.warnings.empty()) {
    s += "<h3>Warnings</h3>\n<ul class=\"warnings\">\n";
    for (const auto& w : collapse_repeats(r.warnings)) s += "<li>" + esc(w) + "</li>\n";
    s += "</ul>\n";
  }
  s += r.series ? "<h3>Corrections of the first observation</h3>\n" : "<h3>Corrections</h3>\n";
  if (auto c = corrections_chart(r, anchor + "-corrections")) {
    s += figure_html(to_svg(*c, false), c->description);
  }
  s += corrections_table(r);
  if (auto b = budget_chart(r, anchor + "-budget")) {
    s += "<h3>Uncertainty budget of g</h3>\n" + figure_html(to_svg(*b, false), b->description) + budget_table(r);
  }
  if (auto f = series_figure(r, anchor + "-series")) {
    s += (r.series->sweep ? "<h3>Amplitude sweep</h3>\n" + sweep_paragraph(*r.series->sweep) : "<h3>Series fit</h3>\n") +
         figure_html(to_svg(*f, false), f->description) + series_table(*r.series, "L (m)");
  }
  if (auto f = pivot_scan_figure(r, anchor + "-pivot-scan")) {
    const SettingInfo& info = setting_info(r.pivot_scan->setting);
    const std::string setting = std::string(info.words) + " " + info.symbol + " (m)";
    s += std::string(r.pivot_scan->bessel_g ? "<h3>Kater's pendulum</h3>\n" : "<h3>Pivot scan</h3>\n") +
         figure_html(to_svg(*f, false), f->description) + series_table(*r.series, setting);
  }
  if (auto d = decay_figure(r, anchor + "-decay")) {
    s += "<h3>Decay record</h3>\n" + figure_html(to_svg(*d, false), d->description) + decay_table(*r.decay);
  }
  for (std::size_t i = 0; i < r.recordings.size(); ++i) {
    s += recording_part(r.recordings[i], anchor + "-recording-" + std::to_string(i + 1), 3);
  }
  return s + "</section>\n";
}

}  // namespace

std::string scene_report_html(const SceneReport& r) {
  return page(r.title.empty() ? r.input : r.title, "<h1>pendulum-g report</h1>\n" + scene_section(r, "scene"));
}

std::string recording_report_html(const RecordingRecord& r) {
  return page("Recording " + r.input, "<h1>pendulum-g report</h1>\n<section class=\"scene\" id=\"recording\">\n" +
                                          recording_part(r, "recording", 2) + "</section>\n");
}

std::string class_report_html(const std::vector<ClassEntry>& entries) {
  std::vector<ClassPoint> points;
  std::vector<std::pair<ResultStatus, std::optional<double>>> results;
  std::vector<std::pair<double, std::string>> rows;  // by g, as the chart
  std::string failures;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const ClassEntry& e = entries[i];
    const std::string anchor = "scene-" + std::to_string(i + 1);
    if (!e.report) {
      results.emplace_back(ResultStatus::failed, std::nullopt);
      failures += "<tr class=\"failed\"><td class=\"file\"><code>" + breakable(e.input) + "</code></td><td>" + esc(e.error) + "</td></tr>\n";
      continue;
    }
    const SceneReport& r = *e.report;
    const bool ok = r.status == "ok";
    results.emplace_back(ok ? ResultStatus::ok : ResultStatus::suspect, r.g.value);
    const std::size_t slash = e.input.find_last_of('/');
    points.push_back({slash == std::string::npos ? e.input : e.input.substr(slash + 1), "#" + anchor, r.g.value,
                      r.g.uncertainty, r.expected_g, r.z, ok});
    const std::string reason = r.status_reasons.empty() ? "" : brief_reason(r.status_reasons.front()) +
        (r.status_reasons.size() > 1 ? " (+" + std::to_string(r.status_reasons.size() - 1) + " more)" : "");
    rows.emplace_back(r.g.value, "<tr class=\"" + esc(r.status) + "\"><td class=\"file\"><a href=\"#" + anchor + "\"><code>" +
            breakable(e.input) + "</code></a></td><td><strong>" + esc(r.status) + "</strong>" +
            (reason.empty() ? "" : ": " + esc(reason)) + "</td><td class=\"num\">" +
            esc(r.g.uncertainty ? value_with_uncertainty(r.g.value, *r.g.uncertainty, false)
                                : estimate_text(r.g, 5, "")) + "</td><td class=\"num\">" +
            (r.expected_g ? format_fixed(r.expected_g->value, 5) : "\u2014") + "</td><td class=\"num\">" +
            (r.z ? signed_fixed(*r.z, 2) : "\u2014") + "</td><td>" +
            (r.budget.empty() ? "\u2014" : "<code>" + breakable(r.budget.front().input, ".[") + "</code>") + "</td><td class=\"num\">" +
            std::to_string(r.warnings.size()) + "</td></tr>\n");
  }
  const ClassSummary summary = summarise_class(results);
  std::string body = "<h1>pendulum-g class report</h1>\n<div class=\"verdict class\" role=\"status\">\n<p><strong>" +
                     std::to_string(entries.size()) + " scenes: " + std::to_string(entries.size() - summary.count[2]) +
                     " reduced, " + std::to_string(summary.count[2]) + " failed. Status: " +
                     std::to_string(summary.count[0]) + " ok, " + std::to_string(summary.count[1]) + " suspect, " +
                     std::to_string(summary.count[2]) + " failed.</strong></p>\n<p>g of the ok results: ";
  if (!summary.ok_g_mean) {
    body += "none.";
  } else {
    body += "mean " + format_fixed(*summary.ok_g_mean, 4) + " m/s\u00B2";
    if (summary.ok_g_standard_deviation) {
      body += ", standard deviation " + format_fixed(*summary.ok_g_standard_deviation, 4) +
              " m/s\u00B2 (the spread of one result), standard error of the mean " +
              format_fixed(*summary.ok_g_standard_deviation / std::sqrt(summary.ok_g_count), 4) + " m/s\u00B2";
    }
    body += " (" + std::to_string(summary.ok_g_count) + (summary.ok_g_count == 1 ? " result)." : " results).");
  }
  body += " A suspect result is printed but looks like a slip: its row gives the reason in brief, its section the "
          "reasons in full with the fix. Each row links to the scene's own section below.</p>\n</div>\n";
  if (!points.empty()) {
    const CategoryChart chart = class_chart(points, "class-g");
    body += figure_html(to_svg(chart, false), chart.description);
    body += "<table class=\"class\">\n<thead><tr><th scope=\"col\">scene</th><th scope=\"col\">status</th>"
            "<th scope=\"col\" class=\"num\">g (m/s\u00B2)</th><th scope=\"col\" class=\"num\">expected g (m/s\u00B2)</th>"
            "<th scope=\"col\" class=\"num\">z</th><th scope=\"col\">largest in the budget</th>"
            "<th scope=\"col\" class=\"num\">warnings</th></tr></thead>\n<tbody>\n";
    std::stable_sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& row : rows) body += row.second;
    body += "</tbody>\n</table>\n";
  }
  if (summary.count[2]) {
    body += "<h2>Files that failed</h2>\n<table class=\"failures\">\n<thead><tr><th scope=\"col\">file</th>"
            "<th scope=\"col\">error</th></tr></thead>\n<tbody>\n" + failures + "</tbody>\n</table>\n";
  }
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (entries[i].report) body += scene_section(*entries[i].report, "scene-" + std::to_string(i + 1));
  }
  return page("pendulum-g class report", body);
}

}  // namespace pendulum::report
