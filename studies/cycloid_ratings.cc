// The catalogue numbers of a cycloid drive (docs/ratings.md).
#include "studies/cycloid_ratings.h"

#include <cmath>
#include <map>
#include <stdexcept>

#include "model/common/catalogue_ratings.h"
#include "model/cycloid/tooth_profile.h"
#include "studies/format.h"

namespace camopt::studies::cycloid_common {

namespace {

/// One LTCA cycle per torque asked, each asked once (the root searches revisit their brackets).
class TorqueEvaluator {
 public:
  TorqueEvaluator(const RatingsInput& in, const LifeSpec& life, const cycloid::LoadedTca& tca,
                  const std::vector<double>& angles, double ratio,
                  const std::function<void(const std::string&)>& progress)
      : in_(in), life_(life), tca_(tca), angles_(angles), ratio_(ratio), progress_(progress) {}

  const TorquePoint& At(double torque_Nm) {
    auto it = memo_.find(torque_Nm);
    if (it != memo_.end()) return it->second;
    TorquePoint p;
    p.torque_Nm = torque_Nm;
    const double t_Nmm = torque_Nm * 1000.0;
    const cycloid::CycleResult c = cycloid::RunCycle(tca_, t_Nmm, angles_);
    ++cycles_;
    if (!c.converged)
      throw std::invalid_argument("the LTCA did not converge at " + Format(torque_Nm, 6) + " N m");
    p.max_contact_stress_MPa = c.max_pressure_MPa;
    p.max_pair_load_N = c.max_pair_load_N;
    LifeSpec one = life_;
    one.lines = {OperatingLine{t_Nmm, in_.rated_output_speed_rpm * ratio_, 1.0}};
    const LifeResult l = RunLife(one, tca_, angles_, t_Nmm, &c.meshes);
    p.shortest_L10h = l.shortest_L10h;
    p.shortest = l.shortest;
    for (const ElementLife& e : l.elements) {
      if (e.name == "crank_bearing") p.crank_bearing_max_load_N = e.life.max_load_N;
      if (e.name == "pins") p.pins_max_load_N = e.life.max_load_N;
    }
    if (progress_) progress_(std::to_string(cycles_) + " LTCA cycles");
    return memo_.emplace(torque_Nm, p).first->second;
  }
  int cycles() const { return cycles_; }

 private:
  const RatingsInput& in_;
  const LifeSpec& life_;
  const cycloid::LoadedTca& tca_;
  const std::vector<double>& angles_;
  double ratio_;
  const std::function<void(const std::string&)>& progress_;
  std::map<double, TorquePoint> memo_;
  int cycles_ = 0;
};

/// The torque at which a ratio falling with the torque (a life over the rated life, a capacity over
/// its demand) is 1: RatedTorqueForLife (model/common/catalogue_ratings.h), its error named.
template <typename F>
double SolveTorqueForRatio(const F& ratio, double start_Nm, const std::string& what) {
  try {
    // The LTCA's loads carry its contact tolerance (relative 1e-6 and below): a bracket of 1e-9 T
    // is well inside it.
    return RatedTorqueForLife(ratio, 1.0, start_Nm, 1e-9);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(what + ": " + e.what());
  }
}

/// A capacity ratio that falls with the torque, its limiting item and the target 1: the smallest
/// of capacity / demand over the items given.
struct Capacity {
  double ratio = kInf;
  std::string by;
};

}  // namespace

RatingsResult SolveRatings(const RatingsInput& in, const PeakLimits& limits, const LifeSpec& life,
                           const cycloid::LoadedTca& tca, const std::vector<double>& angles, double ratio,
                           double start_torque_Nm, const std::function<void(const std::string&)>& progress) {
  TorqueEvaluator eval(in, life, tca, angles, ratio, progress);
  RatingsResult r;
  // Rated torque: the shortest L10 at the rated speed equals the rated life.
  const double start = start_torque_Nm;
  r.rated_torque_Nm = SolveTorqueForRatio(
      [&](double t) { return eval.At(t).shortest_L10h / in.rated_life_h; }, start, "the rated life");
  const TorquePoint& rated = eval.At(r.rated_torque_Nm);
  r.rated_by = rated.shortest;
  r.rated_L10h = rated.shortest_L10h;
  // Peak (acceleration) torque: the contact limits.
  auto peak = [&](double t) {
    const TorquePoint& p = eval.At(t);
    Capacity c;
    if (limits.contact_stress_MPa && p.max_contact_stress_MPa > 0 &&
        *limits.contact_stress_MPa / p.max_contact_stress_MPa < c.ratio)
      c = {*limits.contact_stress_MPa / p.max_contact_stress_MPa, "limits.contact_stress_MPa"};
    if (limits.pair_load_N && p.max_pair_load_N > 0 && *limits.pair_load_N / p.max_pair_load_N < c.ratio)
      c = {*limits.pair_load_N / p.max_pair_load_N, "limits.roller_load_N"};
    return c;
  };
  if (limits.contact_stress_MPa || limits.pair_load_N) {
    r.peak_torque_Nm = SolveTorqueForRatio([&](double t) { return peak(t).ratio; }, r.rated_torque_Nm,
                                           "the peak torque's limits");
    r.peak_by = peak(*r.peak_torque_Nm).by;
  } else {
    r.peak_note = "not computed: no limits.contact_stress_MPa or limits.roller_load_N";
  }
  // Momentary torque: every rated bearing keeps s0 = C0 / P0max >= momentary_static_safety.
  auto momentary = [&](double t) {
    const TorquePoint& p = eval.At(t);
    Capacity c;
    const double s = in.momentary_static_safety;
    if (life.crank_bearing.static_N > 0 && p.crank_bearing_max_load_N > 0)
      c = {life.crank_bearing.static_N / (s * p.crank_bearing_max_load_N), "crank_bearing (static rating)"};
    if (life.pins_rated && life.pins.static_N > 0 && p.pins_max_load_N > 0 &&
        life.pins.static_N / (s * p.pins_max_load_N) < c.ratio)
      c = {life.pins.static_N / (s * p.pins_max_load_N), "pins (static rating)"};
    return c;
  };
  if (life.crank_bearing.static_N > 0 || (life.pins_rated && life.pins.static_N > 0)) {
    r.momentary_torque_Nm = SolveTorqueForRatio([&](double t) { return momentary(t).ratio; }, r.rated_torque_Nm,
                                                "the bearings' static ratings");
    r.momentary_by = momentary(*r.momentary_torque_Nm).by;
    if (in.momentary_peaks)
      r.momentary_peaks_allowed =
          AllowedMomentaryPeakCount(in.momentary_peaks->output_speed_rpm, in.momentary_peaks->duration_s, ratio);
  } else {
    r.momentary_note = "not computed: no static rating (static_rating_N) of the crank bearing or the pins";
  }
  r.ltca_cycles = eval.cycles();
  return r;
}

namespace {

/// Area and polar second moment about the origin of a closed polygon (Green's theorem; the sign
/// of the orientation removed).
void PolygonMoments(const std::vector<Vec2<double>>& p, double& area, double& polar) {
  double a = 0, j = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const Vec2<double>& u = p[i];
    const Vec2<double>& v = p[(i + 1) % p.size()];
    const double cross = u.x() * v.y() - v.x() * u.y();
    a += cross;
    j += cross * (u.x() * u.x() + u.x() * v.x() + v.x() * v.x() + u.y() * u.y() + u.y() * v.y() + v.y() * v.y());
  }
  area = std::abs(a) / 2.0;
  polar = std::abs(j) / 12.0;
}

}  // namespace

