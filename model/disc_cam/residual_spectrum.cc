#include "model/disc_cam/residual_spectrum.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>

namespace camopt::disc_cam {
namespace {

using Complex = std::complex<double>;

// Gauss–Kronrod 7–15 nodes and weights on [−1, 1] (Piessens et al., QUADPACK, qk15).
constexpr double kXgk[8] = {0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
                            0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
                            0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
                            0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
constexpr double kWgk[8] = {0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
                            0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
                            0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
                            0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
constexpr double kWg[4] = {0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
                           0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Panel {
  Complex kronrod, gauss;
};

template <typename F>
Panel Kronrod15(const F& f, double a, double b) {
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  const Complex fc = f(c);
  Complex k = kWgk[7] * fc, g = kWg[3] * fc;
  for (int j = 0; j < 7; ++j) {
    const Complex s = f(c - h * kXgk[j]) + f(c + h * kXgk[j]);
    k += kWgk[j] * s;
    if (j % 2 == 1) g += kWg[j / 2] * s;  // the Gauss nodes are the odd Kronrod ones
  }
  return {k * h, g * h};
}

}  // namespace

ResidualAmplitude ResidualAmplitudeAt(const motion::MotionSegment<double>& seg, double zeta, double tau,
                                      double tolerance) {
  if (seg.law == motion::MotionLaw::kDwell || !(std::abs(seg.rise) > 0.0))
    throw std::invalid_argument("residual spectrum: the segment has no rise (a dwell)");
  if (!(seg.duration > 0.0)) throw std::invalid_argument("residual spectrum: the segment's duration must be > 0");
  if (!(tau > 0.0) || !std::isfinite(tau)) throw std::invalid_argument("residual spectrum: tau must be > 0");
  if (!(zeta >= 0.0 && zeta < 1.0)) throw std::invalid_argument("residual spectrum: the damping ratio must be in [0, 1)");
  if (!(tolerance > 0.0)) throw std::invalid_argument("residual spectrum: tolerance must be > 0");
  const double h = seg.rise, root = std::sqrt(1.0 - zeta * zeta);
  const double decay = 2.0 * kPi * zeta * tau, turn = 2.0 * kPi * tau * root;
  // e^{−2πζτ} N'(u) e^{−c u} = N'(u) e^{−2πζτ(1 − u)} e^{−i 2πτ√(1−ζ²) u}, N' = (h N)'/h.
  const auto f = [&](double u) {
    const double dn = motion::MotionSegmentShape(seg, u).v / h;
    return dn * std::exp(-decay * (1.0 - u)) * Complex(std::cos(turn * u), -std::sin(turn * u));
  };
  // Adaptive bisection from panels of at most a quarter of the oscillation's period; an interval
  // is accepted when |K15 − G7| is within its share (by length) of the tolerance.
  const int start = std::max(4, static_cast<int>(std::ceil(4.0 * tau * root)));
  struct Item {
    double a, b;
  };
  std::vector<Item> stack;
  for (int i = start; i-- > 0;) stack.push_back({double(i) / start, double(i + 1) / start});
  Complex sum = 0.0;
  double error = 0.0;
  long panels = 0;
  constexpr long kMaxPanels = 200000;
  while (!stack.empty()) {
    const Item it = stack.back();
    stack.pop_back();
    const Panel p = Kronrod15(f, it.a, it.b);
    const double e = std::abs(p.kronrod - p.gauss);
    if (e <= tolerance * (it.b - it.a) || it.b - it.a < 1e-12) {
      sum += p.kronrod;
      error += e;
    } else {
      const double m = 0.5 * (it.a + it.b);
      stack.push_back({m, it.b});
      stack.push_back({it.a, m});
    }
    if (++panels > kMaxPanels)
      throw std::runtime_error("residual spectrum: the quadrature did not reach " + std::to_string(tolerance) +
                               " at tau = " + std::to_string(tau));
  }
  return {std::abs(sum) / root, error / root};
}

std::vector<double> ResidualSpectrum(const motion::MotionSegment<double>& seg, double zeta,
                                     const std::vector<double>& tau) {
  std::vector<double> out;
  out.reserve(tau.size());
  for (double t : tau) out.push_back(ResidualAmplitudeAt(seg, zeta, t).amplitude);
  return out;
}

std::vector<SpectrumMinimum> ResidualSpectrumMinima(const motion::MotionSegment<double>& seg, double zeta,
                                                    double tau_lo, double tau_hi, int samples,
                                                    double zero_tolerance) {
  if (!(tau_lo > 0.0) || !(tau_hi > tau_lo) || samples < 3)
    throw std::invalid_argument("residual spectrum minima: needs 0 < tau_lo < tau_hi and at least 3 samples");
  std::vector<double> tau(static_cast<size_t>(samples));
  for (int i = 0; i < samples; ++i) tau[size_t(i)] = tau_lo + (tau_hi - tau_lo) * i / (samples - 1);
  const std::vector<double> a = ResidualSpectrum(seg, zeta, tau);
  std::vector<SpectrumMinimum> out;
  const auto amp = [&](double t) { return ResidualAmplitudeAt(seg, zeta, t).amplitude; };
  for (int i = 1; i + 1 < samples; ++i) {
    if (!(a[size_t(i)] <= a[size_t(i - 1)] && a[size_t(i)] < a[size_t(i + 1)])) continue;
    // Golden section on the bracket [τ_{i−1}, τ_{i+1}].
    double lo = tau[size_t(i - 1)], hi = tau[size_t(i + 1)];
    const double g = 0.5 * (std::sqrt(5.0) - 1.0), width = 1e-10 * (tau_hi - tau_lo);
    double c = hi - g * (hi - lo), d = lo + g * (hi - lo), fc = amp(c), fd = amp(d);
    while (hi - lo > width) {
      if (fc < fd) hi = d, d = c, fd = fc, c = hi - g * (hi - lo), fc = amp(c);
      else lo = c, c = d, fc = fd, d = lo + g * (hi - lo), fd = amp(d);
    }
    SpectrumMinimum m;
    m.tau = 0.5 * (lo + hi);
    m.amplitude = amp(m.tau);
    m.zero = m.amplitude <= zero_tolerance;
    out.push_back(m);
  }
  return out;
}

}  // namespace camopt::disc_cam
