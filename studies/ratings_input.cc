// The output bearing of "output_bearing" and "external_loads" (studies/ratings_input.h).
#include "studies/ratings_input.h"

#include <cmath>

#include "model/common/catalogue_ratings.h"

#include "studies/format.h"

namespace camopt::studies {

std::pair<double, double> SegmentTorques(const Node& stiffness, const StiffnessCatalogueInput& in) {
  const double tr = in.rated_torque_Nm;
  if (!in.segments_Nm) return {0.25 * tr, 0.75 * tr};
  const std::vector<double>& t = *in.segments_Nm;
  if (t.size() != 2 || !(t[0] > 0 && t[0] < t[1] && t[1] < tr))
    stiffness["segments_Nm"].Fail("[T1, T2] with 0 < T1 < T2 < rated_torque_Nm = " + Format(tr, 6));
  return {t[0], t[1]};
}

std::vector<ExternalLoadInput> ParseExternalLoads(const Node& root, bool output_bearing,
                                                  const std::optional<std::vector<ExternalLoadInput>>& loads,
                                                  std::optional<double> default_output_speed_rpm) {
  if (loads && !output_bearing) root["external_loads"].FailWith("external_loads need an output_bearing to act on");
  std::vector<ExternalLoadInput> out;
  if (!output_bearing) return out;
  if (!loads) (void)root["external_loads"];  // "missing required field"
  double shares = 0;
  for (size_t k = 0; k < loads->size(); ++k) {
    ExternalLoadInput line = (*loads)[k];
    shares += line.time_share;
    if (!line.output_speed_rpm) {
      if (!default_output_speed_rpm)
        root["external_loads"][k].FailWith(
            "output_speed_rpm (no ratings.rated_output_speed_rpm or load.input_speed_rpm to take it from)");
      line.output_speed_rpm = default_output_speed_rpm;
    }
    out.push_back(line);
  }
  if (std::abs(shares - 1.0) > 1e-6)
    root["external_loads"].Fail("time shares that sum to 1 within 1e-6 (they sum to " + Format(shares, 9) + ")");
  return out;
}

OutputBearingResult SolveOutputBearing(const OutputBearingInput& in, const std::vector<ExternalLoadInput>& loads) {
  const OutputBearing b = ToOutputBearing(in);
  std::vector<OutputBearingLine<double>> lines;
  for (const ExternalLoadInput& l : loads)
    lines.push_back({l.time_share, l.output_speed_rpm.value_or(0.0), l.radial_N, l.axial_N, l.moment_Nm});
  OutputBearingResult r;
  r.average = OutputBearingAverageLoads(lines, b.kind);
  r.equivalent_load_N =
      DynamicEquivalentRadialLoad(r.average.radial_N, r.average.axial_N, r.average.moment_Nm, b.pitch_diameter_mm);
  r.L10h = OutputBearingLifeHours(b, r.equivalent_load_N, r.average.speed_rpm, in.load_factor);
  r.largest = OutputBearingMaximumLoads(lines);
  r.static_load_N = StaticEquivalentRadialLoad(r.largest.radial_N, r.largest.axial_N, r.largest.moment_Nm,
                                               b.pitch_diameter_mm);
  r.static_safety = OutputBearingStaticSafetyFactor(b, lines);
  if (in.oscillation)
    r.oscillating_L10h = OscillatingOutputBearingLifeHours(b, r.equivalent_load_N, in.load_factor,
                                                           in.oscillation->per_min, in.oscillation->angle_deg / 2.0);
  if (in.moment_stiffness_Nm_per_arcmin) r.tilt_arcmin = OutputBearingTiltArcmin(b, r.largest.moment_Nm);
  return r;
}

std::optional<OutputBearingResult> TrySolveOutputBearing(const OutputBearingInput& in,
                                                         const std::vector<ExternalLoadInput>& loads,
                                                         std::string* failed) {
  try {
    return SolveOutputBearing(in, loads);
  } catch (const std::invalid_argument& e) {
    *failed = e.what();
    return std::nullopt;
  }
}

OutputBearingBlock OutputBearingBlock::Of(const OutputBearingInput& in, const OutputBearingResult& r) {
  OutputBearingBlock j;
  j.type = in.type;
  j.dynamic_rating_N = in.dynamic_rating_N;
  j.static_rating_N = in.static_rating_N;
  j.pitch_diameter_mm = in.pitch_diameter_mm;
  j.load_factor = in.load_factor;
  j.average_radial_N = r.average.radial_N;
  j.average_axial_N = r.average.axial_N;
  j.average_moment_Nm = r.average.moment_Nm;
  j.average_output_speed_rpm = r.average.speed_rpm;
  j.P_C_N = r.equivalent_load_N;
  j.L10h = r.L10h;
  j.max_radial_N = r.largest.radial_N;
  j.max_axial_N = r.largest.axial_N;
  j.max_moment_Nm = r.largest.moment_Nm;
  j.P0_N = r.static_load_N;
  j.static_safety = r.static_safety;
  j.L_OC_h = r.oscillating_L10h;
  j.tilt_arcmin = r.tilt_arcmin;
  j.definitions =
      "catalogue output-bearing rating (docs/ratings.md): revolution-weighted B-means of |F_r|, |F_a|, |M| over "
      "external_loads (B = 10/3 cross-roller, 3 angular-contact pair), P_C = X (F_r + 2M/d_p) + Y F_a (X = 1, Y = "
      "0.45 when F_a <= 1.5 (F_r + 2M/d_p), else 0.67, 0.67), L10 = 1e6/(60 N_av) (C/(f_w P_C))^B h; L_OC = 1e6/(60 "
      "n_1) (90/theta) (C/(f_w P_C))^B with theta half the oscillating angle; P0 = F_rmax + 2 M_max/d_p + 0.44 "
      "F_amax, f_s = C0/P0; tilt = M_max / moment stiffness";
  return j;
}

void JointModelBlock::SetTilt(const std::optional<OutputBearingInput>& in) {
  if (in && in->moment_stiffness_Nm_per_arcmin) {
    tilt_stiffness_Nm_per_rad = *in->moment_stiffness_Nm_per_arcmin * kArcminPerRad;
    tilt_note = "output_bearing.moment_stiffness_Nm_per_arcmin (the catalogue's K_B, linear)";
  } else {
    tilt_stiffness_Nm_per_rad.reset();
    tilt_note = "not given: no output_bearing.moment_stiffness_Nm_per_arcmin (rigid in tilt)";
  }
}

void CheckSizingRatingsAlone(const Node& root, bool life_limit, bool duty_cycle) {
  if (life_limit)
    root["ratings"].FailWith("the rated torque is a life limit of its own (the rated life at the rated torque and "
                             "speed): not with limits.life_h; would fit: one of the two");
  if (duty_cycle)
    root["ratings"].FailWith("the rated torque sets the lives' one line (the rated torque and speed): not with "
                             "duty_cycle; would fit: one of the two");
}

}  // namespace camopt::studies