PartMasses CycloidMasses(const cycloid::Drive& d, const std::vector<Vec2<double>>& profile, int discs,
                         double stack_width_mm, double bore_mm, const cycloid::OutputPins* output,
                         double output_pin_length_mm, double density_kg_m3) {
  if (profile.size() < 3 || !(density_kg_m3 > 0)) throw std::invalid_argument("masses: a profile and a density > 0");
  double area = 0, polar = 0;  // mm², mm⁴
  PolygonMoments(profile, area, polar);
  auto hole = [&](double r, double centre) {
    const double a = kPi * r * r;
    area -= a;
    polar -= a * r * r / 2.0 + a * centre * centre;
  };
  if (bore_mm > 0) hole(bore_mm / 2.0, 0.0);
  if (output)
    for (int k = 0; k < output->pins; ++k) hole(output->hole_radius_mm, output->pin_circle_radius_mm);
  const double rho = density_kg_m3 * 1e-9;  // kg/mm³
  PartMasses m;
  m.disc_kg = rho * area * d.face_width_mm;
  m.disc_inertia_kgm2 = rho * polar * d.face_width_mm * 1e-6;
  const double pin_area = kPi * d.roller_radius_mm * d.roller_radius_mm;
  m.ring_pins_kg = rho * pin_area * stack_width_mm * d.rollers;
  if (output) {
    const double r = output->pin_radius_mm;
    m.output_pins_kg = rho * kPi * r * r * output_pin_length_mm * output->pins;
  }
  m.total_kg = discs * m.disc_kg + m.ring_pins_kg + m.output_pins_kg;
  // The disc's centre orbits at the input speed ω_in = i ω_out at radius e and the disc turns with
  // the output: T = ½ (m e² i² + J_d) ω_out² per disc.
  const double i = double(d.teeth) / double(d.rollers - d.teeth);
  const double e_m = d.eccentricity_mm * 1e-3;
  m.reflected_inertia_kgm2 = discs * (m.disc_kg * e_m * e_m * i * i + m.disc_inertia_kgm2);
  m.outer_diameter_mm = 2.0 * (d.roller_position_radius_mm + d.roller_radius_mm);
  m.width_mm = stack_width_mm;
  m.includes = "the discs (" + std::to_string(discs) + ", with their bore" + std::string(output ? " and holes" : "") +
               "), the ring pins over the discs' stack" + std::string(output ? " and the output pins" : "") +
               "; not the crank, its bearings, the housing, the output flange or the motor. Reflected inertia: the "
               "discs' orbit m e^2 i^2 and spin J_d, at the output";
  return m;
}

}  // namespace camopt::studies::cycloid_common
