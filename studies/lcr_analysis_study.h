// Study kind "lcr_analysis": one lobe cam reducer over an input revolution. Parse reads the study
// file into a Study, Run calls the LCR stages of model/lcr/ that the study asks for and fills the
// declared result.json (Result::Json), Write writes it with series.csv, SVG plots and DXF profiles.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/common/bearing_life.h"
#include "model/common/catalogue_ratings.h"
#include "model/common/material.h"
#include "model/lcr/contact3d_cycle.h"
#include "model/lcr/cycle.h"
#include "model/lcr/life.h"
#include "studies/archive.h"
#include "studies/contact_fatigue_input.h"
#include "studies/lcr_contact_input.h"
#include "studies/input.h"
#include "studies/geometry_files.h"
#include "studies/lcr_input.h"
#include "studies/lcr_tolerance_input.h"
#include "studies/lubrication_input.h"
#include "model/lcr/lubrication.h"
#include "studies/material_input.h"
#include "studies/ratings.h"
#include "studies/ratings_input.h"
#include "studies/measured_profile.h"
#include "studies/study.h"
#include "studies/torsional_dynamics_input.h"
#include "studies/writers.h"

namespace camopt::studies::lcr_analysis {

/// The study file as declared: each field once, in the file's units, with its default, bounds and
/// description (studies/archive.h); the blocks shared with the other LCR kinds are those of
/// studies/lcr_input.h, lcr_contact_input.h, lcr_tolerance_input.h and material_input.h. Parse
/// reads it, checks what spans fields and converts it (Study); `camopt schema lcr_analysis` is
/// emitted from it.
struct Input {
  struct Load {
    double output_torque_Nm = 0, friction_coefficient = 0, cam_weight_N = 0;
    std::optional<double> input_speed_rpm;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("output_torque_Nm", &output_torque_Nm,
               Field().Required().NonNegative().Unit("N·m").Desc("T_o, the output torque"));
      a->Visit("friction_coefficient", &friction_coefficient,
               Field().In(0.0, 1.0).Desc("μ of the eccentric, T_in = (F_t + μ F_r) e (the paper's eq. 32)"));
      a->Visit("cam_weight_N", &cam_weight_N, Field().NonNegative().Unit("N").Desc("W_c, the cam's weight along −y"));
      a->Visit("input_speed_rpm", &input_speed_rpm,
               Field().Positive().Unit("rpm").Desc(
                   "input speed: the bearing lives at the load's torque (a one-line duty cycle; docs/life.md); not "
                   "with duty_cycle"));
    }
  };
  struct Limits : LubricationLimitsInput {
    std::optional<double> contact_stress_MPa, roller_load_N;
    double undercut_margin_mm = 0, roller_gap_mm = 0;
    std::optional<double> life_h;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("contact_stress_MPa", &contact_stress_MPa,
               Field().Positive().Unit("MPa").Desc("allowable contact stress: adds the cams' contact_stress_ok"));
      a->Visit("roller_load_N", &roller_load_N,
               Field().Positive().Unit("N").Desc("the rollers' bearing limit: adds the cams' roller_load_ok"));
      a->Visit("undercut_margin_mm", &undercut_margin_mm,
               Field().NonNegative().Unit("mm").Desc(
                   "smallest margin of the cam's convex radius of curvature over the roller radius (the report's "
                   "verdict)"));
      a->Visit("roller_gap_mm", &roller_gap_mm,
               Field().NonNegative().Unit("mm").Desc("smallest gap between neighbouring rollers (the report's verdict)"));
      a->Visit("life_h", &life_h,
               Field().Positive().Unit("h").Desc(
                   "required life: pass/fail of each life of life.table (bearings, sliced rollers, cam contacts); "
                   "needs a speed"));
      VisitLubricationLimits(a);
    }
  };
  struct Analysis {
    int angle_steps = 3600, profile_points = 3600;
    std::optional<std::vector<std::string>> evaluate;
    std::string load_model = "rigid";
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("angle_steps", &angle_steps, Field().AtLeast(12).Desc("samples of the input revolution"));
      a->Visit("profile_points", &profile_points, Field().AtLeast(100).Desc("points of the drawn and DXF profiles"));
      a->Visit("evaluate", &evaluate,
               Field().OneOf({"profile", "undercut", "forces", "stress", "efficiency"},
                             "one of profile, undercut, forces, stress, efficiency")
                   .Default(nlohmann::json::array({"profile", "undercut", "forces", "stress", "efficiency"}))
                   .Desc("the stages to run (stress and efficiency include forces; profile and undercut need no "
                         "material or load)"));
      a->Visit("load_model", &load_model,
               Field().OneOf({"rigid", "compliant"}).Desc(
                   "load sharing among the rollers: rigid (the paper's law F ∝ arm) or compliant (Palmgren contacts "
                   "of the stiffness model; needs a torque > 0)"));
    }
  };

  std::string study = "lcr_analysis", name;
  std::optional<std::string> description;
  LcrRatedReducerInput reducer;
  std::optional<MaterialWithFatigueInput> material;
  std::optional<Load> load;
  std::optional<Limits> limits;
  std::optional<Analysis> analysis;
  std::optional<LcrTolerancesInput> tolerances;
  std::optional<LcrMonteCarloInput> monte_carlo;
  GeometryFiles geometry_files = true;
  std::optional<LcrContactOptionsInput> contact;
  LcrDutyCycleInput duty_cycle;
  std::optional<LubricantWithContaminationInput> lubricant;
  std::optional<SurfacesInput> surfaces;
  std::optional<LcrBearingFrictionInput> bearing_friction;
  std::optional<EfficiencyMapInput> efficiency_map;
  struct Stiffness : StiffnessCatalogueInput {
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("rated_torque_Nm", &rated_torque_Nm,
               Field().Required().Positive().Unit("N·m").Desc("T_r at the output (the input held)"));
      VisitCatalogue(a);
    }
  };
  std::optional<Stiffness> stiffness;
  std::optional<RatingsInput> ratings;
  std::optional<OutputBearingInput> output_bearing;
  std::optional<std::vector<ExternalLoadInput>> external_loads;
  std::optional<TorsionalDynamicsInput> torsional_dynamics;
  /// The part names of "measured_profile": the two cams (their geometry files' stems and frames).
  struct Parts {
    static std::vector<std::string> Names() { return {"input_cam", "output_cam"}; }
    static std::string Description() {
      return "the measured cam, input_cam or output_cam (the frame of its DXF: origin at the cam's centre)";
    }
  };
  std::optional<InspectionInput> inspection;
  std::optional<MeasuredProfileInputT<Parts>> measured_profile;

  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Required().Const("lcr_analysis").Desc("the study kind"));
    a->Visit("name", &name, Field().Desc("the design's name, in titles"));
    a->Visit("description", &description, Field().Desc("free text"));
    a->Visit("reducer", &reducer, Field().Required().Desc("the lobe cam reducer's design"));
    a->Visit("material", &material,
             Field().Desc("the cams' and rollers' elastic material (required by the stress stage, the compliant load "
                          "model and the tolerances)"));
    a->Visit("load", &load,
             Field().Desc("the load (required by the force stages forces, stress, efficiency, the compliant load "
                          "model and the tolerances)"));
    a->Visit("limits", &limits, Field().Desc("the verdict's limits (report.html, the summary, --strict)"));
    a->Visit("analysis", &analysis, Field().Desc("the angle grid, the stages and the load model"));
    a->Visit("tolerances", &tolerances,
             Field().Desc("± tolerance bands: the transmission error and lost motion (docs/lcr.md)"));
    a->Visit("monte_carlo", &monte_carlo, Field().Desc("the Monte-Carlo of the transmission error (with tolerances)"));
    a->Visit("geometry_files", &geometry_files,
             Field().Desc(
                 "geometry files (docs/studies.md 'Geometry files'); false: none at all (no arc fit, no DXF/STEP/STL)"));
    a->Visit("contact", &contact, Field().Desc("finite-length roller contact model (docs/lcr.md)"));
    a->Visit("duty_cycle", &duty_cycle,
             Field().MinItems(1, kDutyCycleNotEmpty).Desc(
                 "lines of the duty cycle for the bearing lives (docs/life.md); the time shares sum to 1 within "
                 "1e-6, at least one speed > 0"));
    a->Visit("lubricant", &lubricant,
             Field().Desc("the oil: the lubricated losses, efficiency and oil temperature (docs/lubrication.md; "
                          "needs load.input_speed_rpm)"));
    a->Visit("surfaces", &surfaces, Field().Desc("roughness, friction by regime and the rollers' mounting (with lubricant)"));
    a->Visit("bearing_friction", &bearing_friction,
             Field().Desc("Palmgren's factors of the rollers' and the eccentric's bearings (with lubricant; a bearing "
                          "not given adds no loss and is listed as not modelled)"));
    a->Visit("efficiency_map", &efficiency_map,
             Field().Desc("efficiency_map.csv: efficiency, loss and oil temperature over torques × speeds (with "
                          "lubricant)"));
    a->Visit("stiffness", &stiffness,
             Field().Desc("the torsional curve, input held, mean over the input revolution (docs/lcr_stiffness.md): "
                          "catalogue stiffness, three segments, lost motion (docs/ratings.md)"));
    a->Visit("ratings", &ratings,
             Field().Desc("the catalogue's ratings: rated torque for a rated life at a rated output speed, peak torque "
                          "from the contact limits, momentary torque from the static ratings (docs/ratings.md; the "
                          "rollers' ratings of reducer.input and reducer.output)"));
    VisitOutputBearing(a, &output_bearing, &external_loads);
    a->Visit("torsional_dynamics", &torsional_dynamics,
             Field().Desc("the reducer's torsional dynamics from the tangent torsional stiffness of the rollers' "
                          "Palmgren contacts (docs/torsional_dynamics.md): natural frequencies, mode shapes, the "
                          "dynamic transmission error and overload over an input-speed sweep, resonance speeds; "
                          "mesh_stiffness.csv, dynamic_te.csv (needs material and a load torque > 0)"));
    a->Visit("inspection", &inspection,
             Field().Desc("inspection points of each cam's exact profile with the ISO 1101 profile tolerance zone: "
                          "inspection/input_cam.csv, inspection/output_cam.csv (docs/studies.md, \"Inspection points "
                          "and measured parts\"; none when geometry_files is false)"));
    a->Visit("measured_profile", &measured_profile,
             Field().Desc("a measured cam back in: its ISO 1101 profile deviation and the transmission error and lost "
                          "motion of the compliant model as measured beside the nominal (docs/studies.md, "
                          "\"Inspection points and measured parts\"; needs material and a load torque > 0)"));
  }
  /// The stages' needs (material, load), the life's ratings, one form of the speed.
  static nlohmann::ordered_json SchemaRules();
  /// The torque against the material, the duty cycle and the external loads.
  static std::vector<CrossFieldRule> CrossFieldRules() {
    std::vector<CrossFieldRule> rules = ExternalLoadsRules();
    rules.push_back(DutyCycleRule());
    rules.push_back({{"material", "load", "reducer"},
             "the torque within what the output rollers carry at the material's Young's modulus (a soft material "
             "carries less)",
             "a torque the output rollers can carry"});
    return rules;
  }
};

