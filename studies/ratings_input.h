// The catalogue blocks of a reducer analysis (docs/ratings.md): "ratings" (rated torque for a rated
// life at a rated output speed, peak and momentary torque), "output_bearing" with the application's
// "external_loads", and the parts' density for the datasheet's masses and the reflected inertia.
// Declared once (studies/archive.h); cycloid_ltca reads them (studies/cycloid_ratings.h).
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <array>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/common/bearing_life.h"
#include "model/common/output_bearing.h"
#include "studies/archive.h"
#include "studies/input.h"

namespace camopt::studies {

/// "ratings": what a catalogue's rating table states, solved from the model (docs/ratings.md).
struct RatingsInput {
  struct MomentaryPeaks {
    double output_speed_rpm = 0, duration_s = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("output_speed_rpm", &output_speed_rpm,
               Field().Required().Positive().Unit("rpm").Desc("output speed at the momentary (emergency-stop) peak"));
      a->Visit("duration_s", &duration_s,
               Field().Required().Positive().Unit("s").Desc("duration of one momentary peak"));
    }
  };
  double rated_life_h = 0, rated_output_speed_rpm = 0;
  double momentary_static_safety = 1.0;
  std::optional<MomentaryPeaks> momentary_peaks;
  double density_kg_m3 = 7850.0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("rated_life_h", &rated_life_h,
             Field().Required().Positive().Unit("h").Desc(
                 "L10 life at the rated torque and speed: rated_torque_Nm is the torque whose shortest bearing L10 "
                 "equals it (solved, one LTCA cycle per trial torque)"));
    a->Visit("rated_output_speed_rpm", &rated_output_speed_rpm,
             Field().Required().Positive().Unit("rpm").Desc("the rated output speed"));
    a->Visit("momentary_static_safety", &momentary_static_safety,
             Field().Positive().Desc(
                 "static safety s0 = C0/P0max every rated bearing keeps at the momentary torque (ISO 76; 1: the "
                 "static rating itself)"));
    a->Visit("momentary_peaks", &momentary_peaks,
             Field().Desc("the momentary peak's output speed and duration: the number of peaks allowed, "
                          "1e4 / (2 (n R / 60) t) with R the ratio (docs/ratings.md)"));
    a->Visit("density_kg_m3", &density_kg_m3,
             Field().Positive().Unit("kg/m³").Desc(
                 "the parts' density: their masses on the datasheet and the reflected inertia of joint_model "
                 "(steel: 7850)"));
  }
};

/// "ratings" of a sizing kind (cycloid_min_size, lcr_min_size): the rated torque the sized drive must
/// reach, as the analysis kinds' "ratings" define it (docs/ratings.md): every rated bearing's L10 at
/// rated_torque_Nm and rated_output_speed_rpm at least rated_life_h. The sizing holds it as its life
/// rows over the one-line duty cycle {rated_torque_Nm, rated_output_speed_rpm × ratio} with limit
/// rated_life_h (docs/life.md, "Life as a sizing limit").
struct SizingRatingsInput {
  double rated_torque_Nm = 0, rated_life_h = 0, rated_output_speed_rpm = 0;
  std::optional<double> momentary_torque_Nm;
  double momentary_static_safety = 1.0;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("rated_torque_Nm", &rated_torque_Nm,
             Field().Required().Positive().Unit("N·m").Desc(
                 "the rated torque the sized drive must reach: every rated bearing's L10 at it and the rated speed at "
                 "least rated_life_h (a life limit of its own: not with limits.life_h or duty_cycle)"));
    a->Visit("rated_life_h", &rated_life_h,
             Field().Required().Positive().Unit("h").Desc("L10 life at the rated torque and speed"));
    a->Visit("rated_output_speed_rpm", &rated_output_speed_rpm,
             Field().Required().Positive().Unit("rpm").Desc(
                 "the rated output speed (the input turns ratio times faster)"));
    a->Visit("momentary_torque_Nm", &momentary_torque_Nm,
             Field().Positive().Unit("N·m").Desc(
                 "the momentary (emergency-stop) torque the sized drive must reach: every rated bearing with a "
                 "static rating keeps s0 = C0/P0max >= momentary_static_safety at it (absent: none)"));
    a->Visit("momentary_static_safety", &momentary_static_safety,
             Field().Positive().Desc("s0 at the momentary torque (ISO 76; 1: the static rating itself)"));
  }
  /// The one-line duty cycle of the rated point: the output torque [N·mm] at input speed n_out |ratio|.
  OperatingLine RatedLine(double ratio) const {
    return {rated_torque_Nm * 1000.0, rated_output_speed_rpm * std::abs(ratio), 1.0};
  }
};

