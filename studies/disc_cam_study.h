// Study kind "disc_cam": a disc cam with an offset translating or an oscillating roller follower
// (Rzine et al., docs/disc_cam.md), a knife edge (the roller model with r_f = 0), a translating
// flat-faced follower (model/disc_cam/flat_faced.h) or a flat face on an arm
// (model/disc_cam/oscillating_flat_faced.h). Profile, pressure and shift angles, curvature
// and undercut over a cam revolution; for a roller the mechanical error from the tolerances (worst
// case and RMS, eqs. 31–32) and a Monte-Carlo check of the linearised error against the exact
// follower motion.
// Outputs: result.json, series.csv, SVAJ / angle / error plots (SVG), profile.svg, profile.dxf.
#pragma once

#include <array>
#include <cstdint>
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
#include "studies/motion_input.h"
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
  /// face: face_width_mm), checked by Parse and stated by SchemaRules.
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
    /// the face offset an oscillating flat face's; pivot and arm an oscillating follower's (a flat
    /// face on its arm: the pivot only), the offset a translating roller's or knife edge's.
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
    static std::vector<CrossFieldRule> CrossFieldRules() {
      return {{{"samples", "angle_steps", "scales"},
               "samples × angle_steps × scales below 1e8 (the work of the check)", "must stay below 1e8"}};
    }
  };
  struct Analysis {
    int angle_steps = 3600;
    BoolOr<MonteCarlo> monte_carlo = true;
    std::optional<std::vector<std::string>> evaluate;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("angle_steps", &angle_steps,
               Field().AtLeast(36).AtMost(1000000, "a whole number <= 1000000")
                   .Desc("cam angles over a revolution (the analysis grid)"));
      a->Visit("monte_carlo", &monte_carlo,
               Field().Desc("the Monte-Carlo check of the linearised error against the exact motion: true (its "
                            "defaults), false (off) or its settings; off when every tolerance is zero"));
      a->Visit("evaluate", &evaluate,
               Field().OneOf({"profile", "error", "monte_carlo"})
                   .Desc("the stages to run (absent: all): the profile always runs; error adds the mechanical error, "
                         "monte_carlo the error and its Monte-Carlo check; either needs the tolerances"));
    }
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
  GeometryFiles geometry_files = true;

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
             Field().Desc(
                 "geometry files (docs/studies.md 'Geometry files'); false: none at all (no arc fit, no "
                 "DXF/STEP/STL)"));
  }
  /// The part name of "measured_profile": the cam (its geometry files' stem).
  struct Parts {
    static std::vector<std::string> Names() { return {"profile"}; }
    static std::string Description() { return "the measured cam, \"profile\" (the frame of profile.dxf)"; }
  };
  std::optional<InspectionInput> inspection;
  std::optional<MeasuredProfileInputT<Parts>> measured_profile;
  /// The design's rules by the follower (DesignSchemaRules); without a roller no mechanical-error
  /// stage, and the error stages need the tolerances: Parse refuses the same with its reasons.
  static nlohmann::ordered_json SchemaRules();
  /// The motion's and the mounting's rules (MotionRules, MountingRule).
  static std::vector<CrossFieldRule> CrossFieldRules();
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

/// The study as Run takes it: the file as declared (`in`, in the file's units) and, checked
/// (CheckDesign passed), the design in model units and the stages to run.
struct Study {
  Input in;
  /// The follower's contact: a roller, a knife edge (the roller model with r_f = 0) or a flat face
  /// (model/disc_cam/flat_faced.h; cam holds its base circle and motion, translating, r_f = 0), or a
  /// flat face on an arm (model/disc_cam/oscillating_flat_faced.h; cam holds its base circle, motion and
  /// pivot distance, oscillating, r_f = 0; the face offset d below).
  enum class Contact { kRoller, kKnifeEdge, kFlatFaced } contact = Contact::kRoller;
  /// Flat face: its width in the cam plane, centred on the axis [mm] (follower.face_width_mm).
  std::optional<double> follower_face_width_mm;
  /// Oscillating flat face: d, the face's distance from the pivot toward the cam [mm].
  double face_offset_mm = 0.0;
  camopt::disc_cam::DiscCam cam;
  camopt::disc_cam::Deviations<double> tolerances;  ///< [mm]
  bool monte_carlo = true;  ///< off when asked or when every tolerance is zero
  camopt::disc_cam::MonteCarloOptions monte_carlo_options;
  /// The stages asked for ("analysis.evaluate"; all when absent). The profile always runs;
  /// without "error" (or "monte_carlo") no tolerances are needed and the mechanical error is not
  /// computed.
  bool error_stage = true;
  /// Geometry files: cam thickness and bore of the solid [mm] (no STEP/STL without a thickness),
  /// a cutter radius for a cutter-path layer (0: none given), "geometry_files" options.
  double cam_thickness_mm = 0, bore_diameter_mm = 0, cutter_radius_mm = 0;
  Mounting mounting;  ///< "keyway", "bolt_circle"
  GeometryFileOptions geometry;
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
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("scale", &scale, Field().Desc("the tolerance multiplier"));
    a->Visit("max_linear_um", &max_linear_um, Field().Unit("µm").Desc("the largest linearised error over the samples"));
    a->Visit("max_exact_um", &max_exact_um, Field().Unit("µm").Desc("the largest exact error"));
    a->Visit("max_difference_um", &max_difference_um, Field().Unit("µm").Desc("the largest absolute difference, exact − linear"));
    a->Visit("relative_difference", &relative_difference, Field().Desc("max_difference over max_linear"));
    a->Visit("at_cam_angle_deg", &at_cam_angle_deg, Field().Unit("deg").Desc("where the largest difference is"));
    a->Visit("within_worst_case_fraction", &within_worst_case_fraction,
             Field().Desc("the share of samples within the worst case (eq. 31)"));
    a->Visit("worst_case_exceeded_by_um", &worst_case_exceeded_by_um, Field().Unit("µm").Desc("by how much at most"));
    a->Visit("sample_rms_um", &sample_rms_um, Field().Unit("µm").Desc("the samples' RMS"));
    a->Visit("linear_rms_uniform_um", &linear_rms_uniform_um,
             Field().Unit("µm").Desc("the linear model's RMS for uniform deviations"));
  }
};

