// The mechanism of a study at one input angle, for the studio's animation (`camopt serve`,
// docs/studio.md): the parts' outlines and positions in the fixed frame, with the loads where they
// are cheap, all from model/ functions (nothing here computes physics of its own).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

namespace camopt::studies {

/// The mechanism of `study` (a study file's JSON) at input angle `input_angle_deg`, `points`
/// points per outline (clamped to [36, 4000]). Supported kinds: lcr_analysis, disc_cam (every
/// follower), cycloid_ltca, and the sizings of the three. An LCR:
///   {"kind": "lcr", "supported": true, "input_angle_deg", "eccentricity_mm",
///    "cam_centre_mm": [x, y], "cam_rotation_deg", "output_turret_rotation_deg",
///    "max_stress_MPa", "sides": [{"name": "input"|"output", "lobes", "rollers",
///    "turret_radius_mm", "roller_radius_mm", "profile_mm": [[x, y], …],
///    "rollers_at": [{"x", "y", "dx", "dy", "force_N", "stress_MPa", "loaded"}, …]}, …]}
/// in the fixed frame [mm], the input turret standing, roller 0 of each turret on +x at 0°; (dx, dy)
/// the unit direction of the force of the roller on the cam; stress_MPa −1 at an undercut contact.
/// A disc cam, the follower standing and the cam turned by −θ (θ against the cam's rotation):
///   {"kind": "disc_cam", "supported": true, "follower", "oscillating", "base_radius_mm",
///    "roller_radius_mm", "profile_mm", "roller_centre_mm", "contact_mm", "follower_direction"
///    (unit, of increasing lift), "lift" (mm or rad), "pressure_angle_deg"[, "pivot_mm",
///    "arm_length_mm"]}.
/// A flat-faced follower (translating or on an arm), the same frame: {"kind": "disc_cam",
///   "flat_face": true, "follower", "oscillating", "base_radius_mm", "profile_mm", "contact_mm",
///   "face_mm" (the face's two ends: the contact's travel over the cycle, or a translating face's
///   face_width_mm centred on its axis), "face_foot_mm", "face_normal" (unit, toward the cam on an
///   arm, toward the follower translating), "contact_on_face_mm" (S' or ℓ), "lift" (mm or rad),
///   "pressure_angle_deg", "radius_of_curvature_mm"[, "pivot_mm", "arm_angle_deg", "face_offset_mm"]}.
/// A cycloid drive at crank angle θ: {"kind": "cycloid", "supported": true, "teeth", "rollers",
///   "roller_position_radius_mm", "roller_radius_mm", "disc_centre_mm", "disc_rotation_deg",
///   "profile_mm" (the disc, at least 48 points per pin), "pins": [{"x", "y", "force_N", "loaded"[,
///   "pressure_MPa", "effective_radius_mm"]}, …], "disc_torque_Nmm", "max_pin_force_N"[,
///   "max_pressure_MPa", "composite_modulus_MPa"], "pin_source": "nominal"|"run", "pin_source_label"[,
///   "run_note", "run"]}: without a run, each pin's rigid-disc force on the nominal tooth and, with
///   the study's material (a loaded study), its Hertz line-contact peak pressure over the face width
///   (−1: a conformal pair). With `run` (its per_angle.csv, see LoadedRun), each pin's force_N and
///   pressure_MPa are the run's LTCA pair load and the pair's own peak pressure at θ (CycloidRunAt;
///   a run whose torque or unloaded transmission error at that row is not the study's is not used),
///   the nominal ones kept as nominal_force_N, nominal_pressure_MPa, and "run": {"file",
///   "rows" (the two data rows, from 0), "angles_deg" (theirs), "weight" (of the second),
///   "pin_shift" (θ's pin i is the rows' pin i − pin_shift), "pressures" (false: a run without the
///   per-pair pressure columns, the pins coloured by force)}; a run it cannot use is said in
///   "run_note" and the nominal view drawn.
/// A sizing kind (lcr_min_size, cycloid_min_size, disc_cam_min_size), its start design against the
/// optimum of its run, each drawn as its analysis kind (SizingAnalysisKind) is:
///   {"kind": "sizing", "sizing_kind", "supported": true, "analysis_kind",
///    "start": {…as the analysis kind…, "study": the start's analysis study},
///    "optimum": {…, "study": `optimum`} or null without `optimum`}
/// with `optimum` the run's best_….json (SizingOptimumFile); the start is the sizing kind's own
/// (KindDescriptor::start_study: an LCR's start needs the optimum's lobe combination). A design the
/// analysis kind refuses is {"supported": false, "why", "study"}. Each kind's drawing is its
/// KindDescriptor::mechanism; a kind without one: {"kind": KIND, "supported": false}. @throws StudyError for a study the CLI
/// would refuse (the kind's Parse).
/// A finished run of a cycloid_ltca study: its output folder (as shown) and the text of its
/// per_angle.csv (crank_angle_deg, load_roller_i_N and max_pressure_roller_i_MPa of i = 1 … n1).
struct LoadedRun {
  std::string folder;
  std::string per_angle_csv;
  double torque_Nm = -1;  ///< result.json's torque_Nm (< 0: not known), checked against the study's
};

nlohmann::json MechanismAt(const nlohmann::json& study, double input_angle_deg, int points,
                           const nlohmann::json& optimum = nullptr, const LoadedRun* run = nullptr);

/// The run's pair loads at crank angle θ [deg] from its per-angle rows φ_k (in increasing order).
/// The drive repeats every mesh period τ = 360°/n1 turned by one pin (pin i at φ + τ carries what
/// pin i − 1 carries at φ: the pins and the disc's n2 teeth both turn into themselves), so a run
/// whose angles sample P whole mesh periods uniformly (φ_k = φ_0 + k h, N h = P τ, the default
/// crank_angles_per_mesh_period and its refined set) gives every θ: θ − φ_0 = m N h + ψ, ψ in
/// [0, N h), pin shift m P; rows j = ⌊ψ/h⌋ and j + 1 (row N: row 0 with P pins more) linearly
/// interpolated with weight t = ψ/h − j. Other angle sets are interpolated between their
/// neighbouring rows within [φ_0, φ_last] (θ taken modulo 360°) only. Loads and pressures are each
/// interpolated linearly (exact at the run's angles). Returns {"force_N": [n1], "pressure_MPa":
/// [n1] (empty without the pressure columns), "rows", "angles_deg", "weight", "pin_shift",
/// "unloaded_te_arcsec" (of the first row; null without the column)} or
/// {"why": text} when the run cannot give θ.
nlohmann::json CycloidRunAt(const std::string& per_angle_csv, int rollers, double crank_deg);

/// The studio's drawing of each analysis kind (KindDescriptor::mechanism): MechanismAt's JSON.
nlohmann::json LcrMechanismAt(const nlohmann::json& study, double input_angle_deg, int points, const LoadedRun* run);
nlohmann::json DiscCamMechanismAt(const nlohmann::json& study, double input_angle_deg, int points,
                                  const LoadedRun* run);
nlohmann::json CycloidMechanismAt(const nlohmann::json& study, double input_angle_deg, int points,
                                  const LoadedRun* run);

/// The analysis kind a sizing kind's designs are studies of ("disc_cam" for "disc_cam_min_size");
/// empty for a kind that is not a sizing.
std::string SizingAnalysisKind(const std::string& kind);
/// The file a run of sizing kind `kind` writes its optimum to ("best_disc_cam.json"); empty
/// for another kind.
std::string SizingOptimumFile(const std::string& kind);

}  // namespace camopt::studies
