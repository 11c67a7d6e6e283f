#include "studies/torsional_dynamics_input.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "model/common/scalar.h"
#include "studies/format.h"
#include "studies/writers.h"

namespace camopt::studies {
namespace {
constexpr double kArcsecPerRad = 180.0 * 3600.0 / kPi;
}

TorsionalDynamicsSpec ParseTorsionalDynamics(const Node& block, const TorsionalDynamicsInput& in) {
  TorsionalDynamicsSpec s;
  s.in = in;
  const Node sweep = block["speed_sweep_rpm"];
  const auto& v = in.speed_sweep_rpm;
  if (!(v[0] < v[1])) sweep.FailWith("expected [lo, hi, n] with lo < hi, found lo " + Format(v[0], 6) + " >= hi " + Format(v[1], 6));
  if (v[2] != std::floor(v[2]) || v[2] < 2 || v[2] > 2000)
    sweep.FailWith("expected [lo, hi, n] with n a whole number in [2, 2000], found n = " + Format(v[2], 6));
  if (in.angles_per_mesh_period % 2 != 0)
    block["angles_per_mesh_period"].FailWith("expected an even number (every other angle is the table's error check)");
  s.lo_rpm = v[0];
  s.hi_rpm = v[1];
  s.speeds = int(v[2]);
  return s;
}

TorsionalDynamicsResult RunTorsionalDynamics(const TorsionalDynamicsSpec& spec, MeshTable table,
                                             const RunContext& ctx, const std::string& kind) {
  TorsionalDynamicsResult r;
  torsion::TorsionalModel m;
  m.input_inertia_kgm2 = spec.in.input_inertia_kgm2;
  m.output_inertia_kgm2 = spec.in.output_inertia_kgm2;
  m.ratio = table.ratio;
  m.input_shaft_stiffness_Nm_per_rad = spec.in.input_shaft_stiffness_Nm_per_rad.value_or(0.0);
  m.damping_ratio = spec.in.damping_ratio;
  m.mesh_period_rad = table.period_rad;
  m.mesh_stiffness_Nm_per_rad = table.stiffness_Nm_per_rad;
  m.static_te_rad = table.static_te_rad;
  m.reference_torque_Nm = table.torque_Nm;
  m.load_torque_Nm = table.torque_Nm;
  r.modes = torsion::LinearModes(m);
  // The table's sampling error: its mean, min and max against those of every other angle.
  {
    const auto& k = table.stiffness_Nm_per_rad;
    std::vector<double> half;
    for (size_t i = 0; i < k.size(); i += 2) half.push_back(k[i]);
    r.mean_error = std::abs(torsion::MeanOf(k) - torsion::MeanOf(half));
    r.min_error = std::abs(*std::min_element(k.begin(), k.end()) - *std::min_element(half.begin(), half.end()));
    r.max_error = std::abs(*std::max_element(k.begin(), k.end()) - *std::max_element(half.begin(), half.end()));
  }
  for (size_t g = 0; g < table.meshes.size(); ++g)
    for (torsion::ResonanceSpeed x : torsion::ResonanceSpeeds(r.modes, table.period_rad / table.meshes[g].second,
                                                              spec.in.harmonics, spec.lo_rpm, spec.hi_rpm)) {
      x.mesh = int(g);
      r.resonances.push_back(x);
    }
  std::stable_sort(r.resonances.begin(), r.resonances.end(),
                   [](const torsion::ResonanceSpeed& a, const torsion::ResonanceSpeed& b) { return a.rpm < b.rpm; });
  // The lowest speed the shooting takes: one mesh period at most kMaxModePeriods periods of the
  // highest mode (CVODE follows each: ~20 steps apiece); slower, the response is the static one.
  {
    constexpr double kMaxModePeriods = 2000.0;
    const double shortest = table.period_rad;
    const double min_rpm = 60.0 * r.modes.frequencies_Hz.back() * shortest / (2.0 * kPi * kMaxModePeriods);
    if (spec.lo_rpm < min_rpm)
      throw StudyError(ctx.study_file + ": /torsional_dynamics/speed_sweep_rpm: lo " + Format(spec.lo_rpm, 6) +
                       " rpm is below " + Format(min_rpm, 3) + " rpm, where one period of the mesh table holds " +
                       Format(kMaxModePeriods, 4) + " periods of the " + Format(r.modes.frequencies_Hz.back(), 4) +
                       " Hz mode (the response there is the static one): start the sweep at " + Format(min_rpm, 3) +
                       " rpm or above");
  }
  Progress progress(kind + " torsional dynamics", ctx.quiet);
  for (int s = 0; s < spec.speeds; ++s) {
    const double rpm = spec.lo_rpm + (spec.hi_rpm - spec.lo_rpm) * double(s) / double(spec.speeds - 1);
    r.sweep.push_back(torsion::PeriodicSteadyState(m, rpm));
    progress.Update(double(s + 1) / double(spec.speeds), std::to_string(spec.speeds) + " speeds");
  }
  progress.Done();
  int unstable = 0;
  double worst_residual = 0.0;
  for (size_t s = 0; s < r.sweep.size(); ++s) {
    const auto& st = r.sweep[s];
    if (!st.stable) {
      ++unstable;
      continue;
    }
    worst_residual = std::max(worst_residual, st.periodicity_residual);
    if (r.peak_index < 0 || st.overload_factor > r.sweep[size_t(r.peak_index)].overload_factor) r.peak_index = int(s);
  }
  if (unstable > 0)
    r.warnings.push_back("torsional dynamics: " + std::to_string(unstable) +
                         " speed(s) parametrically unstable (a Floquet multiplier >= 1): no periodic steady state");
  if (worst_residual > 1e-6)
    r.warnings.push_back("torsional dynamics: the periodic solution's residual reaches " + Format(worst_residual, 3) +
                         " (> 1e-6)");
  for (const auto& st : r.sweep)
    if (st.stable && st.min_mesh_torque_Nm < 0) {
      r.warnings.push_back("torsional dynamics: the mesh torque changes sign at " + Format(st.input_speed_rpm, 6) +
                           " rpm: the contacts would open (the linearised model does not follow them)");
      break;
    }
  r.table = std::move(table);
  return r;
}

TorsionalDynamicsBlock TorsionalDynamicsBlock::Of(const TorsionalDynamicsSpec& spec, const TorsionalDynamicsResult& r) {
  TorsionalDynamicsBlock j;
  const auto& k = r.table.stiffness_Nm_per_rad;
  const double mean = torsion::MeanOf(k), lo = *std::min_element(k.begin(), k.end()),
               hi = *std::max_element(k.begin(), k.end());
  j.natural_frequencies_Hz = r.modes.frequencies_Hz;
  for (const auto& s : r.modes.shapes) j.mode_shapes.push_back({s[0], s[1]});
  j.mode_shapes_note = "each mode's amplitudes of the input inertia's angle referred to the output (theta_in / i) "
                       "and of the output's, the larger +1; the free pair's rigid-body mode (0 Hz) is left out";
  j.ratio = r.table.ratio;
  j.reference_torque_Nm = r.table.torque_Nm;
  for (const auto& [name, order] : r.table.meshes)
    j.meshes.push_back({name, order * 2.0 * kPi / r.table.period_rad});
  j.table_periods_per_input_revolution = 2.0 * kPi / r.table.period_rad;
  j.mesh_stiffness_source = r.table.source;
  j.mean_mesh_stiffness_Nm_per_rad = mean;
  j.min_mesh_stiffness_Nm_per_rad = lo;
  j.max_mesh_stiffness_Nm_per_rad = hi;
  j.mesh_stiffness_ripple_percent = 100.0 * (hi - lo) / mean;
  j.estimated_error = {r.mean_error, r.min_error, r.max_error,
                       "angle sampling only: the table against every other angle; the contact grid's share is not "
                       "estimated"};
  j.mesh_damping_Nms_per_rad = r.modes.mesh_damping_Nms_per_rad;
  j.damping_ratio = spec.in.damping_ratio;
  for (const auto& x : r.resonances) {
    j.resonances.push_back({x.rpm, x.frequency_Hz, r.table.meshes[size_t(x.mesh)].first, x.order, x.mode + 1});
    j.resonance_speeds_rpm.push_back(x.rpm);
  }
  const double step = (spec.hi_rpm - spec.lo_rpm) / double(spec.speeds - 1);
  j.sweep_step_rpm = step;
  if (r.peak_index >= 0) {
    const auto& p = r.sweep[size_t(r.peak_index)];
    SweepPeak& peak = j.sweep_peak.emplace();
    for (const auto& m : r.table.meshes) peak.mesh_frequencies_Hz.push_back(p.mesh_frequency_Hz * m.second);
    double nearest = NAN;
    for (const auto& x : r.resonances)
      if (std::isnan(nearest) || std::abs(x.rpm - p.input_speed_rpm) < std::abs(nearest - p.input_speed_rpm))
        nearest = x.rpm;
    peak.input_speed_rpm = p.input_speed_rpm;
    peak.overload_factor = p.overload_factor;
    peak.dynamic_te_peak_to_peak_arcsec = p.te_peak_to_peak_rad * kArcsecPerRad;
    peak.nearest_resonance_rpm = nearest;
    peak.within_one_step_of_resonance = !std::isnan(nearest) && std::abs(nearest - p.input_speed_rpm) <= step * (1 + 1e-12);
    double sampling = 0.0, residual = 0.0;
    for (const auto& st : r.sweep)
      if (st.stable) sampling = std::max(sampling, st.overload_sampling_error), residual = std::max(residual, st.periodicity_residual);
    peak.overload_sampling_error = sampling;
    peak.note = "the largest of the swept speeds: between speeds the peak is not resolved (the step); sampling error "
                "the largest over the sweep (each speed's periodic solution at all samples against every other sample)";
    j.max_periodicity_residual = residual;
  }
  if (spec.in.max_dynamic_factor) {
    // As the verdict reads it (studies/report.h, EvaluateHeadlines): within the limit plus the
    // value's estimated error, so that this flag and the status say one thing.
    const double error = j.sweep_peak ? j.sweep_peak->overload_sampling_error : 0.0;
    const bool holds =
        r.peak_index >= 0 && r.sweep[size_t(r.peak_index)].overload_factor <= *spec.in.max_dynamic_factor + error;
    j.overload_limit = OverloadLimit{*spec.in.max_dynamic_factor, holds};
  }
  j.model = "two inertias referred to the output, mesh torque T_ref + k(theta)(delta - delta_s(theta)) + c "
            "d(delta)/dt linearised about the loaded contact; periodic steady state by shooting over one mesh "
            "period (CVODE, Adams, rtol 1e-10); docs/torsional_dynamics.md";
  return j;
}

void WriteTorsionalDynamics(const TorsionalDynamicsResult& r, Outputs& out) {
  Table mesh;
  std::vector<double> deg;
  for (double a : r.table.angles_rad) deg.push_back(a * 180.0 / kPi);
  mesh.Add("crank_angle_deg", deg);
  mesh.Add("stiffness_Nm_per_rad", r.table.stiffness_Nm_per_rad);
  std::vector<double> te;
  for (double x : r.table.static_te_rad) te.push_back(x * kArcsecPerRad);
  mesh.Add("static_te_arcsec", te);
  out.Add("mesh_stiffness.csv", ToCsv(mesh));

  Table d;
  std::vector<double> rpm, fm, tepp, ol, near, stable, resid;
  const double step = r.sweep.size() > 1 ? r.sweep[1].input_speed_rpm - r.sweep[0].input_speed_rpm : 0.0;
  for (const auto& st : r.sweep) {
    rpm.push_back(st.input_speed_rpm);
    fm.push_back(st.mesh_frequency_Hz);
    tepp.push_back(st.stable ? st.te_peak_to_peak_rad * kArcsecPerRad : NAN);
    ol.push_back(st.stable ? st.overload_factor : NAN);
    bool n = false;
    for (const auto& x : r.resonances) n = n || std::abs(x.rpm - st.input_speed_rpm) <= 0.5 * step * (1 + 1e-12);
    near.push_back(n ? 1.0 : 0.0);
    stable.push_back(st.stable ? 1.0 : 0.0);
    resid.push_back(st.stable ? st.periodicity_residual : NAN);
  }
  d.Add("input_speed_rpm", rpm);
  if (r.table.meshes.size() == 1) {
    for (double& f : fm) f *= r.table.meshes[0].second;
    d.Add("mesh_frequency_Hz", fm);
  } else {
    d.Add("pattern_frequency_Hz", fm);  // the table's period: every mesh an order of it
    for (const auto& [name, order] : r.table.meshes) {
      std::vector<double> f = fm;
      for (double& x : f) x *= order;
      d.Add(name + "_mesh_frequency_Hz", f);
    }
  }
  d.Add("dynamic_te_pp_arcsec", tepp);
  d.Add("dynamic_overload_factor", ol);
  d.Add("near_resonance", near);
  d.Add("stable", stable);
  d.Add("periodicity_residual", resid);
  out.Add("dynamic_te.csv", ToCsv(d));
}

std::vector<Headline> TorsionalDynamicsHeadlines() {
  return {
      {"first torsional natural frequency", "/torsional_dynamics/natural_frequencies_Hz/0", "Hz"},
      {"mesh stiffness ripple", "/torsional_dynamics/mesh_stiffness_ripple_percent", "%"},
      {"dynamic overload factor (sweep peak)", "/torsional_dynamics/sweep_peak/overload_factor", "",
       "study:/torsional_dynamics/max_dynamic_factor", NAN, true, "/torsional_dynamics/sweep_peak/overload_sampling_error"},
      {"at input speed", "/torsional_dynamics/sweep_peak/input_speed_rpm", "rpm"},
  };
}

}  // namespace camopt::studies
