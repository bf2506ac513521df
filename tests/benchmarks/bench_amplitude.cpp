// Speed against error of the finite-amplitude correction DeltaT/T0 = 2K/pi - 1:
// pendulum-g's methods, the library routes (libstdc++, Boost.Math, GSL, a
// Cephes-style polynomial K written here) and the closed forms students meet.
// Every method takes the amplitude in degrees, as a student types it, and
// returns DeltaT/T0; the library routes form k = sin(theta0/2) as their
// documentation asks.
//
// Time: ns per call over a fixed grid of 10^4 amplitudes, 180 (i + 1/2)/10^4
// deg, swept in increasing order and in a fixed shuffled order (the exact
// method branches on the amplitude); Google Benchmark repetitions, median.
// Error: worst relative error of DeltaT/T0 over the grid and the hard cases
// against tests/quad_reference.hpp.
//
// Run (the figures in docs/amplitude.md come from this command):
//   build/tests/benchmarks/bench_amplitude --benchmark_repetitions=10 \
//       --benchmark_report_aggregates_only=true --write-docs=docs
// --write-docs=DIR writes DIR/amplitude-benchmark.md (the table) and
// DIR/amplitude-benchmark.svg (error against time).
#include <benchmark/benchmark.h>
#include <boost/math/special_functions/ellint_1.hpp>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_sf_ellint.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "../quad_reference.hpp"
#include "pendulum/amplitude.hpp"

