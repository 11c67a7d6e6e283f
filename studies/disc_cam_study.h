// Study kind "disc_cam": a disc cam with an offset translating or an oscillating roller follower
// (Rzine et al., docs/disc_cam.md), a knife edge (the roller model with r_f = 0), a translating
// flat-faced follower (model/disc_cam/flat_faced.h) or a flat face on an arm
// (model/disc_cam/oscillating_flat_faced.h). Profile, pressure and shift angles, curvature
// and undercut over a cam revolution; for a roller the mechanical error from the tolerances (worst
// case and RMS, eqs. 31–32) and a Monte-Carlo check of the linearised error against the exact
// follower motion.
// Outputs: result.json, series.csv, SVAJ / angle / error plots (SVG), profile.svg, profile.dxf.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/disc_cam/disc_cam.h"
#include "model/common/material.h"
#include "model/disc_cam/exact_motion.h"
#include "model/disc_cam/follower_dynamics.h"
#include "model/disc_cam/residual_spectrum.h"
#include "model/disc_cam/kinetostatics.h"
#include "model/disc_cam/mechanical_error.h"
#include "model/disc_cam/oscillating_flat_faced.h"
#include "model/motion/motion_program.h"
#include "studies/archive.h"
#include "studies/geometry_files.h"
#include "studies/measured_profile.h"
#include "studies/material_input.h"
#include "studies/input.h"
#include "studies/study.h"

