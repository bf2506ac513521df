// The pivot-scan plot (report/plots.hpp, pivot_scan_figure) on the bundled
// metre stick and Kater pendulum: the curve is the period model's, it never
// crosses the centre of mass, and the period axis holds every observation.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "pendulum/reduce_scene.hpp"
#include "pendulum/models/physical_pendulum.hpp"
#include "pendulum/report/html_report.hpp"
#include "pendulum/report/plots.hpp"
#include "pendulum/json/scene_json.hpp"
#include "scene_files.hpp"

using namespace pendulum;
using namespace pendulum::report;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinRel;

namespace {

struct Reduced {
  ParsedScene scene;
  Analysis analysis;
  SceneReport report;
};

Reduced reduced(const std::string& file) {
  Reduced r{parse_scene(test::read_text(std::string(PENDULUM_DATA_DIR) + "/" + file)), {}, {}};
  r.analysis = reduce_scene(r.scene);
  r.report = make_scene_report(file, r.scene, r.analysis);
  return r;
}

/// The model's period at setting x for the record's curve: the first
/// observation at the record's amplitude, working period its ideal one.
double model_period(const Reduced& r, double x) {
  const PivotScanRecord& d = *r.report.pivot_scan;
  const double p[3] = {r.analysis.fit.parameters[0].value, r.analysis.fit.parameters[1].value,
                       r.analysis.fit.parameters[2].value};
  Observation<double> o = r.scene.observations.front();
  o.amplitude = d.amplitude;
  o.length = x;
  o.period = PhysicalPendulum::predict(p, o, r.scene.apparatus, d.amplitude_method).ideal;  // T0 needs no period
  return PhysicalPendulum::predict(p, o, r.scene.apparatus, d.amplitude_method).period;
}

/// The checks every pivot scan's plot must pass.
void check_plot(const Reduced& r) {
  REQUIRE(r.report.pivot_scan);
  const PivotScanRecord& d = *r.report.pivot_scan;
  const auto figure = pivot_scan_figure(r.report, "pivot");
  REQUIRE(figure);
  CHECK_FALSE(series_figure(r.report, "series"));  // one plot of the observations, not two

  // The plotted model curves are the record's branches, each point the model's period there.
  std::size_t drawn = 0;
  for (const Curve& c : figure->panels[0].curves) {
    if (c.colour != Colour::vermillion) continue;
    REQUIRE(drawn < d.model.size());
    CHECK(c.x == d.model[drawn].x);
    CHECK(c.y == d.model[drawn].period);
    ++drawn;
  }
  CHECK(drawn == d.model.size());
  for (const auto& b : d.model) {
    REQUIRE(b.x.size() == 400);
    for (std::size_t i : {std::size_t(0), std::size_t(137), std::size_t(399)}) {
      CHECK_THAT(b.period[i], WithinRel(model_period(r, b.x[i]), 1e-12));
    }
  }

  // No segment of a curve crosses its centre of mass, where T is infinite.
  auto one_side = [](const PivotScanRecord::Branch& b, double center) {
    for (std::size_t i = 0; i + 1 < b.x.size(); ++i) {
      if ((b.x[i] - center) * (b.x[i + 1] - center) <= 0.0) return false;
    }
    return true;
  };
  for (const auto& b : d.model) CHECK(one_side(b, d.center));
  for (const auto& b : d.textbook) CHECK(one_side(b, d.textbook_center));

  // The period range holds every observation with its error bar, and every
  // curve stays inside it (the curve near the centre is cut, not the data).
  const SeriesRecord& s = *r.report.series;
  REQUIRE(d.uncertainties.size() == s.periods.size());
  for (std::size_t k = 0; k < s.periods.size(); ++k) {
    CHECK(d.uncertainties[k] >= s.period_uncertainties[k]);  // the period's, and the pivot's and amplitude's
    CHECK(d.period_low < s.periods[k] - d.uncertainties[k]);
    CHECK(s.periods[k] + d.uncertainties[k] < d.period_high);
  }
  for (const auto* branches : {&d.model, &d.textbook}) {
    for (const auto& b : *branches) {
      for (double t : b.period) {
        CHECK(t >= d.period_low);
        CHECK(t <= d.period_high * (1.0 + 1e-15));
      }
    }
  }
  // The curve reaches the top of the range near the centre: its end is the crossing.
  CHECK_THAT(d.model.front().period.back() > d.model.front().period.front() ? d.model.front().period.back()
                                                                           : d.model.front().period.front(),
             WithinRel(d.period_high, 1e-12));

  const std::string svg = to_svg(*figure, true);
  CHECK_THAT(svg, !Contains("length L"));
  CHECK_THAT(svg, !Contains("T\u00B2"));
  CHECK_THAT(scene_report_html(r.report), !Contains("0.00000 \u00B1 0.00000"));
}

}  // namespace

