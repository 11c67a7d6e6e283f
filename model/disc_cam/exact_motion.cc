#include "model/disc_cam/exact_motion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

#include "model/common/roots.h"

namespace camopt::disc_cam {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The follower coordinate at which the roller (radius r) touches point P from outside, at cam
// angle theta; -inf when the roller can never touch P. The search's nominal part n gives θ, U(θ),
// S(θ) and the initial coordinate (the same at every point of one search).
double TouchCoordinate(const DiscCam& cam, const ExactSearchNominal& n, const Vec2<double>& P, double r) {
  const double theta = n.theta;
  const Vec2<double>& u = n.u;
  if (cam.follower == FollowerType::kTranslatingRoller) {
    // |L u + e Ju − P| = r: (L − P·u)² + (e − P·Ju)² = r², larger root.
    const double pv = cam.offset - P.dot(Perp(u));
    const double disc = r * r - pv * pv;
    if (disc < 0.0) return -std::numeric_limits<double>::infinity();
    return P.dot(u) + std::sqrt(disc) - n.initial_coordinate;
  }
  // |O₃ + l u(θ + π − ξ) − P| = r with O₃ = f u(θ): the roller contains P for
  // |θ + π − ξ − ψ| < acos(c/d), ψ the angle of D = P − O₃, c = (l² + d² − r²)/(2l).
  const double l = cam.arm_length;
  const Vec2<double> D = P - cam.pivot_distance * u;
  const double dist = D.norm();
  const double c = (l * l + dist * dist - r * r) / (2.0 * l);
  if (std::abs(c) > dist) return -std::numeric_limits<double>::infinity();
  const double psi = std::atan2(D.y(), D.x());
  const double xi0 = n.initial_coordinate;
  const double xi_nominal = xi0 + n.follower_coordinate;
  const double xi = xi_nominal + std::remainder(theta + kPi - psi + std::acos(c / dist) - xi_nominal,
                                                2.0 * kPi);
  return xi - xi0;
}

template <typename Point>  // CamPoint or CamContact
Vec2<double> PerturbedPoint(const Point& p, const Deviations<double>& d) {
  return p.contact + d.normal * p.normal + d.radial * p.contact / p.radial_dimension;
}

}  // namespace

ExactSearchNominal NominalForExactSearch(const DiscCam& cam, double theta, double window_rad) {
  ExactSearchNominal n;
  n.theta = theta;
  n.window_rad = window_rad;
  n.follower_coordinate = cam.follower == FollowerType::kTranslatingRoller ? 0.0 : cam.motion.Evaluate(theta).s;
  n.initial_coordinate = InitialFollowerCoordinate(cam);
  n.u = U(theta);
  const double step = 2.0 * window_rad / ExactSearchNominal::kScan;
  n.scan.reserve(ExactSearchNominal::kScan + 1);
  for (int k = 0; k <= ExactSearchNominal::kScan; ++k)
    n.scan.push_back(EvaluateCamContact(cam, theta - window_rad + k * step, n.initial_coordinate));
  return n;
}

double ExactFollowerPosition(const DiscCam& cam, const Deviations<double>& d, double theta, double window_rad) {
  return ExactFollowerPosition(cam, d, NominalForExactSearch(cam, theta, window_rad));
}

double ExactFollowerPosition(const DiscCam& cam, const Deviations<double>& d, const ExactSearchNominal& nominal) {
  const double r = cam.roller_radius + d.roller;
  const double theta = nominal.theta, window_rad = nominal.window_rad;
  auto touch_at = [&](const CamContact<double>& p) {
    return TouchCoordinate(cam, nominal, PerturbedPoint(p, d), r);
  };
  // Coarse scan of the window, then Brent's refinement of the maximum around the best sample,
  // started from the best sample and its two neighbours (the touch coordinate is smooth and has a
  // single maximum near the contact: the first step is their parabola's vertex) and stopped once a
  // parabola promises less than 1e-13 (mm or rad) more: 4.7 evaluations a search on the
  // oscillating example, where a cold start to the bracket's 1e-8 took 12.5.
  constexpr int kScan = ExactSearchNominal::kScan;
  const double step = 2.0 * window_rad / kScan;
  double values[kScan + 1];
  int best_k = -1;
  double best = -std::numeric_limits<double>::infinity();
  for (int k = 0; k <= kScan; ++k) {
    values[k] = touch_at(nominal.scan[size_t(k)]);
    if (values[k] > best) best = values[k], best_k = k;
  }
  if (!std::isfinite(best)) return kNaN;
  const double best_t = theta - window_rad + best_k * step;
  const auto f = [&](double t) { return touch_at(EvaluateCamContact(cam, t, nominal.initial_coordinate)); };
  std::pair<double, double> refined;
  if (best_k > 0 && best_k < kScan && std::isfinite(values[best_k - 1]) && std::isfinite(values[best_k + 1])) {
    const bool left_better = values[best_k - 1] >= values[best_k + 1];
    const double tl = best_t - step, tr = best_t + step;
    const BrentStart start{best_t, best, left_better ? tl : tr, values[best_k + (left_better ? -1 : 1)],
                           left_better ? tr : tl, values[best_k + (left_better ? 1 : -1)]};
    refined = BrentMaximize(f, tl, tr, start, 100, 1e-8, 1e-13);
  } else {
    refined = BrentMaximize(f, best_t - step, best_t + step, 100, 1e-8);
  }
  const double f_max = refined.second;
  return std::max(best, f_max);
}