namespace camopt::studies::disc_cam {

/// The study file as declared: each field once, in the file's units, with its default, bounds
/// and description (studies/archive.h). Parse reads it, checks what spans fields (the follower's
/// fields by its type, the plausible lengths against the base circle, the stages against their
/// inputs) and converts it to the model's units (Study); `camopt schema disc_cam` is emitted from
/// it. disc_cam_min_size declares its file with the same parts.
struct Input {
  /// The follower: the fields of its type only (translating: offset_mm; oscillating:
  /// pivot_distance_mm and arm_length_mm, required; a roller: roller_radius_mm, required; a flat
  /// face: face_width_mm), checked by Parse; SchemaRules states the roller's and the face's fields.
  struct Follower {
    std::string type;
    /// Optional without a schema default: an oscillating follower has no offset, a knife edge or a
    /// flat face no roller (a default would be written into its studies by the schema's users).
    std::optional<double> roller_radius_mm, offset_mm, pivot_distance_mm, arm_length_mm, face_width_mm, face_offset_mm;
    /// The follower types with a roller (the others: knife-edge, flat-faced).
    static const std::vector<std::string>& RollerTypes() {
      static const std::vector<std::string> t = {"translating_roller", "oscillating_roller"};
      return t;
    }
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("type", &type,
               Field().Required()
                   .OneOf({"translating_roller", "oscillating_roller", "translating_knife_edge", "oscillating_knife_edge",
                           "translating_flat_faced", "oscillating_flat_faced"})
                   .Desc("the follower's kind: a roller, a knife edge (a roller of radius 0: the profile is the pitch "
                         "curve), a flat face perpendicular to the line of motion or a flat face on a pivoted arm "
                         "(docs/disc_cam.md)"));
      a->Visit("offset_mm", &offset_mm,
               Field().Unit("mm").Desc("translating roller or knife edge only: e, the follower axis's offset from the "
                                        "cam centre, positive as in the paper's Fig. 1; |e| < r_b + r_f (absent: 0)"));
      a->Visit("roller_radius_mm", &roller_radius_mm,
               Field().Positive().Unit("mm").Desc("roller followers only, required: r_f, of the roller (1e-6 to 1e6 "
                                                  "times the base circle)"));
      a->Visit("pivot_distance_mm", &pivot_distance_mm,
               Field().Positive().Unit("mm").Desc("oscillating only, required: f = O₂O₃, cam centre to the arm's pivot "
                                                  "(a flat face: r_b + face_offset_mm < f)"));
      a->Visit("arm_length_mm", &arm_length_mm,
               Field().Positive().Unit("mm").Desc("oscillating roller or knife edge only, required: l, pivot to the roller "
                                                  "centre; |f − l| < r_b + r_f < f + l"));
      a->Visit("face_width_mm", &face_width_mm,
               Field().Positive().Unit("mm").Desc(
                   "flat-faced only: the face's width in the cam plane, centred on the follower's axis; checked "
                   "against the width the contact runs over, 2 max|S'| (absent: not checked); oscillating: the "
                   "face's length along the arm, checked against the length the contact runs over, max ℓ − min ℓ"));
      a->Visit("face_offset_mm", &face_offset_mm,
               Field().Unit("mm").Desc("oscillating flat-faced only: d, the face's distance from the pivot, toward the "
                                       "cam (absent: 0, a face through the pivot); r_b + d < f"));
    }
    /// A roller follower needs its radius, the others have none; the face width is a flat face's,
    /// the face offset an oscillating flat face's.
    static nlohmann::ordered_json SchemaRules();
  };
  /// Manufacturing tolerances (Rzine et al., eqs. 31–32).
  struct Tolerances {
    double profile_radial_um = 0.0, roller_radius_um = 0.0, profile_normal_um = 0.0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("profile_radial_um", &profile_radial_um,
               Field().NonNegative().Unit("µm").Desc("Δr, of the profile's radial dimension (eqs. 26–30)"));
      a->Visit("roller_radius_um", &roller_radius_um, Field().NonNegative().Unit("µm").Desc("Δr_f, of the roller radius (eqs. 18–19, 25)"));
      a->Visit("profile_normal_um", &profile_normal_um,
               Field().NonNegative().Unit("µm").Desc("Δn, the profile's error along its normal (eqs. 16–17, 22)"));
    }
  };
  /// The limits of the verdict; a limit not given takes its default.
  struct Limits {
    std::optional<double> pressure_angle_deg, radius_margin_mm, contact_stress_MPa;
    template <typename Archive>
    void Serialize(Archive* a) {
      // Below the jam limit camopt::disc_cam::kJamPressureAngle (89°); from 1° up: the smallest base
      // circle of a pressure angle φ grows as 1/tan φ, and a denormal limit (1e-320) sent the
      // sizing's sparse solver non-finite numbers.
      a->Visit("pressure_angle_deg", &pressure_angle_deg,
               Field().AtLeast(1.0, "a pressure angle >= 1 and < 89 deg (the jam limit)")
                   .Below(89.0, "a pressure angle >= 1 and < 89 deg (the jam limit)").Unit("deg")
                   .Desc("largest |φ| allowed, checked on the rise (S' ≥ 0, dwells included) and on the return (S' < 0) "
                         "separately (absent: 30 translating, 45 oscillating)"));
      a->Visit("radius_margin_mm", &radius_margin_mm,
               Field().NonNegative().Unit("mm").Desc(
                   "roller: the smallest convex pitch-curve radius minus the roller radius, i.e. the profile's "
                   "smallest convex radius of curvature, at least this (absent: the roller radius); knife edge: the "
                   "profile's smallest convex radius at least this (absent: 0); flat face: the profile's smallest "
                   "radius of curvature r_b + S + S'' above this (absent: 0, a convex cam)"));
      a->Visit("contact_stress_MPa", &contact_stress_MPa,
               Field().Positive().Unit("MPa").Desc(
                   "peak Hertz stress between roller (or flat face) and cam; needs face_width_mm, material and "
                   "dynamics; not for a knife edge, a point contact (absent: not checked)"));
    }
  };
  /// Kinetostatic follower loads at one cam speed (translating followers only).
  struct Dynamics {
    double speed_rpm = 0.0, follower_mass_kg = 0.0, spring_rate_N_per_mm = 0.0, spring_preload_N = 0.0,
           external_load_N = 0.0;
    std::string follower_axis = "vertical_above_cam";
    std::optional<double> follower_stiffness_N_per_mm;
    double damping_ratio = 0.05;
    int revolutions = 3;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("speed_rpm", &speed_rpm, Field().Required().Positive().Unit("rpm").Desc("n, the cam speed"));
      a->Visit("follower_mass_kg", &follower_mass_kg,
               Field().Required().Positive().Unit("kg").Desc("m: follower, roller and a third of the spring"));
      a->Visit("spring_rate_N_per_mm", &spring_rate_N_per_mm,
               Field().NonNegative().Unit("N/mm").Desc("k, the return spring's rate"));
      a->Visit("spring_preload_N", &spring_preload_N,
               Field().NonNegative().Unit("N").Desc("F₀, the spring force on the base circle"));
      a->Visit("external_load_N", &external_load_N,
               Field().Unit("N").Desc("P, a constant load pressing the follower onto the cam (negative: pulling it off)"));
      a->Visit("follower_axis", &follower_axis,
               Field().OneOf({"vertical_above_cam", "vertical_below_cam", "horizontal"},
                             "\"vertical_above_cam\", \"vertical_below_cam\" or \"horizontal\"")
                   .Desc("where the weight m g acts: above the cam it presses the follower onto the cam, below it pulls it "
                         "off, horizontal: across the axis"));
      a->Visit("follower_stiffness_N_per_mm", &follower_stiffness_N_per_mm,
               Field().Positive().Unit("N/mm").Desc(
                   "k_f, the follower train's stiffness between the roller and its mass: with it the one-degree-of-"
                   "freedom dynamic response, its separation and residual vibration, and the dynamic jump speed "
                   "(docs/disc_cam.md, 'Follower dynamics'; absent: the kinetostatic loads only)"));
      a->Visit("damping_ratio", &damping_ratio,
               Field().AtLeast(0.0, "a number in [0, 1]").AtMost(1.0, "a number in [0, 1]").Desc(
                   "zeta of the follower's mode in contact, c = 2 zeta sqrt(m (k_f + k)) (with follower_stiffness_N_per_mm)"));
      a->Visit("revolutions", &revolutions,
               Field().AtLeast(1, "an integer in [1, 50]").AtMost(50, "an integer in [1, 50]").Desc(
                   "revolutions simulated from rest on the cam; the response reported is the last one's (with "
                   "follower_stiffness_N_per_mm)"));
    }
  };
  /// Kinetostatic loads on an oscillating follower's arm at one cam speed (a flat face:
  /// model/disc_cam/oscillating_flat_faced.h; a roller or knife edge: OscillatingRollerLoadAt in
  /// model/disc_cam/kinetostatics.h).
  struct ArmDynamics {
    double speed_rpm = 0.0, arm_inertia_kg_m2 = 0.0, spring_rate_N_m_per_rad = 0.0, spring_preload_N_m = 0.0,
           external_moment_N_m = 0.0;
    std::optional<double> arm_stiffness_N_m_per_rad;
    double damping_ratio = 0.05;
    int revolutions = 3;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("speed_rpm", &speed_rpm, Field().Required().Positive().Unit("rpm").Desc("n, the cam speed"));
      a->Visit("arm_inertia_kg_m2", &arm_inertia_kg_m2,
               Field().Required().Positive().Unit("kg·m²").Desc("J, the arm's (with its face or roller) moment of inertia about the pivot"));
      a->Visit("spring_rate_N_m_per_rad", &spring_rate_N_m_per_rad,
               Field().NonNegative().Unit("N·m/rad").Desc("k, the return spring's rate about the pivot"));
      a->Visit("spring_preload_N_m", &spring_preload_N_m,
               Field().NonNegative().Unit("N·m").Desc("M₀, the spring's moment on the base circle, pressing the arm onto the cam"));
      a->Visit("external_moment_N_m", &external_moment_N_m,
               Field().Unit("N·m").Desc("M_e, a constant moment pressing the arm onto the cam (negative: lifting it off)"));
      a->Visit("arm_stiffness_N_m_per_rad", &arm_stiffness_N_m_per_rad,
               Field().Positive().Unit("N·m/rad").Desc(
                   "k_f, the follower train's torsional stiffness between the cam-imposed arm angle and the arm's "
                   "inertia: with it the one-degree-of-freedom dynamic response of the arm, its separation, residual "
                   "vibration and residual-vibration spectrum, and the dynamic jump speed (docs/disc_cam.md, 'Follower "
                   "dynamics'; absent: the kinetostatic loads only)"));
      a->Visit("damping_ratio", &damping_ratio,
               Field().AtLeast(0.0, "a number in [0, 1]").AtMost(1.0, "a number in [0, 1]").Desc(
                   "zeta of the arm's mode in contact, c = 2 zeta sqrt(J (k_f + k)) (with arm_stiffness_N_m_per_rad)"));
      a->Visit("revolutions", &revolutions,
               Field().AtLeast(1, "an integer in [1, 50]").AtMost(50, "an integer in [1, 50]").Desc(
                   "revolutions simulated from rest on the cam; the response reported is the last one's (with "
                   "arm_stiffness_N_m_per_rad)"));
    }
  };
  /// The Monte-Carlo check of the linearised error (the object form of analysis.monte_carlo).
  struct MonteCarlo {
    int samples = camopt::disc_cam::MonteCarloOptions{}.samples;
    int angle_steps = camopt::disc_cam::MonteCarloOptions{}.angle_steps;
    int seed = 1;
    std::vector<double> scales = camopt::disc_cam::MonteCarloOptions{}.scales;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("samples", &samples, Field().AtLeast(1).Desc("random deviations drawn per tolerance scale"));
      a->Visit("angle_steps", &angle_steps, Field().AtLeast(36).Desc("cam angles per sample"));
      a->Visit("seed", &seed, Field().AtLeast(0).Desc("the random generator's seed"));
      a->Visit("scales", &scales,
               Field().Positive().MinItems(1, "a non-empty array of numbers > 0")
                   .Desc("tolerance multipliers, one run each (samples × angle_steps × scales below 1e8)"));
    }
  };
  struct Analysis {
    int angle_steps = 3600;
    nlohmann::json monte_carlo;  ///< true, false or a MonteCarlo object; null: absent (on)
    std::optional<std::vector<std::string>> evaluate;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("angle_steps", &angle_steps,
               Field().AtLeast(36).AtMost(1000000, "a whole number <= 1000000")
                   .Desc("cam angles over a revolution (the analysis grid)"));
      a->Visit("monte_carlo", &monte_carlo, Field().Schema(MonteCarloSchema()));
      a->Visit("evaluate", &evaluate,
               Field().OneOf({"profile", "error", "monte_carlo"})
                   .Desc("the stages to run (absent: all): the profile always runs; error adds the mechanical error, "
                         "monte_carlo the error and its Monte-Carlo check; either needs the tolerances"));
    }
    /// true/false, or the MonteCarlo object (absent or true: its defaults).
    static nlohmann::ordered_json MonteCarloSchema();
  };

  std::string study = "disc_cam", name = "disc cam";
  std::optional<std::string> description;
  Follower follower;
  double base_circle_radius_mm = 0.0;
  nlohmann::json motion;
  std::optional<Tolerances> tolerances;
  std::optional<Limits> limits;
  std::optional<double> face_width_mm;
  std::optional<MaterialInput> material;
  std::optional<Dynamics> dynamics;
  std::optional<ArmDynamics> arm_dynamics;
  Analysis analysis;
  std::optional<double> cam_thickness_mm, bore_diameter_mm, cutter_radius_mm;
  std::optional<KeywayInput> keyway;
  std::optional<BoltCircleInput> bolt_circle;
  nlohmann::json geometry_files;

  /// The fields disc_cam and disc_cam_min_size share, in the file's order (all but study,
  /// analysis): Serialize visits them between "study" and "analysis". `sizing`: as the start
  /// design of disc_cam_min_size (a translating roller follower only).
  template <typename Archive>
  void SerializeDesign(Archive* a, bool sizing = false) {
    a->Visit("name", &name, Field().Desc("the design's name, in titles"));
    a->Visit("description", &description, Field().Desc("free text"));
    a->Visit("follower", &follower,
             Field().Required().Desc(sizing ? "the start design's follower; a translating or oscillating roller or knife-edge "
                                              "follower, or a translating flat face (an oscillating flat face is refused)"
                                            : "the follower"));
    a->Visit("base_circle_radius_mm", &base_circle_radius_mm,
             Field().Required().Positive().Unit("mm").Desc(
                 sizing ? "r_b, the start (clamped into variables.base_circle_radius_mm)"
                        : "r_b, the base circle of the cam profile"));
    a->Visit("motion", &motion, Field().Required().Schema(MotionSchema(sizing)).Desc(
        "the follower's motion over one cam revolution: segments whose cam angles sum to 360, rising and "
        "returning to the base circle"));
    a->Visit("tolerances", &tolerances,
             Field().Desc("manufacturing tolerances for the mechanical error (absent: none; needed by the error "
                          "stages)"));
    a->Visit("limits", &limits,
             Field().Desc("limits of the verdict (docs/disc_cam.md 'Limits and verdict'); a limit not given takes "
                          "its default"));
    a->Visit("face_width_mm", &face_width_mm,
             Field().Positive().Unit("mm").Desc(
                 "contact length along the camshaft axis of the roller (or flat face) on the cam, for the Hertz "
                 "stress"));
    a->Visit("material", &material, Field().Desc("follower and cam (both), for the Hertz stress"));
    a->Visit("dynamics", &dynamics,
             Field().Desc("kinetostatic follower loads at one cam speed (docs/disc_cam.md 'Kinetostatic loads'); "
                          "translating followers only (an oscillating one takes arm_dynamics)"));
    a->Visit("arm_dynamics", &arm_dynamics,
             Field().Desc("kinetostatic loads on the arm of an oscillating follower at one cam speed, from the moment "
                          "balance about the pivot: contact force (M/ℓ on a flat face, M/(n · dC/dξ) on a roller or "
                          "knife edge), camshaft torque, jump speed, contact stress (docs/disc_cam.md 'Oscillating "
                          "flat-faced follower', 'Loads of an oscillating roller follower'); oscillating followers only"));
  }
  /// The geometry files' fields (after "analysis" in the file).
  template <typename Archive>
  void SerializeGeometry(Archive* a) {
    a->Visit("cam_thickness_mm", &cam_thickness_mm,
             Field().Positive().Unit("mm").Desc("the cam's thickness: profile.step/.stl are written only with it"));
    a->Visit("bore_diameter_mm", &bore_diameter_mm,
             Field().Positive().Unit("mm").Desc("the bore of the STEP/STL solid, inside the base circle (absent: none)"));
    a->Visit("keyway", &keyway, Field().Desc("a key slot in the bore (the geometry files; docs/parts.md)"));
    a->Visit("bolt_circle", &bolt_circle,
             Field().Desc("equal through-holes on a circle about the cam's centre, inside the base circle"));
    a->Visit("cutter_radius_mm", &cutter_radius_mm,
             Field().Positive().Unit("mm").Desc(
                 "r_t ≤ r_f, a cutter for a CUTTER_PATH layer in the DXF (absent or r_t = r_f: the pitch curve is "
                 "its path)"));
    a->Visit("geometry_files", &geometry_files,
             Field().Schema(GeometryFilesSchema(
                 "geometry files (docs/studies.md 'Geometry files'); false: none at all (no arc fit, no "
                 "DXF/STEP/STL)")));
  }
  /// The part name of "measured_profile": the cam (its geometry files' stem).
  struct Parts {
    static std::vector<std::string> Names() { return {"profile"}; }
    static std::string Description() { return "the measured cam, \"profile\" (the frame of profile.dxf)"; }
  };
  std::optional<InspectionInput> inspection;
  std::optional<MeasuredProfileInputT<Parts>> measured_profile;
  /// What a follower without a roller does not take (the mechanical-error stages, a cutter path; a
  /// knife edge no contact-stress limit): Parse refuses the same with its reasons.
  static nlohmann::ordered_json SchemaRules();
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Required().Const("disc_cam").Desc("the study kind"));
    SerializeDesign(a);
    a->Visit("analysis", &analysis, Field().Desc("the analysis grid, the Monte-Carlo check and the stages to run"));
    SerializeGeometry(a);
    a->Visit("inspection", &inspection,
             Field().Desc("inspection points of the cam's exact profile with the ISO 1101 profile tolerance zone: "
                          "inspection/profile.csv (docs/studies.md, \"Inspection points and measured parts\"; none "
                          "when geometry_files is false)"));
    a->Visit("measured_profile", &measured_profile,
             Field().Desc("a measured cam back in: its ISO 1101 profile deviation and the follower's displacement "
                          "error as measured (docs/studies.md, \"Inspection points and measured parts\")"));
  }
  /// The schema of "motion" (read by ParseMotionProgram): rise_mm for a translating, rise_deg for an
  /// oscillating follower; polynomial segments (`sizing`: the same, disc_cam_min_size sizes both).
  static nlohmann::ordered_json MotionSchema(bool sizing);
};

