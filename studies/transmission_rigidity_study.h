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
/// element of a given kind needs or may have is checked by Parse (docs/studies.md lists them per
/// kind), so the element's fields have no default here: a field's default depends on the kind
/// and is in its description.
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

struct Study {
  std::string name;
  std::vector<Element> elements;
  std::optional<double> report_radius_mm;
  std::optional<double> load_torque_Nm;
  std::string chain_where;  ///< "FILE: PATH" of the chain, for an all-rigid chain
  Input::Limits limits;     ///< the verdict's limits at end b
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

struct Result {
  rigidity::ChainResult<double> chain;
  std::optional<double> linear_stiffness_at_report_radius_N_per_mm;
  std::optional<double> deflection_at_end_b_rad;  ///< under load_torque_Nm
  std::vector<ElementResult> elements;
  int most_effective = -1;  ///< index into the dominant element's elasticity, −1 for none
  std::string advice;
};

/// @throws StudyError for bad input (exit 2).
Study Parse(const Node& root);
/// @throws StudyError when a reducer cannot carry its load or every element is rigid.
Result Run(const Study& study, const RunContext& ctx);
nlohmann::json ToJson(const Study& study, const Result& result);
/// result.json, elements.csv and, per reducer k, reducer_k_stiffness.csv/.svg and
/// reducer_k_lost_motion.csv/.svg.
void Write(const Study& study, const Result& result, Outputs& out);

}  // namespace camopt::studies::transmission_rigidity