/// The stages a study asks for ("analysis.evaluate"); stress and efficiency imply forces.
struct Evaluate {
  bool profile = true, undercut = true, forces = true, stress = true, efficiency = true;
};

/// A bearing's load ratings: C (ISO 281) and, when given, C0 (ISO 76; 0 when not given).
struct BearingRating {
  double dynamic_N = 0.0, static_N = 0.0;
  BearingKind kind = BearingKind::kRoller;
  std::optional<ModifiedLifeRating> modified;  ///< C_u and D_pw of the modified life a_ISO, when given
};

/// One line of the duty cycle, in model units (studies/lcr_input.h ParseDutyCycle).
using DutyLine = lcr::LcrDutyLine;

/// The bearing life asked by "load.input_speed_rpm" (one line at the load's torque) or
/// "duty_cycle" (docs/life.md).
struct LifeSpec {
  std::vector<DutyLine> lines;  ///< time shares normalised to sum to 1
  bool from_duty_cycle = false;
  BearingRating input_roller, output_roller;
  std::optional<BearingRating> eccentric;  ///< "reducer.eccentric_bearing"
  /// "lubricant.contamination_factor" e_C: given when some bearing has C_u and D_pw (a_ISO).
  std::optional<double> contamination_factor;
};

/// What the study file says, parsed and validated, in model units (mm, N, N·mm, MPa).
struct Study {
  std::string name;
  lcr::Reducer<double> reducer;
  Material material;
  lcr::LoadCase load;
  int angle_steps = 3600;     ///< input angles over one revolution
  int profile_points = 3600;  ///< points per drawn curve
  Evaluate evaluate;
  double contact_stress_limit_MPa = kInf;  ///< kInf: no limit given
  double roller_load_limit_N = kInf;
  double cutter_radius_input_mm = 0, cutter_radius_output_mm = 0;  ///< half the cutter diameters
  bool cutter_input_given = false, cutter_output_given = false;      ///< a cutter other than the roller
  double bore_diameter_input_mm = 0, bore_diameter_output_mm = 0;    ///< 0: no bore in the solids
  Mounting mounting_input, mounting_output;                          ///< keyway and bolt circle of each cam
  GeometryFileOptions geometry;                                      ///< "geometry_files"
  LcrContactInput contact;  ///< "contact" and the rollers' "crowning"
  lcr::LoadModel load_model = lcr::LoadModel::kRigid;  ///< "analysis.load_model"
  std::optional<LcrToleranceSpec> tolerances;          ///< "tolerances" + "monte_carlo"
  std::optional<LifeSpec> life;                        ///< a speed or a duty cycle given
  /// "material.contact_fatigue": the cams' contact lives (needs a speed or a duty cycle).
  std::optional<ContactFatigueSpec> contact_fatigue;
  double life_limit_h = 0;  ///< "limits.life_h" (0: none): pass/fail of each life in the table
  /// "lubricant" (docs/lubrication.md): the lubricated losses at the load's torque and speed.
  struct Lubrication {
    LubricationCommon common;
    lcr::LubricationSpec spec;
    bool rollers_bearing_given = false, eccentric_bearing_given = false;
  };
  std::optional<Lubrication> lubrication;
  /// "stiffness": the torsional curve's rated torque, T1, T2 and the lost motion's percentage.
  struct StiffnessSpec {
    double rated_torque_Nm = 0, T1_Nm = 0, T2_Nm = 0, lost_motion_percent = 3.0;
  };
  std::optional<StiffnessSpec> stiffness;
  /// "ratings" with the rollers' (and the eccentric's) ratings and the peak limits.
  struct RatingsSpec {
    RatingsInput in;
    LifeSpec life;  ///< lines set per trial torque
    PeakLimits limits;
  };
  std::optional<RatingsSpec> ratings;
  double density_kg_m3 = 7850.0;  ///< "ratings.density_kg_m3" (steel when absent)
  std::optional<OutputBearingInput> output_bearing;
  std::vector<ExternalLoadInput> external_loads;
  /// "torsional_dynamics" (studies/torsional_dynamics_input.h); nullopt: none.
  std::optional<TorsionalDynamicsSpec> torsional;
  std::optional<InspectionInput> inspection;  ///< "inspection"
  /// "measured_profile": the cam and its measurement projected onto its exact profile.
  lcr::Side measured_side = lcr::Side::kInput;
  std::optional<MeasuredProfile> measured;
};