/// result.json's "measured" (with measured_profile): the measured cam's deviation (MeasuredBlock),
/// the follower's displacement error it makes and, with a contact stress, the stress on it. The
/// error is in µm of a translating follower, in arcsec of an oscillating one (the keys say which).
struct DiscCamMeasured : MeasuredBlock {
  struct Follower {
    std::string model;
    int angles = 0;
    std::optional<double> displacement_error_max_um, displacement_error_max_arcsec;
    double displacement_error_max_at_cam_angle_deg = 0;
    std::optional<double> displacement_error_min_um, displacement_error_min_arcsec;
    double displacement_error_min_at_cam_angle_deg = 0;
    std::optional<double> displacement_error_peak_to_peak_um, displacement_error_peak_to_peak_arcsec;
    std::optional<NominalMeasured> follower_range_mm, follower_range_deg;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("model", &model, Field().Desc("the model in words"));
      a->Visit("angles", &angles, Field().Desc("analysis.angle_steps"));
      const char* trans = "a translating follower's";
      const char* osc = "an oscillating follower's";
      a->Visit("displacement_error_max_um", &displacement_error_max_um, Field().Unit("µm").Desc(trans));
      a->Visit("displacement_error_max_arcsec", &displacement_error_max_arcsec, Field().Unit("arcsec").Desc(osc));
      a->Visit("displacement_error_max_at_cam_angle_deg", &displacement_error_max_at_cam_angle_deg, Field().Unit("deg"));
      a->Visit("displacement_error_min_um", &displacement_error_min_um, Field().Unit("µm").Desc(trans));
      a->Visit("displacement_error_min_arcsec", &displacement_error_min_arcsec, Field().Unit("arcsec").Desc(osc));
      a->Visit("displacement_error_min_at_cam_angle_deg", &displacement_error_min_at_cam_angle_deg, Field().Unit("deg"));
      a->Visit("displacement_error_peak_to_peak_um", &displacement_error_peak_to_peak_um,
               Field().Unit("µm").Desc(trans));
      a->Visit("displacement_error_peak_to_peak_arcsec", &displacement_error_peak_to_peak_arcsec,
               Field().Unit("arcsec").Desc(osc));
      a->Visit("follower_range_mm", &follower_range_mm, Field().Unit("mm").Desc("a translating follower's stroke"));
      a->Visit("follower_range_deg", &follower_range_deg, Field().Unit("deg").Desc("an oscillating follower's swing"));
    }
  };
  struct Contact {
    std::string model;
    NominalMeasuredOrInfinite max_contact_stress_MPa;
    NominalMeasured at_max_contact_stress_cam_angle_deg;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("model", &model, Field().Desc("the model in words"));
      a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa, Field().Unit("MPa"));
      a->Visit("at_max_contact_stress_cam_angle_deg", &at_max_contact_stress_cam_angle_deg, Field().Unit("deg"));
    }
  };
  std::optional<Follower> follower;
  std::optional<Contact> contact;
  template <typename Archive>
  void Serialize(Archive* a) {
    MeasuredBlock::Serialize(a);
    a->Visit("follower", &follower, Field().Desc("the follower's displacement error (not for an oscillating flat face)"));
    a->Visit("contact", &contact, Field().Desc("with a contact stress: the stress on the measured profile"));
  }
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
  std::optional<DiscCamMeasured> measured;  ///< result.json's "measured" (with measured_profile)

  /// result.json, declared once (studies/archive.h): Run ends by filling it from the numbers above
  /// (FillResult), Write writes it (WriteResult) and `camopt schema disc_cam --result` prints its
  /// schema. The keys a follower type does not have are std::optional (absent).
  struct Json {
    struct MinMax {
      double min = 0, max = 0;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("min", &min, Field());
        a->Visit("max", &max, Field());
      }
    };
    /// The extremes of a value over the cycle and where they are.
    struct Range {
      double max = 0, at_max_cam_angle_deg = 0, min = 0, at_min_cam_angle_deg = 0;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("max", &max, Field());
        a->Visit("at_max_cam_angle_deg", &at_max_cam_angle_deg, Field().Unit("deg"));
        a->Visit("min", &min, Field());
        a->Visit("at_min_cam_angle_deg", &at_min_cam_angle_deg, Field().Unit("deg"));
      }
    };
    /// The pressure angle φ over the cycle and, but for a translating flat face, against its limit.
    struct PressureAngle {
      double min = 0, at_min_cam_angle_deg = 0, max = 0, at_max_cam_angle_deg = 0;
      std::optional<double> max_rise, at_max_rise_cam_angle_deg, max_return, at_max_return_cam_angle_deg, limit;
      std::optional<bool> rise_ok, return_ok;
      std::optional<std::string> note;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("min", &min, Field().Unit("deg"));
        a->Visit("at_min_cam_angle_deg", &at_min_cam_angle_deg, Field().Unit("deg"));
        a->Visit("max", &max, Field().Unit("deg"));
        a->Visit("at_max_cam_angle_deg", &at_max_cam_angle_deg, Field().Unit("deg"));
        a->Visit("max_rise", &max_rise,
                 Field().Unit("deg").Desc("the largest absolute φ where the follower rises or dwells (S' ≥ 0); not for a "
                                          "translating flat face"));
        a->Visit("at_max_rise_cam_angle_deg", &at_max_rise_cam_angle_deg, Field().Unit("deg"));
        a->Visit("max_return", &max_return,
                 Field().Unit("deg").Desc("the largest absolute φ where the follower returns (S' < 0), when it does"));
        a->Visit("at_max_return_cam_angle_deg", &at_max_return_cam_angle_deg, Field().Unit("deg"));
        a->Visit("limit", &limit, Field().Unit("deg").Desc("limits.pressure_angle_deg, not for a translating flat face"));
        a->Visit("rise_ok", &rise_ok, Field().Desc("max_rise within the limit"));
        a->Visit("return_ok", &return_ok, Field().Desc("max_return within the limit (no return: true)"));
        a->Visit("note", &note, Field().Desc("a translating flat face: why φ is 0"));
      }
    };
    /// A flat face: where the contact runs on it, the profile's radius of curvature ρ and its cusps.
    struct FlatFace {
      std::optional<double> pivot_distance_mm, face_offset_mm, arm_angle_on_base_circle_deg;
      std::optional<Range> contact_on_face_mm;
      std::optional<double> face_length_needed_mm;
      std::optional<Range> contact_offset_mm;
      std::optional<double> face_needed_rise_side_mm, face_needed_return_side_mm, face_width_needed_mm,
          face_width_needed_centred_mm;
      double min_radius_of_curvature_mm = 0, min_radius_of_curvature_at_cam_angle_deg = 0, radius_margin_limit_mm = 0;
      bool radius_margin_ok = false, cusp = false;
      std::vector<std::array<double, 2>> cusp_cam_angle_deg;
      std::optional<double> face_width_mm;
      std::optional<bool> face_width_ok;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("pivot_distance_mm", &pivot_distance_mm, Field().Unit("mm").Desc("on an arm: f, cam centre to pivot"));
        a->Visit("face_offset_mm", &face_offset_mm, Field().Unit("mm").Desc("on an arm: d, the face's distance from the pivot"));
        a->Visit("arm_angle_on_base_circle_deg", &arm_angle_on_base_circle_deg,
                 Field().Unit("deg").Desc("on an arm: its angle on the base circle"));
        a->Visit("contact_on_face_mm", &contact_on_face_mm,
                 Field().Unit("mm").Desc("on an arm: ℓ, the contact along the face from the foot of the pivot's "
                                         "perpendicular"));
        a->Visit("face_length_needed_mm", &face_length_needed_mm, Field().Unit("mm").Desc("on an arm: max ℓ − min ℓ"));
        a->Visit("contact_offset_mm", &contact_offset_mm,
                 Field().Unit("mm").Desc("translating: S', the contact's offset from the follower's axis"));
        a->Visit("face_needed_rise_side_mm", &face_needed_rise_side_mm, Field().Unit("mm").Desc("translating: max(0, max S')"));
        a->Visit("face_needed_return_side_mm", &face_needed_return_side_mm,
                 Field().Unit("mm").Desc("translating: max(0, −min S')"));
        a->Visit("face_width_needed_mm", &face_width_needed_mm, Field().Unit("mm").Desc("translating: both sides"));
        a->Visit("face_width_needed_centred_mm", &face_width_needed_centred_mm,
                 Field().Unit("mm").Desc("translating: a face centred on the axis, twice the larger side"));
        a->Visit("min_radius_of_curvature_mm", &min_radius_of_curvature_mm,
                 Field().Unit("mm").Desc("ρ_min, the profile's smallest radius of curvature (≤ 0: a cusp)"));
        a->Visit("min_radius_of_curvature_at_cam_angle_deg", &min_radius_of_curvature_at_cam_angle_deg, Field().Unit("deg"));
        a->Visit("radius_margin_limit_mm", &radius_margin_limit_mm, Field().Unit("mm").Desc("limits.radius_margin_mm"));
        a->Visit("radius_margin_ok", &radius_margin_ok, Field().Desc("ρ_min above the margin"));
        a->Visit("cusp", &cusp, Field().Desc("the profile has a cusp (ρ ≤ 0 somewhere)"));
        a->Visit("cusp_cam_angle_deg", &cusp_cam_angle_deg, Field().Unit("deg").Desc("[from, to] where ρ ≤ 0"));
        a->Visit("face_width_mm", &face_width_mm, Field().Unit("mm").Desc("follower.face_width_mm, when given"));
        a->Visit("face_width_ok", &face_width_ok, Field().Desc("the face is long (wide) enough, with face_width_mm"));
      }
    };
    struct Tolerances {
      double profile_radial = 0, roller_radius = 0, profile_normal = 0;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("profile_radial", &profile_radial, Field().Unit("µm"));
        a->Visit("roller_radius", &roller_radius, Field().Unit("µm"));
        a->Visit("profile_normal", &profile_normal, Field().Unit("µm"));
      }
    };
    /// The largest value of an error and where it is.
    struct Peak {
      double max = 0, at_cam_angle_deg = 0;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("max", &max, Field());
        a->Visit("at_cam_angle_deg", &at_cam_angle_deg, Field().Unit("deg"));
      }
    };
    struct WorstCase : Peak {
      double min = 0;
      template <typename Archive>
      void Serialize(Archive* a) {
        Peak::Serialize(a);
        a->Visit("min", &min, Field());
      }
    };
    struct Max {
      double max = 0;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("max", &max, Field());
      }
    };
    struct ErrorComponents {
      MinMax radial, roller, normal;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("radial", &radial, Field().Desc("from the profile's radial tolerance"));
        a->Visit("roller", &roller, Field().Desc("from the roller radius's tolerance"));
        a->Visit("normal", &normal, Field().Desc("from the profile's normal tolerance"));
      }
    };
    struct FollowerResponse {
      double follower_stiffness_N_per_mm = 0, damping_ratio = 0;
      int revolutions = 0;
      double natural_frequency_Hz = 0, min_axial_force_N = 0, at_min_axial_force_cam_angle_deg = 0,
             max_axial_force_N = 0, at_max_axial_force_cam_angle_deg = 0;
      bool separates = false;
      std::optional<double> first_separation_cam_angle_deg;
      double residual_vibration_mm = 0, at_residual_vibration_cam_angle_deg = 0;
      long solver_steps = 0;
      int contact_events = 0;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("follower_stiffness_N_per_mm", &follower_stiffness_N_per_mm, Field().Unit("N/mm").Desc("k_f"));
        a->Visit("damping_ratio", &damping_ratio, Field().Desc("ζ"));
        a->Visit("revolutions", &revolutions, Field().Desc("simulated; the last one's response"));
        a->Visit("natural_frequency_Hz", &natural_frequency_Hz, Field().Unit("Hz"));
        a->Visit("min_axial_force_N", &min_axial_force_N, Field().Unit("N"));
        a->Visit("at_min_axial_force_cam_angle_deg", &at_min_axial_force_cam_angle_deg, Field().Unit("deg"));
        a->Visit("max_axial_force_N", &max_axial_force_N, Field().Unit("N"));
        a->Visit("at_max_axial_force_cam_angle_deg", &at_max_axial_force_cam_angle_deg, Field().Unit("deg"));
        a->Visit("separates", &separates, Field().Desc("contact lost in the last revolution"));
        a->Visit("first_separation_cam_angle_deg", &first_separation_cam_angle_deg,
                 Field().NullWhenAbsent().Unit("deg").Desc("where (null: no separation)"));
        a->Visit("residual_vibration_mm", &residual_vibration_mm, Field().Unit("mm"));
        a->Visit("at_residual_vibration_cam_angle_deg", &at_residual_vibration_cam_angle_deg, Field().Unit("deg"));
        a->Visit("solver_steps", &solver_steps, Field().Desc("CVODE's steps"));
        a->Visit("contact_events", &contact_events, Field().Desc("contact losses and returns over the run"));
      }
    };
    struct ArmResponse {
      double arm_stiffness_N_m_per_rad = 0, damping_ratio = 0;
      int revolutions = 0;
      double natural_frequency_Hz = 0, min_contact_moment_N_m = 0, at_min_contact_moment_cam_angle_deg = 0,
             max_contact_moment_N_m = 0, at_max_contact_moment_cam_angle_deg = 0, min_contact_force_N = 0,
             at_min_contact_force_cam_angle_deg = 0, max_contact_force_N = 0, at_max_contact_force_cam_angle_deg = 0;
      bool separates = false;
      std::optional<double> first_separation_cam_angle_deg;
      double residual_vibration_deg = 0, at_residual_vibration_cam_angle_deg = 0;
      long solver_steps = 0;
      int contact_events = 0;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("arm_stiffness_N_m_per_rad", &arm_stiffness_N_m_per_rad, Field().Unit("N·m/rad").Desc("k_f"));
        a->Visit("damping_ratio", &damping_ratio, Field().Desc("ζ"));
        a->Visit("revolutions", &revolutions, Field().Desc("simulated; the last one's response"));
        a->Visit("natural_frequency_Hz", &natural_frequency_Hz, Field().Unit("Hz"));
        a->Visit("min_contact_moment_N_m", &min_contact_moment_N_m, Field().Unit("N·m").Desc("M_a, about the pivot"));
        a->Visit("at_min_contact_moment_cam_angle_deg", &at_min_contact_moment_cam_angle_deg, Field().Unit("deg"));
        a->Visit("max_contact_moment_N_m", &max_contact_moment_N_m, Field().Unit("N·m"));
        a->Visit("at_max_contact_moment_cam_angle_deg", &at_max_contact_moment_cam_angle_deg, Field().Unit("deg"));
        a->Visit("min_contact_force_N", &min_contact_force_N,
                 Field().Unit("N").Desc("the normal contact force at the cam, M_a over its lever arm"));
        a->Visit("at_min_contact_force_cam_angle_deg", &at_min_contact_force_cam_angle_deg, Field().Unit("deg"));
        a->Visit("max_contact_force_N", &max_contact_force_N, Field().Unit("N"));
        a->Visit("at_max_contact_force_cam_angle_deg", &at_max_contact_force_cam_angle_deg, Field().Unit("deg"));
        a->Visit("separates", &separates, Field().Desc("contact lost in the last revolution"));
        a->Visit("first_separation_cam_angle_deg", &first_separation_cam_angle_deg,
                 Field().NullWhenAbsent().Unit("deg").Desc("where (null: no separation)"));
        a->Visit("residual_vibration_deg", &residual_vibration_deg, Field().Unit("deg"));
        a->Visit("at_residual_vibration_cam_angle_deg", &at_residual_vibration_cam_angle_deg, Field().Unit("deg"));
        a->Visit("solver_steps", &solver_steps, Field().Desc("CVODE's steps"));
        a->Visit("contact_events", &contact_events, Field().Desc("contact losses and returns over the run"));
      }
    };
    /// The search of the dynamic jump speed.
    struct JumpSearch {
      double upper_rpm = 0, scan_step_rpm = 0;
      std::array<double, 2> bracket_rpm{};
      int simulations = 0;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("upper_rpm", &upper_rpm, Field().Unit("rpm").Desc("the highest speed scanned"));
        a->Visit("scan_step_rpm", &scan_step_rpm, Field().Unit("rpm"));
        a->Visit("bracket_rpm", &bracket_rpm, Field().Unit("rpm").Desc("the last bracket of the bisection"));
        a->Visit("simulations", &simulations, Field());
      }
    };
    struct SpectrumMinimum {
      double tau = 0, amplitude_per_rise = 0;
      bool zero = false;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("tau", &tau, Field().Desc("T/T_n"));
        a->Visit("amplitude_per_rise", &amplitude_per_rise, Field().Desc("A/h, the amplitude over the rise, there"));
        a->Visit("zero", &zero, Field().Desc("a zero of the spectrum"));
      }
    };
    struct SpectrumSegment {
      int segment = 0;
      std::string law;
      double tau = 0, amplitude_per_rise = 0, amplitude_error = 0;
      std::optional<double> predicted_residual_vibration_deg, predicted_residual_vibration_mm;
      std::vector<SpectrumMinimum> minima;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("segment", &segment, Field().Desc("its index in motion"));
        a->Visit("law", &law, Field());
        a->Visit("tau", &tau, Field().Desc("the segment's T/T_n at the study's speed"));
        a->Visit("amplitude_per_rise", &amplitude_per_rise, Field().Desc("A/h, the residual amplitude over the segment's rise, at that τ"));
        a->Visit("amplitude_error", &amplitude_error, Field());
        a->Visit("predicted_residual_vibration_deg", &predicted_residual_vibration_deg,
                 Field().Unit("deg").Desc("oscillating: r h (A/h), r the stiffness ratio"));
        a->Visit("predicted_residual_vibration_mm", &predicted_residual_vibration_mm,
                 Field().Unit("mm").Desc("translating: r h (A/h), r the stiffness ratio"));
        a->Visit("minima", &minima, Field().Desc("the spectrum's local minima over tau_range"));
      }
    };
    /// The residual-vibration spectrum of each moving segment (model/disc_cam/residual_spectrum.h).
    struct Spectrum {
      double damping_ratio = 0, stiffness_ratio = 0;
      std::array<double, 2> tau_range{};
      int points = 0;
      std::vector<SpectrumSegment> segments;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("damping_ratio", &damping_ratio, Field().Desc("ζ"));
        a->Visit("stiffness_ratio", &stiffness_ratio, Field().Desc("r = k_f/(k_f + k)"));
        a->Visit("tau_range", &tau_range, Field().Desc("the range of τ = T/T_n of residual_spectrum.csv"));
        a->Visit("points", &points, Field().Desc("τ values over the range"));
        a->Visit("segments", &segments, Field().Desc("one per moving segment"));
      }
    };
    /// The keys dynamics and arm_dynamics share: the loads' extremes, the kinetostatic jump speed,
    /// the Hertz stress, the dynamic jump speed and the residual-vibration spectrum.
    struct Loads {
      double min_contact_force_N = 0, at_min_contact_force_cam_angle_deg = 0, max_contact_force_N = 0,
             at_max_contact_force_cam_angle_deg = 0;
      bool separation_ok = false;
      double max_camshaft_torque_Nm = 0, at_max_camshaft_torque_cam_angle_deg = 0;
      std::array<double, 2> camshaft_torque_range_Nm{};
      double jump_speed_rpm = 0;
      std::optional<double> face_width_mm, composite_modulus_MPa, max_contact_stress_MPa,
          at_max_contact_stress_cam_angle_deg, contact_stress_limit_MPa;
      std::optional<bool> contact_stress_ok;
      std::optional<double> dynamic_jump_speed_rpm;
      std::optional<JumpSearch> dynamic_jump_search;
      std::optional<Spectrum> residual_spectrum;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("min_contact_force_N", &min_contact_force_N, Field().Unit("N").Desc("kinetostatic"));
        a->Visit("at_min_contact_force_cam_angle_deg", &at_min_contact_force_cam_angle_deg, Field().Unit("deg"));
        a->Visit("max_contact_force_N", &max_contact_force_N, Field().Unit("N"));
        a->Visit("at_max_contact_force_cam_angle_deg", &at_max_contact_force_cam_angle_deg, Field().Unit("deg"));
        a->Visit("separation_ok", &separation_ok, Field().Desc("the contact force stays above 0"));
        a->Visit("max_camshaft_torque_Nm", &max_camshaft_torque_Nm, Field().Unit("N·m").Desc("the largest absolute camshaft torque T"));
        a->Visit("at_max_camshaft_torque_cam_angle_deg", &at_max_camshaft_torque_cam_angle_deg, Field().Unit("deg"));
        a->Visit("camshaft_torque_range_Nm", &camshaft_torque_range_Nm, Field().Unit("N·m").Desc("[min, max] of T"));
        a->Visit("jump_speed_rpm", &jump_speed_rpm,
                 Field().NullWhenNotFinite().Unit("rpm").Desc(
                     "kinetostatic: the lowest speed the follower leaves the cam (null: it never decelerates)"));
        a->Visit("face_width_mm", &face_width_mm, Field().Unit("mm").Desc("with the Hertz stress"));
        a->Visit("composite_modulus_MPa", &composite_modulus_MPa, Field().Unit("MPa").Desc("E*, with the Hertz stress"));
        a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa,
                 Field().NullWhenNotFinite().Unit("MPa").Desc(
                     "the peak Hertz stress, with face_width_mm and material (null: loaded at an undercut point or a "
                     "cusp)"));
        a->Visit("at_max_contact_stress_cam_angle_deg", &at_max_contact_stress_cam_angle_deg, Field().Unit("deg"));
        a->Visit("contact_stress_limit_MPa", &contact_stress_limit_MPa,
                 Field().Unit("MPa").Desc("limits.contact_stress_MPa, with the stress"));
        a->Visit("contact_stress_ok", &contact_stress_ok, Field().Desc("the stress within its limit"));
        a->Visit("dynamic_jump_speed_rpm", &dynamic_jump_speed_rpm,
                 Field().NullWhenNotFinite().Unit("rpm").Desc(
                     "with the response: the lowest speed the follower leaves the cam on its stiffness (null: none "
                     "up to dynamic_jump_search.upper_rpm)"));
        a->Visit("dynamic_jump_search", &dynamic_jump_search, Field().Desc("with the response"));
        a->Visit("residual_spectrum", &residual_spectrum,
                 Field().Desc("with the response, when the follower rings (damping_ratio < 1)"));
      }
    };
    /// A translating follower's loads ("dynamics").
    struct Dynamics : Loads {
      double speed_rpm = 0, follower_mass_kg = 0, spring_rate_N_per_mm = 0, spring_preload_N = 0, external_load_N = 0;
      std::string follower_axis;
      double weight_toward_cam_N = 0, min_spring_preload_N = 0, min_spring_rate_N_per_mm = 0;
      std::optional<FollowerResponse> response;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("speed_rpm", &speed_rpm, Field().Unit("rpm"));
        a->Visit("follower_mass_kg", &follower_mass_kg, Field().Unit("kg"));
        a->Visit("spring_rate_N_per_mm", &spring_rate_N_per_mm, Field().Unit("N/mm"));
        a->Visit("spring_preload_N", &spring_preload_N, Field().Unit("N"));
        a->Visit("external_load_N", &external_load_N, Field().Unit("N"));
        a->Visit("follower_axis", &follower_axis, Field().OneOf({"vertical_above_cam", "vertical_below_cam", "horizontal"}));
        a->Visit("weight_toward_cam_N", &weight_toward_cam_N, Field().Unit("N"));
        a->Visit("min_spring_preload_N", &min_spring_preload_N,
                 Field().Unit("N").Desc("the smallest preload that keeps contact up to the speed, with this rate"));
        a->Visit("min_spring_rate_N_per_mm", &min_spring_rate_N_per_mm,
                 Field().NullWhenNotFinite().Unit("N/mm").Desc(
                     "the smallest rate that does, with this preload (null: none does, the deficit is on the base "
                     "circle)"));
        Loads::Serialize(a);
        a->Visit("response", &response,
                 Field().Desc("with follower_stiffness_N_per_mm: the one-degree-of-freedom dynamic response"));
      }
    };
    /// An oscillating follower's loads on its arm ("arm_dynamics").
    struct ArmDynamics : Loads {
      double speed_rpm = 0, arm_inertia_kg_m2 = 0, spring_rate_N_m_per_rad = 0, spring_preload_N_m = 0,
             external_moment_N_m = 0;
      std::optional<double> min_spring_preload_N_m, min_spring_rate_N_m_per_rad;
      std::optional<ArmResponse> response;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("speed_rpm", &speed_rpm, Field().Unit("rpm"));
        a->Visit("arm_inertia_kg_m2", &arm_inertia_kg_m2, Field().Unit("kg·m²"));
        a->Visit("spring_rate_N_m_per_rad", &spring_rate_N_m_per_rad, Field().Unit("N·m/rad"));
        a->Visit("spring_preload_N_m", &spring_preload_N_m, Field().Unit("N·m"));
        a->Visit("external_moment_N_m", &external_moment_N_m, Field().Unit("N·m"));
        a->Visit("min_spring_preload_N_m", &min_spring_preload_N_m,
                 Field().Unit("N·m").Desc("a roller or knife edge: the smallest M₀ that keeps contact up to the speed, "
                                          "with this rate"));
        a->Visit("min_spring_rate_N_m_per_rad", &min_spring_rate_N_m_per_rad,
                 Field().NullWhenNotFinite().Unit("N·m/rad").Desc(
                     "a roller or knife edge: the smallest rate that does, with this M₀ (null: none does)"));
        Loads::Serialize(a);
        a->Visit("response", &response,
                 Field().Desc("with arm_stiffness_N_m_per_rad: the arm's one-degree-of-freedom dynamic response"));
      }
    };
    /// The limits of the verdict.
    struct Limits {
      std::optional<double> pressure_angle_deg;
      double radius_margin_mm = 0;
      std::vector<std::string> defaults;
      std::optional<double> face_width_mm, min_contact_force_N, contact_stress_MPa;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("pressure_angle_deg", &pressure_angle_deg, Field().Unit("deg").Desc("not for a translating flat face"));
        a->Visit("radius_margin_mm", &radius_margin_mm, Field().Unit("mm"));
        a->Visit("defaults", &defaults, Field().Desc("the limits the study did not give (their defaults apply)"));
        a->Visit("face_width_mm", &face_width_mm, Field().Unit("mm").Desc("a flat face's width, when given"));
        a->Visit("min_contact_force_N", &min_contact_force_N, Field().Unit("N").Desc("with the loads: 0"));
        a->Visit("contact_stress_MPa", &contact_stress_MPa, Field().Unit("MPa").Desc("when given"));
      }
    };
    /// The motion program: its joints and peak derivatives, in the follower's unit (mm or deg) per rad^k.
    struct Motion {
      std::vector<JointRow> joints;
      std::optional<double> peak_velocity_mm_per_rad, peak_velocity_deg_per_rad, peak_acceleration_mm_per_rad2,
          peak_acceleration_deg_per_rad2, peak_jerk_mm_per_rad3, peak_jerk_deg_per_rad3;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("joints", &joints, Field().Desc("the motion program's joints and their continuity"));
        a->Visit("peak_velocity_mm_per_rad", &peak_velocity_mm_per_rad, Field().Unit("mm/rad").Desc("translating"));
        a->Visit("peak_velocity_deg_per_rad", &peak_velocity_deg_per_rad, Field().Unit("deg/rad").Desc("oscillating"));
        a->Visit("peak_acceleration_mm_per_rad2", &peak_acceleration_mm_per_rad2, Field().Unit("mm/rad²").Desc("translating"));
        a->Visit("peak_acceleration_deg_per_rad2", &peak_acceleration_deg_per_rad2,
                 Field().Unit("deg/rad²").Desc("oscillating"));
        a->Visit("peak_jerk_mm_per_rad3", &peak_jerk_mm_per_rad3, Field().Unit("mm/rad³").Desc("translating"));
        a->Visit("peak_jerk_deg_per_rad3", &peak_jerk_deg_per_rad3, Field().Unit("deg/rad³").Desc("oscillating"));
      }
    };
    /// The Monte-Carlo check of the linearised error, or why it was skipped.
    struct MonteCarlo {
      std::optional<int> samples, angle_steps;
      std::optional<uint64_t> seed;
      std::optional<std::string> distribution;
      std::optional<std::vector<MonteCarloRow>> scales;
      std::optional<std::string> skipped;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("samples", &samples, Field().Desc("per tolerance scale"));
        a->Visit("angle_steps", &angle_steps, Field().Desc("cam angles per sample"));
        a->Visit("seed", &seed, Field());
        a->Visit("distribution", &distribution, Field());
        a->Visit("scales", &scales, Field().Desc("one per tolerance scale"));
        a->Visit("skipped", &skipped, Field().Desc("why it was not run (then the only key)"));
      }
    };

    std::string study = "disc_cam", name, follower;
    int angle_steps = 0;
    double max_radial_dimension_mm = 0, max_radial_dimension_at_cam_angle_deg = 0, min_radial_dimension_mm = 0;
    PressureAngle pressure_angle_deg;
    std::optional<std::vector<std::string>> warnings;
    std::optional<FlatFace> flat_face;
    std::optional<MinMax> shift_angle_deg, cos_shift_over_cos_pressure;
    /// null (NaN): no convex (concave) part.
    std::optional<double> min_radius_of_curvature_mm, min_radius_of_curvature_at_cam_angle_deg,
        min_concave_radius_of_curvature_mm, min_concave_radius_at_cam_angle_deg;
    std::optional<double> radius_margin_limit_mm;
    std::optional<bool> radius_margin_ok, undercut;
    std::optional<std::vector<std::array<double, 2>>> undercut_cam_angle_deg;
    std::optional<std::vector<std::string>> evaluated;
    std::optional<Tolerances> tolerances_um;
    std::optional<WorstCase> worst_case_error_um;
    std::optional<Peak> rms_error_um, worst_case_error_arcsec;
    std::optional<ErrorComponents> error_components_um;
    std::optional<Max> rms_error_arcsec;
    std::optional<ArmDynamics> arm_dynamics;
    std::optional<Dynamics> dynamics;
    Limits limits;
    bool limits_ok = false;
    Motion motion;
    std::optional<MonteCarlo> monte_carlo;
    GeometryFilesBlock geometry_files;
    std::optional<InspectionBlock> inspection;
    std::optional<DiscCamMeasured> measured;
    std::optional<std::vector<std::string>> notes;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("study", &study, Field().Const("disc_cam"));
      a->Visit("name", &name, Field().Desc("the design's name"));
      a->Visit("follower", &follower, Field().Desc("the follower's type, as in the study"));
      a->Visit("angle_steps", &angle_steps, Field().Desc("cam angles of the analysis grid"));
      a->Visit("max_radial_dimension_mm", &max_radial_dimension_mm, Field().Unit("mm").Desc("the profile's largest radius"));
      a->Visit("max_radial_dimension_at_cam_angle_deg", &max_radial_dimension_at_cam_angle_deg, Field().Unit("deg"));
      a->Visit("min_radial_dimension_mm", &min_radial_dimension_mm, Field().Unit("mm").Desc("the profile's smallest radius"));
      a->Visit("pressure_angle_deg", &pressure_angle_deg, Field().Desc("φ over the cycle and against its limit"));
      a->Visit("warnings", &warnings, Field().Desc("a pressure angle above the warning limit"));
      a->Visit("flat_face", &flat_face, Field().Desc("a flat-faced follower: the contact on the face and the profile's convexity"));
      a->Visit("shift_angle_deg", &shift_angle_deg, Field().Unit("deg").Desc("a roller or knife edge"));
      a->Visit("cos_shift_over_cos_pressure", &cos_shift_over_cos_pressure, Field().Desc("a roller or knife edge"));
      a->Visit("min_radius_of_curvature_mm", &min_radius_of_curvature_mm,
               Field().NullWhenNotFinite().Unit("mm").Desc(
                   "a roller or knife edge: the profile's smallest convex radius of curvature (null: no convex part)"));
      a->Visit("min_radius_of_curvature_at_cam_angle_deg", &min_radius_of_curvature_at_cam_angle_deg,
               Field().NullWhenNotFinite().Unit("deg"));
      a->Visit("min_concave_radius_of_curvature_mm", &min_concave_radius_of_curvature_mm,
               Field().NullWhenNotFinite().Unit("mm").Desc("a roller or knife edge: the smallest concave radius (null: "
                                                           "no concave part)"));
      a->Visit("min_concave_radius_at_cam_angle_deg", &min_concave_radius_at_cam_angle_deg,
               Field().NullWhenNotFinite().Unit("deg"));
      a->Visit("radius_margin_limit_mm", &radius_margin_limit_mm,
               Field().Unit("mm").Desc("a roller or knife edge: limits.radius_margin_mm"));
      a->Visit("radius_margin_ok", &radius_margin_ok,
               Field().Desc("a roller or knife edge: the smallest convex radius at least the margin (no convex part: true)"));
      a->Visit("undercut", &undercut, Field().Desc("a roller or knife edge: the profile is undercut somewhere"));
      a->Visit("undercut_cam_angle_deg", &undercut_cam_angle_deg, Field().Unit("deg").Desc("[from, to] where it is"));
      a->Visit("evaluated", &evaluated, Field().Desc("the stages run, when analysis.evaluate is given"));
      a->Visit("tolerances_um", &tolerances_um, Field().Desc("with the mechanical error: the tolerances"));
      a->Visit("worst_case_error_um", &worst_case_error_um,
               Field().Unit("µm").Desc("with the mechanical error: the worst case at the roller centre (eq. 31)"));
      a->Visit("rms_error_um", &rms_error_um, Field().Unit("µm").Desc("with the mechanical error: the RMS (eq. 32)"));
      a->Visit("error_components_um", &error_components_um, Field().Unit("µm").Desc("with the mechanical error"));
      a->Visit("worst_case_error_arcsec", &worst_case_error_arcsec,
               Field().Unit("arcsec").Desc("oscillating, with the mechanical error: of the arm angle"));
      a->Visit("rms_error_arcsec", &rms_error_arcsec, Field().Unit("arcsec").Desc("oscillating, with the mechanical error"));
      a->Visit("arm_dynamics", &arm_dynamics, Field().Desc("with arm_dynamics: the arm's loads"));
      a->Visit("dynamics", &dynamics, Field().Desc("with dynamics: the follower's loads"));
      a->Visit("limits", &limits, Field().Desc("the verdict's limits"));
      a->Visit("limits_ok", &limits_ok, Field().Desc("every limit met"));
      a->Visit("motion", &motion, Field());
      a->Visit("monte_carlo", &monte_carlo, Field().Desc("with the Monte-Carlo stage"));
      a->Visit("geometry_files", &geometry_files, Field().Desc("the cam's geometry files (profile), or why none"));
      a->Visit("inspection", &inspection, Field().Desc("with inspection: its points, files and datum"));
      a->Visit("measured", &measured,
               Field().Desc("with measured_profile: the measured cam's deviation and its follower error"));
      a->Visit("notes", &notes, Field().Desc("what was not computed or checked, and why"));
    }
  };
  Json json;
  template <typename Archive>
  void Serialize(Archive* a) {
    json.Serialize(a);
  }
};

