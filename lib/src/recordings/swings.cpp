#include "pendulum/recordings/swings.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "pendulum/amplitude.hpp"
#include "pendulum/files.hpp"
#include "pendulum/numeric.hpp"
#include "pendulum/input_error.hpp"
#include "pendulum/swing_energy.hpp"
#include "../text.hpp"
#include "huge_pages.hpp"
#include "stages.hpp"

namespace pendulum {
namespace {

using recording_text::median_of;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The smooth amplitude curve (a polynomial in time fitted to log theta): a
/// term joins while its F statistic exceeds this (3 sigmas), up to this
/// order (81 deg to 17 deg in 375 s takes 6 or 7).
constexpr double kSmoothTermF = 9.0;
constexpr int kMaxSmoothOrder = 8;

/// The swing signal: one value per sample, zero on average.
struct Signal {
  std::vector<double> s;
  int crossings_per_period = 2;
  std::array<double, 3> axis{};
  double offset = 0.0;  ///< the mean removed (|a| for acceleration)
  bool has_amplitude = true;
  /// Relative standard uncertainty of a scale common to every sample (a
  /// video track's circle radius); 0 where there is none.
  double scale_uncertainty = 0.0;
  /// A video track's circle: its radius and that radius's standard
  /// uncertainty (the track's unit); 0 where the angles are not its.
  double radius = 0.0, radius_sigma = 0.0;
};

/// DeltaT/T0 (Eq. 8, exact) of a swing whose amplitude theta (rad) a
/// reader estimated: of its size, capped just below pi. A corrupt record's
/// estimate can be negative by rounding or over the top; the analysis
/// refuses such swings where it reports them, not inside its sums.
double estimated_excess(double theta) { return finite_amplitude_agm(std::min(std::fabs(theta), kPi * (1.0 - 1e-9))); }

/// A sampled signal's swings need samples: fewer than 16 (none, where every
/// row lacked a cell it needs) are refused before anything reads them.
void require_several_swings(const Recording& r, const std::string& file) {
  if (r.time.size() < 16) {
    const std::string dropped = r.dropped == 0 ? ""
                                : " (" + std::to_string(r.dropped) + " row" + (r.dropped == 1 ? "" : "s") +
                                      " without a time or a signal's value set aside)";
    throw InputError(file, std::to_string(r.time.size()) + " samples" + dropped +
                               "; expected a recording of several swings");
  }
}

/// Projection on the principal axis of the mean-removed vectors: one pass
/// for the sums (shifted by the first sample, against cancellation), one for
/// the projection. M, the number of axes, is fixed at compile time so that
/// the passes over a long recording keep their sums in registers.
template <int M>
Signal principal_axis_of(const Recording& r) {
  using Vector = Eigen::Matrix<double, M, 1>;
  const std::size_t n = r.time.size();
  std::array<const double*, M> x{};
  Vector shift, sum = Vector::Zero();
  Eigen::Matrix<double, M, M> cross = Eigen::Matrix<double, M, M>::Zero();
  for (int j = 0; j < M; ++j) x[j] = r.channels[j].data(), shift[j] = x[j][0];
  for (std::size_t k = 0; k < n; ++k) {
    Vector d;
    for (int j = 0; j < M; ++j) d[j] = x[j][k] - shift[j];
    sum += d;
    for (int a = 0; a < M; ++a) {
      for (int b = a; b < M; ++b) cross(a, b) += d[a] * d[b];
    }
  }
  Eigen::Matrix<double, M, M> cov;
  const Vector mean = shift + sum / double(n);
  for (int a = 0; a < M; ++a) {
    for (int b = a; b < M; ++b) cov(a, b) = cov(b, a) = cross(a, b) / n - sum[a] * sum[b] / (double(n) * n);
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, M, M>> eig(cov);
  Vector v = eig.eigenvectors().col(M - 1);  // largest eigenvalue last
  Eigen::Index largest = 0;
  v.cwiseAbs().maxCoeff(&largest);
  if (v[largest] < 0.0) v = -v;  // the sign is arbitrary: make it reproducible
  Signal sig;
  for (int j = 0; j < M; ++j) sig.axis[j] = v[j];
  const double offset = v.dot(mean);
  sig.s.reserve(n);
  detail::huge_pages(sig.s);
  sig.s.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    double y = -offset;
    for (int j = 0; j < M; ++j) y += v[j] * x[j][k];
    sig.s[k] = y;
  }
  return sig;
}

/// A rate or acceleration layout has at least one channel (read.cpp's detect).
Signal principal_axis(const Recording& r) {
  switch (std::min<std::size_t>(r.channels.size(), 3)) {
    case 1: return principal_axis_of<1>(r);
    case 2: return principal_axis_of<2>(r);
    default: return principal_axis_of<3>(r);
  }
}

Signal remove_mean(std::vector<double> s) {
  double sum = 0.0;
  for (double x : s) sum += x;
  const double mean = s.empty() ? 0.0 : sum / s.size();
  for (double& x : s) x -= mean;
  Signal sig;
  sig.s = std::move(s);
  sig.offset = mean;
  return sig;
}

/// The angle about the centre of the circle through a video track (Kasa's
/// algebraic fit: x^2 + y^2 + D x + E y + F = 0 by least squares); the
/// projection on the principal axis, without amplitudes, when the track is
/// too straight for a centre.
Signal track_angle(const Recording& r) {
  const auto& x = r.channels[0];
  const auto& y = r.channels[1];
  const std::size_t n = x.size();
  double mx = 0.0, my = 0.0;
  for (std::size_t k = 0; k < n; ++k) mx += x[k], my += y[k];
  mx /= n, my /= n;
  Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
  Eigen::Vector3d atb = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    const Eigen::Vector3d a(x[k] - mx, y[k] - my, 1.0);
    const double b = -((x[k] - mx) * (x[k] - mx) + (y[k] - my) * (y[k] - my));
    ata += a * a.transpose();
    atb += a * b;
  }
  const Eigen::Vector3d c = ata.ldlt().solve(atb);
  double cx = -c[0] / 2.0, cy = -c[1] / 2.0;
  const double radius2 = cx * cx + cy * cy - c[2];
  double spread = 0.0;
  for (std::size_t k = 0; k < n; ++k) spread = std::max(spread, std::hypot(x[k] - mx, y[k] - my));
  // Kasa's fit underestimates the radius of a short noisy arc; Gauss-Newton
  // on the geometric distances |p - c| - R removes that bias.
  double radius = std::sqrt(radius2), radius_variance = 0.0;
  for (int iter = 0; iter < 20 && std::isfinite(radius); ++iter) {
    Eigen::Matrix3d jtj = Eigen::Matrix3d::Zero();
    Eigen::Vector3d jtr = Eigen::Vector3d::Zero();
    double rr = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const double dx = x[k] - mx - cx, dy = y[k] - my - cy, d = std::hypot(dx, dy);
      const Eigen::Vector3d j(-dx / d, -dy / d, -1.0);
      jtj += j * j.transpose();
      jtr += j * (d - radius);
      rr += (d - radius) * (d - radius);
    }
    const Eigen::Vector3d step = jtj.ldlt().solve(-jtr);
    cx += step[0], cy += step[1], radius += step[2];
    // The radius's variance from the step's Gauss-Newton covariance.
    radius_variance = n > 3 ? jtj.inverse()(2, 2) * rr / static_cast<double>(n - 3) : 0.0;
    if (step.norm() < 1e-12 * radius) break;
  }
  if (!(radius > 0.0) || !std::isfinite(radius) || radius > 1e3 * spread) {
    Signal sig = principal_axis(r);
    sig.has_amplitude = false;
    return sig;
  }
  // Angles of the points seen from the centre, relative to the mean point's.
  const double phi0 = std::atan2(-cy, -cx);
  std::vector<double> angle(n);
  for (std::size_t k = 0; k < n; ++k) {
    angle[k] = std::remainder(std::atan2(y[k] - my - cy, x[k] - mx - cx) - phi0, 2.0 * kPi);
  }
  Signal sig = remove_mean(std::move(angle));
  // An angle about a centre off by the radius's error is off by that
  // fraction (300 simulated tracks: 0.7 % in R, 0.8 % in the amplitude).
  sig.radius = radius;
  sig.radius_sigma = std::isfinite(radius_variance) ? std::sqrt(std::max(radius_variance, 0.0)) : 0.0;
  sig.scale_uncertainty = sig.radius_sigma / radius;
  return sig;
}

/// Relative standard uncertainty of a length taken as the distance from the
/// pivot to the tracked point: the period's length is the equivalent simple
/// pendulum's, d (1 + 2/5 (r/d)^2) for a sphere of radius r on a string d
/// (1.6 % at r = d/5), and standard gravity is within 0.3 % of a local g.
constexpr double kTrackLengthModel = 0.02;

/// A video track's angle when its circle is not trusted: asin(u / length),
/// u the displacement along the swing (the principal axis) from its mean,
/// `length` in the track's unit.
Signal displacement_angle(const Recording& r, double length) {
  Signal sig = principal_axis(r);
  for (double& u : sig.s) u = std::asin(std::clamp(u / length, -1.0, 1.0));
  Signal out = remove_mean(std::move(sig.s));
  out.axis = sig.axis;
  out.scale_uncertainty = kTrackLengthModel;
  return out;
}

/// `track_length` (the track's unit): a video track's angles from it
/// instead of its circle (displacement_angle) where positive.
Signal make_signal(const Recording& r, double track_length = 0.0) {
  switch (r.kind) {
    case SignalKind::angular_rate:
    case SignalKind::linear_acceleration: return principal_axis(r);
    case SignalKind::acceleration: {
      std::vector<double> magnitude(r.time.size());
      for (std::size_t k = 0; k < magnitude.size(); ++k) {
        double sum = 0.0;
        for (const auto& c : r.channels) sum += c[k] * c[k];
        magnitude[k] = std::sqrt(sum);
      }
      Signal sig = remove_mean(std::move(magnitude));
      sig.crossings_per_period = 4;
      return sig;
    }
    case SignalKind::angle: return remove_mean(r.channels[0]);
    case SignalKind::unknown: {
      Signal sig = remove_mean(r.channels[0]);
      sig.has_amplitude = false;
      return sig;
    }
    case SignalKind::position: return track_length > 0.0 ? displacement_angle(r, track_length) : track_angle(r);
    case SignalKind::gate_states:
    case SignalKind::blocking_times:
    case SignalKind::event_stamps: break;
  }
  return {};
}

/// Noise sigma from second differences: their median absolute value over
/// 0.6745 sqrt(6) for white noise; a smooth swing adds little to them.
double noise_sigma(const std::vector<double>& s) {
  if (s.size() < 3) return 0.0;
  // At most 2^16 differences, evenly spread: the median needs no more.
  const std::size_t step = std::max<std::size_t>(1, (s.size() - 2) >> 16);
  std::vector<double> d;
  d.reserve((s.size() - 2) / step + 1);
  for (std::size_t k = 1; k + 1 < s.size(); k += step) d.push_back(std::fabs(s[k + 1] - 2.0 * s[k] + s[k - 1]));
  auto mid = d.begin() + d.size() / 2;
  std::nth_element(d.begin(), mid, d.end());
  return *mid / (0.6745 * std::sqrt(6.0));
}

/// Least-squares line s = a + b (t - tm) through samples [i, j]; its zero.
/// Where all their times are one (a clock printed to fewer digits than its
/// frame rate needs), the window widens by a sample each side until two
/// times differ: a line needs two.
Crossing line_zero(const std::vector<double>& t, const std::vector<double>& s, std::size_t i, std::size_t j) {
  // The window's own samples: its weight, and where find_crossings resumes.
  const int window = static_cast<int>(j - i + 1);
  while (t[i] == t[j] && (i > 0 || j + 1 < t.size())) {
    if (i > 0) --i;
    if (j + 1 < t.size()) ++j;
  }
  const double n = static_cast<double>(j - i + 1);
  double tm = 0.0, sm = 0.0;
  for (std::size_t k = i; k <= j; ++k) tm += t[k], sm += s[k];
  tm /= n, sm /= n;
  double stt = 0.0, sts = 0.0;
  for (std::size_t k = i; k <= j; ++k) {
    stt += (t[k] - tm) * (t[k] - tm);
    sts += (t[k] - tm) * (s[k] - sm);
  }
  const double slope = sts / stt;
  return {tm - sm / slope, slope, window};
}

/// The extremum of a sparse half swing (fewer than 7 samples in its middle
/// third: video at 5-20 frames/s) between crossings at ta and tb: the
/// least-squares a + b cos phi + c sin phi + d cos 3phi + e sin 3phi through
/// its samples strictly between ta and tb, phi = pi (t - t_mid)/(tb - ta) in
/// (-pi/2, pi/2): a swing is a cos phi, its finite amplitude adds the third
/// harmonic (theta0^2/16 of it, Kelley Eq. 12), damping and an offset c sin
/// phi and a. At least 7 samples (5 parameters and two to spare), or 6
/// without e sin 3phi (a decay's asymmetry within one half swing, of second
/// order: 20 frames/s of a 0.66 s swing give 6 or 7); maximised by Newton's
/// method from phi = 0 within +-pi/3. Returns the time and |value|.
std::pair<double, double> sparse_peak(const std::vector<double>& t, const std::vector<double>& s, std::size_t i,
                                      double ta, double tb) {
  const double mid = (ta + tb) / 2.0, scale = kPi / (tb - ta);
  Eigen::Matrix<double, 5, 5> ata = Eigen::Matrix<double, 5, 5>::Zero();
  Eigen::Matrix<double, 5, 1> atb = Eigen::Matrix<double, 5, 1>::Zero();
  auto basis = [](double phi) {
    return Eigen::Matrix<double, 5, 1>(1.0, std::cos(phi), std::sin(phi), std::cos(3.0 * phi), std::sin(3.0 * phi));
  };
  int used = 0;
  // From the window's first sample to the last before tb (the caller's j
  // stops at the next crossing's window, a sample or two short of tb).
  for (std::size_t k = i; k < t.size() && t[k] < tb; ++k) {
    if (!(t[k] > ta)) continue;
    const Eigen::Matrix<double, 5, 1> b = basis((t[k] - mid) * scale);
    ata += b * b.transpose(), atb += b * s[k];
    ++used;
  }
  if (used < 6) return {mid, kNaN};  // too few samples for a peak
  Eigen::Matrix<double, 5, 1> c = Eigen::Matrix<double, 5, 1>::Zero();
  if (used == 6) {
    c.head<4>() = ata.topLeftCorner<4, 4>().ldlt().solve(atb.head<4>());
  } else {
    c = ata.ldlt().solve(atb);
  }
  double phi = 0.0;
  for (int iter = 0; iter < 8; ++iter) {
    const double d1 = -c[1] * std::sin(phi) + c[2] * std::cos(phi) - 3.0 * c[3] * std::sin(3.0 * phi) +
                      3.0 * c[4] * std::cos(3.0 * phi);
    const double d2 = -c[1] * std::cos(phi) - c[2] * std::sin(phi) - 9.0 * c[3] * std::cos(3.0 * phi) -
                      9.0 * c[4] * std::sin(3.0 * phi);
    if (d2 == 0.0) break;
    phi = std::clamp(phi - d1 / d2, -kPi / 3.0, kPi / 3.0);
  }
  const double value = basis(phi).dot(c);
  return {mid + phi / scale, std::isfinite(value) ? std::fabs(value) : kNaN};
}