/// The rating life of one bearing over the duty cycle (model/common/bearing_life.h, model/lcr/life.h).
struct BearingLifeResult {
  std::string name;  ///< input_roller, output_roller, eccentric_bearing
  BearingRating rating;
  double revolutions_per_input_revolution = 0;
  double mean_speed_rpm = 0;          ///< Σ t_i n_i × revolutions per input revolution
  double equivalent_load_N = 0;       ///< P of the duty cycle (revolution-weighted p-mean)
  std::vector<double> line_equivalent_load_N;  ///< P_i per duty-cycle line
  double max_load_N = 0;              ///< largest load of any line (P0 of s0)
  double L10_Mrev = 0, L10h = 0;      ///< +inf without load
  double s0 = 0;                      ///< C0 / P0max; 0 when C0 is not given, +inf without load
  /// The sliced life under the 3D contact's tilt and crowning (a roller with a "contact" model
  /// other than line; model/common/sliced_bearing_life.h, model/lcr/sliced_life.h).
  struct Sliced {
    double L10h = 0;
    int slices = 0;
    double slice_rating_N = 0, weibull_slope = 0;
    double worst_slice_y_mm = 0, worst_slice_L10h = 0;
    std::vector<double> slice_equivalent_load_N;  ///< first duty line's P per slice (the load's shape)
    bool converged = true, edge_loaded = false;
  };
  std::optional<Sliced> sliced;
};

/// The contact life of one cam's track over the duty cycle (model/lcr/contact_fatigue.h).
struct CamContactLifeResult {
  std::string name;  ///< input_cam_contact, output_cam_contact
  double passes_per_input_revolution = 0;     ///< N_c = n ψ'
  std::vector<double> line_peak_pressure_MPa; ///< the cam's peak pressure per duty-cycle line
  double equivalent_pressure_MPa = 0;         ///< p_eq (Miner-equivalent at the mean speed)
  double L10h = 0;                            ///< +inf without load
};

struct LifeResult {
  std::vector<BearingLifeResult> bearings;
  std::vector<CamContactLifeResult> cam_contacts;  ///< with material.contact_fatigue
  double shortest_L10h = 0;
  std::string shortest;  ///< name of the bearing with the shortest life
  double mean_input_speed_rpm = 0;
  double efficiency_energy_mean = 0;  ///< output energy / input energy over the duty cycle
  std::vector<double> line_mean_input_torque_Nm;
  /// The oil at the lubricated operating point, when some bearing's modified life a_ISO is asked.
  std::optional<ModifiedLifeOil> oil;
};