/// A sizing's "ratings" is a life limit of its own (its rows over the rated point's one line): not
/// with limits.life_h (`life_limit`) or a duty_cycle. @throws StudyError naming /ratings.
void CheckSizingRatingsAlone(const Node& root, bool life_limit, bool duty_cycle);

/// The catalogue part of a "stiffness" block: the rated torque the torsional curve goes to, the
/// three segments' T1 and T2, the lost motion's percentage (a kind adds where the input is held).
struct StiffnessCatalogueInput {
  double rated_torque_Nm = 0;
  std::optional<std::vector<double>> segments_Nm;
  double lost_motion_percent = 3.0;
  static std::vector<CrossFieldRule> CrossFieldRules() {
    return {{{"segments_Nm", "rated_torque_Nm"}, "the segments' torques 0 < T1 < T2 < rated_torque_Nm", "0 < T1 < T2"}};
  }
  template <typename Archive>
  void VisitCatalogue(Archive* a) {
    a->Visit("segments_Nm", &segments_Nm,
             Field().MinItems(2, "[T1, T2] with 0 < T1 < T2 < rated_torque_Nm").Unit("N·m").Desc(
                 "T1 and T2 of the three-segment stiffness K1 (0–T1), K2 (T1–T2), K3 (T2–T_r) (absent: 25% and "
                 "75% of rated_torque_Nm; docs/ratings.md)"));
    a->Visit("lost_motion_percent", &lost_motion_percent,
             Field().Above(0.0).AtMost(100.0, "a percentage in (0, 100]").Desc(
                 "lost motion at ± this percentage of the rated torque (the catalogues' 3%)"));
  }
};

/// T1 and T2 of `in` (its segments_Nm, or 25% and 75% of the rated torque), checked: 0 < T1 < T2 <
/// T_r. `stiffness` the block's node. @throws StudyError naming stiffness/segments_Nm.
std::pair<double, double> SegmentTorques(const Node& stiffness, const StiffnessCatalogueInput& in);

/// "output_bearing": the reducer's output (cross-roller or angular-contact pair) bearing.
struct OutputBearingInput {
  std::string type = "cross_roller";
  double dynamic_rating_N = 0, static_rating_N = 0, pitch_diameter_mm = 0;
  double load_factor = 1.0;
  struct Oscillation {
    double angle_deg = 0, per_min = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("angle_deg", &angle_deg,
               Field().Required().Positive().AtMost(360.0, "an angle in (0, 360] deg").Unit("deg").Desc(
                   "the whole oscillating angle, end to end (the catalogues' θ is half of it)"));
      a->Visit("per_min", &per_min,
               Field().Required().Positive().Unit("1/min").Desc("round-trip oscillations per minute, n_1"));
    }
  };
  std::optional<double> moment_stiffness_Nm_per_arcmin;
  std::optional<Oscillation> oscillation;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("type", &type,
             Field().OneOf({"cross_roller", "angular_contact_pair"}).Desc(
                 "cross_roller (life exponent 10/3) or angular_contact_pair of ball bearings (exponent 3)"));
    a->Visit("dynamic_rating_N", &dynamic_rating_N, Field().Required().Positive().Unit("N").Desc("C, the catalogue's"));
    a->Visit("static_rating_N", &static_rating_N, Field().Required().Positive().Unit("N").Desc("C0, the catalogue's"));
    a->Visit("pitch_diameter_mm", &pitch_diameter_mm,
             Field().Required().Positive().Unit("mm").Desc("d_p, the rolling elements' pitch circle diameter"));
    a->Visit("load_factor", &load_factor,
             Field().AtLeast(1.0).Desc("f_w: 1–1.2 smooth, 1.2–1.5 normal, 1.5–3 shock and vibration"));
    a->Visit("moment_stiffness_Nm_per_arcmin", &moment_stiffness_Nm_per_arcmin,
             Field().Positive().Unit("N·m/arcmin").Desc("the catalogue's tilting-moment stiffness: the tilt angle"));
    a->Visit("oscillation", &oscillation,
             Field().Desc("oscillating motion: the life L_OC for this swing (docs/ratings.md)"));
  }
};

