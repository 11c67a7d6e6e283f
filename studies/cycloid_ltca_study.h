// Study kind "cycloid_ltca": loaded tooth contact analysis of a cycloid stage over the crank
// angles (model/cycloid/, docs/cycloid.md). Outputs result.json, per_angle.csv, backlash.csv,
// lte.svg, gear_ratio.svg, contact_stress.svg, pressure_map.svg (every contacting pair at the
// angle of the maximum stress), pressure_max.csv and a tooth drawing (tooth.svg, tooth.dxf); with
// "tolerances", transmission_error.csv and .svg (model/cycloid/transmission_error.h).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/common/geometry.h"
#include "model/common/catalogue_ratings.h"
#include "model/cycloid/crowning.h"
#include "model/cycloid/loaded_tca.h"
#include "model/cycloid/form_grinding.h"
#include "model/cycloid/output_mechanism.h"
#include "model/cycloid/stiffness.h"
#include "model/cycloid/transmission_error.h"
#include "model/cycloid/lubrication.h"
#include "studies/archive.h"
#include "studies/lubrication_input.h"
#include "studies/cycloid_input.h"
#include "studies/cycloid_life.h"
#include "studies/cycloid_ratings.h"
#include "studies/cycloid_study_common.h"
#include "studies/geometry_files.h"
#include "studies/parts.h"
#include "studies/input.h"
#include "studies/material_input.h"
#include "studies/measured_profile.h"
#include "studies/ratings.h"
#include "studies/ratings_input.h"
#include "studies/study.h"
#include "studies/tolerance_input.h"
#include "studies/torsional_dynamics_input.h"