/// result.json's "life" (docs/life.md): the bearings' lives over the duty cycle, each bearing's
/// block (with its sliced life under the 3D contact's tilt), the cams' contact lives, the table.
struct LifeBlock {
  /// A duty-cycle line as given, with the line's mean input torque.
  struct DutyLine : DutyCycleEcho {
    double mean_input_torque_Nm = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      DutyCycleEcho::Serialize(a);
      a->Visit("mean_input_torque_Nm", &mean_input_torque_Nm, Field().NullWhenNotFinite().Unit("N·m"));
    }
  };
  /// A roller rated by slices (ISO/TS 16281's idea) under the contact model's tilt and crowning.
  struct Sliced {
    double L10h = 0;
    int slices = 0;
    double misalignment_mrad = 0, slice_rating_N = 0, weibull_slope = 0, worst_slice_y_mm = 0, worst_slice_L10h = 0;
    std::vector<double> slice_equivalent_load_N;
    bool edge_loaded = false, converged = true;
    std::string model;
    template <typename Archive>
    void Serialize(Archive* a) {
      const Field n = Field().NullWhenNotFinite();
      a->Visit("L10h", &L10h, Field(n).Unit("h").Desc("null: unlimited"));
      a->Visit("slices", &slices, Field());
      a->Visit("misalignment_mrad", &misalignment_mrad, Field(n).Unit("mrad"));
      a->Visit("slice_rating_N", &slice_rating_N, Field(n).Unit("N").Desc("C (w/L)^(7/9)"));
      a->Visit("weibull_slope", &weibull_slope, Field(n));
      a->Visit("worst_slice_y_mm", &worst_slice_y_mm, Field(n).Unit("mm"));
      a->Visit("worst_slice_L10h", &worst_slice_L10h, Field(n).Unit("h"));
      a->Visit("slice_equivalent_load_N", &slice_equivalent_load_N,
               Field(n).Unit("N").Desc("the first duty line's P per slice"));
      a->Visit("edge_loaded", &edge_loaded, Field());
      a->Visit("converged", &converged, Field());
      a->Visit("model", &model, Field());
    }
  };
  /// One bearing's life over the duty cycle.
  struct Bearing {
    std::string kind;
    double life_exponent = 0, dynamic_rating_N = 0;
    std::optional<double> static_rating_N, s0;
    double revolutions_per_input_revolution = 0, mean_speed_rpm = 0, equivalent_load_N = 0;
    std::vector<double> line_equivalent_load_N;
    double max_load_N = 0, L10_Mrev = 0, L10h = 0;
    std::optional<Sliced> sliced;
    template <typename Archive>
    void Serialize(Archive* a) {
      const Field n = Field().NullWhenNotFinite();
      a->Visit("kind", &kind, Field().OneOf({"ball", "roller"}));
      a->Visit("life_exponent", &life_exponent, Field(n).Desc("p"));
      a->Visit("dynamic_rating_N", &dynamic_rating_N, Field(n).Unit("N").Desc("C"));
      a->Visit("static_rating_N", &static_rating_N, Field(n).Unit("N").Desc("C0, when given"));
      a->Visit("s0", &s0, Field(n).Desc("C0 / largest load, with C0 (null: no load)"));
      a->Visit("revolutions_per_input_revolution", &revolutions_per_input_revolution, Field(n));
      a->Visit("mean_speed_rpm", &mean_speed_rpm, Field(n).Unit("rpm"));
      a->Visit("equivalent_load_N", &equivalent_load_N, Field(n).Unit("N"));
      a->Visit("line_equivalent_load_N", &line_equivalent_load_N, Field(n).Unit("N"));
      a->Visit("max_load_N", &max_load_N, Field(n).Unit("N"));
      a->Visit("L10_Mrev", &L10_Mrev, Field(n).Unit("Mrev"));
      a->Visit("L10h", &L10h, Field(n).Unit("h").Desc("null: unlimited"));
      a->Visit("sliced", &sliced, Field().Desc("with a 3D contact model: the roller rated by slices"));
    }
  };
  /// One cam's contact life (material.contact_fatigue).
  struct CamContact {
    double contacts_per_input_revolution = 0;
    std::vector<double> line_peak_pressure_MPa;
    double equivalent_pressure_MPa = 0, L10h = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      const Field n = Field().NullWhenNotFinite();
      a->Visit("contacts_per_input_revolution", &contacts_per_input_revolution, Field(n));
      a->Visit("line_peak_pressure_MPa", &line_peak_pressure_MPa, Field(n).Unit("MPa"));
      a->Visit("equivalent_pressure_MPa", &equivalent_pressure_MPa, Field(n).Unit("MPa"));
      a->Visit("L10h", &L10h, Field(n).Unit("h").Desc("null: unlimited"));
    }
  };
  struct ContactLife {
    double reference_pressure_MPa = 0, reference_cycles = 0, exponent = 0;
    std::string exponent_source, pressure_model;
    std::optional<CamContact> input_cam_contact, output_cam_contact;
    std::string model;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("reference_pressure_MPa", &reference_pressure_MPa, Field().Unit("MPa"));
      a->Visit("reference_cycles", &reference_cycles, Field());
      a->Visit("exponent", &exponent, Field().Desc("n of N = N_ref (p_ref/p0)^n"));
      a->Visit("exponent_source", &exponent_source, Field());
      a->Visit("pressure_model", &pressure_model, Field());
      a->Visit("input_cam_contact", &input_cam_contact, Field());
      a->Visit("output_cam_contact", &output_cam_contact, Field());
      a->Visit("model", &model, Field());
    }
  };
  double shortest_L10h = 0;
  std::string shortest_bearing;
  double input_roller_L10h = 0, output_roller_L10h = 0;
  std::optional<double> eccentric_bearing_L10h, input_roller_sliced_L10h, output_roller_sliced_L10h;
  double mean_input_speed_rpm = 0, efficiency_energy_mean = 0;
  std::vector<DutyLine> duty_cycle;
  Bearing input_roller, output_roller;
  std::optional<Bearing> eccentric_bearing;
  std::string model;
  std::optional<double> input_cam_contact_L10h, output_cam_contact_L10h;
  std::optional<ContactLife> contact_life;
  std::optional<double> life_h;
  std::vector<LifeTableRow> table;
  std::optional<double> shortest_L_nm_h;
  std::optional<std::variant<std::string, std::nullptr_t>> shortest_L_nm_bearing;  ///< with a lubricant
  template <typename Archive>
  void Serialize(Archive* a) {
    const Field hours = Field().NullWhenNotFinite().Unit("h");
    a->Visit("shortest_L10h", &shortest_L10h, Field(hours).Desc("of the bearings (null: unlimited)"));
    a->Visit("shortest_bearing", &shortest_bearing, Field());
    a->Visit("input_roller_L10h", &input_roller_L10h, Field(hours).Desc("null: unlimited"));
    a->Visit("output_roller_L10h", &output_roller_L10h, Field(hours).Desc("null: unlimited"));
    a->Visit("eccentric_bearing_L10h", &eccentric_bearing_L10h, Field(hours).Desc("with its rating (null: unlimited)"));
    a->Visit("input_roller_sliced_L10h", &input_roller_sliced_L10h, Field(hours).Desc("with a 3D contact model"));
    a->Visit("output_roller_sliced_L10h", &output_roller_sliced_L10h, Field(hours).Desc("with a 3D contact model"));
    a->Visit("mean_input_speed_rpm", &mean_input_speed_rpm, Field().NullWhenNotFinite().Unit("rpm"));
    a->Visit("efficiency_energy_mean", &efficiency_energy_mean,
             Field().NullWhenNotFinite().Desc("output energy / input energy over the duty cycle"));
    a->Visit("duty_cycle", &duty_cycle, Field());
    a->Visit("input_roller", &input_roller, Field());
    a->Visit("output_roller", &output_roller, Field());
    a->Visit("eccentric_bearing", &eccentric_bearing, Field().Desc("with its rating"));
    a->Visit("model", &model, Field());
    a->Visit("input_cam_contact_L10h", &input_cam_contact_L10h, Field(hours).Desc("with material.contact_fatigue"));
    a->Visit("output_cam_contact_L10h", &output_cam_contact_L10h, Field(hours).Desc("with material.contact_fatigue"));
    a->Visit("contact_life", &contact_life, Field().Desc("with material.contact_fatigue"));
    a->Visit("life_h", &life_h, Field().NullWhenAbsent().Unit("h").Desc("limits.life_h (null: none)"));
    a->Visit("table", &table, Field().Desc("report.html's and datasheet.html's rows"));
    a->Visit("shortest_L_nm_h", &shortest_L_nm_h,
             Field(hours).Desc("with a lubricant: the shortest modified life computed (null: none)"));
    a->Visit("shortest_L_nm_bearing", &shortest_L_nm_bearing, Field().Desc("with a lubricant: its bearing (null: none)"));
  }
};

