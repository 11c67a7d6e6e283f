// AnalyzeTransmissionError (model/cycloid/transmission_error.h): the sensitivities by ceres::Jet
// through the pair and the pin in contact, the shared statistics (model/common/tolerance_stats.h)
// and the Monte-Carlo run of the exact model.
#include "model/cycloid/transmission_error.h"

#include <algorithm>
#include <stdexcept>

#include <ceres/jet.h>

namespace camopt::cycloid {
namespace {

using tolerance::kArcsecPerRad;

// The scalar deviations that move pair `pair` and pin `pin` (the others leave the lag unchanged
// while that pair and pin are the ones in contact).
bool Moves(const ToleranceParameter& p, int pair, int pin) {
  if (p.key == 1 || p.key == 2) return p.index == pair;
  if (p.key >= 5) return p.index == pin;
  return true;
}

// The largest number of deviations that move one pair and one pin: δa, δe, δn; δρ_i, δψ_i; the
// output pin's and the hole's two components and the hole's radius.
constexpr int kActive = 10;
using J = ceres::Jet<double, kActive>;

}  // namespace

std::vector<double> LagSensitivities(const Drive& d, const OutputPins* pins, const std::vector<ToleranceParameter>& params,
                                     double crank, const OutputLag<double>& nominal) {
  const int sense = 1;
  std::vector<double> s(params.size(), 0.0);
  Deviations<J> dev;
  std::vector<size_t> slot;
  for (size_t p = 0; p < params.size(); ++p) {
    if (!Moves(params[p], nominal.pair, nominal.pin)) continue;
    if (slot.size() >= size_t(kActive)) throw std::logic_error("cycloid tolerance: more active deviations than slots");
    AddDeviation(dev, d, pins, params[p], J(0.0, int(slot.size())));
    slot.push_back(p);
  }
  const OutputLag<J> lag = KinematicLag<J>(d, pins, dev, crank, sense, nominal.pair, pins ? nominal.pin : -1);
  for (size_t k = 0; k < slot.size(); ++k) s[slot[k]] = lag.total_rad.v[int(k)];
  return s;
}

namespace {

OutputLag<double> NominalLag(const Drive& d, const OutputPins* pins, double crank, int sense) {
  const OutputLag<double> lag = KinematicLag<double>(d, pins, Deviations<double>{}, crank, sense);
  if (lag.pair < 0 || (pins && lag.pin < 0))
    throw std::domain_error("cycloid tolerance: no " + std::string(lag.pair < 0 ? "ring pin" : "output pin") +
                            " in contact at crank angle " + std::to_string(crank * 180 / kPi) + " deg");
  return lag;
}

}  // namespace

std::vector<ToleranceParameter> ToleranceParameters(const Drive& d, const OutputPins* pins, const ToleranceBands& b) {
  std::vector<ToleranceParameter> p;
  if (b.pin_circle_radius_mm > 0) p.push_back({0, -1, 0, b.pin_circle_radius_mm});
  if (b.pin_diameter_mm > 0)
    for (int i = 0; i < d.rollers; ++i) p.push_back({1, i, 0, 0.5 * b.pin_diameter_mm});
  if (b.pin_pitch_rad > 0)
    for (int i = 0; i < d.rollers; ++i) p.push_back({2, i, 0, b.pin_pitch_rad});
  if (b.eccentricity_mm > 0) p.push_back({3, -1, 0, b.eccentricity_mm});
  if (b.profile_mm > 0) p.push_back({4, -1, 0, b.profile_mm});
  const int z = pins ? pins->pins : 0;
  for (int key : {5, 6}) {
    const double band = key == 5 ? b.output_pin_position_mm : b.output_hole_position_mm;
    if (band > 0)
      for (int j = 0; j < z; ++j)
        for (int c : {0, 1}) p.push_back({key, j, c, band});
  }
  if (b.output_hole_diameter_mm > 0)
    for (int j = 0; j < z; ++j) p.push_back({7, j, 0, 0.5 * b.output_hole_diameter_mm});
  return p;
}

Deviations<double> SampleDeviations(const Drive& d, const OutputPins* pins,
                                    const std::vector<ToleranceParameter>& params, std::uint64_t& state,
                                    std::vector<double>* values) {
  Deviations<double> dev;
  if (values) values->clear();
  for (const ToleranceParameter& p : params) {
    const double v = (2.0 * tolerance::Uniform01(state) - 1.0) * p.band;
    AddDeviation(dev, d, pins, p, v);
    if (values) values->push_back(v);
  }
  return dev;
}

std::vector<double> TransmissionErrorAngles(const Drive& d, int steps) {
  const int n = steps > 0 ? steps : 8 * d.rollers * d.teeth;
  std::vector<double> a;
  for (int k = 0; k < n; ++k) a.push_back(2.0 * kPi * d.teeth * k / n);
  return a;
}

KinematicCurves KinematicOutput(const Drive& d, const OutputPins* pins, const Deviations<double>& dev,
                                const std::vector<double>& crank) {
  KinematicCurves c;
  for (double phi : crank) {
    const OutputLag<double> fwd = KinematicLag<double>(d, pins, dev, phi, 1);
    c.forward_rad.push_back(fwd.total_rad);
    c.forward_pair.push_back(fwd.pair);
    c.reverse_rad.push_back(KinematicLag<double>(d, pins, dev, phi, -1).total_rad);
  }
  return c;
}

std::vector<double> ExactTransmissionError(const Drive& d, const OutputPins* pins, const Deviations<double>& dev,
                                           const std::vector<double>& crank) {
  std::vector<double> te;
  for (double phi : crank)
    te.push_back(KinematicLag<double>(d, pins, dev, phi, 1).total_rad - NominalLag(d, pins, phi, 1).total_rad);
  return te;
}

TransmissionErrorResult AnalyzeTransmissionError(const Drive& d, const OutputPins* pins, const ToleranceBands& bands,
                                                 const TransmissionErrorOptions& o) {
  TransmissionErrorResult res;
  res.crank_angle_rad = TransmissionErrorAngles(d, o.angle_steps);
  const size_t na = res.crank_angle_rad.size();
  const std::vector<ToleranceParameter> params = ToleranceParameters(d, pins, bands);
  res.parameters = int(params.size());
  std::vector<std::vector<double>> s(na);
  std::vector<double> reverse(na);
  for (size_t i = 0; i < na; ++i) {
    const double phi = res.crank_angle_rad[i];
    const OutputLag<double> fwd = NominalLag(d, pins, phi, 1);
    reverse[i] = NominalLag(d, pins, phi, -1).total_rad;
    res.nominal_lag_rad.push_back(fwd.total_rad);
    res.nominal_backlash_rad.push_back(fwd.total_rad - reverse[i]);
    s[i] = LagSensitivities(d, pins, params, phi, fwd);
  }
  res.backlash_nominal_arcmin =
      *std::max_element(res.nominal_backlash_rad.begin(), res.nominal_backlash_rad.end()) * kArcsecPerRad / 60;
  tolerance::LinearStatisticsOf(s, params, ToleranceKeys(), res);

  // Monte-Carlo with the exact model, both flanks (the backlash).
  const std::vector<double> backlash = tolerance::RunMonteCarlo(
      o.samples, o.seed, s,
      [&](std::uint64_t& state, std::vector<double>* values) { return SampleDeviations(d, pins, params, state, values); },
      [&](const Deviations<double>& dev, std::vector<double>& te) {
        double worst_backlash = -kInf;
        bool jammed = false;
        for (size_t i = 0; i < na; ++i) {
          const double phi = res.crank_angle_rad[i];
          const OutputLag<double> fwd = KinematicLag<double>(d, pins, dev, phi, 1);
          const OutputLag<double> rev = KinematicLag<double>(d, pins, dev, phi, -1);
          if (fwd.pair < 0 || rev.pair < 0 || (pins && (fwd.pin < 0 || rev.pin < 0)))
            throw std::domain_error("cycloid tolerance: a sample leaves no pair or pin in contact at crank angle " +
                                    std::to_string(phi * 180 / kPi) + " deg");
          te[i] = fwd.total_rad - res.nominal_lag_rad[i];
          worst_backlash = std::max(worst_backlash, fwd.total_rad - rev.total_rad);
          jammed = jammed || fwd.ring_rad < rev.ring_rad || fwd.pins_rad < rev.pins_rad;
        }
        res.jammed_samples += jammed;
        return worst_backlash;
      },
      o.progress, res);
  if (o.samples > 0) {
    res.backlash_arcmin = *std::max_element(backlash.begin(), backlash.end()) * kArcsecPerRad / 60;
    res.backlash_p99_arcmin = tolerance::Percentile(backlash, 0.99) * kArcsecPerRad / 60;
  } else {
    res.backlash_arcmin = res.backlash_p99_arcmin = res.backlash_nominal_arcmin;
  }
  return res;
}

}  // namespace camopt::cycloid