namespace {

using pendulum::kPi;
constexpr double kDegree = kPi / 180.0;

/// Cephes-style K(m) = P(x) - ln(x) Q(x), x = 1 - m (the form of Cephes's
/// ellpk, written for this benchmark). P and Q of degree 10 were fitted by
/// tests/benchmarks/fit_ellpk.py (weighted least squares on the relative
/// error of K, 60 digits); the fit's own relative error is below 2e-18.
double ellpk_style(double x) {
  static constexpr std::array<double, 11> p{
      1.3862943611198906318,  0.096573590282199163251, 0.030885147747778385476,
      0.014938234091410960521, 0.0087977404372822939947, 0.0062653120900725288425,
      0.007127419703923610523, 0.0099883093593542282541, 0.0077039975259882778546,
      0.0021005428718668811579, 0.00012167156512965621442};
  static constexpr std::array<double, 11> q{
      0.49999999999999999949, 0.12499999999975606516, 0.070312499499982278625,
      0.048827993372469714465, 0.037375336445185142215, 0.030086704545654385997,
      0.023711509129987057428, 0.01504910463351621821, 0.0055927624849371191504,
      0.00082981211803721904392, 0.000025735165706225078979};
  if (!(x > 0.0 && x <= 1.0)) return x == 0.0 ? INFINITY : NAN;
  double pv = p[10], qv = q[10];
  for (int j = 9; j >= 0; --j) {
    pv = pv * x + p[j];
    qv = qv * x + q[j];
  }
  return pv - std::log(x) * qv;
}

using BoostNoPromotion = boost::math::policies::policy<
    boost::math::policies::promote_double<false>>;

double gsl_kcomp(double k) {
  gsl_sf_result r;
  return gsl_sf_ellint_Kcomp_e(k, GSL_PREC_DOUBLE, &r) == GSL_SUCCESS ? r.val : NAN;
}

/// 2K(k)/pi - 1 from a library's K, NaN where it throws (Boost at k = 1).
template <class K>
double from_k(double deg, K complete_k) {
  try {
    return 2.0 * complete_k(std::sin(deg * kDegree / 2.0)) / kPi - 1.0;
  } catch (const std::exception&) {
    return NAN;
  }
}

std::vector<double> grid() {
  std::vector<double> g;
  for (int i = 0; i < 10000; ++i) g.push_back(180.0 * (i + 0.5) / 10000.0);
  return g;
}

std::vector<double> shuffled_grid() {
  std::vector<double> g = grid();
  std::shuffle(g.begin(), g.end(), std::mt19937(20240521));
  return g;
}

std::vector<double> hard_cases() {
  std::vector<double> h{1e-8, 1e-4, 0.18, 179.99999, 179.999999, 179.9999999};
  for (double d = 134.0; d <= 143.0; d += 0.25) h.push_back(d);
  return h;
}

template <class F>
void time_method(benchmark::State& state, F f, bool shuffled) {
  static const std::vector<double> sweep = grid(), mixed = shuffled_grid();
  const std::vector<double>& g = shuffled ? mixed : sweep;
  for (auto _ : state) {
    for (double deg : g) benchmark::DoNotOptimize(f(deg));
  }
  state.counters["ns_per_call"] = benchmark::Counter(
      static_cast<double>(state.iterations() * g.size()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

struct Entry {
  std::string name, formula;
  std::function<double(double)> f;  // for the error sweep only
};

/// Registers a method's two timings (each loop inlines `f` where it can)
/// and returns it for the error sweep.
template <class F>
Entry method(const std::string& name, const std::string& formula, F f) {
  benchmark::RegisterBenchmark((name + "/sweep").c_str(), [f](benchmark::State& s) { time_method(s, f, false); });
  benchmark::RegisterBenchmark((name + "/shuffled").c_str(), [f](benchmark::State& s) { time_method(s, f, true); });
  return {name, formula, f};
}

std::vector<Entry> register_methods() {
  using namespace pendulum;
  return {
      method("agm (pendulum-g exact)", "Landen/AGM + Eq. (8), nome near 180 deg, from the deficit",
             [](double deg) { return finite_amplitude_agm_deg(deg); }),
      method("series, 4 terms", "Eq. (8) truncated, k = sin(theta0/2)",
             [](double deg) { return finite_amplitude_series(deg * kDegree, 4); }),
      method("series, 8 terms", "Eq. (8) truncated",
             [](double deg) { return finite_amplitude_series(deg * kDegree, 8); }),
      method("small_angle", "theta0^2/16",
             [](double deg) { return finite_amplitude_small_angle(deg * kDegree); }),
      method("std::comp_ellint_1", "libstdc++ K(k), 2K/pi - 1",
             [](double deg) { return from_k(deg, [](double k) { return std::comp_ellint_1(k); }); }),
      method("Boost.Math ellint_1", "default policy (promotes to long double)",
             [](double deg) { return from_k(deg, [](double k) { return boost::math::ellint_1(k); }); }),
      method("Boost.Math ellint_1, double", "promote_double<false>", [](double deg) {
        return from_k(deg, [](double k) { return boost::math::ellint_1(k, BoostNoPromotion()); });
      }),
      method("GSL gsl_sf_ellint_Kcomp", "GSL_PREC_DOUBLE",
             [](double deg) { return from_k(deg, gsl_kcomp); }),
      method("Cephes-style ellpk", "P(x) - ln(x) Q(x), x = 1 - k^2, degree 10",
             [](double deg) { return from_k(deg, [](double k) { return ellpk_style(1.0 - k * k); }); }),
      method("Kidd & Fogg", "1/sqrt(cos(theta0/2)) - 1",
             [](double deg) { return 1.0 / std::sqrt(std::cos(deg * kDegree / 2.0)) - 1.0; }),
      method("Lima & Arun", "-ln(a)/(1 - a) - 1, a = cos(theta0/2)",
             [](double deg) {
               const double a = std::cos(deg * kDegree / 2.0);
               return -std::log(a) / (1.0 - a) - 1.0;
             }),
      method("Ganley", "sqrt(x/sin x) - 1, x = (sqrt(3)/2) theta0",
             [](double deg) {
               const double x = std::sqrt(3.0) / 2.0 * deg * kDegree;
               return std::sqrt(x / std::sin(x)) - 1.0;
             }),
      method("Carvalhaes & Suppes", "4/(1 + sqrt(cos(theta0/2)))^2 - 1, the AGM after 2 steps",
             [](double deg) {
               const double r = 1.0 + std::sqrt(std::cos(deg * kDegree / 2.0));
               return 4.0 / (r * r) - 1.0;
             }),
  };
}

struct ErrorResult {
  double worst = 0.0;  // relative, over the finite results
  double at = 0.0;     // deg
  int not_finite = 0;
  double first_not_finite = 0.0;  // deg
};

ErrorResult worst_error(const std::function<double(double)>& f) {
  ErrorResult r;
  std::vector<double> points = grid();
  for (double h : hard_cases()) points.push_back(h);
  for (double deg : points) {
    const double v = f(deg);
    if (!std::isfinite(v)) {
      if (r.not_finite++ == 0) r.first_not_finite = deg;
      continue;
    }
    const pendulum::test::Quad ref = pendulum::test::delta_ratio_quad(deg);
    const double e = static_cast<double>(fabsq((v - ref) / ref));
    if (e > r.worst) {
      r.worst = e;
      r.at = deg;
    }
  }
  return r;
}

/// Collects the median ns/call of every benchmark while printing as usual.
class MedianCollector : public benchmark::ConsoleReporter {
 public:
  std::map<std::string, double> median_ns;
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.aggregate_name == "median" || (run.aggregate_name.empty() && !median_ns.count(run.run_name.str()))) {
        const auto it = run.counters.find("ns_per_call");
        if (it != run.counters.end()) median_ns[run.run_name.str()] = it->second.value * 1e9;
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }
};

std::string format_error(const ErrorResult& e) {
  char text[96];
  std::snprintf(text, sizeof text, "%.1e at %.10g deg", e.worst, e.at);
  return text;
}

std::string format_not_finite(const ErrorResult& e) {
  if (e.not_finite == 0) return "none";
  char text[96];
  std::snprintf(text, sizeof text, "%d (from %.10g deg)", e.not_finite, e.first_not_finite);
  return text;
}

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '&' ? std::string("&amp;") : c == '<' ? std::string("&lt;") : std::string(1, c);
  return out;
}

void write_docs(const std::string& dir, const std::vector<Entry>& methods, const MedianCollector& times) {
  struct Row {
    std::string name, formula;
    double sweep, shuffled;
    ErrorResult error;
  };
  std::vector<Row> rows;
  for (const Entry& m : methods) {
    rows.push_back({m.name, m.formula, times.median_ns.at(m.name + "/sweep"),
                    times.median_ns.at(m.name + "/shuffled"), worst_error(m.f)});
  }
  const Row& agm = rows.front();
  auto find = [&](const std::string& name) -> const Row& {
    return *std::find_if(rows.begin(), rows.end(), [&](const Row& r) { return r.name == name; });
  };
  const Row& ellpk = find("Cephes-style ellpk");
  const Row& std_route = find("std::comp_ellint_1");

  std::ofstream md(dir + "/amplitude-benchmark.md");
  md << "<!-- written by bench_amplitude --write-docs; do not edit by hand -->\n"
     << "| method | formula | ns/call, sweep | ns/call, shuffled | worst relative error of ΔT/T0 (finite results) | "
        "non-finite results |\n"
     << "|---|---|---:|---:|---|---|\n";
  char line[512];
  for (const Row& r : rows) {
    std::snprintf(line, sizeof line, "| %s | %s | %.1f | %.1f | %s | %s |\n", r.name.c_str(),
                  r.formula.c_str(), r.sweep, r.shuffled, format_error(r.error).c_str(),
                  format_not_finite(r.error).c_str());
    md << line;
  }
  std::snprintf(line, sizeof line,
                "\nMedian time of the exact method against the Cephes-style ellpk: %.2f (sweep), %.2f "
                "(shuffled); against std::comp_ellint_1: %.3f (sweep), %.3f (shuffled).\n",
                agm.sweep / ellpk.sweep, agm.shuffled / ellpk.shuffled, agm.sweep / std_route.sweep,
                agm.shuffled / std_route.shuffled);
  md << line;

  // Error (log) against time (log), one labelled point per method, sweep
  // times; a method that returns a non-finite value is drawn at the top.
  const double w = 860, h = 560, left = 70, right = 250, top = 45, bottom = 50;
  const double tmin = 0.3, tmax = 300.0, emin = 1e-17, emax = 1e6;
  auto x = [&](double t) { return left + (w - left - right) * std::log10(t / tmin) / std::log10(tmax / tmin); };
  auto y = [&](double e) {
    const double c = std::min(std::max(e, emin), emax);
    return top + (h - top - bottom) * (1.0 - std::log10(c / emin) / std::log10(emax / emin));
  };
  std::ofstream svg(dir + "/amplitude-benchmark.svg");
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << w << "' height='" << h
      << "' font-family='sans-serif' font-size='11'>\n<rect width='100%' height='100%' fill='white'/>\n";
  for (double t = 1; t <= tmax; t *= 10) {
    svg << "<line x1='" << x(t) << "' y1='" << top << "' x2='" << x(t) << "' y2='" << h - bottom
        << "' stroke='#ddd'/><text x='" << x(t) << "' y='" << h - bottom + 15 << "' text-anchor='middle'>" << t
        << "</text>\n";
  }
  for (int p = -17; p <= 5; p += 2) {
    const double e = std::pow(10.0, p);
    svg << "<line x1='" << left << "' y1='" << y(e) << "' x2='" << w - right << "' y2='" << y(e)
        << "' stroke='#ddd'/><text x='" << left - 5 << "' y='" << y(e) + 4 << "' text-anchor='end'>1e" << p
        << "</text>\n";
  }
  svg << "<text x='" << left << "' y='" << top - 30 << "'>non-finite results: at the top edge</text>\n";
  svg << "<line x1='" << left << "' y1='" << y(1e-15) << "' x2='" << w - right << "' y2='" << y(1e-15)
      << "' stroke='#c00' stroke-dasharray='4 3'/><text x='" << w - right + 4 << "' y='" << y(1e-15) + 4
      << "' fill='#c00'>goal 1e-15</text>\n";
  svg << "<text x='" << (left + w - right) / 2 << "' y='" << h - 12
      << "' text-anchor='middle'>ns per call (median, sweep of 10^4 amplitudes)</text>\n"
      << "<text x='15' y='" << (top + h - bottom) / 2 << "' transform='rotate(-90 15 " << (top + h - bottom) / 2
      << ")' text-anchor='middle'>worst relative error of ΔT/T0</text>\n";
  // Points are numbered; the legend on the right names them (labels at the
  // points would overlap where several methods share a time and an error).
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    const double e = r.error.not_finite > 0 ? emax : r.error.worst;  // a NaN is worse than any error
    const char* colour = i == 0 ? "#c00" : "#036";
    svg << "<circle cx='" << x(r.sweep) << "' cy='" << y(e) << "' r='4' fill='" << colour << "'/><text x='"
        << x(r.sweep) + 5 << "' y='" << y(e) - 5 - 9.0 * (i % 3) << "' fill='" << colour << "'>" << i + 1
        << "</text>\n<text x='" << w - right + 10 << "' y='" << top + 40 + 16.0 * i << "' fill='" << colour
        << "'>" << i + 1 << ". " << xml_escaped(r.name) << "</text>\n";
  }
  svg << "</svg>\n";
}

}  // namespace

int main(int argc, char** argv) {
  gsl_set_error_handler_off();  // GSL aborts at k = 1 otherwise
  std::string docs_dir;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--write-docs=", 13) == 0) {
      docs_dir = argv[i] + 13;
    } else {
      args.push_back(argv[i]);
    }
  }
  int count = static_cast<int>(args.size());
  const std::vector<Entry> methods = register_methods();
  benchmark::Initialize(&count, args.data());
  if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 1;
  MedianCollector reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  if (!docs_dir.empty()) {
    if (reporter.median_ns.size() != 2 * methods.size()) {
      std::fprintf(stderr, "bench_amplitude: --write-docs needs every benchmark: drop the filter\n");
      return 1;
    }
    write_docs(docs_dir, methods, reporter);
  }
  return 0;
}