/// The extremum of a half swing between crossings at ta and tb: a quartic
/// least-squares polynomial through the samples within the middle third of
/// [ta, tb] (+-60 deg of phase about its centre, where the swing is
/// symmetric), maximised by Newton's method from the centre. The window is
/// fixed by the crossings, not by the noisy samples, so noise does not bias
/// the peak upward as picking the largest sample would; a quartic follows a
/// cosine over +-60 deg to 2e-4 of its peak. Returns the time and |value|.
std::pair<double, double> peak(const std::vector<double>& t, const std::vector<double>& s, std::size_t i,
                               std::size_t j, double ta, double tb) {
  const double mid = (ta + tb) / 2.0, half = (tb - ta) / 6.0;
  // Normal equations from power sums: sum u^0..u^8 and sum s u^0..u^4.
  std::array<double, 9> pu{};
  std::array<double, 5> ps{};
  int used = 0;
  const auto first = std::lower_bound(t.begin() + i, t.begin() + j + 1, mid - half);
  for (std::size_t k = first - t.begin(); k <= j && t[k] <= mid + half; ++k) {
    const double u = (t[k] - mid) / half;  // -1 .. 1 inside the window
    double power = 1.0;
    for (int q = 0; q < 5; ++q, power *= u) pu[q] += power, ps[q] += power * s[k];
    for (int q = 5; q < 9; ++q, power *= u) pu[q] += power;
    ++used;
  }
  if (used < 7) return sparse_peak(t, s, i, ta, tb);
  Eigen::Matrix<double, 5, 5> ata;
  for (int a = 0; a < 5; ++a) {
    for (int b = 0; b < 5; ++b) ata(a, b) = pu[a + b];
  }
  const Eigen::Matrix<double, 5, 1> c = ata.ldlt().solve(Eigen::Map<const Eigen::Matrix<double, 5, 1>>(ps.data()));
  double u = 0.0;
  for (int iter = 0; iter < 8; ++iter) {
    const double d1 = c[1] + u * (2.0 * c[2] + u * (3.0 * c[3] + u * 4.0 * c[4]));
    const double d2 = 2.0 * c[2] + u * (6.0 * c[3] + u * 12.0 * c[4]);
    if (d2 == 0.0) break;
    u = std::clamp(u - d1 / d2, -1.0, 1.0);
  }
  const double value = c[0] + u * (c[1] + u * (c[2] + u * (c[3] + u * c[4])));
  return {mid + u * half, std::fabs(value)};
}

/// The largest |s| and the root mean square of s, in one pass.
struct Extent {
  double peak = 0.0, rms = 0.0;
};

Extent extent(const std::vector<double>& s) {
  Extent e;
  for (double x : s) e.peak = std::max(e.peak, std::fabs(x)), e.rms += x * x;
  e.rms = std::sqrt(e.rms / s.size());
  return e;
}

/// Crossings of a sampled signal with adaptive hysteresis: h is a fraction
/// of the last half swing's peak. Where no crossing follows within four mean
/// intervals, the last half swings held a knock, not the swing (from its
/// peak, h lay above every swing after it, and a knock of 1/fraction times
/// the swing lost the rest of the record): the search starts again from the
/// last crossing, once, with h from the least of the last four half swings'
/// peaks, which a knock of up to three half swings leaves a swing's, and
/// of the record's swing level (sqrt 2 rms, `rms` robust: swing_level),
/// which a longer knock (lost tracking: seconds of noise) does not reach.
std::vector<Crossing> find_crossings(const std::vector<double>& t, const Signal& sig, double rms, double noise,
                                     double fraction, std::vector<std::size_t>& at) {
  const auto& s = sig.s;
  const double floor = 5.0 * noise;
  double h = std::max(fraction * std::sqrt(2.0) * rms, floor);
  std::vector<Crossing> out;
  int state = 0;                // -1: beyond -h, +1: beyond +h
  std::size_t last_beyond = 0;  // last sample beyond the threshold of `state`
  std::array<double, 4> peaks;  // the last half swings' peaks, the latest at peaks[crossings % 4]
  peaks.fill(std::numeric_limits<double>::infinity());
  bool retried = false;
  for (std::size_t k = 0; k < s.size(); ++k) {
    // The samples up to the first beyond the threshold opposite `state`, in
    // a loop of their own: it makes no call, so the running peak stays in a
    // register (across the push_backs below it went through memory).
    double half_peak = 0.0;
    const double stall = out.size() >= 3 && !retried
                             ? out.back().time + 4.0 * (out.back().time - out.front().time) / (out.size() - 1)
                             : std::numeric_limits<double>::infinity();
    bool stalled = false;
    for (; k < s.size(); ++k) {
      const double x = s[k];
      half_peak = std::max(half_peak, std::fabs(x));
      if (x < -h || x > h) {
        const int side = x > 0 ? 1 : -1;
        if (state == -side) break;
        state = side;
        last_beyond = k;
      }
      if (t[k] > stall) {
        stalled = true;
        break;
      }
    }
    if (k == s.size()) break;
    if (stalled) {
      retried = true;
      h = std::max(fraction * std::min(*std::min_element(peaks.begin(), peaks.end()), std::sqrt(2.0) * rms), floor);
      k = at.back() + (out.back().samples - 1);  // the sample that made the last crossing
      last_beyond = k, state = s[k] > 0 ? 1 : -1;
      continue;
    }
    out.push_back(line_zero(t, s, last_beyond, k));
    at.push_back(last_beyond);
    peaks[out.size() % peaks.size()] = half_peak;
    h = std::max(fraction * half_peak, floor);
    retried = false;
    state = -state;
    last_beyond = k;
  }
  return out;
}

/// Gate passages: the middle of each blocking, and its duration (NaN for
/// bare blocking times).
/// Each gate event's state as blocked (1) or open (0). A passage blocks the
/// beam for a small part of the swing, and exporters differ in which state
/// they call blocked: the state held for less time overall is. A gate's
/// states are 0 and 1; a light sensor's intensity is split into its dark and
/// bright levels by Otsu's threshold (the split of the sorted samples that
/// maximises the variance between the two levels' means: a passage darkens
/// 1-5 % of the samples, too few for a percentile to find), halfway between
/// their means, with a tenth of their difference either side as hysteresis,
/// so that noise on a slow edge makes no second passage.
std::vector<double> blocked_states(const Recording& r) {
  const auto& state = r.channels[0];
  double middle = 0.5, band = 0.0;
  if (std::any_of(state.begin(), state.end(), [](double s) { return s != 0.0 && s != 1.0; })) {
    std::vector<double> sorted(state);
    std::sort(sorted.begin(), sorted.end());
    const std::size_t n = sorted.size();
    double total = 0.0;
    for (double x : sorted) total += x;
    double below = 0.0, best = -1.0, dark = sorted.front(), bright = sorted.back();
    for (std::size_t i = 1; i < n; ++i) {
      below += sorted[i - 1];
      if (sorted[i] == sorted[i - 1]) continue;
      const double w = static_cast<double>(i) / static_cast<double>(n);
      const double m0 = below / static_cast<double>(i), m1 = (total - below) / static_cast<double>(n - i);
      const double between = w * (1.0 - w) * (m1 - m0) * (m1 - m0);
      if (between > best) best = between, dark = m0, bright = m1;
    }
    middle = (dark + bright) / 2.0;
    band = (bright - dark) / 10.0;
  }
  std::vector<bool> high(state.size());
  for (std::size_t k = 0; k < state.size(); ++k) {
    high[k] = k == 0 ? state[k] > middle : state[k] > middle + band || (high[k - 1] && state[k] > middle - band);
  }
  double time_high = 0.0, time_low = 0.0;
  for (std::size_t k = 0; k + 1 < r.time.size(); ++k) (high[k] ? time_high : time_low) += r.time[k + 1] - r.time[k];
  const bool high_is_blocked = time_high <= time_low;
  std::vector<double> blocked(state.size());
  for (std::size_t k = 0; k < state.size(); ++k) blocked[k] = high[k] == high_is_blocked ? 1.0 : 0.0;
  return blocked;
}

std::vector<Crossing> gate_passages(const Recording& r, std::vector<double>& durations) {
  std::vector<Crossing> out;
  if (r.kind == SignalKind::blocking_times) {
    for (double t : r.time) out.push_back({t, 0.0, 0});
    durations.assign(out.size(), kNaN);
    return out;
  }
  const std::vector<double> state = blocked_states(r);
  std::optional<double> blocked_at;
  for (std::size_t k = 0; k < r.time.size(); ++k) {
    const bool blocked = state[k] > 0.5;
    if (blocked && !blocked_at) blocked_at = r.time[k];
    if (!blocked && blocked_at) {
      out.push_back({(*blocked_at + r.time[k]) / 2.0, 0.0, 0});
      durations.push_back(r.time[k] - *blocked_at);
      blocked_at.reset();
    }
  }
  return out;
}

}  // namespace

namespace {

/// The least standard uncertainty (per unit of x) of a slope fitted to
/// times at x on a clock of resolution q (s): each time rounded to the
/// clock's step carries a uniform error of variance q^2/12, and the straight
/// line's slope then has variance q^2/12 / sum (x_i - mean x)^2. A fit with
/// more terms only adds to it: a floor whatever the model.
double resolution_floor(const std::vector<double>& x, double q) {
  if (!(q > 0.0) || x.size() < 2) return 0.0;
  double mean = 0.0, sxx = 0.0;
  for (double v : x) mean += v / x.size();
  for (double v : x) sxx += (v - mean) * (v - mean);
  return q / std::sqrt(12.0) / std::sqrt(sxx);
}

/// No crossing carries the fit: a weight is at most this many times the
/// median. A swing decaying from 81 deg to 17 deg spreads its crossings'
/// weights (slope squared) over a factor (81/17)^2 = 23 end to end, 4 about
/// the median; a spurious crossing on a one-frame jump of a track has a
/// slope hundreds of times the swing's and, uncapped, took the fit with it.
constexpr double kWeightCap = 25.0;

/// The residuals' lag-1 autocorrelation rho (z standardised, ssr their sum
/// of squares) and the AR(1) variance factor (1 + rho)/(1 - rho) for rho > 0,
/// rho capped at 0.95: the effective sample size of correlated residuals.
void set_autocorrelation(const std::vector<double>& z, double ssr, PeriodEstimate& p) {
  double lag = 0.0;
  for (std::size_t i = 0; i + 1 < z.size(); ++i) lag += z[i] * z[i + 1];
  p.lag1_correlation = ssr > 0.0 ? lag / ssr : 0.0;
  const double rho = std::min(p.lag1_correlation, 0.95);
  p.inflation = rho > 0.0 ? (1.0 + rho) / (1.0 - rho) : 1.0;
}

}  // namespace

PeriodEstimate fit_crossing_times(const std::vector<Crossing>& c, int per_period,
                                  const std::vector<double>& amplitudes, double quantum) {
  const std::size_t n = c.size();
  // The index: i, or the amplitude-weighted u_{i+1} = u_i + 1 + DeltaT/T0(theta_i)
  // (Eq. 8, exact), in which the crossing times of a decaying swing lie on a line.
  // Across a bridged glitch (steps > 1) the count runs on by its steps,
  // each at the swing's smooth amplitude there.
  std::vector<double> u(n);
  std::vector<long> count(n);
  const bool weighted_index = amplitudes.size() + 1 == n;
  for (std::size_t i = 1; i < n; ++i) {
    count[i] = count[i - 1] + c[i].steps;
    const double steps = static_cast<double>(c[i].steps);  // added in this order, one step is as before to the bit
    u[i] = u[i - 1] + steps + steps * (weighted_index ? estimated_excess(amplitudes[i - 1]) : 0.0);
  }
  const double centre = (u[0] + u[n - 1]) / 2.0;  // mid-range: the quadratic term then drops out of the mean
  // Without the amplitude-weighted index, a cubic term too: the finite-amplitude
  // period drifts with theta0^2, whose curvature puts a cubic of some 20 us into
  // 20 s of crossings (a photogate times them to a few us).
  const bool cubic = !weighted_index && n >= 12;
  const int q = cubic ? 5 : 4;  // parameters: 1, x, x^2, (x^3,) (-1)^i
  Eigen::MatrixXd xtwx = Eigen::MatrixXd::Zero(q, q);
  Eigen::VectorXd xtwt = Eigen::VectorXd::Zero(q);
  std::vector<double> w(n, 1.0);
  if (c[0].samples > 0) {
    double mean = 0.0;
    for (std::size_t i = 0; i < n; ++i) mean += (w[i] = c[i].slope * c[i].slope * c[i].samples);
    for (double& x : w) x /= mean / n;
    std::vector<double> sorted = w;
    std::nth_element(sorted.begin(), sorted.begin() + n / 2, sorted.end());
    const double cap = kWeightCap * sorted[n / 2];
    if (cap > 0.0) {
      for (double& x : w) x = std::min(x, cap);
    }
  }
  const double t0 = c[0].time;
  auto row = [&](std::size_t i) {
    const double x = u[i] - centre;
    Eigen::VectorXd r(q);
    r[0] = 1.0, r[1] = x, r[2] = x * x, r[3] = count[i] % 2 ? -1.0 : 1.0;
    if (cubic) r[4] = x * x * x;
    return r;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::VectorXd r = row(i);
    xtwx += w[i] * r * r.transpose();
    xtwt += w[i] * r * (c[i].time - t0);
  }
  const Eigen::MatrixXd inv = xtwx.inverse();
  const Eigen::VectorXd beta = inv * xtwt;
  std::vector<double> z(n);
  double ssr = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    z[i] = (c[i].time - t0 - row(i).dot(beta)) * std::sqrt(w[i]);
    ssr += z[i] * z[i];
  }
  PeriodEstimate p;
  set_autocorrelation(z, ssr, p);
  const double s2 = ssr / (static_cast<double>(n) - q);
  // The mean period over the crossings: the fitted curve's rise from the
  // first to the last, per period. About the centre, x_n = -x_0 = X: the
  // quadratic term adds nothing, the cubic X^2 times its coefficient.
  const double half_range = (u[n - 1] - u[0]) / 2.0;
  Eigen::VectorXd g = Eigen::VectorXd::Zero(q);
  g[1] = 1.0;
  if (cubic) g[4] = half_range * half_range;
  const double scale = per_period * (u[n - 1] - u[0]) / static_cast<double>(count[n - 1]);
  p.value = scale * g.dot(beta);
  p.uncertainty = scale * std::sqrt(s2 * g.dot(inv * g) * p.inflation);
  // Each crossing's time is taken to carry the clock's whole q^2/12 (a line
  // through m samples averages some of it: an upper bound, and a floor).
  p.resolution_floor = scale * resolution_floor(u, quantum);
  p.uncertainty = std::max(p.uncertainty, p.resolution_floor);
  p.residual_rms = std::sqrt(s2);
  p.periods = static_cast<int>(count[n - 1] / per_period);
  return p;
}