/// Numbers of one cam (input cam A / fixed turret, output cam B / output turret).
struct CamResult {
  int lobes = 0, rollers = 0;
  double roller_gap_mm = 0, pitch_point_radius_mm = 0;
  // Undercut stage (evaluate.undercut or evaluate.stress).
  double min_pitch_curve_radius_mm = 0;
  double undercut_margin_mm = 0;  ///< smallest convex cam radius; < 0 is an undercut
  double cutter_diameter_mm = 0, min_cutter_path_radius_mm = 0;
  // Forces stage, extremes over the revolution.
  int actuating_rollers_max = 0, actuating_rollers_min = 0;
  double max_roller_force_N = 0;
  double max_contact_stress_MPa = 0;  ///< +inf when a loaded roller sits on an undercut point
  double contact_length_mm = 0;
  // The peak contact's line-contact half-width and what it is of (the subsurface stresses,
  // docs/life.md "Contact fatigue of the cam surfaces"); b = 0: no loaded contact.
  double peak_half_width_mm = 0;
  std::string subsurface_basis;
};

/// result.json's "measured" (with measured_profile): the measured cam's deviation (MeasuredBlock)
/// and, when the compliant model carries the torque, the reducer with it beside the nominal.
struct LcrMeasured : MeasuredBlock {
  struct Compliant {
    std::string model, contact_stress_note;
    int angles = 0;
    double output_torque_Nm = 0, lost_motion_torque_Nm = 0;
    MeasuredTransmissionError transmission_error;
    NominalMeasured output_rotation_peak_to_peak_arcsec, lost_motion_arcmin, max_roller_force_N;
    NominalMeasuredOrInfinite max_contact_stress_MPa;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("model", &model, Field().Desc("the model in words"));
      a->Visit("angles", &angles, Field().Desc("input angles over one input revolution"));
      a->Visit("output_torque_Nm", &output_torque_Nm, Field().Unit("N·m").Desc("load.output_torque_Nm"));
      transmission_error.Serialize(a, "of the output angle with the measured cam less the nominal's");
      a->Visit("output_rotation_peak_to_peak_arcsec", &output_rotation_peak_to_peak_arcsec, Field().Unit("arcsec"));
      a->Visit("lost_motion_arcmin", &lost_motion_arcmin, Field().Unit("arcmin").Desc("at ± lost_motion_torque_Nm"));
      a->Visit("lost_motion_torque_Nm", &lost_motion_torque_Nm, Field().Unit("N·m"));
      a->Visit("max_roller_force_N", &max_roller_force_N, Field().Unit("N").Desc("on the measured cam's rollers"));
      a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa,
               Field().Unit("MPa").Desc("Hertz line contact on the measured cam's rollers"));
      a->Visit("contact_stress_note", &contact_stress_note, Field().Desc("how the stresses are found"));
    }
  };
  std::optional<Compliant> compliant;
  template <typename Archive>
  void Serialize(Archive* a) {
    MeasuredBlock::Serialize(a);
    a->Visit("compliant", &compliant,
             Field().Desc("the transmission error, lost motion, roller force and contact stress with the measured cam "
                          "beside the nominal (absent when the compliant model cannot carry the torque)"));
  }
};

/// Every number the kind reports; the series are those of the forces stage.
struct Result {
  double speed_ratio = 0, cam_speed_ratio = 0, output_speed_ratio = 0, outer_diameter_mm = 0;
  bool undercut_evaluated = false, any_undercut = false;
  CamResult input_cam, output_cam;
  lcr::CycleSeries series;  ///< empty unless forces were evaluated
  double fixed_turret_torque_Nm = 0;  ///< mean over the revolution
  // Efficiency stage.
  double input_torque_mean_Nm = 0, input_torque_max_Nm = 0, input_torque_min_Nm = 0;
  double input_torque_ideal_Nm = 0;  ///< T_o/|r_i|, frictionless
  double efficiency_mean = 0, efficiency_min = 0, efficiency_max = 0;
  double eccentric_tangential_max_N = 0, eccentric_radial_max_abs_N = 0;
  /// Loads at input angle 0 (loaded rollers of the assembly drawings), when forces and the
  /// profile are evaluated.
  std::optional<lcr::AngleLoads<double>> loads_at_zero;
  std::optional<PlanarCamFit> input_cam_files, output_cam_files;  ///< with the profile stage
  /// inspection/CAM.csv by part name and their point counts ("inspection").
  std::vector<std::pair<std::string, std::string>> inspection_files;
  std::vector<std::pair<std::string, long>> inspection_points;
  std::optional<LcrMeasured> measured;  ///< result.json's "measured" (with measured_profile)
  /// Transmission error and lost motion from the tolerances (model/lcr/transmission_error.h).
  std::optional<lcr::TransmissionErrorResult> transmission_error;
  std::vector<std::string> notes;
  std::optional<TorsionalDynamicsResult> torsional;  ///< with "torsional_dynamics"
  std::string torsional_failed;                      ///< why it is absent
  /// The finite-length contact per cam, when the study has a "contact" object and stress is evaluated.
  std::optional<lcr::Contact3DCycleSide> contact_input, contact_output;
  std::optional<LifeResult> life;  ///< when the study asks for a life
  std::optional<LubricationResult> lubrication;  ///< with "lubricant"
  std::string lubrication_error;                 ///< why it is absent (no thermal equilibrium)
  /// efficiency_map.csv's rows: torque, speed, efficiency, loss, oil temperature, λ, and 1 where
  /// the housing's balance has an equilibrium (0: the values at the oil's limit temperature).
  std::vector<std::array<double, 7>> efficiency_map;
  /// With "stiffness": the mean output rotation [rad] at each torque [N·m] (−T_r … 0−, 0+ … T_r), the
  /// catalogue stiffness (50–100 %, mean of both senses) [N·m/rad], lost motion at 3 % and at the
  /// study's percentage [rad], the three segments [N·m/arcmin].
  std::vector<std::pair<double, double>> torsion_curve;
  double stiffness_Nm_per_rad = 0, lost_motion_rad = 0, lost_motion_user_rad = 0;
  std::optional<ThreeSegmentStiffness> segments;
  /// With "ratings" or "stiffness": the cam's mass, its polar moment about its centre and the
  /// inertia reflected to the output (m e² r_i² + J_c (ω_c/ω_o)²).
  double cam_kg = 0, cam_inertia_kgm2 = 0, reflected_inertia_kgm2 = 0;
  std::optional<RatingsResult> ratings;
  std::string ratings_failed;
  std::optional<OutputBearingResult> output_bearing;
  std::string output_bearing_failed;