/// How the motion's rise is written for a follower (ParseMotionProgram): a length for a
/// translating, an angle for an oscillating one; durations in degrees; polynomial segments.
MotionInputSpec FollowerMotionSpec(bool oscillating);

/// The motion's unit by the follower's type (FollowerRiseRule for translating and oscillating
/// followers): the schema rules of every kind with a disc-cam follower and its "motion".
nlohmann::ordered_json FollowerMotionRules();

/// The schema condition "the study's follower.type is one of `types`" (for an if/then rule).
nlohmann::ordered_json FollowerTypeIs(const std::vector<std::string>& types);

/// The schema "the object does not give `field`" (a rule's refusal).
nlohmann::ordered_json Refuse(const std::string& field);

/// The rules of the design's fields by the follower's type that disc_cam and disc_cam_min_size
/// share (the motion's unit, a cutter path and a contact-stress limit by the contact, the loads
/// by the follower's motion, the inputs of the contact-stress limit, a keyway's bore), as the
/// items of an allOf.
nlohmann::ordered_json DesignSchemaRules();

/// The cam as inspected: its exact profile as a function of the cam angle θ in the frame of
/// profile.dxf, the frame and datum in words.
InspectedPart CamPart(const Study& study);

/// Parses and validates a "disc_cam" study. @throws StudyError (exit 2) naming the JSON path.
Study Parse(const Node& root);
/// Evaluates the cam over the analysis grid, the mechanical error and the Monte-Carlo check, and
/// fills result.json's members (Result::json).
Result Run(const Study& study, const RunContext& ctx);
/// result.json, series.csv, the SVG plots, profile.svg and profile.dxf.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::disc_cam