namespace {

/// Throws unless sin(theta0/2) = `sine` < 1: a peak rate or speed beyond
/// the energy of 180 deg means the pendulum went over the top.
void require_below_top(double sine, const std::string& file) {
  if (!(sine < 1.0)) {
    throw InputError(file, "a swing's peak rate means an amplitude of 180 deg or more "
                           "(the pendulum went over the top); expected a swinging pendulum");
  }
}

/// "12.3456 s"
std::string seconds(double t, int digits = 6) { return format_number(t, digits) + " s"; }

/// The signal's level that sets the first crossing's threshold: its rms or,
/// where a knock many times the swing swells that beyond twice the median
/// |s| (the two agree for a sine; noise's rms is 1.48 times its median |s|),
/// the median |s|, which a knock over less than half the record leaves the
/// swing's. A knock 20 times the swing over 0.7 s of a 20 s record had put
/// the threshold above every swing before it. The median from at most 16384
/// samples, evenly spread.
double swing_level(const std::vector<double>& s, double rms) {
  const std::size_t stride = (s.size() + 16383) >> 14;
  std::vector<double> a;
  a.reserve(s.size() / stride + 1);
  for (std::size_t k = 0; k < s.size(); k += stride) a.push_back(std::fabs(s[k]));
  const double median = median_of(std::move(a));
  return rms > 2.0 * median ? median : rms;
}

/// The swing's amplitude below which the threshold's floor of 5 noise
/// sigmas nears its peaks (half of them and more) and noise crosses it:
/// crossings come from local sine fits instead (sine_fit_crossings).
constexpr double kNoisySwing = 10.0;

/// Crossings of a swing under kNoisySwing noise sigmas: found on the signal
/// averaged over at most the fewest samples that bring the noise to a tenth
/// of the swing (`swing`, its amplitude), then each timed by the least-squares
/// b sin(w u) + c cos(w u), u = t - t_c, through the raw samples within half
/// an interval of that crossing t_c, w = pi / (the median interval): its
/// zero, t_c - atan(c / b) / w. The fit's variance of that time, 2 sigma^2 /
/// (N R^2 w^2) for N samples of a sine of amplitude R, is a line's sigma^2 /
/// (slope^2 n) with the slope R w and n = N / 2. The average's own crossings
/// lag a window's asymmetry and move with its noise; the fits do not.
std::vector<Crossing> sine_fit_crossings(const std::vector<double>& t, const Signal& sig, double swing, double noise,
                                         double fraction, std::vector<std::size_t>& at) {
  const std::size_t n = sig.s.size();
  std::vector<double> prefix(n + 1, 0.0);
  for (std::size_t k = 0; k < n; ++k) prefix[k + 1] = prefix[k] + sig.s[k];
  // The average over m samples also shrinks the swing where m spans much of
  // it (a sparse track, whose curvature swells the second differences'
  // noise: 9 frames a period read 4.5 sigmas): halved down to 1, the m that
  // finds the most crossings, each beyond 5 sigmas of the averaged noise.
  std::vector<std::size_t> rough_at;
  std::vector<Crossing> rough;
  Signal averaged = sig;
  for (auto m = static_cast<std::size_t>(std::ceil(std::pow(kNoisySwing * noise / swing, 2.0))); m >= 1; m /= 2) {
    for (std::size_t k = 0; k < n; ++k) {
      const std::size_t a = k >= m / 2 ? k - m / 2 : 0, b = std::min(n, k + (m - m / 2));
      averaged.s[k] = (prefix[b] - prefix[a]) / static_cast<double>(b - a);
    }
    std::vector<std::size_t> at_m;
    std::vector<Crossing> found =
        find_crossings(t, averaged, swing / std::sqrt(2.0), noise / std::sqrt(static_cast<double>(m)), fraction, at_m);
    if (found.size() > rough.size()) rough = std::move(found), rough_at = std::move(at_m);
  }
  if (rough.size() < 3) {
    at = rough_at;
    return rough;  // too few: the caller refuses the record
  }
  std::vector<double> intervals;
  for (std::size_t i = 1; i < rough.size(); ++i) intervals.push_back(rough[i].time - rough[i - 1].time);
  const double d = median_of(intervals), w = kPi / d;
  std::vector<Crossing> out;
  for (const Crossing& c : rough) {
    const auto lo = std::lower_bound(t.begin(), t.end(), c.time - d / 2.0);
    const auto hi = std::upper_bound(t.begin(), t.end(), c.time + d / 2.0);
    double ss = 0.0, cc = 0.0, sc = 0.0, ys = 0.0, yc = 0.0;
    for (auto it = lo; it != hi; ++it) {
      const double u = w * (*it - c.time), sn = std::sin(u), cs = std::cos(u);
      const double y = sig.s[static_cast<std::size_t>(it - t.begin())];
      ss += sn * sn, cc += cs * cs, sc += sn * cs, ys += y * sn, yc += y * cs;
    }
    const double det = ss * cc - sc * sc;
    if (hi - lo < 4 || !(det > 0.0)) continue;
    const double b = (cc * ys - sc * yc) / det, a = (ss * yc - sc * ys) / det;  // sine and cosine parts
    if (b == 0.0) continue;
    const double shift = -std::atan(a / b) / w;
    const double time = c.time + shift;
    if (!out.empty() && !(time > out.back().time)) continue;
    const int samples = std::max(2, static_cast<int>((hi - lo) / 2));
    out.push_back({time, w * (b * std::cos(w * shift) - a * std::sin(w * shift)), samples});
    at.push_back(static_cast<std::size_t>(std::upper_bound(t.begin(), t.end(), time) - t.begin()) - 1);
  }
  return out;
}

/// Half swings whose peak is no swing's (a knock on the phone, a jump of a
/// track): |log(peak / m)| beyond the larger of log 1.5 and 6 robust sigmas
/// of that log over the record, and |peak - m| beyond 10 times the signal's
/// noise (a swing decayed into the noise scatters so without a knock), m the
/// median of the peaks of the same parity (an alternating offset, or an
/// acceleration's bottoms and dips, keep theirs) up to 8 half swings away, at
/// least 4 of them. A pendulum's amplitude changes far less over so few
/// swings; a knock 25 times the swing read the start amplitude 15 % high
/// through its swings' averages. Their indices, in order.
std::vector<std::size_t> peak_outliers(const std::vector<double>& raw, double noise) {
  const std::size_t n = raw.size();
  std::vector<double> log_ratio(n, kNaN), beside(n, kNaN);
  std::vector<double> near;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(raw[i] > 0.0)) continue;
    near.clear();
    for (std::size_t step = 2; step <= 8; step += 2) {
      if (i >= step && raw[i - step] > 0.0) near.push_back(raw[i - step]);
      if (i + step < n && raw[i + step] > 0.0) near.push_back(raw[i + step]);
    }
    if (near.size() >= 4) beside[i] = median_of(near), log_ratio[i] = std::log(raw[i] / beside[i]);
  }
  std::vector<double> spread;
  for (double x : log_ratio) {
    if (std::isfinite(x)) spread.push_back(std::fabs(x));
  }
  if (spread.empty()) return {};
  const double limit = std::max(std::log(1.5), 6.0 * 1.4826 * median_of(spread));
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::fabs(log_ratio[i]) > limit && std::fabs(raw[i] - beside[i]) > 10.0 * noise) out.push_back(i);
  }
  return out;
}

/// The coarsest decimal step 10^-k s (k = 0..9) of which every time is a
/// multiple: the resolution the file printed its clock to (a timer's 1 ms, a
/// photogate's 10 us); 0 when there is none (times to full double precision,
/// as a simulation's). At most 4096 times, evenly spread, are looked at.
double printed_resolution(const std::vector<double>& t) {
  if (t.empty()) return 0.0;
  const std::size_t stride = std::max<std::size_t>(1, t.size() >> 12);
  for (int k = 0; k <= 9; ++k) {
    const double step = std::pow(10.0, -k);
    bool all = true;
    for (std::size_t i = 0; i < t.size() && all; i += stride) {
      const double x = t[i] / step;
      all = std::fabs(x - std::round(x)) <= 1e-9 + 8.0 * std::numeric_limits<double>::epsilon() * std::fabs(x);
    }
    if (all) return step;
  }
  return 0.0;
}

/// The samples or events of `r` with time in [range.first, range.second].
Recording restricted(const Recording& r, std::pair<double, double> range, const std::string& file) {
  const auto [a, b] = range;
  if (!(a < b) || !std::isfinite(a) || !std::isfinite(b)) {
    throw InputError(file, "got the range " + format_number(a) + ":" + format_number(b) +
                               " s; expected two times, the first before the second (--range A:B, a scene's "
                               "\"range\")");
  }
  const std::size_t first = std::lower_bound(r.time.begin(), r.time.end(), a) - r.time.begin();
  const std::size_t last = std::upper_bound(r.time.begin(), r.time.end(), b) - r.time.begin();
  if (first >= last) {
    throw InputError(file, "no sample in the range " + format_number(a) + ":" + format_number(b) +
                               " s; expected a range within the recording's " +
                               (r.time.empty() ? std::string("(empty)")
                                               : format_number(r.time.front()) + ":" + format_number(r.time.back())) +
                               " s");
  }
  Recording out;
  out.format = r.format, out.kind = r.kind, out.channel_names = r.channel_names;
  out.time_quantum = r.time_quantum, out.notes = r.notes, out.rows = r.rows, out.dropped = r.dropped, out.set = r.set;
  out.time.assign(r.time.begin() + first, r.time.begin() + last);
  for (const auto& c : r.channels) out.channels.emplace_back(c.begin() + first, c.begin() + last);
  if (r.counts.size() == r.time.size()) out.counts.assign(r.counts.begin() + first, r.counts.begin() + last);
  return out;
}

/// Step 7: stretches where the crossings (or stamps, per count: `index`)
/// leave the swing. Each full period, the time from an entry to the one
/// `per_period` entries on, per unit of index (none across more than two
/// periods: a bridged glitch, a run of missed stamps), is compared with the
/// median of its 10 neighbours on either side, in units of its own noise
/// (sqrt(1/w_a + 1/w_b), w the entries' weights, relative to the median's)
/// and of the robust sigma (the rules below; at least the q/sqrt(6) of two
/// times on a clock of resolution q, and 1e-9 of the period). A full
/// period, not a half: an offset between the two directions (a gyroscope's
/// bias, a track's pivot off its vertical, a gate off the lowest point) moves
/// the half swings' lengths apart, and where it drifts (a camera nudged, a
/// bias warming up) it moved them by 20 robust sigmas on a clean track, but
/// it cancels from every full period. With `lengths` (one per interval, in
/// index steps: 1 + DeltaT/T0 of its swing's smooth amplitude) each period
/// is taken per its own length, its noise joined by what `length_errors`
/// (per interval, in the weights' unit) say the lengths may be off by, and
/// without them less a quadratic drift:
/// a strong decay shortens the periods by more than their noise from one
/// to the next. Beyond 6 robust sigmas is an outlier (1 in 5e8 for normal
/// noise); outliers 4 entries apart or less are one stretch, and one within
/// 4 entries of an end reaches it. join_glitches makes glitches of them.
std::vector<Glitch> outlier_stretches(const std::vector<Crossing>& c, const std::vector<long>& index, int per_period,
                                  const std::vector<double>& weight, double quantum,
                                  const std::vector<double>& lengths = {},
                                  const std::vector<double>& length_errors = {}) {
  constexpr double kOutlier = 6.0;
  constexpr std::size_t kJoin = 4, kNeighbours = 10;
  const std::size_t n = c.size(), span = static_cast<std::size_t>(per_period);
  std::vector<Glitch> out;
  if (n < 8 || n <= span) return out;
  // The full periods, from crossing at[v] to at[v] + span; none across a
  // bridged glitch or a long run of missed stamps, whose mean over many
  // periods is no period of its own.
  std::vector<std::size_t> at;
  std::vector<double> d, sd;
  for (std::size_t i = 0; i + span < n; ++i) {
    if (index[i + span] - index[i] > 2 * per_period) continue;
    double steps = 0.0, steps_error = 0.0;
    for (std::size_t k = i; k < i + span; ++k) {
      steps += static_cast<double>(index[k + 1] - index[k]) * (lengths.empty() ? 1.0 : lengths[k]);
      if (!length_errors.empty()) steps_error += static_cast<double>(index[k + 1] - index[k]) * length_errors[k];
    }
    at.push_back(i);
    d.push_back((c[i + span].time - c[i].time) / steps);
    sd.push_back(std::hypot(std::sqrt(1.0 / weight[i] + 1.0 / weight[i + span]), d.back() * steps_error) / steps);
  }
  const std::size_t m = d.size();
  if (m < 4) return out;
  // Less a quadratic drift in time (least squares over the periods within
  // 10 % of the median, again without what lies beyond 5 robust sigmas of
  // it): a swing decaying without amplitudes to
  // weight the index shortens its periods by more than their noise from one
  // to the next, and the median of such a monotonic window is the period
  // itself inside the record and is biased by the drift at its ends.
  std::vector<double> r = d;
  if (lengths.empty() && m >= 8) {
    const double mid = (c[at.front()].time + c[at.back()].time) / 2.0;
    const double half = std::max((c[at.back()].time - c[at.front()].time) / 2.0, 1e-300);
    // A period 10 % off the median is a glitch (a lost count), whatever drifts.
    const double typical = median_of(d);
    std::vector<bool> use(m);
    for (std::size_t i = 0; i < m; ++i) use[i] = std::fabs(d[i] - typical) < 0.1 * typical;
    for (int round = 0; round < 2; ++round) {
      Eigen::Matrix3d ata = Eigen::Matrix3d::Zero();
      Eigen::Vector3d atd = Eigen::Vector3d::Zero();
      for (std::size_t i = 0; i < m; ++i) {
        if (!use[i]) continue;
        const double x = (c[at[i]].time - mid) / half;
        const Eigen::Vector3d row(1.0, x, x * x);
        ata += row * row.transpose(), atd += row * d[i];
      }
      const Eigen::Vector3d q = ata.ldlt().solve(atd);
      if (!q.allFinite()) break;
      for (std::size_t i = 0; i < m; ++i) {
        const double x = (c[at[i]].time - mid) / half;
        r[i] = d[i] - (q[0] + x * (q[1] + x * q[2]));
      }
      std::vector<double> spread(m);
      std::transform(r.begin(), r.end(), spread.begin(), [](double x) { return std::fabs(x); });
      const double robust = 1.4826 * median_of(spread);
      for (std::size_t i = 0; i < m; ++i) use[i] = std::fabs(r[i]) <= 5.0 * robust;
    }
  }
  // Against the median of its neighbours, itself left out: with itself in,
  // a monotonic window's median is the period itself (e = 0 exactly for
  // nearly all of a smooth record, and a robust sigma of nothing).
  std::vector<double> e(m);
  std::vector<double> window;
  for (std::size_t i = 0; i < m; ++i) {
    window.assign(r.begin() + static_cast<long>(i > kNeighbours ? i - kNeighbours : 0), r.begin() + static_cast<long>(i));
    window.insert(window.end(), r.begin() + static_cast<long>(i) + 1,
                  r.begin() + static_cast<long>(std::min(m, i + kNeighbours + 1)));
    e[i] = r[i] - median_of(window);
  }
  const double typical_sd = median_of(sd);
  if (typical_sd > 0.0 && std::isfinite(typical_sd)) {
    for (std::size_t i = 0; i < e.size(); ++i) e[i] *= typical_sd / sd[i];
  }
  std::vector<double> abs_e(e.size());
  std::transform(e.begin(), e.end(), abs_e.begin(), [](double x) { return std::fabs(x); });
  // Where outliers by that sigma are everywhere, in more than half
  // of the blocks of 10 periods in each third of the record (an event
  // logger's hitches, a video's dropped frames), they are the noise, no
  // glitch, and the sigma is the one that puts a fifth of the periods beyond
  // 1.28 of it, as normal noise does. A glitch is local: a release, a catch,
  // a jump, a stretch clicked carelessly (the last 57 % of a track, tested).
  // The robust sigma from the 40th percentile of |e| (0.5244 sigma for
  // normal noise), not the median: a glitchy stretch may be more than half
  // the record (the last 57 % of a track clicked carelessly), and then the
  // median |e| is the glitch's.
  std::vector<double> sorted_e = abs_e;
  std::nth_element(sorted_e.begin(), sorted_e.begin() + static_cast<long>(2 * m / 5), sorted_e.end());
  const double robust = sorted_e[2 * m / 5] / 0.5244;
  double sigma = std::max({robust, quantum / std::sqrt(6.0), 1e-9 * std::fabs(median_of(d))});
  constexpr std::size_t kBlock = 10;
  const std::size_t blocks = m / kBlock;
  if (blocks >= 6) {
    std::array<std::size_t, 3> struck{}, total{};
    for (std::size_t k = 0; k < blocks; ++k) {
      const auto from = abs_e.begin() + static_cast<long>(k * kBlock);
      const std::size_t third = 3 * k / blocks;
      ++total[third];
      struck[third] += std::any_of(from, from + kBlock, [&](double x) { return x > kOutlier * sigma; });
    }
    if (2 * struck[0] > total[0] && 2 * struck[1] > total[1] && 2 * struck[2] > total[2]) {
      std::vector<double> sorted = abs_e;
      std::nth_element(sorted.begin(), sorted.begin() + static_cast<long>(4 * m / 5), sorted.end());
      sigma = std::max(sigma, sorted[4 * m / 5] / 1.2816);
    }
  }
  if (!(sigma > 0.0)) return out;
  std::optional<std::size_t> first, last;  // in full periods
  auto close = [&] {
    Glitch g;
    g.start = at[*first] <= kJoin ? c.front().time : c[at[*first]].time;
    g.end = at[*last] + span + kJoin >= n - 1 ? c.back().time : c[at[*last] + span].time;
    for (std::size_t k = *first; k <= *last; ++k) g.worst = std::max(g.worst, std::fabs(e[k]) / sigma);
    out.push_back(g);
  };
  for (std::size_t i = 0; i < m; ++i) {
    if (!(std::fabs(e[i]) > kOutlier * sigma)) continue;
    if (first && at[i] - at[*last] > kJoin) close(), first.reset();
    if (!first) first = i;
    last = i;
  }
  if (first) close();
  return out;
}