/// The study file, parsed and validated (CheckDesign passed), in model units.
struct Study {
  std::string name;
  /// The follower's contact: a roller, a knife edge (the roller model with r_f = 0) or a flat face
  /// (model/disc_cam/flat_faced.h; cam holds its base circle and motion, translating, r_f = 0), or a
  /// flat face on an arm (model/disc_cam/oscillating_flat_faced.h; cam holds its base circle, motion and
  /// pivot distance, oscillating, r_f = 0; the face offset d below).
  enum class Contact { kRoller, kKnifeEdge, kFlatFaced } contact = Contact::kRoller;
  std::string follower_type = "translating_roller";  ///< as in the file
  /// Flat face: its width in the cam plane, centred on the axis [mm] (follower.face_width_mm).
  std::optional<double> follower_face_width_mm;
  /// Oscillating flat face: d, the face's distance from the pivot toward the cam [mm].
  double face_offset_mm = 0.0;
  camopt::disc_cam::DiscCam cam;
  camopt::disc_cam::Deviations<double> tolerances;  ///< [mm]
  int angle_steps = 3600;
  bool monte_carlo = true;  ///< off when asked or when every tolerance is zero
  camopt::disc_cam::MonteCarloOptions monte_carlo_options;
  /// The stages asked for ("analysis.evaluate"; all when absent). The profile always runs;
  /// without "error" (or "monte_carlo") no tolerances are needed and the mechanical error is not
  /// computed.
  bool error_stage = true;
  bool evaluate_given = false;
  bool tolerances_given = false;  ///< "tolerances" in the file (unused without a roller: a note)
  /// Geometry files: cam thickness and bore of the solid [mm] (no STEP/STL without a thickness),
  /// a cutter radius for a cutter-path layer (0: none given), "geometry_files" options.
  double cam_thickness_mm = 0, bore_diameter_mm = 0, cutter_radius_mm = 0;
  Mounting mounting;  ///< "keyway", "bolt_circle"
  GeometryFileOptions geometry;
  std::optional<InspectionInput> inspection;  ///< "inspection"
  std::optional<MeasuredProfile> measured;    ///< "measured_profile", projected onto the exact profile