namespace camopt::studies::cycloid_ltca {

/// Default samples per mesh period: peak-to-peak LTE and GR need >= 20 (docs/cycloid.md).
inline constexpr int kDefaultCrankAnglesPerMeshPeriod = 32;

/// The study file as declared: each field once, in the file's units, with its default, bounds and
/// description (studies/archive.h); the blocks shared with the other cycloid kinds are those of
/// studies/cycloid_input.h. Parse reads it, checks what spans fields and converts it (Study);
/// `camopt schema cycloid_ltca` is emitted from it.
struct Input {
  struct Load {
    double torque_Nm = 0;
    std::optional<double> input_speed_rpm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("torque_Nm", &torque_Nm,
               Field().Required().NonNegative().Unit("N·m").Desc("the output torque; each of the discs carries torque_Nm / discs"));
      a->Visit("input_speed_rpm", &input_speed_rpm,
               Field().Positive().Unit("rpm").Desc(
                   "input (crank) speed: the bearing lives at load.torque_Nm (a one-line duty cycle; docs/life.md, "
                   "Cycloid); absent: no life unless a duty_cycle is given"));
    }
  };
  struct Analysis {
    std::optional<std::array<int, 2>> grid;
    double tolerance = cycloid::LoadedOptions{}.tolerance;
    std::optional<std::vector<double>> crank_angles_deg;
    std::optional<int> crank_angle_steps;
    std::optional<double> crank_span_deg;
    std::optional<int> crank_angles_per_mesh_period;
    bool estimate_error = true;
    std::optional<std::vector<std::string>> evaluate;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("grid", &grid, cycloid_common::GridField());
      a->Visit("tolerance", &tolerance,
               Field().Positive().Desc("relative compatibility residual of the contact pairs (loose above 0.1)"));
      a->Visit("crank_angles_deg", &crank_angles_deg,
               Field().MinItems(1, "a non-empty array of angles").Unit("deg")
                   .Desc("the crank angles to solve, a list (instead of crank_angles_per_mesh_period)"));
      a->Visit("crank_angle_steps", &crank_angle_steps,
               Field().AtLeast(1).AtMost(100000, "at most 100000 steps")
                   .Desc("uniform crank angles over crank_span_deg (instead of crank_angles_per_mesh_period)"));
      a->Visit("crank_span_deg", &crank_span_deg,
               Field().Positive().Unit("deg").Desc("the span of crank_angle_steps (only with it; absent: 360)"));
      a->Visit("crank_angles_per_mesh_period", &crank_angles_per_mesh_period,
               Field().AtLeast(1).AtMost(10000, "at most 10000")
                   .Desc("uniform crank angles over one mesh period 360/rollers deg (absent, and no other sampling "
                         "given: " + std::to_string(kDefaultCrankAnglesPerMeshPeriod) + ")"));
      a->Visit("estimate_error", &estimate_error,
               Field().Desc("estimate the discretisation error of the headlines (a refined run; loaded stage only)"));
      a->Visit("evaluate", &evaluate,
               Field().OneOf({"unloaded", "loaded"}, "one of \"unloaded\", \"loaded\"")
                   .Desc("the stages to run: [\"unloaded\"] the unloaded TCA only (no material or load needed); "
                         "absent: the loaded stage, which includes the unloaded one"));
    }
    static nlohmann::ordered_json SchemaRules() {  // one sampling at most; the span only with steps
      return {{"dependentRequired", {{"crank_span_deg", {"crank_angle_steps"}}}},
              {"not", {{"anyOf", {{{"required", {"crank_angles_deg", "crank_angle_steps"}}},
                                  {{"required", {"crank_angles_deg", "crank_angles_per_mesh_period"}}},
                                  {{"required", {"crank_angle_steps", "crank_angles_per_mesh_period"}}}}}}}};
    }
  };
  /// "output_mechanism" (studies/cycloid_input.h, shared with cycloid_min_size).
  using OutputMechanism = cycloid_common::CompliantOutputMechanismInput;
  struct Stiffness : StiffnessCatalogueInput {
    std::optional<double> crank_angle_deg;  ///< absent: 0 (no schema default: the block is optional)
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("rated_torque_Nm", &rated_torque_Nm, Field().Required().Positive().Unit("N·m").Desc("T_r at the output"));
      a->Visit("crank_angle_deg", &crank_angle_deg, Field().Unit("deg").Desc("the crank angle held (absent: 0)"));
      VisitCatalogue(a);
    }
  };
  struct Limits : LubricationLimitsInput {
    std::optional<double> contact_stress_MPa, roller_load_N, output_pin_stress_MPa, output_pin_contact_pressure_MPa,
        eccentric_bearing_load_N;
    double min_profile_radius_mm = 0, min_pin_gap_mm = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("contact_stress_MPa", &contact_stress_MPa,
               Field().Positive().Unit("MPa").Desc("largest Hertz pressure of the disc on a ring pin"));
      a->Visit("roller_load_N", &roller_load_N, Field().Positive().Unit("N").Desc("largest load of one pin-tooth pair"));
      a->Visit("output_pin_stress_MPa", &output_pin_stress_MPa,
               Field().Positive().Unit("MPa").Desc("output-pin bending stress (needs output_mechanism)"));
      a->Visit("output_pin_contact_pressure_MPa", &output_pin_contact_pressure_MPa,
               Field().Positive().Unit("MPa").Desc("hole-pin Hertz pressure (needs output_mechanism)"));
      a->Visit("eccentric_bearing_load_N", &eccentric_bearing_load_N,
               Field().Positive().Unit("N").Desc("largest eccentric (crank) bearing load"));
      a->Visit("min_profile_radius_mm", &min_profile_radius_mm,
               Field().NonNegative().Unit("mm").Desc(
                   "smallest convex radius of the tooth, rho_min - rho' (docs/cycloid.md, geometric limits; 0: not "
                   "undercut)"));
      a->Visit("min_pin_gap_mm", &min_pin_gap_mm,
               Field().NonNegative().Unit("mm").Desc(
                   "clearance between neighbouring pins, 2 a sin(pi/(z + 1)) - 2 rho (0: they do not overlap)"));
      VisitLubricationLimits(a);
    }
  };

  /// "tolerances": ± bands of the manufacturing errors (docs/cycloid.md, Transmission error from
  /// tolerances), each optional (absent: 0), as the LCR's (studies/lcr_tolerance_input.h).
  struct Tolerances {
    std::optional<double> pin_circle_radius_um, pin_diameter_um, pin_pitch_arcsec, eccentricity_um, profile_um,
        output_pin_position_um, output_hole_position_um, output_hole_diameter_um;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("pin_circle_radius_um", &pin_circle_radius_um, ToleranceBandField("± band of the pins' circle radius a"));
      a->Visit("pin_diameter_um", &pin_diameter_um, ToleranceBandField("± band of each ring pin's diameter 2 rho"));
      a->Visit("pin_pitch_arcsec", &pin_pitch_arcsec,
               ToleranceArcsecBandField("± band of each ring pin's angular position on the pins' circle"));
      a->Visit("eccentricity_um", &eccentricity_um, ToleranceBandField("± band of the crank's eccentricity e"));
      a->Visit("profile_um", &profile_um,
               ToleranceBandField("± band of the disc profile's normal deviation (equidistant, > 0 adds material)"));
      a->Visit("output_pin_position_um", &output_pin_position_um,
               ToleranceBandField("± band of each output pin's position on the flange, radial and tangential "
                                  "(needs output_mechanism with pin_radius_mm and hole_radius_mm)"));
      a->Visit("output_hole_position_um", &output_hole_position_um,
               ToleranceBandField("± band of each output hole's position in the disc, radial and tangential "
                                  "(needs the output mechanism's radii)"));
      a->Visit("output_hole_diameter_um", &output_hole_diameter_um,
               ToleranceBandField("± band of each output hole's diameter (needs the output mechanism's radii)"));
    }
  };
  /// "monte_carlo" (with "tolerances" only): the exact model's samples over the bands.
  struct MonteCarlo {
    std::optional<int> samples, seed, angle_steps;
    template <typename Archive>
    void Serialize(Archive* a) {
      VisitMonteCarloSamples(a, &samples, &seed);
      a->Visit("angle_steps", &angle_steps,
               Field().AtLeast(4).AtMost(100000, "at most 100000 angle steps")
                   .Desc("crank angles of the transmission error over one output revolution (teeth crank turns; "
                         "absent: 8 per mesh period, 8 rollers × teeth)"));
    }
  };

  /// The part names of "measured_profile": the discs (each its own part frame, model/cycloid/parts.h).
  struct Parts {
    static std::vector<std::string> Names() {
      return {"disc_1", "disc_2", "disc_3", "disc_4", "disc_5", "disc_6", "disc_7", "disc_8"};
    }
    static std::string Description() {
      return "the measured disc, disc_1 … disc_N (N = discs; its part frame: docs/cycloid.md, \"Inspection and "
             "measured discs\")";
    }
  };

  std::string study = "cycloid_ltca", name;
  std::optional<std::string> description;
  cycloid_common::DriveInput drive;
  std::optional<cycloid_common::ModificationInput> modification;
  std::optional<cycloid_common::CrowningInput> crowning;
  std::optional<MaterialInput> material;
  std::optional<Load> load;
  std::optional<Analysis> analysis;
  cycloid_common::CycloidDutyCycleInput duty_cycle;
  GeometryFiles geometry_files = true;
  std::optional<KindedBearingRatingInput<true>> crank_bearing;
  std::optional<BearingRatingInput<true>> pins;
  std::optional<OutputMechanism> output_mechanism;
  int discs = 1;
  std::optional<double> disc_spacing_mm;
  std::optional<Limits> limits;
  std::optional<Stiffness> stiffness;
  std::optional<Tolerances> tolerances;
  std::optional<MonteCarlo> monte_carlo;
  std::optional<LubricantWithContaminationInput> lubricant;
  std::optional<SurfacesInput> surfaces;
  std::optional<CycloidBearingFrictionInput> bearing_friction;
  std::optional<EfficiencyMapInput> efficiency_map;
  std::optional<RatingsInput> ratings;
  std::optional<OutputBearingInput> output_bearing;
  std::optional<std::vector<ExternalLoadInput>> external_loads;
  std::optional<TorsionalDynamicsInput> torsional_dynamics;
  /// "grinding": the form wheel for the modified tooth (model/cycloid/form_grinding.h).
  struct Grinding {
    double wheel_radius_mm = 0;
    double tolerance_um = 0.1;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("wheel_radius_mm", &wheel_radius_mm,
               Field().Required().Positive().Unit("mm").Desc(
                   "the form wheel's largest radius (at the tooth space's root), above the space's depth"));
      a->Visit("tolerance_um", &tolerance_um,
               Field().In(0.001, 100.0).Unit("µm").Default(0.1).Desc(
                   "largest distance of the wheel's dressing polygon (grinding_wheel.csv) from the exact tooth"));
    }
  };
  std::optional<Grinding> grinding;
  std::optional<InspectionInput> inspection;
  std::optional<MeasuredProfileInputT<Parts>> measured_profile;

  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Required().Const("cycloid_ltca").Desc("the study kind"));
    a->Visit("name", &name, Field().Desc("the design's name, in titles"));
    a->Visit("description", &description, Field().Desc("free text"));
    a->Visit("drive", &drive, Field().Required().Desc("the pin ring and the disc"));
    a->Visit("modification", &modification,
             Field().Desc("the tooth profile's modifications (absent: none; micrometres, below the pin radius)"));
    a->Visit("crowning", &crowning, Field().Desc("the axial crowning of the teeth (absent: none)"));
    a->Visit("material", &material,
             Field().Desc("the disc's and pins' elastic material (required by the loaded stage)"));
    a->Visit("load", &load, Field().Desc("the torque and speed (required by the loaded stage)"));
    a->Visit("analysis", &analysis, Field().Desc("the crank angles, the contact grid and the stages to run"));
    a->Visit("geometry_files", &geometry_files,
             Field().Desc(
                 "geometry files (docs/studies.md 'Geometry files'); false: none at all (no arc fit, no DXF/STEP/STL)"));
    cycloid_common::VisitLifeRatings(a, &duty_cycle, &crank_bearing, &pins,
                                     " (one disc); the time shares sum to 1 within 1e-6, at least one speed > 0"
                                     "; each line one LTCA cycle at its torque");
    a->Visit("output_mechanism", &output_mechanism,
             Field().Desc(
                 "output pins in the disc's holes: pin circle radius (inside the disc's root radius) and pin count "
                 "(absent: the continuous limit); with pin_radius_mm and hole_radius_mm the mechanism with clearance "
                 "and compliance (docs/cycloid.md, Output mechanism), else rigid pins for the life (docs/life.md, "
                 "Cycloid)"));
    a->Visit("discs", &discs,
             Field().AtLeast(1).AtMost(8, "at most 8 discs").Desc(
                 "identical discs phased by 360/N deg about the crank, equal torque split (docs/cycloid.md, Output "
                 "mechanism); the crank angles per revolution a multiple of N"));
    a->Visit("disc_spacing_mm", &disc_spacing_mm,
             Field().Positive().Unit("mm").Desc(
                 "distance between neighbouring discs' mid-planes, >= the face width (absent: the face width)"));
    a->Visit("limits", &limits, Field().Desc("the verdict's limits (report.html, the summary, --strict); none by default"));
    a->Visit("stiffness", &stiffness,
             Field().Desc("the torsional curve, input held (docs/cycloid.md, Stiffness, lost motion and backlash): "
                          "torsional_stiffness_Nm_per_arcmin, lost_motion_arcmin, backlash_arcmin, hysteresis.csv"));
    a->Visit("tolerances", &tolerances,
             Field().Desc("± tolerance bands: the kinematic transmission error and backlash, linear and Monte-Carlo "
                          "(docs/cycloid.md, Transmission error from tolerances); one disc"));
    a->Visit("monte_carlo", &monte_carlo, Field().Desc("the Monte-Carlo of the transmission error (with tolerances)"));
    a->Visit("lubricant", &lubricant,
             Field().Desc("the oil: the lubricated losses, efficiency and oil temperature (docs/lubrication.md; needs "
                          "load.input_speed_rpm and output_mechanism)"));
    a->Visit("surfaces", &surfaces,
             Field().Desc("roughness, friction by regime and the ring pins' mounting (with lubricant)"));
    a->Visit("bearing_friction", &bearing_friction,
             Field().Desc("Palmgren's factors of the ring pins', output rollers' and crank bearings (with lubricant; a "
                          "bearing not given adds no loss and is listed as not modelled)"));
    a->Visit("efficiency_map", &efficiency_map,
             Field().Desc("efficiency_map.csv: efficiency, loss and oil temperature over torques × speeds (with "
                          "lubricant; one loaded cycle per torque)"));
    a->Visit("ratings", &ratings,
             Field().Desc("the catalogue's ratings: rated torque for a rated life at a rated output speed, peak torque "
                          "from the contact limits, momentary torque from the static ratings (docs/ratings.md; needs "
                          "crank_bearing, output_mechanism, one disc)"));
    VisitOutputBearing(a, &output_bearing, &external_loads);
    a->Visit("torsional_dynamics", &torsional_dynamics,
             Field().Desc("the reducer's torsional dynamics from the ring-pin mesh stiffness of the LTCA "
                          "(docs/torsional_dynamics.md): natural frequencies, mode shapes, the dynamic transmission "
                          "error and overload over an input-speed sweep, resonance speeds; mesh_stiffness.csv, "
                          "dynamic_te.csv (needs the loaded stage)"));
    a->Visit("grinding", &grinding,
             Field().Desc("form grinding of the modified tooth (docs/parts.md, Form grinding): the wheel's axial "
                          "profile (grinding_wheel.csv), its centre distance and indexing, the residual form error"));
    a->Visit("inspection", &inspection,
             Field().Desc("inspection points of each disc's exact tooth profile with the ISO 1101 profile "
                          "tolerance zone: inspection/disc_k.csv (docs/cycloid.md, \"Inspection and measured "
                          "discs\"; none when geometry_files is false)"));
    a->Visit("measured_profile", &measured_profile,
             Field().Desc("a measured disc back in: its ISO 1101 profile deviation and the kinematic transmission "
                          "error and backlash as measured beside the nominal (docs/cycloid.md, \"Inspection and "
                          "measured discs\")"));
  }
  /// The rules between blocks: the loaded stage needs the material and the load; a life needs the
  /// crank bearing and the output mechanism, one disc and the loaded stage; and so on.
  static nlohmann::ordered_json SchemaRules();
  /// The rules between blocks JSON Schema cannot state: the crowning, the discs and the form wheel
  /// against the drive, the output pins' span against the disc stack, the duty cycle and external
  /// loads.
  static std::vector<CrossFieldRule> CrossFieldRules() {
    std::vector<CrossFieldRule> rules = ExternalLoadsRules();
    rules.push_back(DutyCycleRule());
    rules.push_back({{"crowning", "drive"}, "the crowning's effective length at least the face width",
                     "effective length must be >= the face width"});
    rules.push_back({{"disc_spacing_mm", "drive"}, "the discs' spacing at least the face width",
                     "the discs would overlap"});
    rules.push_back({{"discs", "disc_spacing_mm", "output_mechanism", "drive"},
                     "the output pins' span at least the disc stack (discs − 1) disc_spacing_mm + face_width_mm",
                     "the disc stack"});
    rules.push_back({{"grinding", "drive"}, "the form wheel's radius above the tooth space's depth",
                     "does not exceed the tooth space's depth"});
    return rules;
  }
};