/// Step 7's stretches of outliers, joined: stretches less than 10 periods
/// (s: `period`) apart are one (a glitchy end is many outliers among
/// good-looking intervals), and one that comes within 5 periods of an end
/// reaches it (a release's hand, a catch); neither more than a fifth of the
/// record (a short one is no glitch end to end). A release takes in no
/// stretch that would make it over 10 periods long (an 80 deg swing's
/// outliers every 5-9 periods had made 38 periods of one).
std::vector<Glitch> join_glitches(const std::vector<Glitch>& stretches, const std::vector<Crossing>& c, double period) {
  if (c.empty()) return {};
  const double record = c.back().time - c.front().time;
  const double reach = std::min(10.0 * period, record / 5.0), end_reach = std::min(5.0 * period, record / 5.0);
  std::vector<Glitch> merged;
  for (Glitch g : stretches) {
    if (g.start - c.front().time < end_reach) g.start = c.front().time;
    if (c.back().time - g.end < end_reach) g.end = c.back().time;
    // A release is the first few swings (the hand letting go, the fast modes
    // dying out): it takes in no stretch that would make it over 10 periods.
    const bool release = !merged.empty() && merged.back().start == c.front().time;
    if (!merged.empty() && g.start - merged.back().end < reach &&
        !(release && g.end - c.front().time > 10.0 * period && g.end != c.back().time)) {
      merged.back().end = g.end, merged.back().worst = std::max(merged.back().worst, g.worst);
    } else {
      merged.push_back(g);
    }
  }
  return merged;
}

/// The longest run of consecutive entries of `c` outside every glitch:
/// [first, last], indices into c. An interval is inside a glitch when both
/// its ends are within the glitch's range.
std::pair<std::size_t, std::size_t> clean_stretch(const std::vector<Crossing>& c, const std::vector<Glitch>& glitches) {
  std::pair<std::size_t, std::size_t> best{0, 0};
  auto consider = [&](std::size_t a, std::size_t b) {
    if (b - a > best.second - best.first) best = {a, b};
  };
  std::size_t start = 0;
  for (std::size_t i = 0; i + 1 < c.size(); ++i) {
    const bool bad = std::any_of(glitches.begin(), glitches.end(), [&](const Glitch& g) {
      return c[i].time >= g.start && c[i + 1].time <= g.end;
    });
    if (bad) consider(start, i), start = i + 1;
  }
  consider(start, c.size() - 1);
  return best;
}

/// Notes the glitches and, where the longest clean stretch's period (from
/// `refit` on its first and last index, when it holds 3 periods) differs
/// from the whole record's by more than the latter's uncertainty, adds the
/// difference to it in quadrature: the record then cannot say which is right.
template <class Refit>
void report_glitches(SwingAnalysis& out, const Refit& refit, const char* what) {
  if (out.glitches.empty()) return;
  for (const Glitch& g : out.glitches) {
    out.notes.push_back({0, std::string("from ") + seconds(g.start) + " to " + seconds(g.end) +
                                (g.cause ? std::string(" ") + g.cause + " (its half swings' peaks rise " +
                                               format_number(g.worst, 3) + " robust sigmas)"
                                         : std::string(" the ") + what + " do not fit the swing (an interval " +
                                               format_number(g.worst, 3) + " robust sigmas off its neighbours': "
                                               "a jump, a gap, lost tracking or a glitchy end)")});
  }
  const auto [first, last] = clean_stretch(out.crossings, out.glitches);
  const double a = out.crossings[first].time, b = out.crossings[last].time;
  if (last < first + 7) {
    out.notes.push_back({0, "no stretch of 7 crossings is free of glitches: the period is the whole record's"});
    return;
  }
  const PeriodEstimate clean = refit(first, last);
  if (clean.periods < 3 || !std::isfinite(clean.value)) return;
  const double shift = out.period.value - clean.value;
  std::string text = "the longest stretch without them, " + format_number(a, 6) + ":" + format_number(b, 6) +
                     " s (--range, a scene's \"range\"), gives " + seconds(clean.value, 8) + " +- " +
                     seconds(clean.uncertainty, 2);
  if (std::fabs(shift) > out.period.uncertainty) {
    text += ", " + format_number(std::fabs(shift) / out.period.uncertainty, 2) +
            " sigmas from the whole record's; the difference joins the period's uncertainty";
    out.period.uncertainty = std::hypot(out.period.uncertainty, shift);
  }
  out.notes.push_back({0, text});
}

/// A note where the clock's resolution, not the scatter, sets the period's uncertainty.
void note_floor(SwingAnalysis& out, double quantum) {
  if (out.period.resolution_floor > 0.0 && out.period.resolution_floor >= 0.9 * out.period.uncertainty) {
    out.notes.push_back({0, "the period's uncertainty is (nearly) the least the clock's resolution of " +
                                seconds(quantum, 3) + " allows (q/sqrt(12) a time): the scatter gave less"});
  }
}

/// Step 5: the count of each stamp, in stamps, from the intervals. e[p] is
/// the interval expected after a stamp of count parity p (both the median
/// interval for one stamp a period; the medians of alternate intervals for
/// one a passage, where a gate off the lowest point makes them differ). A
/// stamp whose time after the last one kept is within a quarter of a mean
/// interval of a whole number s >= 1 of intervals advances the count by s
/// (s - 1 stamps missed); any other is dropped (a doubled, a repeated or a
/// stray stamp), both with a note naming its data row. A counter column
/// whose steps share a whole factor k > 1 (N = 1, 3, 5, ... periods against
/// the time they took) counts k periods a stamp interval (fit_stamps).
struct MendedStamps {
  std::vector<Crossing> stamps;
  std::vector<long> count;  ///< in stamp intervals
  long stride = 1;          ///< the counter's counts a stamp interval
};

/// A counter column's stride (recording_text::examine, the rule the reader
/// took the column for a count by: all but a few steps one whole step); 1
/// where there is none, or beyond a million.
long counter_stride(const std::vector<double>& counts) {
  const double stride = recording_text::examine(counts, false).stride;
  return stride > 1.0 && stride <= 1e6 ? static_cast<long>(stride) : 1L;
}

/// More stamps missed in a row than this is no timer log of one pendulum.
constexpr double kMaxMissed = 1000.0;

MendedStamps mend_stamps(const Recording& r, const std::array<double, 2>& e, const std::string& file,
                         std::vector<RecordingNote>& notes) {
  MendedStamps m;
  const double unit = (e[0] + e[1]) / 2.0;
  const bool numbered = r.counts.size() == r.time.size();
  if (numbered) m.stride = counter_stride(r.counts);
  auto row = [&](std::size_t k) {
    return "the stamp at " + seconds(r.time[k]) + " (data row " + std::to_string(k + 1) +
           (numbered ? ", numbered " + format_number(r.counts[k]) + " in the file" : std::string()) + ")";
  };
  m.stamps.push_back({r.time[0], 0.0, 0});
  m.count.push_back(0);
  std::size_t kept = 0;
  for (std::size_t k = 1; k < r.time.size(); ++k) {
    const double x = r.time[k] - r.time[kept];
    if (!(x / unit < kMaxMissed)) {
      throw InputError(file, row(k) + " comes " + format_number(x / unit, 3) +
                                 " intervals after the one before; expected the log of one swinging pendulum "
                                 "(--range cuts a recording in two)");
    }
    // s intervals after a stamp of parity p take (s/2) (e0 + e1), plus e_p for odd s.
    const int parity = static_cast<int>(m.count.back() % 2);
    auto after = [&](long s) { return static_cast<double>(s / 2) * (e[0] + e[1]) + (s % 2 ? e[parity] : 0.0); };
    long best = 1;
    double dev = std::fabs(x - after(1));
    const long guess = static_cast<long>(x / unit);
    for (long s = std::max(2L, guess - 2); s <= guess + 2; ++s) {
      if (std::fabs(x - after(s)) < dev) dev = std::fabs(x - after(s)), best = s;
    }
    if (dev > 0.25 * unit) {
      notes.push_back({0, row(k) + " is dropped: " + format_number(x / unit, 3) +
                              " intervals after the one before, off the grid of whole intervals (a doubled, "
                              "repeated or stray stamp)"});
      continue;
    }
    const long count = m.count.back() + best;
    std::string mended;
    if (numbered && r.counts[k] - r.counts[kept] != static_cast<double>(best * m.stride)) {
      mended = "; its count, " + format_number(r.counts[k]) + " in the file, is mended to " +
               format_number(r.counts[kept] + static_cast<double>(best * m.stride));
    }
    if (best > 1) {
      notes.push_back({0, row(k) + " comes " + format_number(x / unit, 3) + " intervals after the one before: " +
                              std::to_string(best - 1) + (best == 2 ? " stamp" : " stamps") +
                              " missed, and the count advanced by " + std::to_string(best) + mended});
    } else if (!mended.empty()) {
      notes.push_back({0, row(k) + " follows the one before by one interval" + mended});
    }
    m.stamps.push_back({r.time[k], 0.0, 0});
    m.count.push_back(count);
    kept = k;
  }
  return m;
}

/// The line through the stamps against their counts by least squares:
/// t = a + b x + c x^2 (+ h x^3 from 12 stamps on), x = n - (n_first +
/// n_last)/2: the period drifts with the amplitude, and a photogate times
/// that drift to a few us. About the mid-range the quadratic leaves the mean
/// period, the rise from the first stamp to the last per period, as it is:
/// b + h X^2, X = (n_last - n_first)/2. For one stamp a passage (-1)^n (d +
/// e x + f x^2): a gate off the lowest point splits a period into two
/// unequal intervals, and the split drifts as the swing decays (the time
/// from the bottom to the beam goes as arcsin(theta_gate/theta0)). The
/// covariance is scaled by the residual variance and, for positively
/// correlated residuals, the AR(1) factor, as the crossing fit's; never
/// below the floor of a clock of resolution `quantum` (step 6).
PeriodEstimate fit_stamps(const MendedStamps& m, int per_period, double quantum) {
  const std::size_t n = m.stamps.size();
  const bool cubic = n >= 12;
  const int q = (per_period == 2 ? 6 : 3) + (cubic ? 1 : 0);
  const double centre = (static_cast<double>(m.count.front()) + static_cast<double>(m.count.back())) / 2.0;
  const double half_range = (static_cast<double>(m.count.back()) - static_cast<double>(m.count.front())) / 2.0;
  Eigen::MatrixXd xtx = Eigen::MatrixXd::Zero(q, q);
  Eigen::VectorXd xtt = Eigen::VectorXd::Zero(q);
  const double t0 = m.stamps[0].time;
  auto row = [&](std::size_t i) {
    const double x = static_cast<double>(m.count[i]) - centre;
    Eigen::VectorXd r(q);
    r[0] = 1.0, r[1] = x, r[2] = x * x;
    if (per_period == 2) r[3] = m.count[i] % 2 ? -1.0 : 1.0, r[4] = r[3] * x, r[5] = r[3] * x * x;
    if (cubic) r[q - 1] = x * x * x;
    return r;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::VectorXd r = row(i);
    xtx += r * r.transpose();
    xtt += r * (m.stamps[i].time - t0);
  }
  const Eigen::MatrixXd inv = xtx.inverse();
  const Eigen::VectorXd beta = inv * xtt;
  std::vector<double> z(n);
  double ssr = 0.0;
  for (std::size_t i = 0; i < n; ++i) z[i] = m.stamps[i].time - t0 - row(i).dot(beta), ssr += z[i] * z[i];
  PeriodEstimate p;
  set_autocorrelation(z, ssr, p);
  const double s2 = ssr / (static_cast<double>(n) - q);
  // The mean period over the stamps, as the crossing fit's: b + (cubic) X^2 times its coefficient.
  Eigen::VectorXd g = Eigen::VectorXd::Zero(q);
  g[1] = per_period;
  if (cubic) g[q - 1] = per_period * half_range * half_range;
  // A counter's stride of k periods a stamp interval: the period is 1/k of the interval's.
  const double k = static_cast<double>(m.stride);
  p.value = g.dot(beta) / k;
  p.uncertainty = std::sqrt(s2 * g.dot(inv * g) * p.inflation) / k;
  std::vector<double> counts(m.count.begin(), m.count.end());
  p.resolution_floor = per_period * resolution_floor(counts, quantum) / k;
  p.uncertainty = std::max(p.uncertainty, p.resolution_floor);
  p.residual_rms = std::sqrt(s2);
  p.periods = static_cast<int>((m.count.back() - m.count.front()) * m.stride / per_period);
  return p;
}

