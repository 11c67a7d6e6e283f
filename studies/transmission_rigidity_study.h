// Study kind "transmission_rigidity": the torsional rigidity and backlash of a series chain of
// shafts, gears, chains, belts, pull-rods, levers, couplings (the transmission-rigidity paper,
// docs/rigidity.md) and lobe cam reducers, seen from either end, with each element's share of the
// compliance and the design advice the paper gives by hand (which element dominates, which
// dimension to change).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/lcr/reducer.h"
#include "model/rigidity/chain.h"
#include "model/rigidity/chain_elements.h"
#include "model/rigidity/lcr_stiffness.h"
#include "studies/archive.h"
#include "studies/input.h"
#include "studies/lcr_input.h"
#include "studies/material_input.h"
#include "studies/study.h"

namespace camopt::studies::transmission_rigidity {

/// The study file as declared: each field once, in the file's units, with its bounds and
/// description (studies/archive.h); `camopt schema transmission_rigidity` is emitted from it.
/// A chain element is one object holding the fields of every element kind; which of them an
/// element of a given kind needs or may have is declared by Element::SchemaRules (and checked by
/// Parse; docs/studies.md lists them per kind), so the element's fields have no default here: a
/// field's default depends on the kind and is in its description.
struct Input {
  /// The chain's material: each element takes what it needs (a shaft G, a rod E, a reducer E, ν).
  struct Material {
    std::optional<double> shear_modulus_GPa, youngs_modulus_GPa, poisson_ratio;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("shear_modulus_GPa", &shear_modulus_GPa,
               Field().Positive().Unit("GPa").Desc("shear modulus G, for shafts in torsion (steel: 80)"));
      a->Visit("youngs_modulus_GPa", &youngs_modulus_GPa,
               Field().Positive().Unit("GPa").Desc("Young's modulus E, for bending, rods, levers and reducers (steel: 206)"));
      a->Visit("poisson_ratio", &poisson_ratio,
               Field().In(0.0, 0.4999).Desc("Poisson's ratio, for a lobe cam reducer's contacts"));
    }
  };
  struct ReducerLoad {
    double output_torque_Nm = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("output_torque_Nm", &output_torque_Nm,
               Field().Required().Positive().Unit("N·m").Desc("the reducer's output torque of its stiffness cycle"));
    }
  };
  struct Element {
    std::string element;
    std::optional<std::string> name, comment;
    std::optional<double> backlash_arcmin, shear_modulus_GPa, youngs_modulus_GPa;
    std::optional<double> outer_diameter_mm, diameter_mm, inner_diameter_mm, length_mm, pitch_radius_mm;
    std::optional<std::string> support;
    std::optional<double> to_bearing_1_mm, to_bearing_2_mm, bearing_span_mm, overhang_mm;
    std::optional<double> stiffness_N_per_mm, radius_mm, reference_length_mm, span_length_mm;
    std::optional<double> lever_radius_mm, tip_stiffness_N_per_mm, width_mm, height_mm;
    std::optional<double> rigidity_Nm_per_rad;
    std::optional<bool> rigid;
    std::optional<double> ratio, mesh_stiffness_N_per_mm, driven_pitch_radius_mm;
    std::optional<LcrReducerInput> reducer;
    std::optional<MaterialInput> material;
    std::optional<ReducerLoad> load;
    std::optional<double> clearance_um, needle_bearing_radial_stiffness_N_per_mm;
    std::optional<int> angle_steps;
    std::optional<std::string> direction;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("element", &element,
               Field().Required().OneOf({"shaft_torsion", "shaft_bending", "linear_stiffness", "coupling", "gear_stage",
                                         "lever", "pull_rod", "belt_span", "chain_span", "lobe_cam_reducer"})
                   .Desc("the element's kind; its fields are listed per kind in docs/studies.md"));
      a->Visit("name", &name, Field().Desc("the element's name in the results (default: its kind and place)"));
      a->Visit("comment", &comment, Field().Desc("a free note, not read"));
      a->Visit("backlash_arcmin", &backlash_arcmin,
               Field().NonNegative().Unit("arcmin").Desc("the element's own backlash, any kind (default 0)"));
      a->Visit("shear_modulus_GPa", &shear_modulus_GPa,
               Field().Positive().Unit("GPa").Desc("G of this element (default: the study's material)"));
      a->Visit("youngs_modulus_GPa", &youngs_modulus_GPa,
               Field().Positive().Unit("GPa").Desc("E of this element (default: the study's material)"));
      a->Visit("outer_diameter_mm", &outer_diameter_mm,
               Field().Positive().Unit("mm").Desc("shaft_torsion, shaft_bending: the shaft's outer diameter"));
      a->Visit("diameter_mm", &diameter_mm, Field().Positive().Unit("mm").Desc("pull_rod: the rod's diameter"));
      a->Visit("inner_diameter_mm", &inner_diameter_mm,
               Field().NonNegative().Unit("mm").Desc("shafts, pull_rod: the bore, below the outer diameter (default 0)"));
      a->Visit("length_mm", &length_mm,
               Field().Positive().Unit("mm").Desc("shaft_torsion: under torque; pull_rod: the rod; lever: the arm"));
      a->Visit("pitch_radius_mm", &pitch_radius_mm,
               Field().Positive().Unit("mm").Desc("shaft_bending: the gear or sprocket on the shaft"));
      a->Visit("support", &support,
               Field().OneOf({"between_bearings", "overhung"})
                   .Desc("shaft_bending: the wheel between the bearings or overhung (default between_bearings)"));
      a->Visit("to_bearing_1_mm", &to_bearing_1_mm,
               Field().Positive().Unit("mm").Desc("shaft_bending between bearings: wheel to bearing 1"));
      a->Visit("to_bearing_2_mm", &to_bearing_2_mm,
               Field().Positive().Unit("mm").Desc("shaft_bending between bearings: wheel to bearing 2"));
      a->Visit("bearing_span_mm", &bearing_span_mm,
               Field().Positive().Unit("mm").Desc("shaft_bending overhung: between the bearings"));
      a->Visit("overhang_mm", &overhang_mm,
               Field().Positive().Unit("mm").Desc("shaft_bending overhung: outer bearing to the wheel"));
      a->Visit("stiffness_N_per_mm", &stiffness_N_per_mm,
               Field().Positive().Unit("N/mm").Desc(
                   "linear_stiffness: the element's; chain_span, belt_span: of reference_length_mm of chain or belt"));
      a->Visit("radius_mm", &radius_mm,
               Field().Positive().Unit("mm").Desc("linear_stiffness, spans: the radius it acts at (R = S r²)"));
      a->Visit("reference_length_mm", &reference_length_mm,
               Field().Positive().Unit("mm").Desc("chain_span, belt_span: the length stiffness_N_per_mm is for (default 1000)"));
      a->Visit("span_length_mm", &span_length_mm,
               Field().Positive().Unit("mm").Desc("chain_span, belt_span: the loaded span's length"));
      a->Visit("lever_radius_mm", &lever_radius_mm,
               Field().Positive().Unit("mm").Desc("pull_rod: the lever radius it pulls at"));
      a->Visit("tip_stiffness_N_per_mm", &tip_stiffness_N_per_mm,
               Field().Positive().Unit("N/mm").Desc("lever: its stiffness at the tip (or width_mm and height_mm)"));
      a->Visit("width_mm", &width_mm, Field().Positive().Unit("mm").Desc("lever: the section's width"));
      a->Visit("height_mm", &height_mm, Field().Positive().Unit("mm").Desc("lever: the section's height"));
      a->Visit("rigidity_Nm_per_rad", &rigidity_Nm_per_rad,
               Field().Positive().Unit("N·m/rad").Desc("coupling: its torsional rigidity; gear_stage: the mesh's"));
      a->Visit("rigid", &rigid, Field().Desc("coupling: true for a rigid one (or give rigidity_Nm_per_rad)"));
      a->Visit("ratio", &ratio, Field().Positive().Desc("gear_stage: the speed ratio from side a to side b"));
      a->Visit("mesh_stiffness_N_per_mm", &mesh_stiffness_N_per_mm,
               Field().Positive().Unit("N/mm").Desc("gear_stage: the mesh's (with driven_pitch_radius_mm)"));
      a->Visit("driven_pitch_radius_mm", &driven_pitch_radius_mm,
               Field().Positive().Unit("mm").Desc("gear_stage: the driven gear's pitch radius"));
      a->Visit("reducer", &reducer, Field().Desc("lobe_cam_reducer: its design"));
      a->Visit("material", &material, Field().Desc("lobe_cam_reducer: its material (default: the study's)"));
      a->Visit("load", &load, Field().Desc("lobe_cam_reducer: the load of its stiffness cycle"));
      a->Visit("clearance_um", &clearance_um,
               Field().NonNegative().Unit("µm").Desc("lobe_cam_reducer: the rollers' clearance (default 0)"));
      a->Visit("needle_bearing_radial_stiffness_N_per_mm", &needle_bearing_radial_stiffness_N_per_mm,
               Field().Positive().Unit("N/mm").Desc("lobe_cam_reducer: each roller's bearing (default: rigid)"));
      a->Visit("angle_steps", &angle_steps,
               Field().AtLeast(8).Desc("lobe_cam_reducer: input angles of its stiffness cycle (default 720)"));
      a->Visit("direction", &direction,
               Field().OneOf({"forward", "reverse"})
                   .Desc("lobe_cam_reducer: the load along the output's motion or against it (default forward)"));
    }
    /// The fields each element kind requires and allows (a tagged union on "element").
    static nlohmann::ordered_json SchemaRules();
  };

  /// The verdict's limits at end b (none has a default: each is a requirement of the machine).
  struct Limits {
    std::optional<double> rigidity_Nm_per_rad, backlash_arcmin, deflection_deg;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("rigidity_Nm_per_rad", &rigidity_Nm_per_rad,
               Field().Positive().Unit("N·m/rad").Desc("the least torsional rigidity at end b"));
      a->Visit("backlash_arcmin", &backlash_arcmin,
               Field().NonNegative().Unit("arcmin").Desc("the most backlash at end b"));
      a->Visit("deflection_deg", &deflection_deg,
               Field().Positive().Unit("deg").Desc("the most deflection at end b under load_torque_Nm (needs it)"));
    }
  };

  std::string study = "transmission_rigidity", name = "transmission";
  std::optional<std::string> description;
  std::optional<Material> material;
  std::vector<Element> chain;
  std::optional<double> load_torque_Nm, report_radius_mm;
  Limits limits;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Required().Const("transmission_rigidity").Desc("the study kind"));
    a->Visit("name", &name, Field().Desc("the transmission's name, in titles"));
    a->Visit("description", &description, Field().Desc("free text"));
    a->Visit("material", &material, Field().Desc("the material every element takes unless it gives its own"));
    a->Visit("chain", &chain,
             Field().Required().MinItems(1, "a non-empty array of elements")
                 .Desc("the elements in series, from end a (the motor) to end b (the load)"));
    a->Visit("load_torque_Nm", &load_torque_Nm,
             Field().Positive().Unit("N·m").Desc("a torque at end b for the deflection (absent: none reported)"));
    a->Visit("report_radius_mm", &report_radius_mm,
             Field().Positive().Unit("mm").Desc("a radius at end b to report the deflection at as a length"));
    a->Visit("limits", &limits, Field().Desc("requirements at end b for the verdict (each optional)"));
  }
  /// The chain material's moduli and the reducer's material where an element needs them and has
  /// no own.
  static nlohmann::ordered_json SchemaRules();
};