  /// result.json, declared (studies/archive.h; `camopt schema lcr_analysis --result`): Run ends by
  /// filling it (FillResult). Its members sit here because the model's members above have the
  /// names of result.json's keys with other types. The blocks shared with other kinds (the lives,
  /// the transmission error, the lubrication, the ratings, the output bearing, the joint model, the
  /// torsional dynamics, the geometry and inspection files, the measured cam, the subsurface
  /// stresses) are raw JSON described by the schema of the keys camopt reads from them.
  struct Json {
    /// input_cam / output_cam: one cam and its turret's rollers.
    struct Cam {
      int lobes = 0, rollers = 0;
      double roller_gap_mm = 0, pitch_point_radius_mm = 0;
      std::optional<double> min_pitch_curve_radius_mm, min_convex_cam_radius_mm, undercut_margin_mm;
      std::optional<bool> undercut;
      std::optional<double> cutter_diameter_mm, min_cutter_path_radius_mm;
      std::optional<int> actuating_rollers_max, actuating_rollers_min;
      std::optional<double> max_roller_force_N, roller_load_limit_N;
      std::optional<bool> roller_load_ok;
      std::optional<double> max_contact_stress_MPa, contact_stress_limit_MPa;
      std::optional<bool> contact_stress_ok;
      std::optional<double> contact_length_mm;
      std::optional<SubsurfaceOut> subsurface;  ///< SubsurfaceOf's block (null: an undercut peak)
      std::optional<std::string> contact_model;
      std::optional<bool> edge_loaded;
      std::optional<double> worst_input_angle_deg, slice_width_mm, interpolation_error_MPa;
      std::optional<std::array<double, 2>> cell_size_mm;
      std::optional<double> slices_max_contact_stress_MPa;
      template <typename Archive>
      void Serialize(Archive* a) {
        const Field n = Field().NullWhenNotFinite();
        a->Visit("lobes", &lobes, Field().Desc("lobes of the cam"));
        a->Visit("rollers", &rollers, Field().Desc("rollers of its turret"));
        a->Visit("roller_gap_mm", &roller_gap_mm, Field().Unit("mm").Desc("gap between neighbouring rollers"));
        a->Visit("pitch_point_radius_mm", &pitch_point_radius_mm,
                 Field().Unit("mm").Desc("radius of the pitch point, e·n/(n−m)"));
        a->Visit("min_pitch_curve_radius_mm", &min_pitch_curve_radius_mm,
                 Field(n).Unit("mm").Desc("smallest convex radius of the pitch curve (undercut or stress stage)"));
        a->Visit("min_convex_cam_radius_mm", &min_convex_cam_radius_mm,
                 Field(n).Unit("mm").Desc("smallest convex radius of the cam profile, pitch radius less the roller "
                                          "radius; < 0 is an undercut (undercut or stress stage)"));
        a->Visit("undercut_margin_mm", &undercut_margin_mm,
                 Field(n).Unit("mm").Desc("the same number, the verdict's undercut margin (undercut or stress stage)"));
        a->Visit("undercut", &undercut, Field().Desc("the margin is < 0 (undercut or stress stage)"));
        a->Visit("cutter_diameter_mm", &cutter_diameter_mm,
                 Field(n).Unit("mm").Desc("the cutter of the cutter path (undercut or stress stage)"));
        a->Visit("min_cutter_path_radius_mm", &min_cutter_path_radius_mm,
                 Field(n).Unit("mm").Desc("smallest convex radius of the cutter path (undercut or stress stage)"));
        a->Visit("actuating_rollers_max", &actuating_rollers_max,
                 Field().Desc("most rollers carrying load at one angle (force stages)"));
        a->Visit("actuating_rollers_min", &actuating_rollers_min,
                 Field().Desc("fewest rollers carrying load at one angle (force stages)"));
        a->Visit("max_roller_force_N", &max_roller_force_N,
                 Field(n).Unit("N").Desc("largest roller force over the revolution (force stages)"));
        a->Visit("roller_load_limit_N", &roller_load_limit_N,
                 Field().Unit("N").Desc("limits.roller_load_N (force stages, with the limit)"));
        a->Visit("roller_load_ok", &roller_load_ok,
                 Field().Desc("max_roller_force_N <= the limit (force stages, with the limit)"));
        a->Visit("max_contact_stress_MPa", &max_contact_stress_MPa,
                 Field(n).Unit("MPa").Desc("largest Hertz contact stress over the revolution, the paper's eq. 27 (stress "
                                           "stage; null: a loaded roller sits on an undercut point)"));
        a->Visit("contact_stress_limit_MPa", &contact_stress_limit_MPa,
                 Field().Unit("MPa").Desc("limits.contact_stress_MPa (stress stage, with the limit, a finite stress)"));
        a->Visit("contact_stress_ok", &contact_stress_ok,
                 Field().Desc("max_contact_stress_MPa <= the limit (stress stage, with the limit, a finite stress)"));
        a->Visit("contact_length_mm", &contact_length_mm,
                 Field(n).Unit("mm").Desc("the rollers' contact length (stress stage)"));
        a->Visit("subsurface", &subsurface,
                 Field().Desc("the subsurface stresses under the peak pressure (stress stage, a loaded contact; null: "
                              "an undercut peak; {}: no roller carries load)"));
        a->Visit("contact_model", &contact_model,
                 Field().OneOf({"line", "slices", "half_space"}).Desc("the finite-length contact model (with contact)"));
        a->Visit("edge_loaded", &edge_loaded,
                 Field().Desc("the pressure reaches an end of the contact at some angle (with contact)"));
        a->Visit("worst_input_angle_deg", &worst_input_angle_deg,
                 Field(n).Unit("deg").Desc("input angle of the largest pressure (with contact)"));
        a->Visit("slice_width_mm", &slice_width_mm,
                 Field(n).Unit("mm").Desc("resolution of the slices model (with a contact model other than line)"));
        a->Visit("interpolation_error_MPa", &interpolation_error_MPa,
                 Field(n).Unit("MPa").Desc("error of the pressure table's interpolation against exact solves (with a "
                                           "contact model other than line)"));
        a->Visit("cell_size_mm", &cell_size_mm,
                 Field(n).Unit("mm").Desc("half_space cell across rolling and along the roller (half_space)"));
        a->Visit("slices_max_contact_stress_MPa", &slices_max_contact_stress_MPa,
                 Field(n).Unit("MPa").Desc("the slices model at the same contact (half_space)"));
      }
    };
    /// input_torque_Nm (efficiency stage).
    struct InputTorque {
      double mean = 0, max = 0, min = 0, ideal = 0;
      template <typename Archive>
      void Serialize(Archive* a) {
        const Field n = Field().NullWhenNotFinite().Unit("N·m");
        a->Visit("mean", &mean, Field(n).Desc("mean over the revolution, T_in = (F_t + μ F_r) e (the paper's eq. 32)"));
        a->Visit("max", &max, Field(n).Desc("largest over the revolution"));
        a->Visit("min", &min, Field(n).Desc("smallest over the revolution"));
        a->Visit("ideal", &ideal, Field(n).Desc("T_o/|r_i|, frictionless"));
      }
    };
    /// efficiency (efficiency stage).
    struct Efficiency {
      double mean = 0, min = 0, max = 0;
      template <typename Archive>
      void Serialize(Archive* a) {
        const Field n = Field().NullWhenNotFinite();
        a->Visit("mean", &mean, Field(n).Desc("mean over the revolution (the paper's eq. 33)"));
        a->Visit("min", &min, Field(n).Desc("smallest over the revolution"));
        a->Visit("max", &max, Field(n).Desc("largest over the revolution"));
      }
    };
    /// eccentric_load_N (efficiency stage).
    struct EccentricLoad {
      double tangential_max = 0, radial_max_abs = 0;
      template <typename Archive>
      void Serialize(Archive* a) {
        const Field n = Field().NullWhenNotFinite().Unit("N");
        a->Visit("tangential_max", &tangential_max, Field(n).Desc("largest tangential force F_t on the eccentric"));
        a->Visit("radial_max_abs", &radial_max_abs, Field(n).Desc("largest |radial force F_r| on the eccentric"));
      }
    };
    /// contact: the finite-length contact model asked for.
    struct Contact {
      std::string model;
      double misalignment_mrad = 0;
      std::optional<int> slices;
      std::optional<std::array<int, 2>> grid;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("model", &model, Field().OneOf({"line", "slices", "half_space"}).Desc("contact.model"));
        a->Visit("misalignment_mrad", &misalignment_mrad, Field().Unit("mrad").Desc("contact.misalignment"));
        a->Visit("slices", &slices, Field().Desc("slices along the roller (a model other than line)"));
        a->Visit("grid", &grid, Field().Desc("half_space cells across rolling and along the roller (half_space)"));
      }
    };
    /// masses (with stiffness or ratings).
    struct Masses {
      double density_kg_m3 = 0, cam_kg = 0, cam_inertia_kgm2 = 0, outer_diameter_mm = 0, reflected_inertia_kgm2 = 0;
      std::string includes;
      template <typename Archive>
      void Serialize(Archive* a) {
        const Field n = Field().NullWhenNotFinite();
        a->Visit("density_kg_m3", &density_kg_m3, Field().Unit("kg/m³").Desc("ratings.density_kg_m3, steel when absent"));
        a->Visit("cam_kg", &cam_kg, Field(n).Unit("kg").Desc("the cam: both profiles less their bores"));
        a->Visit("cam_inertia_kgm2", &cam_inertia_kgm2, Field(n).Unit("kg·m²").Desc("the cam's polar moment about its centre"));
        a->Visit("outer_diameter_mm", &outer_diameter_mm, Field(n).Unit("mm"));
        a->Visit("reflected_inertia_kgm2", &reflected_inertia_kgm2,
                 Field(n).Unit("kg·m²").Desc("at the output: m e² r_i² + J_c (ω_c/ω_o)²"));
        a->Visit("includes", &includes, Field().Desc("what the masses and the inertia are of"));
      }
    };
    /// stiffness: the torsional curve, input held (docs/lcr_stiffness.md).
    struct Stiffness {
      double rated_torque_Nm = 0, lost_motion_percent = 0, lost_motion_at_percent_arcmin = 0,
             hysteresis_width_arcmin = 0;
      std::string definitions;
      template <typename Archive>
      void Serialize(Archive* a) {
        a->Visit("rated_torque_Nm", &rated_torque_Nm, Field().Unit("N·m").Desc("stiffness.rated_torque_Nm"));
        a->Visit("lost_motion_percent", &lost_motion_percent, Field().Unit("%").Desc("stiffness.lost_motion_percent"));
        a->Visit("lost_motion_at_percent_arcmin", &lost_motion_at_percent_arcmin,
                 Field().NullWhenNotFinite().Unit("arcmin").Desc("lost motion at ± lost_motion_percent of the rated torque"));
        a->Visit("hysteresis_width_arcmin", &hysteresis_width_arcmin,
                 Field().Unit("arcmin").Desc("0: the contact model is frictionless"));
        a->Visit("definitions", &definitions, Field());
      }
    };
    /// stiffness_segments: the catalogue's three-segment stiffness (docs/ratings.md).
    struct StiffnessSegments {
      double T1_Nm = 0, T2_Nm = 0, rated_torque_Nm = 0, K1_Nm_per_arcmin = 0, K2_Nm_per_arcmin = 0,
             K3_Nm_per_arcmin = 0;
      std::string definitions;
      template <typename Archive>
      void Serialize(Archive* a) {
        const Field n = Field().NullWhenNotFinite();
        a->Visit("T1_Nm", &T1_Nm, Field().Unit("N·m"));
        a->Visit("T2_Nm", &T2_Nm, Field().Unit("N·m"));
        a->Visit("rated_torque_Nm", &rated_torque_Nm, Field().Unit("N·m"));
        a->Visit("K1_Nm_per_arcmin", &K1_Nm_per_arcmin, Field(n).Unit("N·m/arcmin").Desc("0 … T1"));
        a->Visit("K2_Nm_per_arcmin", &K2_Nm_per_arcmin, Field(n).Unit("N·m/arcmin").Desc("T1 … T2"));
        a->Visit("K3_Nm_per_arcmin", &K3_Nm_per_arcmin, Field(n).Unit("N·m/arcmin").Desc("T2 … rated torque"));
        a->Visit("definitions", &definitions, Field());
      }
    };

