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
///   "max_pressure_MPa", "composite_modulus_MPa"]}: each pin's rigid-disc force on the nominal tooth
///   and, with the study's material (a loaded study), its Hertz line-contact peak pressure over the
///   face width (−1: a conformal pair).
/// A sizing kind (lcr_min_size, cycloid_min_size, disc_cam_min_size), its start design against the
/// optimum of its run, each drawn as its analysis kind (SizingAnalysisKind) is:
///   {"kind": "sizing", "sizing_kind", "supported": true, "analysis_kind",
///    "start": {…as the analysis kind…, "study": the start's analysis study},
///    "optimum": {…, "study": `optimum`} or null without `optimum`}
/// with `optimum` the run's best_….json (SizingOptimumFile); the start is the sizing kind's own
/// (disc_cam_min_size::StartDiscCamStudy, cycloid_min_size::StartCycloidLtcaStudy,
/// lcr_min_size::StartLcrAnalysisStudy: an LCR's start needs the optimum's lobe combination). A
/// design the analysis kind refuses is {"supported": false, "why", "study"}.
/// Another kind: {"kind": KIND, "supported": false}. @throws StudyError for a study the CLI
/// would refuse (the kind's Parse).
nlohmann::json MechanismAt(const nlohmann::json& study, double input_angle_deg, int points,
                           const nlohmann::json& optimum = nullptr);

/// The analysis kind a sizing kind's designs are studies of ("disc_cam" for "disc_cam_min_size");
/// empty for a kind that is not a sizing.
std::string SizingAnalysisKind(const std::string& kind);
/// The file a run of sizing kind `kind` writes its optimum to ("best_disc_cam.json"); empty
/// for another kind.
std::string SizingOptimumFile(const std::string& kind);

}  // namespace camopt::studies