/// A lobe_cam_reducer element's own inputs (model units).
struct ReducerElement {
  lcr::Reducer<double> reducer;
  lcr::Material material;
  double torque_Nmm = 0;             ///< output torque (magnitude)
  double clearance_mm = 0;
  double bearing_N_per_mm = 0;       ///< needle bearing radial stiffness; 0 = rigid
  int angle_steps = 720;
  std::string direction = "forward";
  double sense = 1;                  ///< sign of the loaded torque in the model's convention
  std::string where;                 ///< "FILE: PATH" of the element, for load errors
};

struct Element {
  rigidity::ElementSpec spec;  ///< for a reducer, ratio and rigidity are filled by Run
  std::optional<ReducerElement> reducer;
};

/// The study as Run takes it: the file as declared (`in`) and its chain's elements, each checked
/// and in model units.
struct Study {
  Input in;
  std::vector<Element> elements;
  std::string chain_where;  ///< "FILE: PATH" of the chain, for an all-rigid chain
};

/// What a reducer element reports besides its chain numbers.
struct ReducerResult {
  double speed_reduction_ratio = 0;  ///< signed, as the LCR model defines it
  rigidity::ReducerStiffnessCycle cycle;    ///< under the load, in its sense
  rigidity::ReducerStiffnessCycle reverse;  ///< under the load in the other sense
  std::vector<double> torques_Nmm, rotations_rad;  ///< lost-motion curve, in the load sense
  double dead_band_rad = 0;
  double lost_motion_rad = 0;        ///< between ±3 % of the load torque
  double rigidity_at_input_Nm_per_rad = 0;  ///< its own rigidity seen from its input shaft
};