  /// The limits of the verdict ("limits"; docs/disc_cam.md "Limits and verdict"). A limit not
  /// given takes its default (recorded in *_default): the pressure angle 30° translating / 45°
  /// oscillating, the radius margin the roller radius; the contact stress has no default.
  struct Limits {
    double pressure_angle_deg = 30.0;
    bool pressure_angle_default = true;
    double radius_margin_mm = 0.0;
    bool radius_margin_default = true;
    std::optional<double> contact_stress_MPa;  ///< no default: needs a material's strength
  } limits;
  /// Contact length of roller and cam [mm] and their material (both bodies), for the Hertz stress.
  std::optional<double> face_width_mm;
  std::optional<Material> material;
  /// Kinetostatic follower loads ("dynamics"; translating followers only).
  struct Dynamics {
    double speed_rpm = 0.0;
    std::string follower_axis = "vertical_above_cam";
    camopt::disc_cam::FollowerLoads loads;
    /// The dynamic response (model/disc_cam/follower_dynamics.h): k_f [N/mm] (absent: none), ζ, turns.
    std::optional<double> follower_stiffness_N_per_mm;
    double damping_ratio = 0.05;
    int revolutions = 3;
  };
  std::optional<Dynamics> dynamics;
  /// The arm's loads of an oscillating follower ("arm_dynamics").
  struct ArmDynamics {
    double speed_rpm = 0.0;
    camopt::disc_cam::ArmLoads loads;
    /// The arm's dynamic response (follower_dynamics.h, SimulateArm): k_f [N·m/rad] (absent: none), ζ, turns.
    std::optional<double> arm_stiffness_N_m_per_rad;
    double damping_ratio = 0.05;
    int revolutions = 3;
  };
  std::optional<ArmDynamics> arm_dynamics;
};