/// The output mechanism with clearance and compliance (studies/cycloid_study_common.h).
using OutputSpec = cycloid_common::CompliantOutputSpec;

struct Study {
  std::string name;
  /// limits.contact_stress_MPa, drawn on contact_stress.svg (the verdict reads it from the study).
  std::optional<double> contact_stress_limit_MPa;
  cycloid::Drive drive;
  cycloid::Crowning crowning;
  cycloid::Material material;
  double torque_Nm = 0;  ///< on the disc, as in the file
  cycloid::LoadedOptions options;
  std::vector<double> crank_angles_rad;
  /// Uniform samples of one mesh period 2π/n1 (0 when the file gives crank_angle_steps or
  /// crank_angles_deg instead).
  int crank_angles_per_mesh_period = 0;
  /// analysis.estimate_error: the refinement runs (the half-step-shifted crank angles, whose union
  /// with the study's angles is the doubled set reported, and the coarse grid) and the errors.
  bool estimate_error = true;
  /// analysis.evaluate: false when only the unloaded TCA is asked (["unloaded"]): no material, load
  /// or contact solves; the loaded stage ("loaded", the default) includes the unloaded one.
  bool loaded = true;
  double bore_diameter_mm = 0;   ///< drive.bore_diameter_mm: bore of the disc's solid, 0 = none
  GeometryFileOptions geometry;  ///< "geometry_files"
  /// The bearing life (load.input_speed_rpm or duty_cycle, the ratings, the output mechanism;
  /// docs/life.md, "Cycloid"); nullopt: no life asked, result.json without "life".
  std::optional<cycloid_common::LifeSpec> life;
  /// "output_mechanism" with the pins' and holes' radii; nullopt: no output-mechanism outputs.
  std::optional<OutputSpec> output;
  /// "stiffness": {"rated_torque_Nm", "crank_angle_deg"}: the torsional curve (model/cycloid/stiffness.h).
  struct StiffnessSpec {
    double rated_torque_Nm = 0, crank_angle_deg = 0;
  };
  std::optional<StiffnessSpec> stiffness;
  /// "stiffness.segments_Nm" (T1, T2) and "stiffness.lost_motion_percent".
  double segment_T1_Nm = 0, segment_T2_Nm = 0, lost_motion_percent = 3.0;
  /// "ratings" with the rated elements (crank bearing, pins, output mechanism) and the peak limits.
  struct RatingsSpec {
    RatingsInput in;
    cycloid_common::LifeSpec life;  ///< lines empty: set per trial torque
    PeakLimits limits;
  };
  std::optional<RatingsSpec> ratings;
  double density_kg_m3 = 7850.0;  ///< "ratings.density_kg_m3" (steel when absent)
  /// "output_bearing" and "external_loads" (each line's speed resolved).
  std::optional<OutputBearingInput> output_bearing;
  std::vector<ExternalLoadInput> external_loads;
  /// "tolerances" and "monte_carlo": the transmission error from tolerances
  /// (model/cycloid/transmission_error.h); nullopt: none.
  struct ToleranceSpec {
    cycloid::ToleranceBands bands;
    int samples = 0;          ///< "monte_carlo.samples" (0: linear only)
    std::uint64_t seed = 1;   ///< "monte_carlo.seed"
    int angle_steps = 0;      ///< "monte_carlo.angle_steps" over one output revolution (0: 8 per mesh period)
  };
  std::optional<ToleranceSpec> tolerances;
  int discs = 1;                 ///< "discs": N, phased by 360°/N about the crank, each carrying T/N
  double disc_spacing_mm = 0;    ///< "disc_spacing_mm": mid-plane to mid-plane (default the face width)
  /// The torque on each disc [N·mm]: load.torque_Nm (the output torque) over the discs (equal split
  /// of identical discs).
  double disc_torque_Nmm() const { return torque_Nm * 1000.0 / discs; }
  /// "lubricant" (docs/lubrication.md): the lubricated losses at the load's torque and speed.
  struct Lubrication {
    LubricationCommon common;
    cycloid::CycloidLubricationSpec spec;
    cycloid::OutputMechanism mechanism;                  ///< the rigid pins' forces
    std::optional<cycloid::OutputPinContact> pins;       ///< with the pins' and holes' radii
    bool ring_pins_given = false, output_rollers_given = false, crank_given = false;
  };
  std::optional<Lubrication> lubrication;
  /// "torsional_dynamics" (studies/torsional_dynamics_input.h); nullopt: none.
  std::optional<TorsionalDynamicsSpec> torsional;
  /// "grinding": the form wheel, computed while parsing (a wheel too small is an input error).
  std::optional<cycloid::FormWheel> grinding;
  double grinding_tolerance_um = 0;
  /// crank_bearing.designation and pins.designation (bom.csv); empty when not given.
  std::string crank_bearing_designation, pin_designation;
  std::optional<InspectionInput> inspection;  ///< "inspection"
  /// "measured_profile": the disc (1-based) and its measurement projected onto its exact profile.
  int measured_disc = 0;
  std::optional<MeasuredProfile> measured;
};