struct ElementResult {
  rigidity::ElementSpec spec;        ///< with a reducer's ratio and rigidity filled in
  double compliance_rad_per_Nmm = 0; ///< own compliance (0: rigid)
  /// ∂ln R/∂ln p of the chain's rigidity for each named parameter of the element.
  std::vector<std::pair<std::string, double>> elasticity;
  std::optional<ReducerResult> reducer;
};

/// The run's answer: result.json as declared (its `Serialize`; `camopt schema
/// transmission_rigidity --result` is emitted from it), then the model's numbers the CSV and SVG
/// files are drawn from, which result.json does not hold.
struct Result {
  /// A lobe_cam_reducer element's own numbers (result.json's elements[i].reducer).
  struct ReducerRow {
    double speed_reduction_ratio = 0, output_torque_Nm = 0;
    std::string direction;
    double clearance_um = 0;
    std::optional<double> needle_bearing_radial_stiffness_N_per_mm;
    std::string contact_law;
    double mean_secant_rigidity_Nm_per_rad = 0, mean_secant_rigidity_Nm_per_arcmin = 0;
    double min_secant_rigidity_Nm_per_rad = 0, max_secant_rigidity_Nm_per_rad = 0, secant_ripple = 0;
    double mean_tangent_rigidity_Nm_per_rad = 0, min_tangent_rigidity_Nm_per_rad = 0;
    double max_tangent_rigidity_Nm_per_rad = 0, reverse_mean_secant_rigidity_Nm_per_rad = 0;
    double rigidity_at_input_Nm_per_rad = 0, mean_elastic_rotation_arcmin = 0;
    double lost_motion_arcmin_at_3pct_torque = 0, dead_band_arcmin = 0;
    double max_roller_force_input_N = 0, max_roller_force_output_N = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("speed_reduction_ratio", &speed_reduction_ratio, Field().Desc("signed, as the LCR model defines it"));
      a->Visit("output_torque_Nm", &output_torque_Nm, Field().Unit("N·m").Desc("the load of its stiffness cycle"));
      a->Visit("direction", &direction, Field().OneOf({"forward", "reverse"}).Desc("the load's sense"));
      a->Visit("clearance_um", &clearance_um, Field().Unit("µm").Desc("the rollers' clearance"));
      a->Visit("needle_bearing_radial_stiffness_N_per_mm", &needle_bearing_radial_stiffness_N_per_mm,
               Field().Unit("N/mm").Desc("each roller's bearing, when not rigid"));
      a->Visit("contact_law", &contact_law, Field().Desc("the roller contacts' load-deflection law"));
      a->Visit("mean_secant_rigidity_Nm_per_rad", &mean_secant_rigidity_Nm_per_rad,
               Field().Unit("N·m/rad").Desc("torsional rigidity at the output, secant, mean over an input turn"));
      a->Visit("mean_secant_rigidity_Nm_per_arcmin", &mean_secant_rigidity_Nm_per_arcmin,
               Field().Unit("N·m/arcmin").Desc("the same per arcminute"));
      a->Visit("min_secant_rigidity_Nm_per_rad", &min_secant_rigidity_Nm_per_rad, Field().Unit("N·m/rad"));
      a->Visit("max_secant_rigidity_Nm_per_rad", &max_secant_rigidity_Nm_per_rad, Field().Unit("N·m/rad"));
      a->Visit("secant_ripple", &secant_ripple, Field().Desc("(max − min) / mean of the secant rigidity"));
      a->Visit("mean_tangent_rigidity_Nm_per_rad", &mean_tangent_rigidity_Nm_per_rad, Field().Unit("N·m/rad"));
      a->Visit("min_tangent_rigidity_Nm_per_rad", &min_tangent_rigidity_Nm_per_rad, Field().Unit("N·m/rad"));
      a->Visit("max_tangent_rigidity_Nm_per_rad", &max_tangent_rigidity_Nm_per_rad, Field().Unit("N·m/rad"));
      a->Visit("reverse_mean_secant_rigidity_Nm_per_rad", &reverse_mean_secant_rigidity_Nm_per_rad,
               Field().Unit("N·m/rad").Desc("the mean secant rigidity under the load in the other sense"));
      a->Visit("rigidity_at_input_Nm_per_rad", &rigidity_at_input_Nm_per_rad,
               Field().Unit("N·m/rad").Desc("its own rigidity seen from its input shaft"));
      a->Visit("mean_elastic_rotation_arcmin", &mean_elastic_rotation_arcmin,
               Field().Unit("arcmin").Desc("the output's rotation under the load at the mean secant rigidity"));
      a->Visit("lost_motion_arcmin_at_3pct_torque", &lost_motion_arcmin_at_3pct_torque,
               Field().Unit("arcmin").Desc("rotation between ±3 % of the load torque"));
      a->Visit("dead_band_arcmin", &dead_band_arcmin, Field().Unit("arcmin").Desc("the clearance's free rotation"));
      a->Visit("max_roller_force_input_N", &max_roller_force_input_N, Field().Unit("N"));
      a->Visit("max_roller_force_output_N", &max_roller_force_output_N, Field().Unit("N"));
    }
  };
  /// One element of the chain (result.json's elements[i]).
  struct ElementRow {
    int index = 0;
    std::string name, element;
    double rigidity_Nm_per_rad = 0, rigidity_at_end_b_Nm_per_rad = 0, compliance_share = 0;
    double rigidity_if_rigid_Nm_per_rad = 0;
    std::optional<double> ratio;
    double backlash_arcmin = 0, backlash_at_end_b_arcmin = 0;
    std::map<std::string, double> rigidity_elasticity;
    std::optional<ReducerRow> reducer;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("index", &index, Field().Desc("its place in the chain, from end a"));
      a->Visit("name", &name, Field().Desc("the study's name for it, or its kind and place"));
      a->Visit("element", &element, Field().Desc("its kind"));
      a->Visit("rigidity_Nm_per_rad", &rigidity_Nm_per_rad,
               Field().NullWhenNotFinite().Unit("N·m/rad").Desc("its own torsional rigidity (null: rigid)"));
      a->Visit("rigidity_at_end_b_Nm_per_rad", &rigidity_at_end_b_Nm_per_rad,
               Field().NullWhenNotFinite().Unit("N·m/rad").Desc("the same seen at end b, through the ratios after it"));
      a->Visit("compliance_share", &compliance_share, Field().Desc("its share of the chain's compliance at end b"));
      a->Visit("rigidity_if_rigid_Nm_per_rad", &rigidity_if_rigid_Nm_per_rad,
               Field().NullWhenNotFinite().Unit("N·m/rad").Desc("the chain's rigidity at end b had this element been rigid"));
      a->Visit("ratio", &ratio, Field().Desc("gear_stage, lobe_cam_reducer: its speed ratio (other kinds: absent)"));
      a->Visit("backlash_arcmin", &backlash_arcmin, Field().Unit("arcmin").Desc("its own backlash"));
      a->Visit("backlash_at_end_b_arcmin", &backlash_at_end_b_arcmin,
               Field().Unit("arcmin").Desc("the same seen at end b"));
      a->Visit("rigidity_elasticity", &rigidity_elasticity,
               Field().Desc("∂ln R/∂ln p of the chain's rigidity at end b for each of its named parameters p"));
      a->Visit("reducer", &reducer, Field().Desc("lobe_cam_reducer: its stiffness cycle and lost motion"));
    }
  };
  /// The element holding the largest share of the compliance, and the paper's advice on it.
  struct Dominant {
    int index = 0;
    std::string name, element;
    double compliance_share = 0;
    std::optional<std::string> most_effective_parameter;
    std::optional<double> most_effective_parameter_elasticity;
    std::string advice;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("index", &index, Field().Desc("its place in the chain"));
      a->Visit("name", &name, Field().Desc("its name"));
      a->Visit("element", &element, Field().Desc("its kind"));
      a->Visit("compliance_share", &compliance_share, Field().Desc("its share of the chain's compliance at end b"));
      a->Visit("most_effective_parameter", &most_effective_parameter,
               Field().Desc("its dimension with the largest |elasticity| (not a modulus or a ratio)"));
      a->Visit("most_effective_parameter_elasticity", &most_effective_parameter_elasticity,
               Field().Desc("that elasticity, % of the chain's rigidity per +1 %"));
      a->Visit("advice", &advice, Field().Desc("which dimension to change, in words"));
    }
  };

  std::string study = "transmission_rigidity", name;
  double rigidity_Nm_per_rad = 0, rigidity_at_end_b_Nm_per_rad = 0, rigidity_at_end_a_Nm_per_rad = 0;
  double total_ratio = 0, backlash_at_end_b_arcmin = 0, backlash_at_end_a_arcmin = 0;
  std::optional<double> report_radius_mm, linear_stiffness_at_report_radius_N_per_mm;
  std::optional<double> load_torque_Nm, deflection_at_end_b_deg;
  std::optional<Input::Limits> limits;  ///< the study's limits, when it gives any
  std::optional<bool> rigidity_ok, backlash_ok, deflection_ok, limits_ok;
  std::vector<ElementRow> element_rows;  ///< result.json's "elements"
  Dominant dominant;
  std::vector<std::string> notes;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("study", &study, Field().Const("transmission_rigidity"));
    a->Visit("name", &name, Field().Desc("the transmission's name"));
    a->Visit("rigidity_Nm_per_rad", &rigidity_Nm_per_rad,
             Field().Unit("N·m/rad").Desc("the chain's torsional rigidity at end b (the load)"));
    a->Visit("rigidity_at_end_b_Nm_per_rad", &rigidity_at_end_b_Nm_per_rad, Field().Unit("N·m/rad").Desc("the same"));
    a->Visit("rigidity_at_end_a_Nm_per_rad", &rigidity_at_end_a_Nm_per_rad,
             Field().Unit("N·m/rad").Desc("the chain's torsional rigidity at end a (the motor)"));
    a->Visit("total_ratio", &total_ratio, Field().Desc("the speed ratio from end a to end b"));
    a->Visit("backlash_at_end_b_arcmin", &backlash_at_end_b_arcmin,
             Field().Unit("arcmin").Desc("the chain's backlash seen at end b"));
    a->Visit("backlash_at_end_a_arcmin", &backlash_at_end_a_arcmin,
             Field().Unit("arcmin").Desc("the chain's backlash seen at end a"));
    a->Visit("report_radius_mm", &report_radius_mm,
             Field().Unit("mm").Desc("the study's report radius at end b, when it gives one"));
    a->Visit("linear_stiffness_at_report_radius_N_per_mm", &linear_stiffness_at_report_radius_N_per_mm,
             Field().Unit("N/mm").Desc("the rigidity at end b as a linear stiffness at that radius"));
    a->Visit("load_torque_Nm", &load_torque_Nm, Field().Unit("N·m").Desc("the study's torque at end b, when it gives one"));
    a->Visit("deflection_at_end_b_deg", &deflection_at_end_b_deg, Field().Unit("deg").Desc("end b's deflection under it"));
    a->Visit("limits", &limits, Field().Desc("the study's limits at end b, when it gives any"));
    a->Visit("rigidity_ok", &rigidity_ok, Field().Desc("the rigidity at end b meets its limit (with that limit)"));
    a->Visit("backlash_ok", &backlash_ok, Field().Desc("the backlash at end b meets its limit (with that limit)"));
    a->Visit("deflection_ok", &deflection_ok, Field().Desc("the deflection at end b meets its limit (with that limit)"));
    a->Visit("limits_ok", &limits_ok, Field().Desc("every limit given is met (with limits)"));
    a->Visit("elements", &element_rows, Field().Desc("the chain's elements, from end a to end b"));
    a->Visit("dominant", &dominant, Field().Desc("the most compliant element"));
    a->Visit("notes", &notes, Field().Desc("remarks for the report"));
  }

  // Not in result.json: the model's numbers (model units) the files are drawn from.
  rigidity::ChainResult<double> chain;
  std::vector<ElementResult> elements;
  int most_effective = -1;  ///< index into the dominant element's elasticity, −1 for none
  std::string advice;
};

/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
/// @throws StudyError when a reducer cannot carry its load or every element is rigid.
Result Run(const Study& study, const RunContext& ctx);
/// result.json, elements.csv and, per reducer k, reducer_k_stiffness.csv/.svg and
/// reducer_k_lost_motion.csv/.svg.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::transmission_rigidity