/// The residual-vibration spectrum's range of τ = T/T_n and its number of points (result.json's
/// residual_spectrum, residual_spectrum.csv and .svg).
inline constexpr double kSpectrumTauLow = 0.5, kSpectrumTauHigh = 10.0;
inline constexpr int kSpectrumPoints = 381;  // steps of 0.025

/// A value and the cam angle where it is reached.
struct AtAngle {
  double value = 0.0;
  double cam_angle_deg = 0.0;
};

struct MinMax {
  double min = 0.0, max = 0.0;
};

/// One tolerance scale of the Monte-Carlo check, in the units of result.json (µm at the roller
/// centre).
struct MonteCarloRow {
  double scale, max_linear_um, max_exact_um, max_difference_um, relative_difference;
  double at_cam_angle_deg, within_worst_case_fraction, worst_case_exceeded_by_um;
  double sample_rms_um, linear_rms_uniform_um;
};

/// Every number the kind reports. "Follower unit" is mm (translating) or deg (oscillating);
/// errors are at the roller centre in µm (l·Δξ for an oscillating follower).
struct Result {
  bool oscillating = false;
  std::string follower_unit;  ///< "mm" or "deg"

  /// Series over the analysis grid (the columns of series.csv).
  struct Series {
    std::vector<double> cam_angle_deg;
    std::vector<double> follower, velocity_per_rad, acceleration_per_rad2, jerk_per_rad3;
    std::vector<double> pressure_angle_deg, shift_angle_deg, radial_dimension_mm;
    std::vector<double> contact_x_mm, contact_y_mm, pitch_x_mm, pitch_y_mm, q_mm;
    std::vector<double> pitch_curvature_per_mm;
    std::vector<double> error_radial_um, error_roller_um, error_normal_um, error_worst_case_um,
        error_rms_um;
  } series;