/// Whether consecutive stamp intervals alternate: the medians of the even
/// and the odd ones differ by more than 5 standard errors of that
/// difference (a median's is 1.2533 sigma/sqrt(n/2) for normal scatter).
bool intervals_alternate(const std::vector<double>& d) {
  std::vector<double> even, odd;
  for (std::size_t i = 0; i < d.size(); ++i) (i % 2 ? odd : even).push_back(d[i]);
  if (even.size() < 3 || odd.size() < 3) return false;
  const double m0 = median_of(even), m1 = median_of(odd);
  std::vector<double> dev(d.size());
  for (std::size_t i = 0; i < d.size(); ++i) dev[i] = std::fabs(d[i] - (i % 2 ? m1 : m0));
  const double sigma = 1.4826 * median_of(dev);
  return std::fabs(m0 - m1) > 5.0 * 1.2533 * sigma * std::sqrt(2.0 / even.size() + 2.0 / odd.size()) &&
         std::fabs(m0 - m1) > 1e-9 * (m0 + m1);
}

/// Steps 5 to 7 for event stamps.
SwingAnalysis analyse_stamps(const Recording& r, const std::string& file, const SwingOptions& options,
                             double quantum) {
  if (r.time.size() < 6) {
    throw InputError(file, std::to_string(r.time.size()) + " event stamps; expected at least 6 (three periods)");
  }
  std::vector<double> d(r.time.size() - 1);
  for (std::size_t i = 0; i + 1 < r.time.size(); ++i) d[i] = r.time[i + 1] - r.time[i];
  SwingAnalysis out;
  int per_period = 1;
  std::array<double, 2> e{};
  if (options.stamps_per_period) {
    per_period = *options.stamps_per_period;
    if (per_period != 1 && per_period != 2) {
      throw InputError(file, "got " + std::to_string(per_period) +
                                 " stamps a period; expected 1 (a timer, a photogate's pendulum mode) or 2 (one "
                                 "a passage)");
    }
  } else {
    per_period = intervals_alternate(d) ? 2 : 1;
    out.notes.push_back({0, per_period == 2 ? "one stamp a passage: consecutive intervals alternate (a gate off the "
                                              "lowest point); --stamps-per-period says otherwise"
                                            : "one stamp a period: the intervals do not alternate; --stamps-per-period "
                                              "2 for one a passage"});
  }
  if (per_period == 2) {
    std::vector<double> even, odd;
    for (std::size_t i = 0; i < d.size(); ++i) (i % 2 ? odd : even).push_back(d[i]);
    e = {median_of(even), median_of(odd)};
  } else {
    e[0] = e[1] = median_of(d);
  }
  if (!(e[0] > 0.0 && e[1] > 0.0)) {
    throw InputError(file, "the event stamps' median interval is 0 s; expected stamps of a swinging pendulum");
  }
  const MendedStamps m = mend_stamps(r, e, file, out.notes);
  out.crossings = m.stamps;
  out.crossings_per_period = per_period;
  const long span = (m.count.back() - m.count.front()) * m.stride;
  if (m.stride > 1) {
    out.notes.push_back({0, "the counter steps by " + std::to_string(m.stride) + ": each stamp comes " +
                                std::to_string(m.stride) + " periods after the one before (a count of periods at "
                                "each time), so the period is 1/" + std::to_string(m.stride) + " of the interval"});
  }
  if (m.stamps.size() < 6 || span < 3 * per_period) {
    throw InputError(file, "found " + std::to_string(m.stamps.size()) + " usable stamps (" +
                               std::to_string(span / per_period) + " full periods); expected at least three periods");
  }
  out.period = fit_stamps(m, per_period, quantum);
  if (!(out.period.value > 0.0) || !std::isfinite(out.period.uncertainty)) {
    throw InputError(file, "no regular oscillation: the stamps give no period");
  }
  out.outliers = outlier_stretches(m.stamps, m.count, per_period, std::vector<double>(m.stamps.size(), 1.0), quantum);
  out.glitches = join_glitches(out.outliers, m.stamps, out.period.value);
  report_glitches(out, [&](std::size_t a, std::size_t b) {
    MendedStamps part;
    part.stamps.assign(m.stamps.begin() + a, m.stamps.begin() + b + 1);
    part.count.assign(m.count.begin() + a, m.count.begin() + b + 1);
    part.stride = m.stride;
    return fit_stamps(part, per_period, quantum);
  }, "stamps");
  note_floor(out, quantum);
  const double origin = m.stamps[0].time;
  for (std::size_t i = 0; i + 1 < m.stamps.size(); ++i) {
    out.swings.push_back({m.stamps[i].time, m.stamps[i + 1].time, (m.stamps[i].time + m.stamps[i + 1].time) / 2.0, kNaN});
    const std::size_t j = i + per_period;
    if (j < m.stamps.size() && m.count[j] - m.count[i] == per_period) {
      out.period_curve.push_back({(m.stamps[i].time + m.stamps[j].time) / 2.0 - origin, kNaN,
                                  (m.stamps[j].time - m.stamps[i].time) / static_cast<double>(m.stride)});
    }
  }
  out.small_amplitude_period = kNaN;
  out.start_amplitude = out.end_amplitude = out.start_amplitude_uncertainty = kNaN;
  out.notes.push_back({0, "no amplitudes: event stamps time the swing but do not measure it (the scene's amplitude "
                          "is needed)"});
  return out;
}

/// Why a recording gave no amplitudes, for its note.
std::string no_amplitude_reason(const Recording& r, const Signal& sig, const SwingOptions& options) {
  switch (r.kind) {
    case SignalKind::blocking_times: return "a list of blocking times holds no blocking durations";
    case SignalKind::gate_states:
      if (!options.bob_width) return "a photogate's need the bob's width across the beam (--bob-width-m, a scene's bob_width)";
      break;
    case SignalKind::position:
      if (!sig.has_amplitude) return "the track is too straight for the centre of its circle (the pivot)";
      break;
    case SignalKind::event_stamps: return "event stamps time the swing but do not measure it";
    case SignalKind::unknown:
      return "the file does not say what its signal measures (if it is an angle, say so with --columns, e.g. "
             "\"t:s,theta:deg\")";
    default: break;
  }
  return "fewer than 8 swings, or fewer than half of them, gave a peak (a half swing needs 6 samples for one)";
}

/// Steps 1 to 7 on all of `r`.
/// A glitch inside the record whose count was carried across (step 8): the
/// crossings between the good ones at `start` and `end` (s) are dropped and
/// the one at `end` comes `steps` intervals after the one at `start`.
struct Bridge {
  double start = 0.0, end = 0.0;
  long steps = 1;
  double worst = 0.0;  ///< the glitch's largest |period residual|, in robust sigmas
};

/// The index of the crossing of `c` at time `t` (s), within a tenth of the
/// interval after it (another analysis of the same samples moves crossings
/// by far less: its mean and thresholds differ slightly); c.size() if none.
std::size_t crossing_at(const std::vector<Crossing>& c, double t) {
  const auto k = static_cast<std::size_t>(std::min_element(c.begin(), c.end(), [t](const Crossing& x, const Crossing& y) {
                                             return std::fabs(x.time - t) < std::fabs(y.time - t);
                                           }) - c.begin());
  return k + 1 < c.size() && std::fabs(c[k].time - t) <= 0.1 * (c[k + 1].time - c[k].time) ? k : c.size();
}

/// Drops the crossings inside each bridge, with their sample windows `at`
/// and gate `durations` where there are any, and sets the steps across it.
/// A bridge whose ends are not crossings here is not applied, and a note
/// says so.
void apply_bridges(const std::vector<Bridge>& bridges, std::vector<Crossing>& c, std::vector<std::size_t>& at,
                   std::vector<double>& durations, std::vector<RecordingNote>& notes) {
  for (const Bridge& b : bridges) {
    const std::size_t i = crossing_at(c, b.start), j = crossing_at(c, b.end);
    if (i >= c.size() || j >= c.size() || j <= i) {
      notes.push_back({0, "the glitch from " + seconds(b.start) + " to " + seconds(b.end) +
                              " is not bridged here: its ends are no crossings of this stretch"});
      continue;
    }
    c[j].steps = b.steps;
    auto drop = [&](auto& v) {
      if (!v.empty()) v.erase(v.begin() + static_cast<long>(i) + 1, v.begin() + static_cast<long>(j));
    };
    drop(c), drop(at), drop(durations);
  }
}

/// A swing that grows at the start: a hand or a drive pumping it (a free
/// pendulum's swing only decays), no free swing, cut as the release. The
/// half swings' raw peaks `peaks` (NaN where none), two neighbours' mean as
/// a log, their running median of 5 the level; where the level's largest lies beyond the first
/// full window's by log 1.25 and by 6 robust sigmas of the peaks about the
/// level, the stretch from the first crossing to the first half swing whose
/// level comes within log(1/0.97) (or 2 sigmas) of that largest, provided it
/// ends within the record's first half (later growth is a second push, not a
/// release), the level never falls below its start by that much before (a
/// decay pushed again) and, 5 windows after its largest, is within twice that
/// of it (a jump of a few half swings falls back). `worst` is the growth in those sigmas. A remote lab's drive
/// pumped a 20 frames/s record from 44 to 66 deg over 8 s, the periods there
/// 3 % short with the amplitude, and the mean period of the whole record 0.5 %
/// below the swing's steady one.
std::optional<Glitch> growth_at_start(const std::vector<double>& peaks, const std::vector<Crossing>& c) {
  // Two half swings' mean: an offset the mean's removal left alternates in
  // sign between them (|p_i| = A_i +- delta), and a running median of
  // single half swings would step between the two.
  std::vector<std::size_t> at;
  std::vector<double> logs;
  for (std::size_t i = 0; i + 1 < peaks.size(); ++i) {
    const double mean = (peaks[i] + peaks[i + 1]) / 2.0;
    if (std::isfinite(mean) && mean > 0.0) at.push_back(i), logs.push_back(std::log(mean));
  }
  const std::size_t n = logs.size();
  if (n < 10) return std::nullopt;
  std::vector<double> level(n), residuals;
  for (std::size_t k = 2; k + 2 < n; ++k) {
    level[k] = median_of(std::vector<double>(logs.begin() + static_cast<long>(k) - 2, logs.begin() + static_cast<long>(k) + 3));
    residuals.push_back(std::fabs(logs[k] - level[k]));
  }
  const double sigma = std::max(1.4826 * median_of(residuals), 1e-4);  // no peak is read to better than 0.01 %
  const auto top = std::max_element(level.begin() + 2, level.end() - 2);
  const double growth = *top - level[2];
  if (!(growth > std::max(std::log(1.25), 6.0 * sigma))) return std::nullopt;
  const double near = std::max(-std::log(0.97), 2.0 * sigma);
  // A rise from the start, and a swing that stays up: not a decay pushed
  // again, nor a jump of a few half swings' peaks.
  const std::size_t t = static_cast<std::size_t>(top - level.begin());
  if (*std::min_element(level.begin() + 2, top + 1) < level[2] - near) return std::nullopt;
  if (level[std::min(t + 5, n - 3)] < *top - 2.0 * near) return std::nullopt;
  std::size_t k = 2;
  while (level[k] < *top - near) ++k;
  const double end = c[at[k]].time;
  if (!(end - c.front().time < (c.back().time - c.front().time) / 2.0)) return std::nullopt;
  return Glitch{c.front().time, end, growth / sigma, "the swing grows: a hand or a drive pumping it, not yet a free swing"};
}

/// Where the smooth amplitude `curve` (one per swing, rad) misses the
/// swings' own amplitudes `theta`: the mean of their residuals over the 2
/// swings on either side, where beyond 3 sigmas of the swings' scatter about
/// the curve (the mean of a few noisy swings is no misfit, and would hide a
/// real release), else 0. A curve of order 8 in log theta does not follow a
/// decay from 91 deg that ends in a bearing's dry friction (linear in theta).
std::vector<double> local_misfits(const std::vector<double>& theta, const std::vector<double>& curve) {
  std::vector<double> residuals, out(curve.size(), 0.0);
  for (std::size_t k = 0; k < curve.size(); ++k) {
    if (std::isfinite(theta[k]) && theta[k] > 0.0) residuals.push_back(std::fabs(theta[k] - curve[k]));
  }
  const double scatter = 1.4826 * median_of(residuals);  // of one swing's amplitude about the curve
  for (std::size_t i = 0; i < curve.size(); ++i) {
    double sum = 0.0;
    int count = 0;
    for (std::size_t k = i > 2 ? i - 2 : 0; k < std::min(theta.size(), i + 3); ++k) {
      if (std::isfinite(theta[k]) && theta[k] > 0.0) sum += theta[k] - curve[k], ++count;
    }
    const double mean = count ? sum / count : 0.0;
    if (count && std::fabs(mean) > 3.0 * scatter / std::sqrt(count)) out[i] = mean;
  }
  return out;
}

