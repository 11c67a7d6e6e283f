// The catalogue numbers of a cycloid drive (docs/ratings.md).
#include "studies/cycloid_ratings.h"

#include <cmath>
#include <stdexcept>

#include "model/common/catalogue_ratings.h"
#include "model/common/polygon.h"
#include "model/cycloid/tooth_profile.h"
#include "studies/format.h"

namespace camopt::studies::cycloid_common {

RatingPoint CycloidRatingPoint(const RatingsInput& in, const LifeSpec& life, const cycloid::LoadedTca& tca,
                               const std::vector<double>& angles, double ratio, double torque_Nm) {
  RatingPoint p;
  const double t_Nmm = torque_Nm * 1000.0;
  const cycloid::CycleResult c = cycloid::RunCycle(tca, t_Nmm, angles);
  if (!c.converged) throw std::invalid_argument("the LTCA did not converge at " + Format(torque_Nm, 6) + " N m");
  p.max_contact_stress_MPa = c.max_pressure_MPa;
  p.max_roller_load_N = c.max_pair_load_N;
  LifeSpec one = life;
  one.lines = {OperatingLine{t_Nmm, in.rated_output_speed_rpm * ratio, 1.0}};
  const LifeResult l = RunLife(one, tca, angles, t_Nmm, &c.meshes);
  p.shortest_L10h = l.shortest_L10h;
  p.shortest = l.shortest;
  for (const ElementLife& e : l.elements) p.statics.push_back({e.name, e.rating.static_N, e.life.max_load_N});
  return p;
}

PartMasses CycloidMasses(const cycloid::Drive& d, const std::vector<Vec2<double>>& profile, int discs,
                         double stack_width_mm, double bore_mm, const cycloid::OutputPins* output,
                         double output_pin_length_mm, double density_kg_m3) {
  if (profile.size() < 3 || !(density_kg_m3 > 0)) throw std::invalid_argument("masses: a profile and a density > 0");
  const PolygonMoments pm = PolygonAreaAndPolarMoment(profile);
  double area = pm.area, polar = pm.polar;  // mm², mm⁴
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