  AtAngle max_radial_dimension_mm;
  double min_radial_dimension_mm = 0.0;
  AtAngle min_pressure_angle_deg, max_pressure_angle_deg;
  MinMax shift_angle_deg, cos_shift_over_cos_pressure;
  std::optional<AtAngle> min_radius_of_curvature_mm;          ///< convex parts; none when none
  std::optional<AtAngle> min_concave_radius_of_curvature_mm;  ///< concave parts
  bool undercut = false;
  std::vector<std::pair<double, double>> undercut_cam_angle_deg;  ///< [from, to] intervals

  AtAngle max_worst_case_error_um, max_rms_error_um;
  double min_worst_case_error_um = 0.0;
  MinMax radial_error_um, roller_error_um, normal_error_um;
  std::optional<AtAngle> max_worst_case_error_arcsec;  ///< oscillating only
  std::optional<double> max_rms_error_arcsec;          ///< oscillating only

  /// Largest |φ| where the follower rises or dwells (S' ≥ 0) and where it returns (S' < 0).
  AtAngle max_pressure_angle_rise_deg;
  std::optional<AtAngle> max_pressure_angle_return_deg;

  /// Kinetostatic loads (Study::dynamics given; model/disc_cam/kinetostatics.h).
  struct Loads {
    AtAngle min_contact_force_N, max_contact_force_N;
    AtAngle max_abs_camshaft_torque_Nm;     ///< largest |T|
    double min_camshaft_torque_Nm = 0.0, max_camshaft_torque_Nm = 0.0;  ///< signed range
    double jump_speed_rpm = 0.0;  ///< +infinity when the follower never decelerates
    /// The spring that keeps contact at every speed up to the study's (kinetostatics.h): the
    /// smallest preload with the study's rate, the smallest rate with its preload (+infinity: none).
    camopt::disc_cam::SpringRequirement spring;
    double weight_N = 0.0;
    /// Peak Hertz stress (face width and material given); stress_finite false when a loaded
    /// point of the profile is undercut.
    bool stress_evaluated = false, stress_finite = true;
    AtAngle max_contact_stress_MPa;
    std::vector<double> contact_force_N, camshaft_torque_Nm, contact_stress_MPa;  ///< series
    /// With a follower stiffness: the response at the speed and the dynamic jump speed searched up
    /// to 1.5 times the kinetostatic one (none when that is infinite).
    std::optional<camopt::disc_cam::FollowerDynamicsResult> response;
    std::optional<camopt::disc_cam::DynamicJumpSpeed> dynamic_jump;
    double dynamic_jump_upper_rpm = 0.0;
    /// With the arm's stiffness: its response (the dynamic jump in dynamic_jump), and the normal
    /// contact force at the cam, M_a over the normal's lever arm about the pivot, at the response's
    /// samples (series) and its extremes over them.
    std::optional<camopt::disc_cam::ArmDynamicsResult> arm_response;
    std::vector<double> arm_contact_force_N;
    AtAngle min_dynamic_contact_force_N, max_dynamic_contact_force_N;
  };
  std::optional<Loads> loads;