std::vector<MonteCarloScale> MonteCarloLinearisation(const DiscCam& cam,
                                                     const Deviations<double>& tol,
                                                     const MonteCarloOptions& options) {
  const int n = options.angle_steps;
  std::vector<CamPoint<double>> points(n);
  std::vector<double> thetas(n);
  for (int i = 0; i < n; ++i) {
    thetas[i] = 2.0 * kPi * i / n;
    points[i] = EvaluateCam(cam, thetas[i]);
  }
  std::vector<ExactSearchNominal> nominal;
  nominal.reserve(size_t(n));
  for (int i = 0; i < n; ++i) nominal.push_back(NominalForExactSearch(cam, thetas[i]));
  std::vector<MonteCarloScale> out;
  std::vector<double> worst_case(static_cast<size_t>(n));
  for (double scale : options.scales) {
    std::mt19937_64 rng(options.seed);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    MonteCarloScale r;
    r.scale = scale;
    r.bound_exceed = -std::numeric_limits<double>::infinity();
    Deviations<double> bound{scale * tol.normal, scale * tol.radial, scale * tol.roller};
    // The angle where the linear RMS bound is largest: sample statistics are taken there.
    int i_rms = 0;
    double rms_max = -1.0;
    for (int i = 0; i < n; ++i) {
      const MechanicalError<double> e = FollowerError(cam, points[i], bound);
      worst_case[size_t(i)] = e.worst_case;  // the same for every sample
      if (e.rms > rms_max) rms_max = e.rms, i_rms = i;
    }
    double sum_sq = 0.0;
    int within = 0;
    for (int s = 0; s < options.samples; ++s) {
      const Deviations<double> d{bound.normal * unit(rng), bound.radial * unit(rng),
                                 bound.roller * unit(rng)};
      bool ok = true;
      for (int i = 0; i < n; ++i) {
        const double exact = ExactFollowerPosition(cam, d, nominal[size_t(i)]) - points[i].s;
        const double linear = [&] {
          const MechanicalError<double> e = FollowerError(cam, points[i], d);
          return e.normal + e.radial + e.roller;
        }();
        const double worst = worst_case[size_t(i)];
        r.max_linear = std::max(r.max_linear, std::abs(linear));
        r.max_exact = std::max(r.max_exact, std::abs(exact));
        const double diff = std::abs(exact - linear);
        if (diff > r.max_difference) r.max_difference = diff, r.at_cam_angle_rad = thetas[i];
        r.bound_exceed = std::max(r.bound_exceed, std::abs(exact) - worst);
        if (std::abs(exact) > worst) ok = false;
        if (i == i_rms) sum_sq += exact * exact;
      }
      within += ok;
    }
    r.relative_difference = r.max_linear > 0.0 ? r.max_difference / r.max_linear : 0.0;
    r.within_bound_fraction = options.samples > 0 ? double(within) / options.samples : 0.0;
    r.sample_rms = options.samples > 0 ? std::sqrt(sum_sq / options.samples) : 0.0;
    // A uniform deviation on ±b has variance b²/3: the linear RMS of eq. (32) over sqrt(3).
    r.predicted_rms = rms_max / std::sqrt(3.0);
    out.push_back(r);
  }
  return out;
}

}  // namespace camopt::disc_cam