/// `track_length`: as make_signal's; `circle`, where given, is a track's
/// track_angle, which the caller fitted once for its radius too.
SwingAnalysis analyse_once(const Recording& r, const std::string& file, const SwingOptions& options,
                           const std::vector<Bridge>& bridges, double track_length, const Signal* circle = nullptr) {
  // The clock's resolution (step 6): the reader's quantum where stamps
  // repeat; for events (stamps, gate changes), also the decimals the file
  // printed its times with. Not for samples: a regular clock printed to its
  // own step (50 Hz to 0.01 s) is exact, and crossings interpolated between
  // samples are legitimately finer than the step.
  const bool events = r.kind == SignalKind::gate_states || r.kind == SignalKind::blocking_times ||
                      r.kind == SignalKind::event_stamps;
  const double quantum = std::max(r.time_quantum, events ? printed_resolution(r.time) : 0.0);
  if (r.kind == SignalKind::event_stamps) return analyse_stamps(r, file, options, quantum);
  SwingAnalysis out;
  std::vector<std::size_t> at;  // first sample of each crossing's window
  std::vector<double> durations;
  Signal sig;
  if (events) {
    out.crossings = gate_passages(r, durations);
  } else {
    require_several_swings(r, file);
    sig = circle ? *circle : make_signal(r, track_length);
    out.axis = sig.axis;
    out.crossings_per_period = sig.crossings_per_period;
    out.noise = noise_sigma(sig.s);
    const Extent e = extent(sig.s);
    // The swing's amplitude from the signal's level over its noise (a sine's
    // rms is its amplitude over sqrt 2; the noise adds in quadrature). A
    // swing 3 noise sigmas high is one, even where no sample reaches 10; a
    // record mostly at rest has its level near the noise, and passes by its
    // largest excursion, as before.
    const double level = swing_level(sig.s, e.rms);
    const double swing = std::sqrt(2.0 * std::max(level * level - out.noise * out.noise, 0.0));
    const bool swinging = swing > 3.0 * out.noise;
    if ((!swinging && !(e.peak > 10.0 * out.noise)) || e.peak == 0.0) {
      throw InputError(file, "no oscillation: the signal's largest excursion (" + format_number(e.peak, 3) +
                                 ") is within 10 times its noise (" + format_number(out.noise, 3) +
                                 ", from second differences), and its level (" + format_number(level, 3) +
                                 ", the rms or past a knock the median |s|) leaves a swing of amplitude " +
                                 format_number(swing, 2) + ", under 3 times the noise; expected a swinging pendulum");
    }
    // Not for |a| (4 crossings a period): its bottoms and dips differ in
    // depth, and a sine through a crossing is no model of it.
    if (swinging && swing < kNoisySwing * out.noise && sig.crossings_per_period == 2) {
      out.notes.push_back({0, "the swing, " + format_number(swing, 3) + " (from the signal's level over its noise), " +
                                  "is " + format_number(swing / out.noise, 2) + " times its noise: the crossings are "
                                  "timed by sine fits over half a swing each, not by thresholds the noise crosses"});
      out.crossings = sine_fit_crossings(r.time, sig, swing, out.noise, options.hysteresis_fraction, at);
    } else {
      out.crossings = find_crossings(r.time, sig, level, out.noise, options.hysteresis_fraction, at);
    }
  }
  apply_bridges(bridges, out.crossings, at, durations, out.notes);
  const int cpp = out.crossings_per_period;
  long count = 0;
  for (std::size_t i = 1; i < out.crossings.size(); ++i) count += out.crossings[i].steps;
  const int periods = static_cast<int>(count / cpp);
  if (periods < 3 || out.crossings.size() < 7) {
    throw InputError(file, "found " + std::to_string(out.crossings.size()) + " crossings (" +
                               std::to_string(periods) + " full periods); expected at least three swings");
  }
  out.period = fit_crossing_times(out.crossings, cpp, {}, quantum);
  if (!(out.period.value > 0.0) || !std::isfinite(out.period.uncertainty)) {
    throw InputError(file, "no regular oscillation: the crossing times give no period");
  }

  // Swings and their raw peaks (rate, angle, |a| - mean, or speed).
  const std::size_t nc = out.crossings.size();
  std::vector<double> raw(nc - 1, kNaN);
  out.swings.resize(nc - 1);
  for (std::size_t i = 0; i + 1 < nc; ++i) {
    RecordedSwing& w = out.swings[i];
    w.start = out.crossings[i].time;
    w.end = out.crossings[i + 1].time;
    w.peak_time = (w.start + w.end) / 2.0;
    if (!events && out.crossings[i + 1].steps == 1) {  // a bridged glitch is no swing
      const auto [tp, value] = peak(r.time, sig.s, at[i], at[i + 1], w.start, w.end);
      w.peak_time = tp;
      raw[i] = value;
    }
  }
  if (const std::vector<std::size_t> knocked = peak_outliers(raw, out.noise); !knocked.empty()) {
    std::string when;
    for (std::size_t k = 0; k < knocked.size() && k < 3; ++k) {
      when += (k ? ", " : "") + seconds(out.swings[knocked[k]].peak_time, 4);
    }
    if (knocked.size() > 3) when += ", ...";
    out.notes.push_back({0, std::to_string(knocked.size()) + " half swing" + (knocked.size() > 1 ? "s" : "") +
                                " (at " + when + ") peaked far from the swings beside them (a knock or a jump of "
                                "the track): they, and the swings averaged with them, give no amplitude"});
    for (std::size_t i : knocked) raw[i] = kNaN;
  }
  const std::optional<Glitch> growth = growth_at_start(raw, out.crossings);
  // Amplitudes (rad), by kind.
  std::vector<double> theta(nc - 1, kNaN);
  out.small_amplitude_period = kNaN;
  auto solve_with_t0 = [&](auto amplitude_of) {  // theta0 of swing i given T0, NaN if unknown
    const double T = out.period.value;
    double t0 = T;
    for (int iter = 0; iter < 5; ++iter) {
      double mean_correction = 0.0;
      int count = 0;
      for (std::size_t i = 0; i < theta.size(); ++i) {
        theta[i] = amplitude_of(i, t0);
        if (std::isfinite(theta[i])) mean_correction += estimated_excess(theta[i]), ++count;
      }
      t0 = T / (1.0 + (count ? mean_correction / count : 0.0));
    }
    out.small_amplitude_period = t0;
  };
  // A mean removed from a record of no whole number of swings leaves an
  // offset delta that alternates in sign between swings: |p_i| = A_i +- delta.
  // The weights 1/4, 1/2, 1/4 over three swings cancel it, but lift a curved
  // decay by a quarter of its second difference (90 ppm at 81 deg, 18 ppm of
  // g swing by swing). Less that difference over alternate swings, whose
  // offsets agree, they are (-1, 4, 10, 4, -1)/16: blind to the offset and
  // exact for a quadratic, as (1, 5, 3, -1)/8 is for the second swing (and
  // mirrored, the last but one). The first and last get no amplitude.
  if (!events && r.kind != SignalKind::acceleration) {
    const std::size_t n = raw.size();
    std::vector<double> smooth(n, kNaN);
    for (std::size_t i = 1; i + 1 < n; ++i) {
      if (i >= 2 && i + 2 < n) {
        smooth[i] = (-raw[i - 2] + 4.0 * raw[i - 1] + 10.0 * raw[i] + 4.0 * raw[i + 1] - raw[i + 2]) / 16.0;
      } else if (n >= 4) {
        const std::size_t j = i == 1 ? i - 1 : i + 1, k = i == 1 ? i + 1 : i - 1;  // outward, towards the middle
        smooth[i] = (raw[j] + 5.0 * raw[i] + 3.0 * raw[k] - raw[2 * k - i]) / 8.0;
      }
      // Beside a swing without a peak (a sparse or glitchy track), or where a
      // neighbour many times larger drives the weighted sum below zero, the
      // three, whose weights are all positive.
      if (!(smooth[i] >= 0.0)) smooth[i] = (raw[i - 1] + 2.0 * raw[i] + raw[i + 1]) / 4.0;
    }
    raw = smooth;
  }
  // Amplitudes (rad), by kind; those from a rate or a speed need T0, hence the period.
  auto amplitudes = [&] {
    switch (r.kind) {
      case SignalKind::angular_rate:
        solve_with_t0([&](std::size_t i, double t0) {
        if (!std::isfinite(raw[i])) return kNaN;
        require_below_top(raw[i] * t0 / (4.0 * kPi), file);
        return amplitude_from_peak_rate(raw[i], t0);
      });
        break;
      case SignalKind::linear_acceleration:
        // The tangential acceleration at a turning point is g sin theta0
        // (standard g: a local g 0.3 % off moves theta0 by 0.3 %).
        for (std::size_t i = 0; i < raw.size(); ++i) {
          if (std::isfinite(raw[i])) theta[i] = amplitude_from_turning_acceleration(std::min(raw[i], kStandardGravity), kStandardGravity);
        }
        break;
      case SignalKind::angle:
      case SignalKind::position:
        if (sig.has_amplitude) theta = raw;
        break;
      case SignalKind::acceleration:
        // Quarter swings alternate: |a| peaks at the bottom, g(3 - 2 cos theta0),
        // and dips at the turning points, g cos theta0; the ratio needs no g.
        for (std::size_t i = 1; i + 1 < raw.size(); ++i) {
          if (sig.s[(at[i] + at[i + 1]) / 2] < 0.0) continue;  // a dip, not a bottom
          if (!std::isfinite(raw[i - 1] + raw[i] + raw[i + 1])) continue;
          const double ratio = (sig.offset + raw[i]) / (sig.offset - (raw[i - 1] + raw[i + 1]) / 2.0);
          theta[i] = amplitude_from_acceleration_ratio(std::max(ratio, 1.0));
        }
        break;
      case SignalKind::gate_states:
        if (options.bob_width && !durations.empty()) {
          // RecordedSwing i runs from passage i to passage i + 1 round a turning point:
          // its amplitude is the mean of theirs.
          solve_with_t0([&](std::size_t i, double t0) {
            if (out.crossings[i + 1].steps > 1) return kNaN;  // a bridged glitch
            const double sqrt_gl = options.length ? 2.0 * kPi * *options.length / t0
                                                  : kStandardGravity * t0 / (2.0 * kPi);
            double sum = 0.0;
            for (std::size_t k : {i, i + 1}) {
              const double v = *options.bob_width / durations[k];
              require_below_top(v / (2.0 * sqrt_gl), file);
              sum += amplitude_from_bottom_speed(v, sqrt_gl);
            }
            return sum / 2.0;
          });
        }
        break;
      case SignalKind::blocking_times:
      case SignalKind::event_stamps:
      case SignalKind::unknown: break;
    }
  };
  amplitudes();
  // Refit with the amplitude-weighted index once the swings have amplitudes:
  // a long decaying record's crossing times then lie on a line instead of a
  // curve no quadratic fits. The index takes a smooth amplitude, a polynomial
  // in time fitted to log theta: each swing's own amplitude would carry its noise
  // into the index as a random walk, which the period then inherits.
  std::vector<double> tk, lk;
  for (std::size_t i = 0; i < theta.size(); ++i) {
    if (std::isfinite(theta[i]) && theta[i] > 0.0) tk.push_back(out.swings[i].peak_time), lk.push_back(std::log(theta[i]));
  }
  out.start_amplitude = out.end_amplitude = out.start_amplitude_uncertainty = kNaN;
  std::vector<double> index_amplitudes;  // the smooth amplitude the period's index took, one per swing
  // The smooth curve at each swing, and where it misses them (local_misfits).
  std::vector<double> curve(theta.size(), kNaN), misfits(theta.size(), 0.0);
  if (tk.size() >= 8 && tk.size() * 2 >= theta.size() / (cpp / 2)) {
    const double mid = (tk.front() + tk.back()) / 2.0, half = (tk.back() - tk.front()) / 2.0;
    const Eigen::Map<const Eigen::VectorXd> y(lk.data(), lk.size());
    auto design = [&](int q) {
      Eigen::MatrixXd a(tk.size(), q + 1);
      for (std::size_t k = 0; k < tk.size(); ++k) {
        for (int j = 0; j <= q; ++j) a(k, j) = std::pow((tk[k] - mid) / half, j);
      }
      return a;
    };
    // The average over neighbouring swings (above) leaves the slow part of
    // the noise as it was but shrinks the residuals' variance by the sum of
    // its squared weights, (1 + 16 + 100 + 16 + 1)/256: the factor 128/67
    // restores it.
    const double averaged = !events && r.kind != SignalKind::acceleration ? 128.0 / 67.0 : 1.0;
    auto smooth_with = [&](const Eigen::VectorXd& coef, double t) {
      const double x = (t - mid) / half;  // beyond +-1 by half a swing at most
      double v = 0.0;
      for (Eigen::Index j = coef.size(); j-- > 0;) v = v * x + coef[j];
      return std::exp(v);
    };
    // Not for a photogate: its amplitudes take the bob's speed as constant
    // through the beam, which reads theta0 low by about theta_g^2/(6 theta0^2)
    // (theta_g the beam's half-width in angle), a bias that drifts as the
    // swing decays and, through the index, moves the period by several of its
    // sub-microsecond uncertainties. The cubic model of the plain index is
    // unbiased there (tests/test_recordings.cpp, photogate coverage).
    const bool indexed = cpp == 2 && !events;
    // The sum of squares of the period's fit whose index takes the curve;
    // NaN where the curve passes 180 deg.
    auto crossing_ssr = [&](const Eigen::VectorXd& coef) {
      std::vector<double> smooth(theta.size());
      for (std::size_t i = 0; i < theta.size(); ++i) {
        if (!((smooth[i] = smooth_with(coef, out.swings[i].peak_time)) < kPi)) return kNaN;
      }
      const PeriodEstimate p = fit_crossing_times(out.crossings, cpp, smooth, quantum);
      return p.residual_rms * p.residual_rms * (static_cast<double>(nc) - 4.0);
    };
    // The order grows with the record: the value at the ends of a fit of
    // order q through n noisy points scatters as (q + 1)/sqrt(n), and a short
    // record's log theta is a line (Eq. 25 over a few per cent of decay).
    int order = tk.size() >= 400 ? 3 : tk.size() >= 100 ? 2 : 1;
    Eigen::MatrixXd a = design(order);
    Eigen::VectorXd c = a.colPivHouseholderQr().solve(y);
    double ssr = (y - a * c).squaredNorm(), crossings = indexed ? crossing_ssr(c) : kNaN;
    // A strong decay (81 deg to 17 deg) bends log theta more than that: a
    // misfit of a per cent, summed into the index, scattered the crossings
    // 180 times their noise. A term joins while it is beyond 3 sigmas in the
    // swings' log amplitudes or in the crossings (whose index sums the
    // curve's errors: they see a misfit the swings' scatter hides), with at
    // least 20 swings a coefficient.
    while (order < kMaxSmoothOrder && static_cast<int>(tk.size()) >= 20 * (order + 2)) {
      const Eigen::MatrixXd a1 = design(order + 1);
      const Eigen::VectorXd c1 = a1.colPivHouseholderQr().solve(y);
      const double ssr1 = (y - a1 * c1).squaredNorm();
      const double s2 = ssr1 / (static_cast<double>(tk.size()) - (order + 2)) * averaged;
      const double crossings1 = indexed ? crossing_ssr(c1) : kNaN;
      if (indexed && !std::isfinite(crossings1)) break;
      const bool swings_say = ssr - ssr1 > kSmoothTermF * s2;
      const bool crossings_say = indexed && crossings - crossings1 > kSmoothTermF * crossings1 / (nc - 5.0);
      if (!swings_say && !crossings_say) break;
      ++order, a = a1, c = c1, ssr = ssr1, crossings = crossings1;
    }
    // Covariance of the coefficients from the residuals, each its own swing's
    // variance (the sandwich (A^T A)^-1 A^T diag(r_i^2 / (1 - h_i)) A (A^T
    // A)^-1, h_i the leverage, unbiased for equal variances): a constant noise
    // in angle is a relative one that grows as the swing decays, 0.02 % at
    // 81 deg to 0.07 % at 17 deg, and one variance for all put the curve's
    // error at the start twice its scatter.
    const Eigen::MatrixXd inverse = (a.transpose() * a).inverse();
    Eigen::VectorXd r2 = (y - a * c).array().square();
    for (Eigen::Index k = 0; k < r2.size(); ++k) r2[k] /= 1.0 - a.row(k).dot(inverse * a.row(k).transpose());
    const Eigen::MatrixXd cov = inverse * (a.transpose() * r2.asDiagonal() * a) * inverse * averaged;
    auto smooth_at = [&](double t) { return smooth_with(c, t); };
    if (indexed) {
      // The index takes the curve where it follows the swings and, where it
      // misses them beyond their scatter, the swings' local mean: a curve 2 %
      // low at 91 deg read the periods there 0.7 % long.
      for (std::size_t i = 0; i < theta.size(); ++i) curve[i] = smooth_with(c, out.swings[i].peak_time);
      misfits = local_misfits(theta, curve);
      auto period_with = [&](const Eigen::VectorXd& coef) {
        std::vector<double> smooth(theta.size());
        for (std::size_t i = 0; i < theta.size(); ++i) {
          smooth[i] = smooth_with(coef, out.swings[i].peak_time) + misfits[i];
          // The curve through the swings' log amplitudes can pass 180 deg
          // where the swings scatter wildly: no swinging pendulum there.
          if (!(smooth[i] < kPi)) {
            throw InputError(file, "the smooth amplitude curve reaches " + format_number(degrees(smooth[i]), 4) +
                                       " deg at " + seconds(out.swings[i].peak_time) +
                                       " (180 deg or more: over the top); expected a swinging pendulum");
          }
        }
        return fit_crossing_times(out.crossings, cpp, smooth, quantum);
      };
      out.period = period_with(c);
      index_amplitudes.resize(theta.size());
      for (std::size_t i = 0; i < theta.size(); ++i) index_amplitudes[i] = curve[i] + misfits[i];
      // The smooth amplitude's own uncertainty moves the index, hence the
      // period: g^T C g = sum_k (the period's change for a step of one
      // standard uncertainty along C's k-th principal axis)^2, the
      // dependence linear at that scale. Along the axes, not one coefficient
      // at a time: those of a high order are strongly correlated, and one
      // moved alone by its own sigma is a curve the swings rule out (order 8
      // through 91 deg to 10 deg had reached 222 deg half a swing before the
      // first measured one).
      const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> axes(cov);
      double variance = 0.0;
      for (int k = 0; k <= order; ++k) {
        const double sigma = std::sqrt(std::max(axes.eigenvalues()[k], 0.0));
        if (sigma > 0.0) variance += std::pow(period_with(c + sigma * axes.eigenvectors().col(k)).value - out.period.value, 2);
      }
      out.period.amplitude_uncertainty = std::sqrt(variance);
      out.period.uncertainty = std::max(std::hypot(out.period.uncertainty, out.period.amplitude_uncertainty),
                                        out.period.resolution_floor);
      amplitudes();  // again, with the final period
    }
    // The ends of the timing, a swing or so beyond the first and last
    // amplitudes: the cubic extrapolated by a few per cent of its span.
    out.smooth_amplitudes.resize(theta.size());
    for (std::size_t i = 0; i < theta.size(); ++i) out.smooth_amplitudes[i] = smooth_at(out.swings[i].peak_time);
    out.start_amplitude = smooth_at(out.crossings.front().time);
    out.end_amplitude = smooth_at(out.crossings.back().time);
    out.smooth_curve.mid = mid, out.smooth_curve.half = half;
    out.smooth_curve.coefficients.assign(c.data(), c.data() + c.size());
    Eigen::MatrixXd scaled = cov;
    scaled(0, 0) += sig.scale_uncertainty * sig.scale_uncertainty;
    out.smooth_curve.covariance.assign(scaled.data(), scaled.data() + scaled.size());  // symmetric: either order
    if (r.kind == SignalKind::angle || r.kind == SignalKind::position) {
      // log theta's variance at the start from the coefficients', x^T C x.
      Eigen::VectorXd x(order + 1);
      for (int j = 0; j <= order; ++j) x[j] = std::pow((out.crossings.front().time - mid) / half, j);
      out.start_amplitude_uncertainty =
          out.start_amplitude * std::hypot(std::sqrt(std::max(x.dot(cov * x), 0.0)), sig.scale_uncertainty);
    }
  }
  // Step 7, on the final period.
  std::vector<long> index(nc);
  std::vector<double> weight(nc, 1.0);
  for (std::size_t i = 0; i < nc; ++i) {
    index[i] = i ? index[i - 1] + out.crossings[i].steps : 0;
    if (!events) weight[i] = out.crossings[i].slope * out.crossings[i].slope * out.crossings[i].samples;
  }
  // Each interval's length in index steps, and what it may be off by where
  // the smooth curve misses the swings' own amplitudes there (the mean of
  // their residuals over the 2 swings on either side: a curve that bends
  // too little at the start crosses them within a few swings): a curve 2 %
  // low at 91 deg read the periods there 0.7 % long, a drift that against
  // the crossings' noise alone was a release of 96 sigmas, cut pass after
  // pass (33 s of a 133 s record, the start amplitude 53 deg for 91).
  // The misfit, which the index took up, stays in the lengths' errors: the
  // swings' local mean is that uncertain.
  std::vector<double> lengths, length_errors;
  for (std::size_t i = 0; i < index_amplitudes.size(); ++i) {
    lengths.push_back(1.0 + estimated_excess(index_amplitudes[i]));
    if (!(out.noise > 0.0)) continue;
    // In the weights' unit: a crossing's time scatters by noise / sqrt(weight).
    const double smooth = curve[i];
    length_errors.push_back(
        std::fabs(estimated_excess(smooth + std::fabs(misfits[i])) - estimated_excess(smooth)) / out.noise);
  }
  out.outliers = outlier_stretches(out.crossings, index, cpp, weight, quantum, lengths, length_errors);
  if (growth) out.outliers.insert(out.outliers.begin(), *growth);
  out.glitches = join_glitches(out.outliers, out.crossings, out.period.value);
  report_glitches(out, [&](std::size_t a, std::size_t b) {
    const std::vector<Crossing> part(out.crossings.begin() + a, out.crossings.begin() + b + 1);
    const std::vector<double> amplitudes =
        index_amplitudes.empty() ? std::vector<double>{}
                                 : std::vector<double>(index_amplitudes.begin() + a, index_amplitudes.begin() + b);
    return fit_crossing_times(part, cpp, amplitudes, quantum);
  }, "crossings");
  if (!events && out.noise > 0.0) {
    // The crossing times' scatter against the signal's noise: the weighted
    // residual of crossing i has variance noise^2 / mean(slope^2 samples).
    double mean_weight = 0.0;
    for (double w : weight) mean_weight += w / nc;
    const double ratio = out.period.residual_rms * std::sqrt(mean_weight) / out.noise;
    if (ratio > 5.0) {
      out.notes.push_back({0, "the crossing times scatter " + format_number(ratio, 2) +
                                  " times more than the signal's noise explains (rms " +
                                  seconds(out.period.residual_rms, 2) +
                                  "): the period's uncertainty is from that scatter; look for glitches"});
    }
  }
  note_floor(out, quantum);
  const double origin = out.crossings[0].time;
  for (std::size_t i = 0; i < out.swings.size(); ++i) {
    out.swings[i].amplitude = theta[i];
    if (std::isfinite(theta[i]) && theta[i] > 0.0) {
      out.decay.times.push_back(out.swings[i].peak_time - origin);
      out.decay.amplitudes.push_back(theta[i]);
    }
  }
  if (out.decay.amplitudes.empty()) out.notes.push_back({0, "no amplitudes: " + no_amplitude_reason(r, sig, options)});
  for (std::size_t i = 0; i + cpp < nc; i += cpp) {
    PeriodPoint p;
    p.time = (out.crossings[i].time + out.crossings[i + cpp].time) / 2.0 - origin;
    long steps = 0;
    for (int k = 1; k <= cpp; ++k) steps += out.crossings[i + k].steps;
    p.period = (out.crossings[i + cpp].time - out.crossings[i].time) * cpp / static_cast<double>(steps);
    double sum = 0.0;
    int count = 0;
    for (int k = 0; k < cpp; ++k) {
      if (std::isfinite(theta[i + k])) sum += theta[i + k], ++count;
    }
    p.amplitude = count ? sum / count : kNaN;
    out.period_curve.push_back(p);
  }
  return out;
}