  /// Flat-faced follower (model/disc_cam/flat_faced.h): where the contact runs on the face, and the
  /// profile's radius of curvature ρ = r_b + S + S'' (min_radius_of_curvature_mm holds ρ_min). On an
  /// arm (model/disc_cam/oscillating_flat_faced.h) the contact offset is ℓ, along the face from the
  /// foot of the pivot's perpendicular, and ρ = h + h_φφ.
  struct FlatFace {
    AtAngle max_contact_offset_mm, min_contact_offset_mm;  ///< S' (translating) or ℓ (on an arm) [mm]
    AtAngle min_radius_of_curvature_mm;                    ///< ρ_min, where it is (≤ 0: a cusp)
    std::vector<std::pair<double, double>> cusp_cam_angle_deg;  ///< [from, to] where ρ ≤ 0
    std::vector<double> contact_offset_mm, radius_of_curvature_mm;  ///< series
  };
  std::optional<FlatFace> flat_face;

  /// The residual-vibration spectrum of each moving segment (model/disc_cam/residual_spectrum.h),
  /// with the response: A/|h| over kSpectrumTau, the segment's τ at the study's speed, A/|h| there,
  /// the predicted residual vibration r |h| A/h (follower unit) and the spectrum's minima.
  struct SpectrumSegment {
    int index = 0;  ///< the segment's position in the motion (from 0)
    std::string law;
    double tau = 0.0, amplitude = 0.0, amplitude_error = 0.0, predicted_residual = 0.0;
    std::vector<double> spectrum;
    std::vector<camopt::disc_cam::SpectrumMinimum> minima;
  };
  struct Spectrum {
    double zeta = 0.0, stiffness_ratio = 0.0;  ///< ζ and r = k_f/(k_f + k)
    std::vector<double> tau;
    std::vector<SpectrumSegment> segments;
  };
  std::optional<Spectrum> residual_spectrum;