/// The model's bearing (model/common/output_bearing.h).
inline OutputBearing ToOutputBearing(const OutputBearingInput& in) {
  OutputBearing b;
  b.dynamic_rating_N = in.dynamic_rating_N;
  b.static_rating_N = in.static_rating_N;
  b.pitch_diameter_mm = in.pitch_diameter_mm;
  b.kind = in.type == "cross_roller" ? BearingKind::kRoller : BearingKind::kBall;
  b.moment_stiffness_Nm_per_arcmin = in.moment_stiffness_Nm_per_arcmin.value_or(0.0);
  return b;
}

/// One line of "external_loads": the application's loads on the output bearing.
struct ExternalLoadInput {
  double radial_N = 0, axial_N = 0, moment_Nm = 0, time_share = 1.0;
  std::optional<double> output_speed_rpm;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("radial_N", &radial_N, Field().NonNegative().Unit("N").Desc("F_r"));
    a->Visit("axial_N", &axial_N, Field().NonNegative().Unit("N").Desc("F_a"));
    a->Visit("moment_Nm", &moment_Nm,
             Field().NonNegative().Unit("N·m").Desc("the tilting moment about the bearing's centre"));
    a->Visit("time_share", &time_share, Field().In(0.0, 1.0).Desc("share of the time (the shares sum to 1)"));
    a->Visit("output_speed_rpm", &output_speed_rpm,
             Field().NonNegative().Unit("rpm").Desc(
                 "output speed on this line (absent: ratings.rated_output_speed_rpm, else the load's input speed "
                 "over the ratio)"));
  }
};

/// "external_loads" with every line's output speed: its own, else `default_output_speed_rpm`; the
/// time shares summing to 1 within 1e-6; `root` the study. Empty without an output bearing.
/// @throws StudyError (exit 2) naming the JSON path.
std::vector<ExternalLoadInput> ParseExternalLoads(const Node& root, bool output_bearing,
                                                  const std::optional<std::vector<ExternalLoadInput>>& loads,
                                                  std::optional<double> default_output_speed_rpm);

/// The rules of "external_loads" against the study (ParseExternalLoads): the time shares sum to 1,
/// and every line has an output speed (its own, the rated one or the load's input speed).
inline std::vector<CrossFieldRule> ExternalLoadsRules() {
  return {{{"external_loads"}, "the lines' time shares sum to 1 (within 1e-6)", "time shares that sum to 1"},
          {{"external_loads", "ratings", "load"},
           "every line's output speed: its own output_speed_rpm, ratings.rated_output_speed_rpm or the load's input "
           "speed over the ratio",
           "no ratings.rated_output_speed_rpm or load.input_speed_rpm"}};
}

/// "output_bearing" and "external_loads", as every kind that rates a reducer declares them.
template <typename Archive>
void VisitOutputBearing(Archive* a, std::optional<OutputBearingInput>* bearing,
                        std::optional<std::vector<ExternalLoadInput>>* loads) {
  a->Visit("output_bearing", bearing,
           Field().Desc("the output bearing (cross-roller or angular-contact pair) under external_loads: P_C, L10, "
                        "static safety f_s, tilt (docs/ratings.md)"));
  a->Visit("external_loads", loads,
           Field().MinItems(1, "a non-empty array of load lines").Desc(
               "the application's loads on the output bearing, lines of a duty cycle (the time shares sum to 1 "
               "within 1e-6)"));
}

/// The output bearing's numbers under the external loads (docs/ratings.md).
struct OutputBearingResult {
  OutputBearingAverages<double> average;
  double equivalent_load_N = 0, L10h = 0, static_load_N = 0, static_safety = 0;
  OutputBearingLine<double> largest;      ///< F_rmax, F_amax, M_max of the lines
  std::optional<double> oscillating_L10h, tilt_arcmin;
};

/// `loads` with every output speed given (the study fills the absent ones).
/// @throws std::invalid_argument as model/common/output_bearing.h.
OutputBearingResult SolveOutputBearing(const OutputBearingInput& in, const std::vector<ExternalLoadInput>& loads);