TEST_CASE("pivot scan plot: the metre stick", "[report][pivot]") {
  const Reduced r = reduced("metre_stick_pivot_scan.json");
  check_plot(r);
  const PivotScanRecord& d = *r.report.pivot_scan;
  REQUIRE(d.model.size() == 2);  // both sides of the centre
  CHECK(d.model[0].x.back() < d.center);
  CHECK(d.model[1].x.front() > d.center);
  // Every correction of a metre stick in air (amplitude, buoyancy) is the same
  // at every pivot at one amplitude (5 deg for all 18), so the curve is the
  // analysis's T_model/T0 times the ideal period: at the minimum, the
  // analysis's 2 pi sqrt(2k/g), and at the first pivot, its T_model.
  const ObservationResult& first = r.analysis.observations.front();
  CHECK(d.amplitude_min == d.amplitude_max);
  CHECK_THAT(d.minimum_model_period,
             WithinRel(d.minimum_period.value * first.period_model / first.period_ideal.value, 1e-12));
  CHECK_THAT(d.conjugate_period, WithinRel(first.period_model, 1e-12));
  // The conjugate of the first pivot, h' = k^2/h, on the other side of the centre.
  const double h = d.center - r.scene.observations.front().length;
  CHECK_THAT(d.conjugate_x->value, WithinRel(d.center + d.radius_of_gyration * d.radius_of_gyration / h, 1e-12));

  const auto f = pivot_scan_figure(r.report, "pivot");
  CHECK_THAT(f->title, Contains("Pivot scan: period T against pivot position"));
  CHECK_THAT(f->x.label, Contains("pivot position"));
  CHECK_THAT(f->description, Contains("at the observations' amplitude of 5.00 deg"));
  CHECK_THAT(f->description, !Contains("Bessel"));
  CHECK(plot_names(r.report) == std::vector<std::string>{"corrections", "budget", "pivot-scan"});
  CHECK(plot_svg(r.report, "series") == plot_svg(r.report, "pivot-scan"));
}

TEST_CASE("pivot scan plot: Kater's reversible pendulum", "[report][pivot]") {
  const Reduced r = reduced("kater_reversible_pendulum.json");
  check_plot(r);
  const PivotScanRecord& d = *r.report.pivot_scan;
  REQUIRE(d.bessel_g);
  const auto f = pivot_scan_figure(r.report, "kater");
  CHECK_THAT(f->title, Contains("Kater's pendulum"));
  CHECK_THAT(f->description, Contains("Bessel's formula on their ideal periods gives g = " + format_fixed(*d.bessel_g, 5)));
  CHECK_THAT(f->description, Contains("No degree of freedom is left"));
  // Two knife edges, two observations; the textbook's line through both
  // (two points, g and k) passes through both measured periods.
  const SeriesRecord& s = *r.report.series;
  REQUIRE(s.periods.size() == 2);
  for (std::size_t k = 0; k < 2; ++k) {
    const double h = std::abs(s.lengths[k] - d.textbook_center);
    const double t = 2.0 * kPi * std::sqrt((d.textbook_k * d.textbook_k + h * h) / (d.textbook_g * h));
    CHECK_THAT(t, WithinRel(s.periods[k], 1e-12));
  }
}

TEST_CASE("pivot scan plot: amplitudes that vary, the curve at their median", "[report][pivot]") {
  Reduced r{parse_scene(test::read_text(std::string(PENDULUM_DATA_DIR) + "/metre_stick_pivot_scan.json")), {}, {}};
  // 18 amplitudes 2, 2.5, ..., 10.5 deg: the median is (6.0 + 6.5)/2 = 6.25 deg.
  for (std::size_t k = 0; k < r.scene.observations.size(); ++k) {
    r.scene.observations[k].amplitude = (2.0 + 0.5 * k) * kPi / 180.0;
  }
  r.analysis = reduce_scene(r.scene);
  r.report = make_scene_report("varied", r.scene, r.analysis);
  check_plot(r);
  CHECK_THAT(r.report.pivot_scan->amplitude, WithinRel(6.25 * kPi / 180.0, 1e-15));
  const auto f = pivot_scan_figure(r.report, "pivot");
  CHECK_THAT(f->description, Contains("at the median amplitude 6.25 deg (the observations' amplitudes range from 2.00 to 10.50 deg)"));
}

TEST_CASE("pivot scan plot: none for a simple pendulum's series", "[report][pivot]") {
  const Reduced r = reduced("pendulum_lengths_series.json");
  CHECK_FALSE(r.report.pivot_scan);
  CHECK_FALSE(pivot_scan_figure(r.report, "pivot"));
  CHECK(series_figure(r.report, "series"));
  CHECK_THROWS_WITH(plot_svg(r.report, "pivot-scan"), Contains("not a pivot scan"));
}