/// A circle whose radius is known to worse than this fraction makes every
/// angle that uncertain, five times the pendulum's length's own (kTrackLengthModel).
constexpr double kLooseRadius = 0.1;

/// Metres per unit of a video track's x and y: by the x column's unit (m,
/// cm, mm); where none is stated, metres when the circle's `radius` read in
/// metres is within sqrt(10) of `length` (m), halfway on a log scale to the
/// next unit (Tracker exports metres). 0 for pixels, or where the numbers
/// cannot tell.
double metres_per_track_unit(const Recording& r, double radius, double length) {
  for (const RecordingColumn& c : r.columns) {
    if (c.role != "x") continue;
    if (c.unit == "m") return 1.0;
    if (c.unit == "cm") return 0.01;
    if (c.unit == "mm") return 0.001;
    if (!c.unit.empty()) return 0.0;
  }
  return std::fabs(std::log10(radius / length)) < 0.5 ? 1.0 : 0.0;
}

/// The length (m) of the simple pendulum of the small-amplitude period the
/// swings give, with standard gravity.
double period_length(const SwingAnalysis& a) {
  double sum = 0.0;
  int count = 0;
  for (const RecordedSwing& w : a.swings) {
    if (std::isfinite(w.amplitude) && w.amplitude > 0.0) sum += finite_amplitude_agm(w.amplitude), ++count;
  }
  const double t0 = a.period.value / (1.0 + (count ? sum / count : 0.0));
  return kStandardGravity * t0 * t0 / (4.0 * kPi * kPi);  // length_for_period rounds otherwise: stored outputs keep these bits
}

/// Steps 1 to 7 on all of `r`, a video track's angles checked: its circle
/// gives them only where its radius is determined (kLooseRadius) and agrees
/// with the pendulum's length (`--length-m`, else the period's) within 3
/// sigmas of both; else they are asin(x / length), x the displacement along
/// the swing, the period's length solved with them, and a note says why.
SwingAnalysis analyse_record(const Recording& r, const std::string& file, const SwingOptions& options,
                             const std::vector<Bridge>& bridges = {}) {
  if (r.kind != SignalKind::position) return analyse_once(r, file, options, bridges, 0.0);
  require_several_swings(r, file);  // before the circle, which reads the first sample
  const Signal circle = track_angle(r);  // once: the angles and the radius they are checked by
  SwingAnalysis out = analyse_once(r, file, options, bridges, 0.0, &circle);
  if (!std::isfinite(out.start_amplitude)) return out;
  double length = options.length ? *options.length : period_length(out);
  const double metres = metres_per_track_unit(r, circle.radius, length);
  if (!(metres > 0.0)) return out;
  const double radius = circle.radius * metres, sigma = circle.radius_sigma * metres;
  const double apart = std::fabs(radius - length) / std::hypot(sigma, kTrackLengthModel * length);
  const bool loose = sigma > kLooseRadius * radius;
  if (!(apart > 3.0) && !loose) return out;
  const double circle_start = out.start_amplitude;
  double used = length;
  for (int pass = 0; pass < 4; ++pass) {  // the period's length moves with the amplitudes it corrects for
    used = length;
    out = analyse_once(r, file, options, bridges, used / metres);
    if (options.length) break;
    length = period_length(out);
    if (std::fabs(length - used) <= 1e-4 * used) break;
  }
  const std::string source = options.length ? "the stated length (--length-m)"
                                            : "the length the small-amplitude period gives with standard gravity";
  out.notes.push_back(
      {0, "the track's circle has a radius of " + format_number(radius, 3) + " +- " + format_number(sigma, 2) + " m" +
              (loose ? ", too uncertain to scale the angles"
                     : ", " + format_number(apart, 2) + " sigmas from " + source + ", " + format_number(used, 4) +
                           " m (the tracked point's distance from the pivot taken within " +
                           format_number(100.0 * kTrackLengthModel, 2) + " %)") +
              ": a camera not square to the swing or a poor track of the height bends it; the angles are asin(x / " +
              format_number(used, 4) + " m), x the displacement along the swing from its mean, instead of the "
              "circle's (start " + format_number(degrees(circle_start), 4) + " deg)" +
              (options.length ? "" : "; --length-m gives the pivot to the tracked point")});
  return out;
}

/// What a cut of the record from `from` to `to` (s) holds, for its note:
/// the release (a glitch from the first crossing), the catch (one to the
/// last), the shorter side of a glitch inside.
Cut describe_cut(double from, double to, const SwingAnalysis& whole) {
  Cut k;
  k.start = from, k.end = to;
  bool release = false, end = false, inside = false;
  const char* cause = nullptr;
  for (const Glitch& g : whole.glitches) {
    if (!(g.start < to && g.end > from)) continue;
    k.worst = std::max(k.worst, g.worst);
    (g.start == whole.crossings.front().time ? release : g.end == whole.crossings.back().time ? end : inside) = true;
    if (g.cause) cause = g.cause;
  }
  for (const auto& [holds, what] : {std::pair{release, "the release"}, std::pair{inside, "the shorter side of a glitch"},
                                    std::pair{end, "the catch or a glitchy end"}}) {
    if (holds) k.why += (k.why.empty() ? "" : " and ") + std::string(what);
  }
  if (cause) k.why += std::string(", where ") + cause;
  return k;
}

/// Step 8's count across `g`, a glitch inside `from`'s record: the bridge
/// from the good crossing before it to the one after, where the count of
/// half swings across is certain and the clock ran on. Each side must hold
/// 3 periods and together more time than the glitch. The time across over
/// the half swing on either side (the median full period of the 10 beside
/// it, per interval) gives two counts; a decaying swing's half swings
/// shorten monotonically, so the true count lies between them. Both must
/// be within half an interval of the same whole number m of the parity the
/// two crossings' directions say (the next candidate is then 1.5 intervals
/// off), or within a quarter where the directions are not known (gate
/// events, quarter swings). And the time across must be m mean half swings
/// to within m times half their difference (the decay), half the
/// alternation of the two directions' half swings for odd m, and 4 times
/// the two sides' crossing scatter (1.4826 median |full period - median|
/// / sqrt 2 a crossing): a clock that jumped, or a track whose zero moved,
/// is no count to carry.
std::optional<Bridge> bridge_of(const SwingAnalysis& from, const Glitch& g) {
  constexpr std::size_t kPeriods = 10, kSidePeriods = 3;
  const std::vector<Crossing>& c = from.crossings;
  const std::size_t cpp = static_cast<std::size_t>(from.crossings_per_period);
  const std::size_t i = crossing_at(c, g.start), j = crossing_at(c, g.end);
  if (j >= c.size() || j <= i || i < kSidePeriods * cpp || c.size() - 1 - j < kSidePeriods * cpp) return std::nullopt;
  const double across = c[j].time - c[i].time;
  if (!(across < c[i].time - c.front().time + c.back().time - c[j].time)) return std::nullopt;
  std::vector<long> count(c.size());
  for (std::size_t k = 1; k < c.size(); ++k) count[k] = count[k - 1] + c[k].steps;
  struct Side {
    double half = kNaN, scatter = kNaN, alternation = 0.0;
  };
  auto side = [&](std::size_t lo, std::size_t hi) {  // the full periods within crossings [lo, hi]
    std::vector<double> d, kind[2];
    for (std::size_t k = lo; k + cpp <= hi; ++k) {
      if (count[k + cpp] - count[k] != static_cast<long>(cpp)) continue;
      d.push_back((c[k + cpp].time - c[k].time) / static_cast<double>(cpp));
      kind[count[k] % 2].push_back(c[k + 1].time - c[k].time);
    }
    Side s;
    if (d.size() < 3) return s;
    s.half = median_of(d);
    for (double& x : d) x = std::fabs(x - s.half);
    s.scatter = 1.4826 * median_of(d) * static_cast<double>(cpp) / std::sqrt(2.0);
    if (!kind[0].empty() && !kind[1].empty()) s.alternation = std::fabs(median_of(kind[0]) - median_of(kind[1])) / 2.0;
    return s;
  };
  const Side before = side(i > kPeriods * cpp ? i - kPeriods * cpp : 0, i);
  const Side after = side(j, std::min(c.size() - 1, j + kPeriods * cpp));
  const double x_before = across / before.half, x_after = across / after.half;
  if (!std::isfinite(x_before + x_after + before.scatter + after.scatter)) return std::nullopt;
  const bool directions = cpp == 2 && c[i].slope != 0.0 && c[j].slope != 0.0;
  const double mean = (x_before + x_after) / 2.0;
  long steps = std::lround(mean);
  if (directions) {
    const long parity = (c[i].slope > 0.0) == (c[j].slope > 0.0) ? 0 : 1;
    steps = 2 * std::lround((mean - parity) / 2.0) + parity;
  }
  const double m = static_cast<double>(steps), tolerance = directions ? 0.5 : 0.25;
  if (steps < 1 || std::fabs(x_before - m) >= tolerance || std::fabs(x_after - m) >= tolerance) return std::nullopt;
  const double allowed = m * std::fabs(before.half - after.half) / 2.0 +
                         (steps % 2 ? std::max(before.alternation, after.alternation) : 0.0) +
                         4.0 * std::hypot(before.scatter, after.scatter);
  if (std::fabs(across - m * (before.half + after.half) / 2.0) > allowed) return std::nullopt;
  return Bridge{c[i].time, c[j].time, steps};
}