/// SolveOutputBearing, or nullopt with `failed` saying why (a bad bearing or duty cycle).
std::optional<OutputBearingResult> TrySolveOutputBearing(const OutputBearingInput& in,
                                                         const std::vector<ExternalLoadInput>& loads,
                                                         std::string* failed);

/// result.json's "output_bearing" (docs/ratings.md): the bearing as given, the duty cycle's
/// revolution-weighted means and extremes, its life, static safety and tilt.
struct OutputBearingBlock {
  std::string type;
  double dynamic_rating_N = 0, static_rating_N = 0, pitch_diameter_mm = 0, load_factor = 0;
  double average_radial_N = 0, average_axial_N = 0, average_moment_Nm = 0, average_output_speed_rpm = 0;
  double P_C_N = 0, L10h = 0, max_radial_N = 0, max_axial_N = 0, max_moment_Nm = 0, P0_N = 0, static_safety = 0;
  std::optional<double> L_OC_h, tilt_arcmin;
  std::string definitions;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("type", &type, Field().OneOf({"cross_roller", "angular_contact_pair"}).Desc("the bearing's type"));
    a->Visit("dynamic_rating_N", &dynamic_rating_N, Field().Unit("N").Desc("C, as given"));
    a->Visit("static_rating_N", &static_rating_N, Field().Unit("N").Desc("C0, as given"));
    a->Visit("pitch_diameter_mm", &pitch_diameter_mm, Field().Unit("mm").Desc("d_p, as given"));
    a->Visit("load_factor", &load_factor, Field().Desc("f_w, as given"));
    a->Visit("average_radial_N", &average_radial_N, Field().Unit("N").Desc("F_rav, the B-mean of |F_r|"));
    a->Visit("average_axial_N", &average_axial_N, Field().Unit("N").Desc("F_aav"));
    a->Visit("average_moment_Nm", &average_moment_Nm, Field().Unit("N·m").Desc("M_av"));
    a->Visit("average_output_speed_rpm", &average_output_speed_rpm, Field().Unit("rpm").Desc("N_av"));
    a->Visit("P_C_N", &P_C_N, Field().Unit("N").Desc("the dynamic equivalent radial load"));
    a->Visit("L10h", &L10h, Field().NullWhenNotFinite().Unit("h").Desc("the rating life (null: unlimited)"));
    a->Visit("max_radial_N", &max_radial_N, Field().Unit("N").Desc("F_rmax of the lines"));
    a->Visit("max_axial_N", &max_axial_N, Field().Unit("N").Desc("F_amax"));
    a->Visit("max_moment_Nm", &max_moment_Nm, Field().Unit("N·m").Desc("M_max"));
    a->Visit("P0_N", &P0_N, Field().Unit("N").Desc("the static equivalent radial load"));
    a->Visit("static_safety", &static_safety, Field().NullWhenNotFinite().Desc("f_s = C0 / P0"));
    a->Visit("L_OC_h", &L_OC_h,
             Field().NullWhenAbsent().NullWhenNotFinite().Unit("h").Desc("the oscillating life (null: no oscillation)"));
    a->Visit("tilt_arcmin", &tilt_arcmin,
             Field().NullWhenAbsent().Unit("arcmin").Desc("M_max / the moment stiffness (null: no stiffness given)"));
    a->Visit("definitions", &definitions, Field().Desc("the formulas, in words"));
  }
  static OutputBearingBlock Of(const OutputBearingInput& in, const OutputBearingResult& r);
};