  std::vector<motion::JointContinuity> joints;
  double peak_velocity = 0.0, peak_acceleration = 0.0, peak_jerk = 0.0;  ///< follower unit/rad^k

  enum class MonteCarlo { kOff, kSkippedUndercut, kDone } monte_carlo = MonteCarlo::kOff;
  bool error_evaluated = false;  ///< the mechanical-error stage ran (the error fields are set)
  std::vector<MonteCarloRow> monte_carlo_rows;
  PlanarCamFit profile_files;  ///< the cam's geometry files (arcs of the exact profile)
  /// inspection/profile.csv and its point count ("inspection").
  std::vector<std::pair<std::string, std::string>> inspection_files;
  std::vector<std::pair<std::string, long>> inspection_points;
  nlohmann::json measured;  ///< result.json's "measured" (null: none)
};

/// The cam as inspected: its exact profile as a function of the cam angle θ in the frame of
/// profile.dxf, the frame and datum in words.
InspectedPart CamPart(const Study& study);

/// Parses and validates a "disc_cam" study. @throws StudyError (exit 2) naming the JSON path.
Study Parse(const Node& root);
/// Evaluates the cam over the analysis grid, the mechanical error and the Monte-Carlo check.
Result Run(const Study& study, const RunContext& ctx);
/// result.json.
nlohmann::json ToJson(const Study& study, const Result& result);
/// result.json, series.csv, the SVG plots, profile.svg and profile.dxf.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::disc_cam
