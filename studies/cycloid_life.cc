// The bearing lives of a cycloid drive over a duty cycle (docs/life.md, "Cycloid").
#include "studies/cycloid_life.h"

#include <cmath>

#include "studies/bearing_life_io.h"

namespace camopt::studies::cycloid_common {

LifeResult RunLife(const LifeSpec& spec, const cycloid::LoadedTca& tca, const std::vector<double>& crank_angles_rad,
                   double solved_torque_Nmm, const std::vector<cycloid::MeshLoad>* solved_meshes) {
  using namespace camopt::cycloid;
  const Drive& drive = tca.drive();
  std::vector<cycloid::BearingLineSamples> crank, pins;
  LifeResult out;
  for (const OperatingLine& line : spec.lines) {
    std::vector<MeshLoad> meshes;
    if (solved_meshes && line.output_torque_Nmm == solved_torque_Nmm) {
      meshes = *solved_meshes;
    } else if (line.output_torque_Nmm > 0.0) {
      meshes = RunCycle(tca, line.output_torque_Nmm, crank_angles_rad).meshes;
    } else {  // no torque, no load: no contact solve
      for (double a : crank_angles_rad) {
        MeshLoad m;
        m.crank_angle_rad = a;
        meshes.push_back(m);
      }
    }
    const std::vector<double> b = cycloid::CrankBearingLoads(drive, spec.output, meshes, line.output_torque_Nmm);
    out.crank_bearing_samples = int(b.size());
    crank.push_back({line.time_share, line.input_speed_rpm, b, std::vector<double>(b.size(), 1.0)});
    if (spec.pins_rated) {
      const cycloid::PinLoadSamples p = cycloid::PinBearingLoads(drive, meshes);
      pins.push_back({line.time_share, line.input_speed_rpm, p.load_N, p.spin_rate});
    }
    out.mean_input_speed_rpm += line.time_share * line.input_speed_rpm;
  }
  auto add = [&](const std::string& name, const RollingBearingRating& rating, double revolutions,
                 const std::vector<cycloid::BearingLineSamples>& lines) {
    ElementLife e;
    e.name = name;
    e.rating = rating;
    e.life = cycloid::LifeOverDutyCycle(rating.dynamic_N, rating.kind, revolutions, lines);
    if (rating.static_N > 0) e.s0 = StaticSafetyFactor(rating.static_N, std::vector<double>{e.life.max_load_N});
    if (out.shortest.empty() || e.life.L10h < out.shortest_L10h) out.shortest_L10h = e.life.L10h, out.shortest = name;
    out.elements.push_back(std::move(e));
  };
  add("crank_bearing", spec.crank_bearing, cycloid::CrankBearingRevolutionsPerInputRevolution(drive), crank);
  if (spec.pins_rated) {
    // The spin rates are the same on every line (geometry only): their mean over one roller's
    // period is its revolutions per input revolution.
    double mean = 0.0;
    for (double w : pins.front().weight) mean += w;
    mean /= double(pins.front().weight.size());
    add("pins", spec.pins, mean, pins);
  }
  return out;
}

LifeBlock LifeBlockOf(const LifeSpec& spec, const LifeResult& l) {
  LifeBlock lj;
  lj.shortest_L10h = l.shortest_L10h;
  lj.shortest_bearing = l.shortest;
  double shortest_nm_h = kInf;  // the modified lives computed (a bearing with C_u and D_pw, kappa >= 0.1)
  std::string shortest_nm;
  for (const ElementLife& e : l.elements) {
    lj.SetElementLife(e.name, e.life.L10h);
    LifeTableRow row = BearingLifeRow(e.name, e.rating.kind == BearingKind::kBall, e.life.equivalent_load_N,
                                      e.life.max_load_N, e.life.revolutions_per_input_revolution, e.rating.dynamic_N,
                                      e.rating.static_N, e.s0, e.life.L10h, 0.0);
    row.line_equivalent_load_N = e.life.line_equivalent_load_N;
    row.mean_speed_rpm = e.life.mean_speed_rpm;
    row.L10_Mrev = e.life.L10_Mrev;
    if (l.oil && e.rating.modified) {
      const double l_nm = AddModifiedLife(row, e.rating.kind, *e.rating.modified, *l.oil, e.life.mean_speed_rpm,
                                          e.life.equivalent_load_N, e.life.L10h);
      if (!std::isnan(l_nm) && (shortest_nm.empty() || l_nm < shortest_nm_h)) shortest_nm_h = l_nm, shortest_nm = e.name;
    }
    lj.table.push_back(std::move(row));
  }
  if (l.oil) {
    lj.shortest_L_nm_h = shortest_nm.empty() ? NAN : shortest_nm_h;
    if (shortest_nm.empty()) lj.shortest_L_nm_bearing = nullptr;
    else lj.shortest_L_nm_bearing = shortest_nm;
  }
  lj.duty_cycle = DutyCycleEchoOf(spec.lines);
  lj.mean_input_speed_rpm = l.mean_input_speed_rpm;
  lj.output_mechanism.pin_count = LifeOutputMechanism::PinCount(spec.output.pin_count);
  lj.output_mechanism.pin_circle_radius_mm = spec.output.pin_circle_radius_mm;
  lj.output_mechanism.model =
      spec.output.pin_count > 0
          ? "rigid zero-clearance output pins, Q_j = Q_max max(0, sin phi_j) (Blagojevic et al. 2011)"
          : "continuous limit of rigid output pins: resultant 4 T / (pi R_w) along the crank";
  lj.crank_bearing_samples_per_line = l.crank_bearing_samples;
  lj.efficiency = "not computed: the cycloid model is frictionless (docs/cycloid.md, Limits)";
  lj.model = "ISO 281:2007 basic rating life L10 over the duty cycle (Palmgren-Miner); each line one LTCA cycle "
             "at its torque; crank bearing: |B| = |ring-pin forces + output-pin forces| over its load period, "
             "n1/n2 revolutions per input revolution; pins: the pair loads, revolution-weighted by the rolling "
             "spin (C - I).N / (n2 rho); " + ModifiedLifeModelText(l.oil.has_value());
  return lj;
}

}  // namespace camopt::studies::cycloid_common