/// result.json's "joint_model" (cycloid_ltca and lcr_analysis, with stiffness): the parameters
/// `camopt export` turns into a simulator's joint (docs/export.md: each field's unit and meaning).
struct JointModelBlock {
  struct Segments {
    double T1_Nm = 0, T2_Nm = 0, K1_Nm_per_rad = 0, K2_Nm_per_rad = 0, K3_Nm_per_rad = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      const Field n = Field().NullWhenNotFinite();
      a->Visit("T1_Nm", &T1_Nm, Field(n).Unit("N·m"));
      a->Visit("T2_Nm", &T2_Nm, Field(n).Unit("N·m"));
      a->Visit("K1_Nm_per_rad", &K1_Nm_per_rad, Field(n).Unit("N·m/rad").Desc("up to T1"));
      a->Visit("K2_Nm_per_rad", &K2_Nm_per_rad, Field(n).Unit("N·m/rad").Desc("up to T2"));
      a->Visit("K3_Nm_per_rad", &K3_Nm_per_rad, Field(n).Unit("N·m/rad").Desc("above T2"));
    }
  };
  struct Loss {
    double input_speed_rad_s = 0, efficiency_forward = 0, efficiency_backward = 0, friction_torque_input_Nm = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      const Field n = Field().NullWhenNotFinite();
      a->Visit("input_speed_rad_s", &input_speed_rad_s, Field(n).Unit("rad/s"));
      a->Visit("efficiency_forward", &efficiency_forward, Field(n));
      a->Visit("efficiency_backward", &efficiency_backward, Field(n));
      a->Visit("friction_torque_input_Nm", &friction_torque_input_Nm, Field(n).Unit("N·m"));
    }
  };
  double ratio = 0, rated_torque_Nm = 0, stiffness_Nm_per_rad = 0;
  Segments stiffness_segments;
  std::vector<std::array<double, 2>> torsion_curve;
  double backlash_rad = 0, lost_motion_rad = 0;
  int lost_motion_percent = 3;
  double reflected_inertia_kgm2 = 0;
  std::string inertia_includes;
  double damping_Nms_per_rad = 0;
  std::string damping_note;
  double friction_torque_Nm = 0;
  std::string friction_note;
  std::optional<double> efficiency;
  std::vector<Loss> loss_table;
  std::optional<double> tilt_stiffness_Nm_per_rad;
  std::string tilt_note;

  /// tilt_stiffness_Nm_per_rad (the output bearing's moment stiffness K_B, the output's tilt about
  /// each axis across the reducer's; null when not given) and tilt_note.
  void SetTilt(const std::optional<OutputBearingInput>& in);
  template <typename Archive>
  void Serialize(Archive* a) {
    const Field n = Field().NullWhenNotFinite();
    a->Visit("ratio", &ratio, Field(n).Desc("input turns per output turn"));
    a->Visit("rated_torque_Nm", &rated_torque_Nm, Field(n).Unit("N·m"));
    a->Visit("stiffness_Nm_per_rad", &stiffness_Nm_per_rad,
             Field(n).Unit("N·m/rad").Desc("the slope from 50 to 100 % of the rated torque"));
    a->Visit("stiffness_segments", &stiffness_segments, Field().Desc("the three-slope curve"));
    a->Visit("torsion_curve", &torsion_curve,
             Field(n).Desc("[torque N·m, output angle rad] along the loading branch, by ascending torque"));
    a->Visit("backlash_rad", &backlash_rad, Field(n).Unit("rad").Desc("the dead band's width"));
    a->Visit("lost_motion_rad", &lost_motion_rad, Field(n).Unit("rad"));
    a->Visit("lost_motion_percent", &lost_motion_percent, Field().Unit("%").Desc("of the rated torque"));
    a->Visit("reflected_inertia_kgm2", &reflected_inertia_kgm2, Field(n).Unit("kg·m²").Desc("at the output"));
    a->Visit("inertia_includes", &inertia_includes, Field());
    a->Visit("damping_Nms_per_rad", &damping_Nms_per_rad, Field(n).Unit("N·m·s/rad"));
    a->Visit("damping_note", &damping_note, Field());
    a->Visit("friction_torque_Nm", &friction_torque_Nm, Field(n).Unit("N·m").Desc("no-load running torque at the output"));
    a->Visit("friction_note", &friction_note, Field());
    a->Visit("efficiency", &efficiency, Field(n).NullWhenAbsent().Desc("both directions (null: not computed)"));
    a->Visit("loss_table", &loss_table, Field().Desc("losses over the input speed (may be empty)"));
    a->Visit("tilt_stiffness_Nm_per_rad", &tilt_stiffness_Nm_per_rad,
             Field(n).NullWhenAbsent().Unit("N·m/rad").Desc("the output bearing's K_B (null: rigid in tilt)"));
    a->Visit("tilt_note", &tilt_note, Field());
  }
};

}  // namespace camopt::studies