    std::string study = "lcr_analysis", name;
    double speed_ratio = 0, cam_speed_ratio = 0, output_speed_ratio = 0, outer_diameter_mm = 0;
    int angle_steps = 0;
    std::string load_model;
    Cam input_cam, output_cam;
    std::optional<double> fixed_turret_torque_Nm;
    std::optional<std::string> fixed_turret_torque_model;
    std::optional<double> output_torque_Nm;
    std::optional<InputTorque> input_torque_Nm;
    std::optional<Efficiency> efficiency;
    std::optional<EccentricLoad> eccentric_load_N;
    std::optional<double> friction_coefficient;
    std::optional<Contact> contact;
    std::optional<LcrTransmissionErrorBlock> transmission_error;
    std::optional<LifeBlock> life;                     ///< the bearing and cam-contact lives
    std::optional<OrError<LubricationResult>> lubrication;  ///< the losses, or why they are absent
    RatingsKeys ratings;  ///< rated_torque_Nm, peak_torque_Nm, momentary_torque_Nm, "ratings" (flat)
    std::optional<OrError<OutputBearingBlock>> output_bearing;  ///< the rating, or why it is absent
    std::optional<Masses> masses;
    std::optional<double> torsional_stiffness_Nm_per_arcmin, lost_motion_arcmin, backlash_arcmin;
    std::optional<Stiffness> stiffness;
    std::optional<StiffnessSegments> stiffness_segments;
    std::optional<JointModelBlock> joint_model;        ///< the parameters `camopt export` reads
    std::optional<OrError<TorsionalDynamicsBlock>> torsional_dynamics;  ///< the dynamics, or why they are absent
    std::vector<std::string> notes;
    std::optional<GeometryFilesBlock> geometry_files;  ///< GeometryFilesOf's block
    std::optional<InspectionBlock> inspection;
    std::optional<LcrMeasured> measured;
    template <typename Archive>
    void Serialize(Archive* a) {
      const Field n = Field().NullWhenNotFinite();
      a->Visit("study", &study, Field().Const("lcr_analysis").Desc("the study kind"));
      a->Visit("name", &name, Field().Desc("the design's name"));
      a->Visit("speed_ratio", &speed_ratio, Field().Desc("speed reduction ratio r_i, input over output speed"));
      a->Visit("cam_speed_ratio", &cam_speed_ratio, Field().Desc("the cam's spin over the input speed"));
      a->Visit("output_speed_ratio", &output_speed_ratio, Field().Desc("the output turret's speed over the input speed"));
      a->Visit("outer_diameter_mm", &outer_diameter_mm, Field().Unit("mm").Desc("over the larger turret's rollers"));
      a->Visit("angle_steps", &angle_steps, Field().Desc("samples of the input revolution"));
      a->Visit("load_model", &load_model, Field().OneOf({"rigid", "compliant"}).Desc("analysis.load_model"));
      a->Visit("input_cam", &input_cam, Field().Desc("cam A and the fixed turret's rollers"));
      a->Visit("output_cam", &output_cam, Field().Desc("cam B and the output turret's rollers"));
      a->Visit("fixed_turret_torque_Nm", &fixed_turret_torque_Nm,
               Field(n).Unit("N·m").Desc("mean torque on the fixed turret (force stages)"));
      a->Visit("fixed_turret_torque_model", &fixed_turret_torque_model,
               Field().Desc("how the fixed turret's torque is found (force stages with friction)"));
      a->Visit("output_torque_Nm", &output_torque_Nm, Field().Unit("N·m").Desc("load.output_torque_Nm (force stages)"));
      a->Visit("input_torque_Nm", &input_torque_Nm, Field().Desc("the input torque (efficiency stage)"));
      a->Visit("efficiency", &efficiency, Field().Desc("the paper's friction model (efficiency stage)"));
      a->Visit("eccentric_load_N", &eccentric_load_N, Field().Desc("the eccentric's load (efficiency stage)"));
      a->Visit("friction_coefficient", &friction_coefficient,
               Field().Desc("load.friction_coefficient μ of the eccentric (efficiency stage)"));
      a->Visit("contact", &contact, Field().Desc("the finite-length contact model (with contact)"));
      a->Visit("transmission_error", &transmission_error,
               Field().Desc("transmission error and lost motion from the tolerances (with tolerances; docs/lcr.md)"));
      a->Visit("life", &life,
               Field().Desc("the bearing lives and the cams' contact lives (with a speed or a duty cycle; docs/life.md)"));
      a->Visit("lubrication", &lubrication,
               Field().Desc("the lubricated losses (with lubricant; docs/lubrication.md)"));
      ratings.Serialize(a);
      a->Visit("output_bearing", &output_bearing,
               Field().Desc("the output bearing's life (with output_bearing)"));
      a->Visit("masses", &masses, Field().Desc("the cam's mass and the inertia at the output (with stiffness or ratings)"));
      a->Visit("torsional_stiffness_Nm_per_arcmin", &torsional_stiffness_Nm_per_arcmin,
               Field(n).Unit("N·m/arcmin").Desc("mean of both senses' slopes, 50-100% of the rated torque (with stiffness)"));
      a->Visit("lost_motion_arcmin", &lost_motion_arcmin,
               Field(n).Unit("arcmin").Desc("at ±3% of the rated torque (with stiffness)"));
      a->Visit("backlash_arcmin", &backlash_arcmin,
               Field().Unit("arcmin").Desc("0: conjugate profiles have no clearance (with stiffness)"));
      a->Visit("stiffness", &stiffness, Field().Desc("the torsional curve (with stiffness)"));
      a->Visit("stiffness_segments", &stiffness_segments, Field().Desc("with stiffness"));
      a->Visit("joint_model", &joint_model,
               Field().Desc("the joint `camopt export` writes for a simulator (with stiffness)"));
      a->Visit("torsional_dynamics", &torsional_dynamics,
               Field().Desc("with torsional_dynamics (docs/torsional_dynamics.md)"));
      a->Visit("notes", &notes, Field().Desc("what the numbers do not say (an undercut, a zero torque, a model's warning)"));
      a->Visit("geometry_files", &geometry_files, Field().Desc("the cams' geometry files (with the profile stage)"));
      a->Visit("inspection", &inspection, Field().Desc("the inspection files (with inspection)"));
      a->Visit("measured", &measured,
               Field().Desc("the measured cam and the compliant model with it (with measured_profile)"));
    }
  };
  Json json;
  template <typename Archive>
  void Serialize(Archive* a) {
    json.Serialize(a);
  }
};

/// @throws StudyError (exit 2) naming the JSON path of bad input.
Study Parse(const Node& root);
/// A cam as inspected: its exact profile in the frame of its DXF (origin at the cam's centre),
/// the frame and datum in words.
InspectedPart CamPart(const Study& study, lcr::Side side);
/// Runs the stages asked. @throws StudyError for a design no roller can carry load on.
Result Run(const Study& study, const RunContext& ctx);
/// result.json's members of `result` (Result::json) from its model numbers; Run ends with it.
void FillResult(const Study& study, Result& result);
/// result.json, series.csv and plots (forces), DXF/SVG drawings (profile).
void Write(const Study& study, const Result& result, Outputs& out);

/// Assembled view of side `s` at input angle 0: the cam (centre at e u(0), not yet turned) with
/// its rollers, the rollers loaded in `loads` red (nullptr: none marked).
Drawing AssemblyDrawing(const lcr::Reducer<double>& r, lcr::Side s, const lcr::AngleLoads<double>* loads, int points,
                        const std::string& title);

}  // namespace camopt::studies::lcr_analysis
