// `camopt export RESULT_DIR --to mujoco|modelica|json [--out DIR] [--name NAME]`: the reducer of a
// result (its result.json's "joint_model", written by the cycloid_ltca and lcr_analysis kinds) as a
// joint for a simulator: a MuJoCo MJCF model, a Modelica package (MSL 4.0), or joint.json
// (docs/export.md). Every file records the result's camopt_version and study_sha256.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

namespace camopt::studies {

/// One row of a joint model's loss table (speeds and torques at the input, efficiencies as fractions).
struct JointLossRow {
  double input_speed_rad_s = 0.0;
  double efficiency_forward = 1.0;   ///< input drives the output
  double efficiency_backward = 1.0;  ///< output drives the input
  double friction_torque_input_Nm = 0.0;
};

/// result.json's "joint_model" (docs/export.md: every field, its unit and meaning).
struct JointModel {
  double ratio = 1.0;  ///< input turns per output turn, > 0
  double rated_torque_Nm = 0.0;
  double stiffness_Nm_per_rad = 0.0;  ///< catalogue stiffness (the 50–100 % slope)
  double T1_Nm = 0.0, T2_Nm = 0.0;    ///< stiffness_segments: the segments' torque bounds
  double K1_Nm_per_rad = 0.0, K2_Nm_per_rad = 0.0, K3_Nm_per_rad = 0.0;
  /// Loading branch {torque [N m], angle [rad]} from −T_r to +T_r by ascending torque; two points at
  /// torque 0 (0− and 0+) whose angles differ by the backlash.
  std::vector<std::pair<double, double>> torsion_curve;
  double backlash_rad = 0.0;  ///< total free play (dead band width)
  double lost_motion_rad = 0.0;
  double lost_motion_percent = 0.0;
  double reflected_inertia_kgm2 = 0.0;  ///< at the output
  std::string inertia_includes;
  double damping_Nms_per_rad = 0.0;
  std::string damping_note;
  double friction_torque_Nm = 0.0;  ///< no-load running torque at the output
  std::string friction_note;
  bool has_efficiency = false;
  double efficiency = 1.0;  ///< when has_efficiency
  std::vector<JointLossRow> loss_table;  ///< by ascending input speed; may be empty
  /// The output bearing's moment (tilting) stiffness K_B about each axis across the reducer's; 0:
  /// not given (the output does not tilt).
  double tilt_stiffness_Nm_per_rad = 0.0;
  std::string tilt_note;
};

/// What an export reads: the joint model and the provenance of the result it came from.
struct ExportSource {
  std::string file;  ///< the result.json read (for messages and the files' headers)
  std::string camopt_version, study_sha256, study, name;
  JointModel joint;
};

/// The joint model of a parsed result.json (`file` names it in messages). StudyError (exit 2)
/// "FILE: /joint_model/KEY: expected …, found …" for a missing field, a wrong type, null (a NaN
/// written by a JSON writer) or a value out of range; a result without "joint_model" names its kind.
ExportSource ParseExportSource(const nlohmann::json& result, const std::string& file);

/// The name of the joint in the files: `name` when given (a letter, then letters, digits or '_';
/// StudyError otherwise), else the result folder's name with every other character made '_'.
std::string ExportJointName(const std::string& name, const std::string& result_dir);
/// The Modelica package name of a joint name: CamelCase ("cycloid_nnm" → "CycloidNnm").
std::string ModelicaPackageName(const std::string& joint_name);

/// The MuJoCo model (MJCF, MuJoCo 2.2.2 and later): a base, then a chain of three hinges about z —
/// `<joint>_motor_side` (armature = reflected inertia, frictionloss, damping), `<joint>_backlash`
/// (range ±backlash/2, a stiff limit), `<joint>_elastic` (stiffness, springref 0) — ending in the
/// body `<joint>_output`, and the actuator `<joint>_motor` (gear = ratio). The numbers are written
/// in full precision; the parameters are repeated as comments with their units.
std::string ExportMujocoXml(const ExportSource& source, const std::string& joint_name);

/// The Modelica package `package_name`: the constant torsionCurve and the model Joint (input
/// inertia, LossyGear, ElastoBacklash between flange_a and flange_b), Modelica 3.x syntax, MSL 4.0.
std::string ExportModelicaPackage(const ExportSource& source, const std::string& package_name);

/// The rows of LossyGear's lossTable [|w_a|, eta_mf1, eta_mf2, |tau_bf1|, |tau_bf2|] (input speed,
/// forward and backward mesh efficiency, bearing friction torques at the input): the loss table's
/// rows; without one, one row from the efficiency with the no-load running torque referred to the
/// input (friction_torque_Nm / ratio); without an efficiency, a lossless mesh with that torque.
std::vector<std::vector<double>> ModelicaLossTable(const JointModel& joint);

/// joint.json: the same values, each key with its unit, and the result's provenance.
nlohmann::ordered_json ExportJointJson(const ExportSource& source, const std::string& joint_name);

/// The formats of `--to`.
std::vector<std::string> ExportFormats();

/// What `camopt export` was asked.
struct ExportRequest {
  std::string result;  ///< RESULT_DIR (or its result.json)
  std::string to;      ///< "mujoco", "modelica" or "json"
  std::string out;     ///< the folder to write; "" → RESULT_DIR/export
  std::string name;    ///< the joint's name; "" → from RESULT_DIR's name
};

/// What an export wrote.
struct ExportAnswer {
  std::string out_dir;
  std::string file;  ///< the file of the requested format, inside out_dir
};

/// Reads the result, writes the requested file into the output folder, whole or not at all (an
/// OutputFolder: the previous folder swapped out in one rename). The files of an earlier export of
/// the same result in that folder (other formats) are kept; those of another result are not. The
/// default folder RESULT_DIR/export is added to RESULT_DIR's list of what camopt wrote, so that the
/// next `camopt run` into RESULT_DIR may replace it. StudyError (exit 2) for bad input.
ExportAnswer RunExport(const ExportRequest& request);

}  // namespace camopt::studies