/// An analysis's small-amplitude period T0 (s): the one its amplitudes were
/// solved with, or, where too few swings had one for that, the period over
/// 1 + the mean DeltaT/T0 of the swings that have one below 180 deg (Eq. 8,
/// exact; a cut stretch analysed alone may hold a knock's "amplitude" of 18
/// rad: fuzz_recording, session 28); NaN without amplitudes.
double small_amplitude_period_of(const SwingAnalysis& a) {
  if (std::isfinite(a.small_amplitude_period)) return a.small_amplitude_period;
  double sum = 0.0;
  int count = 0;
  for (const RecordedSwing& w : a.swings) {
    if (w.amplitude > 0.0 && w.amplitude < kPi) sum += finite_amplitude_agm(w.amplitude), ++count;
  }
  return count ? a.period.value / (1.0 + sum / count) : kNaN;
}

/// The period to compare stretches by, and its standard uncertainty (s):
/// T0 where `small_amplitude` (the period's uncertainty scaled to it), else
/// the period.
std::pair<double, double> comparable_period(const SwingAnalysis& a, bool small_amplitude) {
  if (!small_amplitude) return {a.period.value, a.period.uncertainty};
  const double t0 = small_amplitude_period_of(a);
  return {t0, a.period.uncertainty * t0 / a.period.value};
}

/// Step 8's check of what was cut: each cut (not a bridge) of 3 periods or
/// more analysed alone (`alone`, on its time range: its own clean stretch),
/// its T0 (its period where either stretch has no amplitudes) against the
/// kept stretch's; beyond 5 combined sigmas and 1 % (3 % without
/// amplitudes) a note says they disagree.
template <class Alone>
void compare_cuts(SwingAnalysis& out, const Alone& analyse_alone) {
  std::vector<std::string> disagree;
  for (Cut& k : out.cuts) {
    if (k.periods_carried > 0.0 || k.end - k.start < 3.0 * out.period.value) continue;
    SwingAnalysis alone;
    try {
      alone = analyse_alone(std::make_pair(k.start, k.end));
    } catch (const InputError&) {
      continue;  // too glitchy, or too short, to give a period: nothing to compare
    }
    k.small_amplitude = std::isfinite(small_amplitude_period_of(alone)) && std::isfinite(small_amplitude_period_of(out));
    const auto [cut, cut_sigma] = comparable_period(alone, k.small_amplitude);
    const auto [kept, kept_sigma] = comparable_period(out, k.small_amplitude);
    if (!(std::isfinite(cut) && std::isfinite(cut_sigma))) continue;
    PeriodEstimate p = alone.period;
    p.value = cut, p.uncertainty = cut_sigma;
    k.period_alone = p;
    const double sigmas = std::fabs(cut - kept) / std::hypot(cut_sigma, kept_sigma);
    k.agrees = !(sigmas > 5.0 && std::fabs(cut - kept) > (k.small_amplitude ? 0.01 : 0.03) * kept);
    if (!k.agrees) {
      disagree.push_back(format_number(k.start, 6) + ":" + format_number(k.end, 6) + " s gives " +
                         (k.small_amplitude ? "T0 = " : "T = ") + seconds(cut, 6) + " +- " + seconds(cut_sigma, 2) +
                         " (" + format_number(sigmas, 3) + " sigmas from the kept stretch's " + seconds(kept, 6) + ")");
    }
  }
  if (!disagree.empty()) {
    std::string text = "what was cut does not agree with what was kept: ";
    for (std::size_t i = 0; i < disagree.size(); ++i) text += (i ? "; " : "") + disagree[i];
    out.notes.insert(out.notes.begin() + 1, {0, text + ". A second pendulum, or a wrong column? --range picks a stretch, "
                                                       "--columns a column"});
  }
}

/// Step 8: the glitches inside bridged where their count is certain, and
/// the longest run of crossings free of the others analysed alone, with
/// what it cut; again while that run shows glitches of its own (the start
/// of a careless stretch, which the glitch it led into had hidden), at most
/// eight times. `whole` itself where no run holds three periods or the
/// first gives no analysis of its own (its notes say why). With
/// `check_cuts`, each cut is analysed alone (its own clean stretch, not
/// checked again) and compared with what was kept (compare_cuts).
SwingAnalysis clean_stretch_of(const Recording& r, const std::string& file, const SwingOptions& options,
                               SwingAnalysis whole, bool check_cuts = true) {
  constexpr int kPasses = 8;
  SwingOptions inner = options;
  inner.whole_record = true;
  std::optional<SwingAnalysis> clean;
  std::vector<Cut> cuts;
  std::vector<Bridge> bridges;
  std::pair<double, double> range;
  for (int pass = 0; pass < kPasses; ++pass) {
    const SwingAnalysis& from = clean ? *clean : whole;
    if (from.glitches.empty()) break;
    const std::vector<Crossing>& c = from.crossings;
    // Step 7's stretches inside the record, bridged where the count across
    // is certain; one that joins a glitch at an end (a release, a catch, a
    // swing dying into the noise) is cut with it.
    std::vector<Bridge> spans = bridges;
    std::vector<Glitch> unbridged;
    auto at_an_end = [&](const Glitch& g) {
      return std::any_of(from.glitches.begin(), from.glitches.end(), [&](const Glitch& j) {
        return (j.start == c.front().time || j.end == c.back().time) && g.start < j.end && g.end > j.start;
      });
    };
    for (Glitch g : from.outliers) {
      // Event stamps' counts are step 5's (a missed stamp mended), not bridged.
      if (at_an_end(g) || r.kind == SignalKind::event_stamps) {
        unbridged.push_back(g);
        continue;
      }
      // A stretch that touches a bridge (its ends showed a glitch) is one with it.
      for (const Bridge& x : spans) {
        if (g.start <= x.end && x.start <= g.end) {
          g.start = std::min(g.start, x.start), g.end = std::max(g.end, x.end), g.worst = std::max(g.worst, x.worst);
        }
      }
      std::optional<Bridge> b = bridge_of(from, g);
      if (!b) {
        unbridged.push_back(g);
        continue;
      }
      b->worst = g.worst;
      spans.erase(std::remove_if(spans.begin(), spans.end(),
                                 [&](const Bridge& x) { return x.start < b->end && x.end > b->start; }),
                  spans.end());
      spans.push_back(*b);
    }
    const auto [first, last] = clean_stretch(c, join_glitches(unbridged, c, from.period.value));
    if (last < first + 7 || last - first < 3 * static_cast<std::size_t>(from.crossings_per_period)) break;
    const double a = c[first].time, b = c[last].time;
    auto inside = [&](const auto& x) { return x.start > a && x.end < b; };
    spans.erase(std::remove_if(spans.begin(), spans.end(), [&](const Bridge& x) { return !inside(x); }), spans.end());
    // A quarter of an interval beyond each end crossing: the samples its line needs, not the next crossing's.
    const double margin = 0.25 * (b - a) / static_cast<double>(last - first);
    SwingAnalysis next;
    try {
      next = analyse_record(restricted(r, {a - margin, b + margin}, file), file, inner, spans);
    } catch (const InputError& e) {
      if (!clean) {
        whole.notes.push_back({0, "the stretch without glitches, " + format_number(a, 6) + ":" + format_number(b, 6) +
                                      " s, gives no analysis of its own (" + one_line(e.what(), 160) +
                                      "): the whole record's is kept"});
      }
      break;
    }
    // Only the bridges this stretch's crossings took (apply_bridges notes any other).
    spans.erase(std::remove_if(spans.begin(), spans.end(),
                               [&](const Bridge& x) {
                                 const std::size_t j = crossing_at(next.crossings, x.end);
                                 return j >= next.crossings.size() || next.crossings[j].steps != x.steps;
                               }),
                spans.end());
    if (first > 0) cuts.push_back(describe_cut(c.front().time, a, from));
    if (last + 1 < c.size()) cuts.push_back(describe_cut(b, c.back().time, from));
    // Bridges of earlier passes are this pass's `spans` again, or grown into one, or left out of the stretch.
    cuts.erase(std::remove_if(cuts.begin(), cuts.end(), [](const Cut& x) { return x.periods_carried > 0.0; }),
               cuts.end());
    for (const Bridge& x : spans) {
      Cut k;
      k.start = x.start, k.end = x.end, k.why = "a glitch inside, its count carried across", k.worst = x.worst;
      k.periods_carried = static_cast<double>(x.steps) / from.crossings_per_period;
      cuts.push_back(k);
    }
    bridges = spans;
    range = {a - margin, b + margin};
    clean = std::move(next);
  }
  if (!clean) return whole;
  SwingAnalysis out = std::move(*clean);
  // Cuts of successive passes that touch are one; a bridge stays its own.
  std::sort(cuts.begin(), cuts.end(), [](const Cut& x, const Cut& y) { return x.start < y.start; });
  for (const Cut& x : cuts) {
    // Touching: at the same crossing, as two analyses of the stretch find it (within a tenth of a half swing).
    const double touch = 0.05 * out.period.value;
    if (out.cuts.empty() || x.start > out.cuts.back().end + touch || x.periods_carried > 0.0 ||
        out.cuts.back().periods_carried > 0.0) {
      out.cuts.push_back(x);
      continue;
    }
    Cut& joined = out.cuts.back();
    joined.end = std::max(joined.end, x.end), joined.worst = std::max(joined.worst, x.worst);
    if (joined.why.find(x.why) == std::string::npos) joined.why += " and " + x.why;
  }
  cuts = out.cuts;
  std::string text = "the clean stretch " + format_number(range.first, 6) + ":" + format_number(range.second, 6) +
                     " s is analysed, by default: cut ";
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    const Cut& x = cuts[k];
    text += (k ? "; " : "") + format_number(x.start, 6) + ":" + format_number(x.end, 6) + " s, " + x.why + " (" +
            (x.periods_carried > 0.0 ? format_number(x.periods_carried, 4) + (x.periods_carried == 1.0 ? " period; " : " periods; ") : "") +
            format_number(x.worst, 3) + " robust sigmas)";
  }
  const PeriodEstimate& p = whole.period;
  text += ". The whole record (--range all, a scene's \"range\": \"all\") gives " + seconds(p.value, 8) + " +- " +
          seconds(p.uncertainty, 2) + ", " +
          format_number(std::fabs(p.value - out.period.value) / std::hypot(p.uncertainty, out.period.uncertainty), 2) +
          " sigmas from the clean stretch's";
  out.notes.insert(out.notes.begin(), {0, text});
  if (check_cuts) {
    compare_cuts(out, [&](std::pair<double, double> range) {
      const Recording part = restricted(r, range, file);
      SwingAnalysis alone = analyse_record(part, file, inner);
      return alone.glitches.empty() ? alone : clean_stretch_of(part, file, options, std::move(alone), false);
    });
  }
  out.analysed = range;
  out.whole_record_period = p;
  return out;
}

}  // namespace

SwingAnalysis analyse_swings(const Recording& r, const std::string& file, const SwingOptions& options) {
  if (options.range) {
    const Recording cut = restricted(r, *options.range, file);
    SwingAnalysis out = analyse_record(cut, file, options);
    out.notes.insert(out.notes.begin(),
                     {0, "analysed from " + seconds(options.range->first) + " to " + seconds(options.range->second) +
                             " (--range, a scene's \"range\"): " + std::to_string(cut.time.size()) + " of " +
                             std::to_string(r.time.size()) + (r.kind == SignalKind::angular_rate ||
                                                                      r.kind == SignalKind::acceleration ||
                                                                      r.kind == SignalKind::linear_acceleration ||
                                                                      r.kind == SignalKind::angle ||
                                                                      r.kind == SignalKind::position ||
                                                                      r.kind == SignalKind::unknown
                                                                  ? " samples"
                                                                  : " events")});
    out.analysed = options.range;
    return out;
  }
  SwingAnalysis whole = analyse_record(r, file, options);
  if (options.whole_record || whole.glitches.empty()) return whole;
  return clean_stretch_of(r, file, options, std::move(whole));
}

std::vector<double> swing_signal(const Recording& r) {
  if (r.kind == SignalKind::gate_states) return blocked_states(r);
  if (r.kind == SignalKind::blocking_times) return {};
  return make_signal(r).s;
}

SwingAnalysis analyse_candidates(const Recording& r, const std::string& path, RecordingFormat format,
                                 const SwingOptions& options, const RecordingLimits& limits, const std::string& set) {
  const std::string name = r.set.empty() ? path : path + "/" + r.set;
  SwingAnalysis out = analyse_swings(r, name, options);
  const PeriodEstimate& first = out.period;
  const SignalCandidate& used = r.candidates.empty() ? SignalCandidate{} : r.candidates[0];
  // A zip's sets are picked with --set, a file's signals with --columns.
  const auto option = [](const SignalCandidate& c) {
    return c.set.empty() ? "--columns \"" + c.columns + "\"" : "--set \"" + c.set + "\"";
  };
  const auto period = [&](const Recording& signal) { return analyse_swings(signal, name, options).period; };
  for (std::size_t k = 1; k < r.candidates.size(); ++k) {
    const SignalCandidate& c = r.candidates[k];
    PeriodEstimate other;
    try {
      // A zip's sets come parsed; a file's other signal is its columns read again.
      other = c.recording ? period(*c.recording) : period(read_recording(path, format, limits, set, c.columns));
    } catch (const InputError& e) {
      out.notes.push_back({0, c.what + " gives no period (" + one_line(e.what(), 160) + "); " + used.what + " is used"});
      continue;
    }
    const double difference = other.value - first.value;
    const double sigma = std::hypot(first.uncertainty, other.uncertainty);
    const std::string both = used.what + " gives " + format_number(first.value, 8) + " +- " +
                             format_number(first.uncertainty, 2) + " s, " + c.what + " " + format_number(other.value, 8) +
                             " +- " + format_number(other.uncertainty, 2) + " s";
    if (std::fabs(difference) > 5.0 * sigma && std::fabs(difference) > 1e-3 * first.value) {
      throw InputError(c.set.empty() ? name : path, "two signals give different periods: " + both + "; expected one pendulum's: pick its " +
                                 (c.set.empty() ? "signal with --columns (a scene's \"columns\"): \"" + used.columns +
                                                      "\" or \"" + c.columns + "\""
                                                : "set with --set (a scene's \"set\"): \"" + used.set + "\" or \"" +
                                                      c.set + "\""));
    }
    out.notes.push_back({0, both + ": they agree (" + format_number(std::fabs(difference) / sigma, 2) + " sigmas); " +
                                used.what + " is used (" + option(c) + " takes the other)"});
  }
  return out;
}

RecordingSummary analyse_recording(const std::string& path, RecordingFormat format, const SwingOptions& options,
                                   const RecordingLimits& limits, const std::string& set,
                                   const std::string& columns) {
  const Recording r = read_recording(path, format, limits, set, columns);
  RecordingSummary s;
  s.file = printable_name(path);
  s.format = r.format;
  s.kind = r.kind;
  s.rows = r.rows;
  s.dropped = r.dropped;
  s.set = r.set;
  s.columns = r.columns;
  s.notes = r.notes;
  s.column_spec = columns;
  s.channels = r.channel_names;
  s.swings = analyse_candidates(r, path, format, options, limits, set);
  return s;
}

}  // namespace pendulum