using cycloid_common::ElementLife;
using cycloid_common::LifeResult;

/// Largest factor on |v(N) − v(2N)| in the crank-angle error (no shrinking of the differences
/// observed); the smallest is 1 (docs/cycloid.md, "Estimated error").
inline constexpr double kMaxTailFactor = 4.0;
/// A headline output whose estimated error exceeds this share of its value gets a warning.
inline constexpr double kErrorShare = 0.05;

/// analysis.tolerance above this moves the peak-to-peak LTE or GR of the paper's examples by more
/// than kToleranceShare of its value (measured: docs/cycloid.md, "Solver tolerance"): a warning.
inline constexpr double kLooseTolerance = 0.1;
inline constexpr double kToleranceShare = 0.05;

/// result.json's "measured" (with measured_profile): the measured disc's deviation (MeasuredBlock),
/// its rigid kinematic output beside the nominal disc's and, with the loaded stage, its loaded TCA.
struct CycloidMeasured : MeasuredBlock {
  struct Kinematic {
    std::string model, crank_angles_over, lost_motion_note;
    long crank_angles = 0;
    MeasuredTransmissionError transmission_error;
    NominalMeasured output_lag_peak_to_peak_arcsec, backlash_max_arcmin, backlash_min_arcmin, backlash_mean_arcmin,
        lost_motion_kinematic_arcmin;
    int angles_without_contact = 0, jammed_angles = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("model", &model, Field().Desc("the model in words"));
      a->Visit("crank_angles", &crank_angles, Field().Desc("the crank angles evaluated"));
      a->Visit("crank_angles_over", &crank_angles_over, Field().Desc("what they span"));
      transmission_error.Serialize(a, "of the measured disc's output angle less the nominal's");
      a->Visit("output_lag_peak_to_peak_arcsec", &output_lag_peak_to_peak_arcsec,
               Field().Unit("arcsec").Desc("the output angle's ripple, forward torque"));
      a->Visit("backlash_max_arcmin", &backlash_max_arcmin, Field().Unit("arcmin"));
      a->Visit("backlash_min_arcmin", &backlash_min_arcmin, Field().Unit("arcmin"));
      a->Visit("backlash_mean_arcmin", &backlash_mean_arcmin, Field().Unit("arcmin"));
      a->Visit("lost_motion_kinematic_arcmin", &lost_motion_kinematic_arcmin,
               Field().Unit("arcmin").Desc("the largest backlash (rigid parts)"));
      a->Visit("lost_motion_note", &lost_motion_note, Field().Desc("what the lost motion leaves out"));
      a->Visit("angles_without_contact", &angles_without_contact,
               Field().Desc("crank angles at which no ring pin touches the measured disc's loaded flank"));
      a->Visit("jammed_angles", &jammed_angles,
               Field().Desc("crank angles at which the measured disc interferes with the pins"));
    }
  };
  struct Loaded {
    struct Life {
      NominalMeasuredOrInfinite shortest_L10h;
      std::map<std::string, NominalMeasuredOrInfinite> L10h;
      std::string crank_angles_over;
      struct Names {
        std::string nominal, measured;
        template <typename Archive>
        void Serialize(Archive* a) {
          a->Visit("nominal", &nominal, Field().Desc("the nominal disc's"));
          a->Visit("measured", &measured, Field().Desc("the measured disc's"));
        }
      } shortest;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("shortest_L10h", &shortest_L10h, Field().Unit("h").Desc("the shortest bearing life"));
        a->Visit("shortest", &shortest, Field().Desc("the element of the shortest life"));
        a->Visit("L10h", &L10h, Field().Unit("h").Desc("each element's life"));
        a->Visit("crank_angles_over", &crank_angles_over, Field().Desc("the angles the lives are on"));
      }
    };
    std::string model, crank_angles_over;
    long crank_angles = 0;
    double disc_torque_Nm = 0;
    NominalMeasured max_contact_stress_MPa, max_pair_load_N, lte_peak_to_peak_arcsec;
    bool converged = false;
    std::optional<Life> life;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("model", &model, Field().Desc("the model in words"));
      a->Visit("crank_angles", &crank_angles, Field().Desc("the crank angles evaluated"));
      a->Visit("crank_angles_over", &crank_angles_over, Field().Desc("what they span"));
      a->Visit("disc_torque_Nm", &disc_torque_Nm, Field().Unit("N·m").Desc("the torque on the disc"));
      a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa, Field().Unit("MPa"));
      a->Visit("max_pair_load_N", &max_pair_load_N, Field().Unit("N"));
      a->Visit("lte_peak_to_peak_arcsec", &lte_peak_to_peak_arcsec, Field().Unit("arcsec"));
      a->Visit("converged", &converged, Field().Desc("both loaded TCAs converged at every angle"));
      a->Visit("life", &life, Field().Desc("with life: the lives as made beside the nominal"));
    }
  };
  Kinematic kinematic;
  std::optional<Loaded> loaded;
  template <typename Archive>
  void Serialize(Archive* a) {
    MeasuredBlock::Serialize(a);
    a->Visit("kinematic", &kinematic, Field().Desc("the rigid kinematic output, measured beside nominal"));
    a->Visit("loaded", &loaded, Field().Desc("with the loaded stage: the loaded TCA, measured beside nominal"));
  }
};

/// The run's answer: result.json as declared (`camopt schema cycloid_ltca --result`; the loaded
/// stage's keys, or the unloaded stage's alone with analysis.evaluate ["unloaded"]), then the
/// model's numbers the tables, plots and drawings are drawn from.
struct Result {
  /// result.json's "transmission_error" (with "tolerances"): the shared statistics and the
  /// cycloid's backlash (model/cycloid/transmission_error.h).
  struct TransmissionErrorBlock : ToleranceStatisticsBlock {
    std::string model, output_mechanism, distribution, peak_to_peak;
    int angle_steps = 0, parameters = 0, jammed_samples = 0;
    double crank_span_deg = 0, backlash_arcmin = 0, backlash_p99_arcmin = 0, backlash_nominal_arcmin = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      ToleranceStatisticsBlock::Serialize(a);
      const Field n = Field().NullWhenNotFinite();
      a->Visit("model", &model, Field());
      a->Visit("output_mechanism", &output_mechanism, Field().Desc("how the output pins take part"));
      a->Visit("distribution", &distribution, Field().Desc("the deviations' distribution"));
      a->Visit("angle_steps", &angle_steps, Field().Desc("crank angles over one output revolution"));
      a->Visit("crank_span_deg", &crank_span_deg, Field().Unit("deg").Desc("the crank angles' span"));
      a->Visit("parameters", &parameters, Field().Desc("scalar deviations"));
      a->Visit("jammed_samples", &jammed_samples, Field().Desc("samples in which the drive jams somewhere"));
      a->Visit("backlash_arcmin", &backlash_arcmin,
               Field(n).Unit("arcmin").Desc("the samples' largest (without samples: the nominal's)"));
      a->Visit("backlash_p99_arcmin", &backlash_p99_arcmin, Field(n).Unit("arcmin").Desc("their 99th percentile"));
      a->Visit("backlash_nominal_arcmin", &backlash_nominal_arcmin, Field(n).Unit("arcmin"));
      a->Visit("peak_to_peak", &peak_to_peak, Field().Desc("what the peak-to-peak keys span"));
    }
  };
  /// One pin-tooth pair in contact at a crank angle (per_angle[i].loads).
  struct PairLoadOut {
    int roller = 0;
    double load_N = 0, max_contact_stress_MPa = 0, approach_um = 0, arm_mm = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("roller", &roller, Field().Desc("the ring pin, 1 … rollers"));
      a->Visit("load_N", &load_N, Field().Unit("N"));
      a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa, Field().Unit("MPa").Desc("the pair's peak pressure"));
      a->Visit("approach_um", &approach_um, Field().Unit("µm").Desc("the pair's elastic approach"));
      a->Visit("arm_mm", &arm_mm, Field().Unit("mm").Desc("the pair's lever arm l_i").NullWhenNotFinite());
    }
  };
  /// One crank angle (per_angle[i]): the unloaded stage gives the angle and β0 alone.
  struct PerAngle {
    double crank_angle_deg = 0;
    std::optional<double> max_contact_stress_MPa;
    std::optional<int> pairs_in_contact;
    std::optional<double> lte_arcsec;
    double unloaded_te_arcsec = 0;
    std::optional<double> gear_ratio;
    std::optional<bool> converged;
    std::optional<std::vector<PairLoadOut>> loads;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("crank_angle_deg", &crank_angle_deg, Field().Unit("deg"));
      a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa,
               Field().Unit("MPa").Desc("the largest over the pairs (loaded stage)"));
      a->Visit("pairs_in_contact", &pairs_in_contact, Field().Desc("pairs carrying load (loaded stage)"));
      a->Visit("lte_arcsec", &lte_arcsec, Field().Unit("arcsec").Desc("loaded transmission error (loaded stage)"));
      a->Visit("unloaded_te_arcsec", &unloaded_te_arcsec, Field().Unit("arcsec").Desc("unloaded transmission error β0"));
      a->Visit("gear_ratio", &gear_ratio, Field().Desc("instantaneous gear ratio (loaded stage)"));
      a->Visit("converged", &converged, Field().Desc("the contact solve converged (loaded stage)"));
      a->Visit("loads", &loads, Field().Desc("the pairs in contact (loaded stage)"));
    }
  };
  /// estimated_error_sources.grid: the coarser grid's run.
  struct GridErrorSource {
    std::array<int, 2> coarse_grid{0, 0};
    int angles = 0;
    std::map<std::string, double> error;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("coarse_grid", &coarse_grid, Field().Desc("cells across the profile and along the face"));
      a->Visit("angles", &angles, Field().Desc("the crank angles of the coarse run"));
      a->Visit("error", &error, Field().Desc("the grid's part of each headline's error, by its name"));
    }
  };
  /// estimated_error_sources.crank_angles: the crank angles' part (the half-step-shifted set).
  struct CrankErrorSource {
    int coarse_angles = 0, refined_angles = 0;
    std::string method;
    std::map<std::string, double> error;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("coarse_angles", &coarse_angles, Field());
      a->Visit("refined_angles", &refined_angles, Field());
      a->Visit("method", &method, Field());
      a->Visit("error", &error, Field().Desc("the crank angles' part of each headline's error, by its name"));
    }
  };
  /// estimated_error_sources (empty without analysis.estimate_error).
  struct ErrorSources {
    std::optional<GridErrorSource> grid;
    std::optional<CrankErrorSource> crank_angles;
    std::optional<double> warning_share;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("grid", &grid, Field());
      a->Visit("crank_angles", &crank_angles, Field().Desc("when the crank angles were refined"));
      a->Visit("warning_share", &warning_share, Field().Desc("a headline whose error exceeds this share of it warns"));
    }
  };
  /// "grinding": the form wheel (model/cycloid/form_grinding.h).
  struct GrindingOut {
    std::string file, note;
    double wheel_radius_mm = 0, centre_distance_mm = 0, wheel_width_mm = 0, edge_radius_mm = 0, least_radius_mm = 0,
           root_x_mm = 0, tip_x_mm = 0, index_deg = 0, least_concave_radius_mm = 0, residual_form_error_um = 0,
           tolerance_um = 0;
    std::vector<double> index_angles_deg;
    int points = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      const Field n = Field().NullWhenNotFinite();
      a->Visit("file", &file, Field().Desc("the wheel's axial profile"));
      a->Visit("wheel_radius_mm", &wheel_radius_mm, Field(n).Unit("mm"));
      a->Visit("centre_distance_mm", &centre_distance_mm, Field(n).Unit("mm"));
      a->Visit("wheel_width_mm", &wheel_width_mm, Field(n).Unit("mm"));
      a->Visit("edge_radius_mm", &edge_radius_mm, Field(n).Unit("mm"));
      a->Visit("least_radius_mm", &least_radius_mm, Field(n).Unit("mm"));
      a->Visit("root_x_mm", &root_x_mm, Field(n).Unit("mm"));
      a->Visit("tip_x_mm", &tip_x_mm, Field(n).Unit("mm"));
      a->Visit("index_deg", &index_deg, Field(n).Unit("deg"));
      a->Visit("index_angles_deg", &index_angles_deg, Field(n).Unit("deg").Desc("one pass per tooth space"));
      a->Visit("least_concave_radius_mm", &least_concave_radius_mm, Field(n).Unit("mm"));
      a->Visit("residual_form_error_um", &residual_form_error_um, Field(n).Unit("µm"));
      a->Visit("tolerance_um", &tolerance_um, Field(n).Unit("µm"));
      a->Visit("points", &points, Field().Desc("points of the wheel's dressing polygon"));
      a->Visit("note", &note, Field());
    }
  };
  /// "output_mechanism": the mechanism with clearance, or {"error": why} when not solved.
  struct OutputMechanismOut {
    std::optional<std::string> error, pin_support, model, disc_split;
    std::optional<int> pins, discs, samples;
    std::optional<double> pin_circle_radius_mm, pin_radius_mm, hole_radius_mm, contact_radius_mm, clearance_mm,
        pin_span_mm, disc_spacing_mm, disc_torque_Nm, load_period_crank_deg, max_net_crank_force_N,
        max_crank_couple_Nmm, max_moment_residual_relative, roller_radius_mm;
    std::optional<std::vector<double>> disc_planes_mm;
    template <typename Archive>
    void Serialize(Archive* a) {
      const Field n = Field().NullWhenNotFinite();
      a->Visit("error", &error, Field().Desc("why the mechanism was not solved (then the only key)"));
      a->Visit("pins", &pins, Field());
      a->Visit("pin_circle_radius_mm", &pin_circle_radius_mm, Field(n).Unit("mm"));
      a->Visit("pin_radius_mm", &pin_radius_mm, Field(n).Unit("mm"));
      a->Visit("hole_radius_mm", &hole_radius_mm, Field(n).Unit("mm"));
      a->Visit("contact_radius_mm", &contact_radius_mm, Field(n).Unit("mm").Desc("the pin's, or its roller's"));
      a->Visit("clearance_mm", &clearance_mm, Field(n).Unit("mm").Desc("hole - contact radius - e"));
      a->Visit("pin_support", &pin_support, Field().OneOf({"cantilever", "both_ends"}));
      a->Visit("pin_span_mm", &pin_span_mm, Field(n).Unit("mm"));
      a->Visit("disc_planes_mm", &disc_planes_mm, Field(n).Unit("mm").Desc("the discs' mid-planes on the pin"));
      a->Visit("disc_spacing_mm", &disc_spacing_mm, Field(n).Unit("mm"));
      a->Visit("discs", &discs, Field());
      a->Visit("disc_torque_Nm", &disc_torque_Nm, Field(n).Unit("N·m"));
      a->Visit("load_period_crank_deg", &load_period_crank_deg, Field(n).Unit("deg"));
      a->Visit("samples", &samples, Field().Desc("crank angles over the load period"));
      a->Visit("max_net_crank_force_N", &max_net_crank_force_N, Field(n).Unit("N"));
      a->Visit("max_crank_couple_Nmm", &max_crank_couple_Nmm, Field(n).Unit("N·mm"));
      a->Visit("max_moment_residual_relative", &max_moment_residual_relative, Field(n));
      a->Visit("model", &model, Field());
      a->Visit("disc_split", &disc_split, Field());
      a->Visit("roller_radius_mm", &roller_radius_mm, Field(n).Unit("mm").Desc("with rollers on the pins"));
    }
  };
  /// "stiffness": the torsional curve, input held (model/cycloid/stiffness.h).
  struct StiffnessOut {
    double rated_torque_Nm = 0, crank_angle_deg = 0, stiffness_positive_Nm_per_arcmin = 0,
           stiffness_negative_Nm_per_arcmin = 0, ring_pins_share = 0, output_pins_share = 0,
           hysteresis_width_arcmin = 0;
    std::string output_pins, definitions;
    int contact_solves = 0;
    std::optional<double> lost_motion_percent, lost_motion_at_percent_arcmin;
    template <typename Archive>
    void Serialize(Archive* a) {
      const Field n = Field().NullWhenNotFinite();
      a->Visit("rated_torque_Nm", &rated_torque_Nm, Field().Unit("N·m"));
      a->Visit("crank_angle_deg", &crank_angle_deg, Field().Unit("deg"));
      a->Visit("stiffness_positive_Nm_per_arcmin", &stiffness_positive_Nm_per_arcmin, Field(n).Unit("N·m/arcmin"));
      a->Visit("stiffness_negative_Nm_per_arcmin", &stiffness_negative_Nm_per_arcmin, Field(n).Unit("N·m/arcmin"));
      a->Visit("ring_pins_share", &ring_pins_share, Field(n).Desc("the ring pins' share of the compliance"));
      a->Visit("output_pins_share", &output_pins_share, Field(n).Desc("the output pins' share of the compliance"));
      a->Visit("output_pins", &output_pins, Field());
      a->Visit("contact_solves", &contact_solves, Field());
      a->Visit("hysteresis_width_arcmin", &hysteresis_width_arcmin, Field().Unit("arcmin"));
      a->Visit("definitions", &definitions, Field());
      a->Visit("lost_motion_percent", &lost_motion_percent,
               Field().Unit("%").Desc("stiffness.lost_motion_percent (with the three segments)"));
      a->Visit("lost_motion_at_percent_arcmin", &lost_motion_at_percent_arcmin,
               Field().Unit("arcmin").Desc("lost motion at ± lost_motion_percent of the rated torque"));
    }
  };
  /// "stiffness_segments": the catalogue's three-segment stiffness (docs/ratings.md).
  struct StiffnessSegmentsOut {
    double T1_Nm = 0, T2_Nm = 0, rated_torque_Nm = 0, K1_Nm_per_arcmin = 0, K2_Nm_per_arcmin = 0,
           K3_Nm_per_arcmin = 0;
    std::string definitions;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("T1_Nm", &T1_Nm, Field().Unit("N·m"));
      a->Visit("T2_Nm", &T2_Nm, Field().Unit("N·m"));
      a->Visit("rated_torque_Nm", &rated_torque_Nm, Field().Unit("N·m"));
      a->Visit("K1_Nm_per_arcmin", &K1_Nm_per_arcmin, Field().Unit("N·m/arcmin").Desc("0 … T1"));
      a->Visit("K2_Nm_per_arcmin", &K2_Nm_per_arcmin, Field().Unit("N·m/arcmin").Desc("T1 … T2"));
      a->Visit("K3_Nm_per_arcmin", &K3_Nm_per_arcmin, Field().Unit("N·m/arcmin").Desc("T2 … rated torque"));
      a->Visit("definitions", &definitions, Field());
    }
  };
  /// "masses": the parts' masses and the inertia at the output (with stiffness or ratings).
  struct MassesOut {
    double density_kg_m3 = 0, disc_kg = 0, disc_inertia_kgm2 = 0, ring_pins_kg = 0, output_pins_kg = 0,
           total_kg = 0, outer_diameter_mm = 0, width_mm = 0, reflected_inertia_kgm2 = 0;
    std::string includes;
    template <typename Archive>
    void Serialize(Archive* a) {
      const Field n = Field().NullWhenNotFinite();
      a->Visit("density_kg_m3", &density_kg_m3, Field().Unit("kg/m³"));
      a->Visit("disc_kg", &disc_kg, Field(n).Unit("kg").Desc("one disc"));
      a->Visit("disc_inertia_kgm2", &disc_inertia_kgm2, Field(n).Unit("kg·m²").Desc("one disc, about its centre"));
      a->Visit("ring_pins_kg", &ring_pins_kg, Field(n).Unit("kg"));
      a->Visit("output_pins_kg", &output_pins_kg, Field(n).Unit("kg"));
      a->Visit("total_kg", &total_kg, Field(n).Unit("kg"));
      a->Visit("outer_diameter_mm", &outer_diameter_mm, Field(n).Unit("mm"));
      a->Visit("width_mm", &width_mm, Field(n).Unit("mm"));
      a->Visit("reflected_inertia_kgm2", &reflected_inertia_kgm2, Field(n).Unit("kg·m²").Desc("at the output"));
      a->Visit("includes", &includes, Field().Desc("what the masses and the inertia are of"));
    }
  };

  std::string study = "cycloid_ltca", name;
  std::optional<std::vector<std::string>> evaluated;  ///< ["unloaded"] for the unloaded stage alone
  std::optional<double> unloaded_te_peak_to_peak_arcsec;
  std::optional<double> torque_Nm, max_contact_stress_MPa, max_contact_stress_crank_angle_deg,
      lte_peak_to_peak_arcsec, lte_mean_abs_arcsec, gear_ratio_nominal, gear_ratio_peak_to_peak;
  std::optional<int> max_pairs_in_contact;
  std::optional<double> max_pair_load_N;
  int crank_angles_per_mesh_period = 0;
  std::optional<int> crank_angles_used;
  std::optional<bool> crank_angles_refined;
  std::optional<double> axial_cell_mm;
  std::optional<std::array<int, 2>> grid;
  std::optional<double> composite_modulus_out;  ///< result.json's composite_modulus_MPa
  std::optional<int> contact_solves;
  std::optional<bool> converged;
  std::optional<std::string> warning_out;                       ///< result.json's warning
  std::optional<std::map<std::string, double>> error_values;    ///< result.json's estimated_error
  std::optional<ErrorSources> estimated_error_sources;
  std::optional<std::vector<std::string>> warnings_out;         ///< result.json's warnings (loaded stage)
  std::vector<PerAngle> per_angle;
  double min_profile_radius_mm = 0, pin_gap_mm = 0;
  GeometryFilesBlock geometry_files;             ///< GeometryFilesOf's block
  std::optional<std::variant<PartsBlock, GeometryFilesOff>> parts_json;  ///< result.json's parts (PartsOf)
  std::optional<GrindingOut> grinding;
  std::optional<TransmissionErrorBlock> transmission_error_json;  ///< result.json's transmission_error
  std::optional<InspectionBlock> inspection;
  std::optional<CycloidMeasured> measured_json;
  std::optional<cycloid_common::LifeBlock> life_json;  ///< result.json's life
  std::optional<int> discs;
  std::optional<double> disc_torque_Nm;
  /// NaN: null (the curve or the mechanism asked for but not solved).
  std::optional<double> torsional_stiffness_Nm_per_arcmin, lost_motion_arcmin, backlash_arcmin;
  std::optional<double> max_ring_pin_force_N, max_output_pin_force_out, eccentric_bearing_load_N,
      output_pin_bending_stress_MPa, output_pin_contact_pressure_MPa;
  std::optional<OutputMechanismOut> output_mechanism;
  std::optional<StiffnessOut> stiffness;
  RatingsKeys ratings_keys;  ///< rated_torque_Nm, peak_torque_Nm, momentary_torque_Nm, "ratings" (flat)
  std::optional<OrError<OutputBearingBlock>> output_bearing_json;  ///< the rating, or why it is absent
  std::optional<StiffnessSegmentsOut> stiffness_segments;
  std::optional<MassesOut> masses_out;                ///< result.json's masses
  std::optional<JointModelBlock> joint_model;         ///< the parameters `camopt export` reads
  std::optional<OrError<LubricationResult>> lubrication_json;  ///< the losses, or why they are absent
  std::optional<OrError<TorsionalDynamicsBlock>> torsional_dynamics;  ///< the dynamics, or why they are absent
  template <typename Archive>
  void Serialize(Archive* a) {
    const Field n = Field().NullWhenNotFinite();
    const Field loaded = Field().Desc("loaded stage");
    a->Visit("study", &study, Field().Const("cycloid_ltca"));
    a->Visit("name", &name, Field().Desc("the design's name"));
    a->Visit("evaluated", &evaluated, Field().Desc("[\"unloaded\"]: the unloaded stage alone was run"));
    a->Visit("unloaded_te_peak_to_peak_arcsec", &unloaded_te_peak_to_peak_arcsec,
             Field().Unit("arcsec").Desc("unloaded stage alone"));
    a->Visit("torque_Nm", &torque_Nm, Field().Unit("N·m").Desc("the output torque (loaded stage)"));
    a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa,
             Field().Unit("MPa").Desc("largest Hertz pressure of the disc on a ring pin (loaded stage)"));
    a->Visit("max_contact_stress_crank_angle_deg", &max_contact_stress_crank_angle_deg,
             Field().Unit("deg").Desc("its crank angle (loaded stage)"));
    a->Visit("lte_peak_to_peak_arcsec", &lte_peak_to_peak_arcsec,
             Field().Unit("arcsec").Desc("loaded transmission error, peak to peak (loaded stage)"));
    a->Visit("lte_mean_abs_arcsec", &lte_mean_abs_arcsec,
             Field().Unit("arcsec").Desc("mean absolute loaded transmission error (loaded stage)"));
    a->Visit("gear_ratio_nominal", &gear_ratio_nominal, Field().Desc("the teeth (loaded stage)"));
    a->Visit("gear_ratio_peak_to_peak", &gear_ratio_peak_to_peak, loaded);
    a->Visit("max_pairs_in_contact", &max_pairs_in_contact, loaded);
    a->Visit("max_pair_load_N", &max_pair_load_N,
             Field().Unit("N").Desc("largest load of one pin-tooth pair (loaded stage)"));
    a->Visit("crank_angles_per_mesh_period", &crank_angles_per_mesh_period,
             Field().Desc("uniform samples of one mesh period (0: the file gives the angles otherwise)"));
    a->Visit("crank_angles_used", &crank_angles_used, Field().Desc("the reported angles (loaded stage)"));
    a->Visit("crank_angles_refined", &crank_angles_refined,
             Field().Desc("the reported angles are the study's and the half-step-shifted ones (loaded stage)"));
    a->Visit("axial_cell_mm", &axial_cell_mm, Field().Unit("mm").Desc("loaded stage"));
    a->Visit("grid", &grid, Field().Desc("contact cells across the profile and along the face (loaded stage)"));
    a->Visit("composite_modulus_MPa", &composite_modulus_out, Field().Unit("MPa").Desc("E* (loaded stage)"));
    a->Visit("contact_solves", &contact_solves, loaded);
    a->Visit("converged", &converged,
             Field().Desc("every crank angle's contact converged (loaded stage)").Decides(RunFact::kConverged));
    a->Visit("warning", &warning_out,
             Field().Desc("the first angle that did not converge, or empty (loaded stage)").Decides(RunFact::kWarning));
    a->Visit("estimated_error", &error_values,
             Field().Desc("estimated discretisation error of each headline, by its name, in its unit (loaded stage)"));
    a->Visit("estimated_error_sources", &estimated_error_sources, Field().Desc("the error's parts (loaded stage)"));
    a->Visit("warnings", &warnings_out, Field().Desc("the run's warnings"));
    a->Visit("per_angle", &per_angle, Field().Desc("each crank angle"));
    a->Visit("min_profile_radius_mm", &min_profile_radius_mm,
             Field().Unit("mm").Desc("smallest convex radius of the tooth, rho_min - rho'"));
    a->Visit("pin_gap_mm", &pin_gap_mm, Field().Unit("mm").Desc("clearance between neighbouring pins"));
    a->Visit("geometry_files", &geometry_files, Field().Desc("the tooth's geometry files, or why none"));
    a->Visit("parts", &parts_json, Field().Desc("the drive's parts (studies/parts.h), or {written: false}"));
    a->Visit("grinding", &grinding, Field().Desc("the form wheel (with grinding)"));
    a->Visit("transmission_error", &transmission_error_json,
             Field().Desc("the kinematic transmission error from the tolerances (with tolerances)"));
    a->Visit("inspection", &inspection, Field().Desc("the inspection files (with inspection)"));
    a->Visit("measured", &measured_json, Field().Desc("the measured disc (with measured_profile)"));
    a->Visit("life", &life_json, Field().Desc("the bearing lives, when asked"));
    a->Visit("discs", &discs, Field().Desc("with more than one disc"));
    a->Visit("disc_torque_Nm", &disc_torque_Nm, Field().Unit("N·m").Desc("each disc's torque (more than one disc)"));
    a->Visit("torsional_stiffness_Nm_per_arcmin", &torsional_stiffness_Nm_per_arcmin,
             Field(n).Unit("N·m/arcmin").Desc("50-100% of the rated torque (with stiffness; null: not solved)"));
    a->Visit("lost_motion_arcmin", &lost_motion_arcmin,
             Field(n).Unit("arcmin").Desc("±3% of the rated torque (with stiffness; null: not solved)"));
    a->Visit("backlash_arcmin", &backlash_arcmin, Field(n).Unit("arcmin").Desc("with stiffness; null: not solved"));
    a->Visit("max_ring_pin_force_N", &max_ring_pin_force_N,
             Field(n).Unit("N").Desc("with output_mechanism; null: not solved"));
    a->Visit("max_output_pin_force_N", &max_output_pin_force_out,
             Field(n).Unit("N").Desc("with output_mechanism; null: not solved"));
    a->Visit("eccentric_bearing_load_N", &eccentric_bearing_load_N,
             Field(n).Unit("N").Desc("largest eccentric (crank) bearing load (with output_mechanism; null: not solved)"));
    a->Visit("output_pin_bending_stress_MPa", &output_pin_bending_stress_MPa,
             Field(n).Unit("MPa").Desc("with output_mechanism; null: not solved"));
    a->Visit("output_pin_contact_pressure_MPa", &output_pin_contact_pressure_MPa,
             Field(n).Unit("MPa").Desc("hole-pin Hertz pressure (with output_mechanism; null: not solved)"));
    a->Visit("output_mechanism", &output_mechanism, Field().Desc("with output_mechanism's pin and hole radii"));
    a->Visit("stiffness", &stiffness, Field().Desc("the torsional curve (with stiffness)"));
    ratings_keys.Serialize(a);
    a->Visit("output_bearing", &output_bearing_json,
             Field().Desc("the output bearing's life (with output_bearing)"));
    a->Visit("stiffness_segments", &stiffness_segments, Field().Desc("with stiffness"));
    a->Visit("masses", &masses_out, Field().Desc("with stiffness or ratings"));
    a->Visit("joint_model", &joint_model,
             Field().Desc("the joint `camopt export` writes for a simulator (with stiffness)"));
    a->Visit("lubrication", &lubrication_json,
             Field().Desc("the lubricated losses (with lubricant; docs/lubrication.md)"));
    a->Visit("torsional_dynamics", &torsional_dynamics,
             Field().Desc("with torsional_dynamics (docs/torsional_dynamics.md)"));
  }
  /// The schemas of the raw blocks shared with kinds whose result is not declared yet: the keys
  /// camopt reads from them (report.html's headlines), the rest open.

  // Not in result.json: the model's numbers.
  /// Per angle (meshes) and over the cycle, at crank_angles_rad: the study's angles, or their
  /// union with the half-step-shifted set (twice as many) when the crank angles were refined.
  cycloid::CycleResult cycle;
  std::vector<double> crank_angles_rad;  ///< the angles of `cycle` (and of the per-angle outputs)
  double composite_modulus_MPa = 0;
  /// Unloaded backlash [arcsec] per roller (outer index) and crank angle; −1 off the loaded flank.
  std::vector<std::vector<double>> backlash_arcsec;
  std::string warning;          ///< the first angle that did not converge, or empty
  /// Estimated discretisation error of each headline output (by its result.json name, its unit):
  /// the sum of the grid and crank-angle parts; empty when not estimated.
  std::vector<std::pair<std::string, double>> estimated_error, error_grid, error_crank;
  std::array<int, 2> coarse_grid{0, 0};  ///< the grid of the error run
  /// Angles of the coarser sampling the crank-angle error compares with (the study's own, when
  /// the reported cycle is the doubled set); 0: not estimated.
  int crank_error_angles = 0;
  std::vector<std::string> warnings;     ///< headline errors above kErrorShare, and the like
  std::vector<double> unloaded_te_arcsec;    ///< β0 per crank angle (both stages)
  std::vector<Vec2<double>> tooth_profile;   ///< the modified profile of the whole disc [mm]
  std::vector<Vec2<double>> roller_centres;  ///< in the disc frame at crank angle 0 [mm]
  PlanarCamFit tooth_files;  ///< the disc's geometry files (arcs of the modified profile)
  /// The drive's parts (studies/cycloid_parts.h): discs with holes and bore, pins, crank, housing;
  /// empty when the geometry files are off or the disc has no solid.
  PartsSet parts;
  std::optional<LifeResult> life;
  std::optional<LubricationResult> lubrication;  ///< with "lubricant"
  std::string lubrication_error;                 ///< why it is absent (no thermal equilibrium)
  /// efficiency_map.csv's rows (as lcr_analysis's): torque, speed, efficiency, loss, oil
  /// temperature, λ, and 1 where the housing's balance has an equilibrium.
  std::vector<std::array<double, 7>> efficiency_map;
  /// The output mechanism over the crank bearing's load period (output_angles_rad), per disc k:
  /// the disc's own solve at its crank angle φ + 2πk/N.
  struct DiscSample {
    cycloid::OutputPinLoads<double> pins;
    Vec2<double> bearing_crank_frame{0.0, 0.0};  ///< B on the disc, the disc's crank frame
    Vec2<double> bearing_fixed_frame{0.0, 0.0};
  };
  std::vector<double> output_angles_rad;
  std::vector<std::vector<DiscSample>> output;  ///< [angle][disc]
  std::vector<double> net_crank_force_N;        ///< |Σ_k B_k| per angle (the crankshaft's net radial load)
  std::vector<double> crank_couple_Nmm;         ///< |Σ_k (z_k − z̄) B_k| per angle
  std::vector<double> pin_bending_stress_MPa;   ///< per angle, the largest over the pins
  double max_output_pin_force_N = 0, max_contact_pressure_MPa = 0, max_bearing_load_N = 0,
         max_bending_stress_MPa = 0, max_net_crank_force_N = 0, max_couple_Nmm = 0, max_moment_residual = 0;
  std::optional<cycloid::TorsionCurve> torsion;       ///< with "stiffness"
  /// Why the output mechanism or the torsional curve could not be solved (a torque the output pins
  /// cannot carry); empty when solved. Their result keys are then null, and `warnings` says why.
  std::string output_failed, torsion_failed;
  std::vector<double> bearing_load_at_ltca_angles_N;  ///< |B| of disc 1 at crank_angles_rad (per_angle.csv)
  std::optional<cycloid::TransmissionErrorResult> transmission_error;  ///< with "tolerances"
  std::optional<RatingsResult> ratings;                  ///< with "ratings"
  std::string ratings_failed;                            ///< why they are absent
  std::optional<OutputBearingResult> output_bearing;     ///< with "output_bearing"
  std::string output_bearing_failed;                     ///< why it is absent
  std::optional<ThreeSegmentStiffness> segments;         ///< with "stiffness" (N·m/arcmin)
  double lost_motion_user_rad = 0;                       ///< at stiffness.lost_motion_percent
  cycloid_common::PartMasses masses;                     ///< with "stiffness" or "ratings"
  std::optional<TorsionalDynamicsResult> torsional;      ///< with "torsional_dynamics"
  std::string torsional_failed;                          ///< why it is absent (an LTCA not converged)
  /// inspection/disc_k.csv by part name, and the point counts ("inspection").
  std::vector<std::pair<std::string, std::string>> inspection_files;
  std::vector<std::pair<std::string, long>> inspection_points;
  std::optional<CycloidMeasured> measured;  ///< result.json's "measured" (with measured_profile)
};

/// Disc k's part (1-based) as inspected: its exact tooth profile in its part frame
/// (model/cycloid/parts.h), the frame and datum in words.
InspectedPart DiscPart(const Study& s, int k);

/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
Result Run(const Study& study, const RunContext& ctx);
/// result.json's members of `result` (its Serialize) from its model numbers; Run ends with it.
void FillResult(const Study& study, Result& result);
/// result.json and the tables, plots and drawings listed above.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::cycloid_ltca
