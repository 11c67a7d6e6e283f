#include "studies/export.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <set>
#include <sstream>

#include "studies/format.h"
#include "studies/input.h"
#include "studies/provenance.h"
#include "studies/study.h"
#include "studies/suggest.h"

namespace camopt::studies {

namespace fs = std::filesystem;

namespace {

// A number as JSON writes it: the shortest text that reads back as the same double ("15.0",
// "0.00025", "1e-10"), which XML attributes, Modelica literals and JSON all accept. The joint
// model's values are written so; the export's own choices (stand-in inertias, sizes) with six
// digits (Short), computed from values already rounded so (Round6), so that text and model agree.
std::string Num(double v) { return nlohmann::json(v).dump(); }
std::string Short(double v) { return Format(v, 6); }
double Round6(double v) { return std::stod(Format(v, 6)); }

// A fraction in (0, 1] (an efficiency).
double Fraction(const Node& n) {
  const double v = n.Number();
  if (!(v > 0 && v <= 1)) n.Fail("a number in (0, 1]");
  return v;
}

// Text inside an XML comment: no "--" (not allowed there) and no line breaks.
std::string XmlCommentText(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  for (size_t at = text.find("--"); at != std::string::npos; at = text.find("--", at))
    text.replace(at, 2, "- -");
  if (!text.empty() && text.back() == '-') text += ' ';
  return text;
}

// Text of a Modelica // comment: one line.
std::string ModelicaCommentText(std::string text) {
  for (char& c : text)
    if (c == '\n' || c == '\r') c = ' ';
  return text;
}

// A Modelica string literal's content: " and \ escaped, one line.
std::string ModelicaString(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += (c == '\n' || c == '\r') ? ' ' : c;
  }
  return out;
}

bool IsIdentifier(const std::string& s) {
  if (s.empty() || !std::isalpha(static_cast<unsigned char>(s[0]))) return false;
  return std::all_of(s.begin(), s.end(), [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// The result's "joint_model" and provenance, every value checked where it is read.
JointModel ParseJointModel(const Node& j) {
  JointModel m;
  m.ratio = j["ratio"].Positive();
  m.rated_torque_Nm = j["rated_torque_Nm"].Positive();
  m.stiffness_Nm_per_rad = j["stiffness_Nm_per_rad"].Positive();
  const Node seg = j["stiffness_segments"];
  m.T1_Nm = seg["T1_Nm"].Positive();
  m.T2_Nm = seg["T2_Nm"].Positive();
  if (!(m.T2_Nm >= m.T1_Nm)) seg["T2_Nm"].Fail("a torque >= T1_Nm (" + Num(m.T1_Nm) + ")");
  m.K1_Nm_per_rad = seg["K1_Nm_per_rad"].Positive();
  m.K2_Nm_per_rad = seg["K2_Nm_per_rad"].Positive();
  m.K3_Nm_per_rad = seg["K3_Nm_per_rad"].Positive();
  const Node curve = j["torsion_curve"];
  const std::vector<Node> points = curve.Elements();
  if (points.size() < 2) curve.Fail("an array of at least two [torque_Nm, angle_rad] points");
  for (const Node& p : points) {
    if (!p.json().is_array() || p.json().size() != 2) p.Fail("a [torque_Nm, angle_rad] pair");
    const double torque = p[0].Number(), angle = p[1].Number();
    if (!m.torsion_curve.empty() && torque < m.torsion_curve.back().first)
      p[0].Fail("a torque >= the previous point's " + Num(m.torsion_curve.back().first) +
                " N m (the loading branch by ascending torque)");
    if (!m.torsion_curve.empty() && angle < m.torsion_curve.back().second)
      p[1].Fail("an angle >= the previous point's " + Num(m.torsion_curve.back().second) +
                " rad (the loading branch rises)");
    m.torsion_curve.emplace_back(torque, angle);
  }
  m.backlash_rad = j["backlash_rad"].NonNegative();
  m.lost_motion_rad = j["lost_motion_rad"].NonNegative();
  m.lost_motion_percent = j["lost_motion_percent"].NonNegative();
  m.reflected_inertia_kgm2 = j["reflected_inertia_kgm2"].Positive();
  m.inertia_includes = j["inertia_includes"].String();
  m.damping_Nms_per_rad = j["damping_Nms_per_rad"].NonNegative();
  m.damping_note = j["damping_note"].String();
  m.friction_torque_Nm = j["friction_torque_Nm"].NonNegative();
  m.friction_note = j["friction_note"].String();
  const Node eff = j["efficiency"];
  if (!eff.json().is_null()) {
    if (!eff.json().is_number()) eff.Fail("a number in (0, 1] or null");
    m.has_efficiency = true;
    m.efficiency = Fraction(eff);
  }
  // Results before the output bearing's tilt was part of the joint have no tilt_stiffness_Nm_per_rad.
  if (j.Has("tilt_stiffness_Nm_per_rad") && !j["tilt_stiffness_Nm_per_rad"].json().is_null())
    m.tilt_stiffness_Nm_per_rad = j["tilt_stiffness_Nm_per_rad"].Positive();
  if (j.Has("tilt_note")) m.tilt_note = j["tilt_note"].String();
  for (const Node& row : j["loss_table"].Elements()) {
    JointLossRow r;
    r.input_speed_rad_s = row["input_speed_rad_s"].NonNegative();
    if (!m.loss_table.empty() && !(r.input_speed_rad_s > m.loss_table.back().input_speed_rad_s))
      row["input_speed_rad_s"].Fail("a speed > the previous row's " + Num(m.loss_table.back().input_speed_rad_s) +
                                    " rad/s (rows by ascending speed)");
    r.efficiency_forward = Fraction(row["efficiency_forward"]);
    r.efficiency_backward = Fraction(row["efficiency_backward"]);
    r.friction_torque_input_Nm = row["friction_torque_input_Nm"].NonNegative();
    m.loss_table.push_back(r);
  }
  return m;
}

// The stand-in inertia of each of the two bodies after the motor side (the flange between dead band
// and spring, and the output), as a fraction of the reflected inertia: camopt does not compute the
// output-side parts' inertia; a flange is of this order (docs/export.md).
constexpr double kNodeInertiaFraction = 0.1;
// The motor side body's own inertia, a fraction of the armature (MuJoCo needs a mass on a moving body).
constexpr double kMotorBodyInertiaFraction = 1e-6;
// The radius of the discs the bodies' masses are computed for (and drawn with) [m].
constexpr double kDiscRadius_m = 0.05;

// A time step at most `dt`, rounded down to two significant digits.
double RoundDown2(double dt) {
  const double scale = std::pow(10.0, std::floor(std::log10(dt)) - 1);
  return std::floor(dt / scale) * scale;
}

std::string Inertial(double inertia) {
  // A thin disc of radius kDiscRadius_m about z: I_z = m r^2 / 2; I_x = I_y a little over I_z / 2.
  const double mass = 2 * inertia / (kDiscRadius_m * kDiscRadius_m);
  return "<inertial pos=\"0 0 0\" mass=\"" + Short(mass) + "\" diaginertia=\"" + Short(0.6 * inertia) + " " +
         Short(0.6 * inertia) + " " + Short(inertia) + "\"/>";
}

std::string ReadIfSmall(const fs::path& file) {
  try {
    return ReadFileCapped(file.string(), size_t{64} << 20, "file");
  } catch (const StudyError&) {
    return "";
  }
}

}  // namespace

ExportSource ParseExportSource(const nlohmann::json& result, const std::string& file) {
  const Node root(&result, file, "/");
  if (!result.is_object()) root.Fail("the object of a result.json");
  ExportSource s;
  s.file = file;
  s.study = root["study"].String();
  s.camopt_version = root["camopt_version"].String();
  s.study_sha256 = root["study_sha256"].String();
  s.name = root.StringOr("name", "");
  if (!root.Has("joint_model")) {
    const bool kind_has_one = s.study == "cycloid_ltca" || s.study == "lcr_analysis";
    throw StudyError(file + ": /joint_model: expected the joint model of a cycloid_ltca or lcr_analysis result, found " +
                         (kind_has_one ? "none (written by camopt " + s.camopt_version +
                                             " before results carried one: run the study again)"
                                       : "none: a " + s.study + " result has no joint to export"),
                     file, "/joint_model", "the joint model of a cycloid_ltca or lcr_analysis result", "nothing");
  }
  const Node j = root["joint_model"];
  if (!j.json().is_object()) j.Fail("an object");
  s.joint = ParseJointModel(j);
  return s;
}

std::string ExportJointName(const std::string& name, const std::string& result_dir) {
  if (!name.empty()) {
    if (!IsIdentifier(name))
      throw StudyError("--name: expected a letter, then letters, digits or _ (a name MJCF and Modelica accept), found \"" +
                       name + "\"");
    return name;
  }
  std::error_code ec;
  fs::path dir = fs::weakly_canonical(fs::absolute(result_dir, ec), ec);
  if (!dir.has_filename()) dir = dir.parent_path();
  std::string out;
  for (char c : dir.filename().string())
    out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  if (out.empty() || !std::isalpha(static_cast<unsigned char>(out[0]))) out = "joint_" + out;
  return out;
}

std::string ModelicaPackageName(const std::string& joint_name) {
  std::string out;
  bool upper = true;
  for (char c : joint_name) {
    if (c == '_') {
      upper = true;
      continue;
    }
    out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
    upper = false;
  }
  if (out.empty() || !std::isalpha(static_cast<unsigned char>(out[0]))) out = "Joint" + out;
  // Modelica's predefined types and the names the package uses inside would be shadowed.
  static const std::set<std::string> taken = {"Real", "Integer", "Boolean", "String", "Modelica", "Joint"};
  if (taken.count(out)) out += "Reducer";
  return out;
}

std::vector<std::string> ExportFormats() { return {"mujoco", "modelica", "json"}; }

std::vector<std::vector<double>> ModelicaLossTable(const JointModel& j) {
  std::vector<std::vector<double>> rows;
  for (const JointLossRow& r : j.loss_table)
    rows.push_back({r.input_speed_rad_s, r.efficiency_forward, r.efficiency_backward, r.friction_torque_input_Nm,
                    r.friction_torque_input_Nm});
  if (rows.empty()) {
    const double eta = j.has_efficiency ? j.efficiency : 1.0;
    const double tau_bf = j.friction_torque_Nm / j.ratio;  // the no-load running torque at the input
    rows.push_back({0.0, eta, eta, tau_bf, tau_bf});
  }
  return rows;
}

std::string ExportMujocoXml(const ExportSource& s, const std::string& name) {
  const JointModel& j = s.joint;
  const double node_inertia = Round6(kNodeInertiaFraction * j.reflected_inertia_kgm2);
  const double motor_body_inertia = Round6(kMotorBodyInertiaFraction * j.reflected_inertia_kgm2);
  // The stiffest mode: the flange and the output body on the spring, each against the other
  // (in the dead band; in contact the flange is held and the mode is slower). Semi-implicit Euler
  // is stable for omega dt < 2; a quarter of that keeps the ringing's frequency within ~1 %.
  // With the output bearing's tilt, the output body also swings about x and y on K_B against its
  // 0.6 I (Inertial below): that mode is usually the stiffest.
  const bool tilt = j.tilt_stiffness_Nm_per_rad > 0;
  const double omega_max = std::max(std::sqrt(j.stiffness_Nm_per_rad * (2.0 / node_inertia)),
                                    tilt ? std::sqrt(j.tilt_stiffness_Nm_per_rad / (0.6 * node_inertia)) : 0.0);
  const double timestep = std::min(0.002, RoundDown2(0.5 / omega_max));
  // The limit as stiff as the integrator allows: time constant 2 dt (MuJoCo's floor), critically
  // damped, impedance 0.9999 (mjMAXIMP) at any penetration: a residual compliance of
  // 1e-4 (2 dt)^2 times the dof's inverse inertia, far below 1/K (docs/export.md).
  const double limit_timeconst = 2 * timestep;
  const bool dead_band = j.backlash_rad > 0;

  std::ostringstream x;
  x << "<?xml version=\"1.0\" encoding=\"utf-8\"?>\n";
  x << "<!-- camopt export: the reducer of a result as a MuJoCo joint (MJCF, MuJoCo 2.2.2 or later)\n";
  x << "     result:         " << XmlCommentText(s.file) << "\n";
  x << "     study:          " << XmlCommentText(s.study) << " \"" << XmlCommentText(s.name) << "\"\n";
  x << "     camopt_version: " << XmlCommentText(s.camopt_version) << " (the result's; exported by camopt "
    << XmlCommentText(CamoptVersion()) << ")\n";
  x << "     study_sha256:   " << XmlCommentText(s.study_sha256) << "\n";
  x << "\n     Parameters (SI units; where each goes):\n";
  x << "       ratio               " << Num(j.ratio) << " input turns per output turn: actuator " << name
    << "_motor gear\n";
  x << "       rated torque        " << Num(j.rated_torque_Nm) << " N m\n";
  x << "       stiffness           " << Num(j.stiffness_Nm_per_rad)
    << " N m/rad, the catalogue slope (50 to 100 % of the rated torque): joint " << name << "_elastic stiffness\n";
  x << "       stiffness segments  K1 " << Num(j.K1_Nm_per_rad) << " N m/rad up to T1 " << Num(j.T1_Nm) << " N m, K2 "
    << Num(j.K2_Nm_per_rad) << " N m/rad up to T2 " << Num(j.T2_Nm) << " N m, K3 " << Num(j.K3_Nm_per_rad)
    << " N m/rad above\n";
  x << "                           (a MuJoCo joint spring is linear: the segments and the torsion curve are in\n";
  x << "                           joint.json and the Modelica export's torsionCurve)\n";
  x << "       backlash            " << Num(j.backlash_rad) << " rad total free play: joint " << name
    << "_backlash range +/-" << Num(j.backlash_rad / 2) << " rad\n";
  x << "       lost motion         " << Num(j.lost_motion_rad) << " rad (" << Num(j.lost_motion_percent)
    << " %)\n";
  x << "       reflected inertia   " << Num(j.reflected_inertia_kgm2) << " kg m2 at the output: joint " << name
    << "_motor_side armature\n";
  x << "                           (includes: " << XmlCommentText(j.inertia_includes) << ")\n";
  x << "       damping             " << Num(j.damping_Nms_per_rad) << " N m s/rad: joint " << name
    << "_motor_side damping (" << XmlCommentText(j.damping_note) << ")\n";
  x << "       friction torque     " << Num(j.friction_torque_Nm) << " N m no-load running torque at the output: joint "
    << name << "_motor_side frictionloss (" << XmlCommentText(j.friction_note) << ")\n";
  x << "       efficiency          " << (j.has_efficiency ? Num(j.efficiency) : std::string("not given"))
    << " (MuJoCo has no gear efficiency: the Modelica export's LossyGear has it)\n";
  x << "\n     Model: base, then three hinges about z in series, ending in the body " << name << "_output\n";
  x << "     that your link attaches to (a child body without a joint, or geoms in it):\n";
  x << "       " << name << "_motor_side  the gear's input side seen at the output: the actuator, the reflected\n";
  x << "                          inertia, friction and damping;\n";
  if (dead_band)
    x << "       " << name << "_backlash    the dead band: free within +/-backlash/2, a stiff limit at its ends;\n";
  else
    x << "       (no dead band: the backlash is 0)\n";
  x << "       " << name << "_elastic     the torsional spring, stiffness K, springref 0.\n";
  x << "     A torque T at the output, the motor side held, turns the output by backlash/2 + T/K.\n";
  if (tilt)
    x << "     " << name << "_tilt_x, " << name << "_tilt_y: the output bearing's moment stiffness K_B "
      << Num(j.tilt_stiffness_Nm_per_rad) << " N m/rad\n     about x and y (a moment M tilts the output by M/K_B; "
      << XmlCommentText(j.tilt_note) << ").\n";
  else
    x << "     No tilt: the result gives no output-bearing moment stiffness (the output is rigid in tilt).\n";
  x << "     The bodies " << name << "_flange and " << name << "_output carry " << Short(node_inertia)
    << " kg m2 each (" << Short(kNodeInertiaFraction * 100)
    << " % of the reflected inertia, a stand-in\n";
  x << "     for the output flange: camopt does not compute it; MuJoCo needs an inertia on a moving body).\n";
  x << "     The time step " << Short(timestep) << " s is a quarter of the stability bound of the stiffest mode,\n";
  x << "     " << (tilt ? "max(sqrt(K (1/I_flange + 1/I_output)), sqrt(K_B / (0.6 I_output)))"
                    : "sqrt(K (1/I_flange + 1/I_output))")
    << " = " << Short(omega_max)
    << " rad/s; a link you attach only slows that mode.\n";
  x << "     The limit: solreflimit time constant 2 dt, critically damped, solimplimit 0.9999 (the most\n";
  x << "     MuJoCo allows): it yields 1e-4 (2 dt)^2 / I rad per N m, far below 1/K. -->\n";
  x << "<mujoco model=\"" << name << "\">\n";
  x << "  <compiler angle=\"radian\"/>\n";
  x << "  <option timestep=\"" << Short(timestep) << "\" integrator=\"Euler\"/>\n";
  x << "  <worldbody>\n";
  x << "    <body name=\"" << name << "_base\">\n";
  x << "      <geom name=\"" << name << "_housing\" type=\"cylinder\" size=\"" << Short(1.2 * kDiscRadius_m)
    << " 0.02\" pos=\"0 0 -0.03\" contype=\"0\" conaffinity=\"0\" rgba=\"0.6 0.6 0.65 1\"/>\n";
  x << "      <body name=\"" << name << "_motor_side\">\n";
  x << "        " << Inertial(motor_body_inertia) << "\n";
  x << "        <!-- reflected inertia " << Num(j.reflected_inertia_kgm2) << " kg m2, damping "
    << Num(j.damping_Nms_per_rad) << " N m s/rad, no-load running torque " << Num(j.friction_torque_Nm)
    << " N m -->\n";
  x << "        <joint name=\"" << name << "_motor_side\" type=\"hinge\" axis=\"0 0 1\" armature=\""
    << Num(j.reflected_inertia_kgm2) << "\" damping=\"" << Num(j.damping_Nms_per_rad) << "\" frictionloss=\""
    << Num(j.friction_torque_Nm) << "\"/>\n";
  x << "        <body name=\"" << name << "_flange\">\n";
  x << "          " << Inertial(node_inertia) << "\n";
  if (dead_band) {
    x << "          <!-- backlash " << Num(j.backlash_rad) << " rad: free within +/-" << Num(j.backlash_rad / 2)
      << " rad -->\n";
    x << "          <joint name=\"" << name << "_backlash\" type=\"hinge\" axis=\"0 0 1\" limited=\"true\" range=\""
      << Num(-j.backlash_rad / 2) << " " << Num(j.backlash_rad / 2) << "\" solreflimit=\"" << Short(limit_timeconst)
      << " 1\" solimplimit=\"0.9999 0.9999 0.001 0.5 2\"/>\n";
  }
  x << "          <body name=\"" << name << "_output\">\n";
  x << "            " << Inertial(node_inertia) << "\n";
  x << "            <!-- catalogue stiffness " << Num(j.stiffness_Nm_per_rad) << " N m/rad -->\n";
  x << "            <joint name=\"" << name << "_elastic\" type=\"hinge\" axis=\"0 0 1\" stiffness=\""
    << Num(j.stiffness_Nm_per_rad) << "\" springref=\"0\"/>\n";
  if (tilt) {
    x << "            <!-- output bearing moment stiffness " << Num(j.tilt_stiffness_Nm_per_rad) << " N m/rad -->\n";
    for (const char* axis : {"x", "y"})
      x << "            <joint name=\"" << name << "_tilt_" << axis << "\" type=\"hinge\" axis=\""
        << (axis[0] == 'x' ? "1 0 0" : "0 1 0") << "\" stiffness=\"" << Num(j.tilt_stiffness_Nm_per_rad)
        << "\" springref=\"0\"/>\n";
  }
  x << "            <geom name=\"" << name << "_output_disc\" type=\"cylinder\" size=\"" << Short(kDiscRadius_m)
    << " 0.005\" pos=\"0 0 0.005\" contype=\"0\" conaffinity=\"0\" rgba=\"0.3 0.5 0.8 1\"/>\n";
  x << "            <geom name=\"" << name << "_output_mark\" type=\"box\" size=\"0.01 0.004 0.004\" pos=\""
    << Short(0.8 * kDiscRadius_m) << " 0 0.014\" contype=\"0\" conaffinity=\"0\" rgba=\"0.9 0.3 0.2 1\"/>\n";
  x << "            <site name=\"" << name << "_output\" pos=\"0 0 0.01\"/>\n";
  x << "            <!-- your link: a child body here -->\n";
  x << "          </body>\n";
  x << "        </body>\n";
  x << "      </body>\n";
  x << "    </body>\n";
  x << "  </worldbody>\n";
  x << "  <actuator>\n";
  x << "    <!-- ctrl: the motor torque at the input [N m]; the joint gets ratio x ctrl at the output -->\n";
  x << "    <motor name=\"" << name << "_motor\" joint=\"" << name << "_motor_side\" gear=\"" << Num(j.ratio) << "\"/>\n";
  x << "  </actuator>\n";
  x << "</mujoco>\n";
  return x.str();
}

std::string ExportModelicaPackage(const ExportSource& s, const std::string& package) {
  const JointModel& j = s.joint;
  std::ostringstream m;
  m << "// camopt export: the reducer of a result as a Modelica package (Modelica 3.x, MSL 4.0)\n";
  m << "// result: " << ModelicaCommentText(s.file) << "\n";
  m << "// study: " << ModelicaCommentText(s.study) << " \"" << ModelicaCommentText(s.name) << "\"\n";
  m << "// camopt_version: " << ModelicaCommentText(s.camopt_version) << " (the result's; exported by camopt "
    << ModelicaCommentText(CamoptVersion()) << ")\n";
  m << "// study_sha256: " << ModelicaCommentText(s.study_sha256) << "\n";
  m << "// Units: SI (N.m, rad, kg.m2, rad/s, N.m.s/rad).\n";
  m << "package " << package << " \"" << ModelicaString("Reducer joint exported by camopt: " + s.name) << "\"\n";
  m << "  // Loading branch of the torsion curve by ascending angle, {angle [rad], torque [N.m]}, from\n";
  m << "  // -" << Num(j.rated_torque_Nm) << " to +" << Num(j.rated_torque_Nm)
    << " N.m; the two rows at torque 0 are the ends of the dead band (backlash " << Num(j.backlash_rad)
    << " rad).\n";
  m << "  // For a nonlinear spring, e.g. Modelica.Blocks.Tables.CombiTable1Ds(table = torsionCurve): torque of angle.\n";
  m << "  constant Real torsionCurve[:, 2] = [";
  std::vector<std::pair<double, double>> rows;
  for (const auto& [torque, angle] : j.torsion_curve)
    if (rows.empty() || rows.back() != std::make_pair(angle, torque)) rows.emplace_back(angle, torque);
  for (size_t i = 0; i < rows.size(); ++i)
    m << (i == 0 ? "" : ";") << "\n    " << Num(rows[i].first) << ", " << Num(rows[i].second);
  m << "] \"Torsion curve {angle [rad], torque [N.m]}\";\n";
  m << "  // Stiffness segments: K1 " << Num(j.K1_Nm_per_rad) << " N.m/rad up to T1 " << Num(j.T1_Nm) << " N.m, K2 "
    << Num(j.K2_Nm_per_rad) << " N.m/rad up to T2 " << Num(j.T2_Nm) << " N.m, K3 " << Num(j.K3_Nm_per_rad)
    << " N.m/rad above.\n";
  m << "  // Lost motion " << Num(j.lost_motion_rad) << " rad (" << Num(j.lost_motion_percent)
    << " %); rated torque " << Num(j.rated_torque_Nm) << " N.m.\n";
  if (j.tilt_stiffness_Nm_per_rad > 0)
    m << "  // Output bearing moment (tilting) stiffness K_B about each axis across the reducer's, for a\n"
         "  // multibody model (Modelica.Mechanics.MultiBody); the rotational Joint below has no tilt.\n"
         "  constant Real tiltStiffness = "
      << Num(j.tilt_stiffness_Nm_per_rad) << " \"Output bearing moment stiffness [N.m/rad]\";\n";
  m << "\n";
  m << "  model Joint \"" << ModelicaString("Reducer: input inertia, lossy gear, elasticity with backlash") << "\"\n";
  m << "    Modelica.Mechanics.Rotational.Interfaces.Flange_a flange_a \"Input (motor side)\";\n";
  m << "    Modelica.Mechanics.Rotational.Interfaces.Flange_b flange_b \"Output\";\n";
  m << "    // Reflected inertia " << Num(j.reflected_inertia_kgm2) << " kg.m2 at the output, at the input: / ratio^2.\n";
  m << "    // Includes: " << ModelicaCommentText(j.inertia_includes) << "\n";
  m << "    Modelica.Mechanics.Rotational.Components.Inertia inputInertia(J = "
    << Num(j.reflected_inertia_kgm2 / (j.ratio * j.ratio)) << ") \"Input side inertia [kg.m2]\";\n";
  if (!j.loss_table.empty())
    m << "    // lossTable from the result's loss table: input speed [rad/s], forward and backward efficiency,\n"
         "    // friction torque at the input [N.m] (for both directions).\n";
  else if (j.has_efficiency)
    m << "    // lossTable: one row, the efficiency " << Num(j.efficiency)
      << " both ways and the no-load running torque " << Num(j.friction_torque_Nm) << " N.m / ratio at the input.\n";
  else if (j.friction_torque_Nm > 0)
    m << "    // lossTable: no efficiency given: a lossless mesh, with the no-load running torque "
      << Num(j.friction_torque_Nm) << " N.m / ratio at the input.\n";
  else
    m << "    // lossTable: no efficiency and no running torque given: lossless.\n";
  m << "    // Friction note: " << ModelicaCommentText(j.friction_note) << "\n";
  m << "    Modelica.Mechanics.Rotational.Components.LossyGear gear(ratio = " << Num(j.ratio) << ", lossTable = [";
  const std::vector<std::vector<double>> loss = ModelicaLossTable(j);
  for (size_t i = 0; i < loss.size(); ++i) {
    m << (i == 0 ? "" : "; ");
    for (size_t k = 0; k < loss[i].size(); ++k) m << (k == 0 ? "" : ", ") << Num(loss[i][k]);
  }
  m << "]) \"Ratio (input turns per output turn) and losses [|w_a|, eta_mf1, eta_mf2, |tau_bf1|, |tau_bf2|]\";\n";
  m << "    // Catalogue stiffness c [N.m/rad] (50 to 100 % slope; the segments and torsionCurve above for a\n";
  m << "    // nonlinear spring), damping d [N.m.s/rad] (" << ModelicaCommentText(j.damping_note)
    << "), backlash b [rad] (total free play).\n";
  m << "    Modelica.Mechanics.Rotational.Components.ElastoBacklash elastoBacklash(c = " << Num(j.stiffness_Nm_per_rad)
    << ", d = " << Num(j.damping_Nms_per_rad) << ", b = " << Num(j.backlash_rad)
    << ") \"Torsional stiffness, damping and backlash at the output\";\n";
  m << "  equation\n";
  m << "    connect(flange_a, inputInertia.flange_a);\n";
  m << "    connect(inputInertia.flange_b, gear.flange_a);\n";
  m << "    connect(gear.flange_b, elastoBacklash.flange_a);\n";
  m << "    connect(elastoBacklash.flange_b, flange_b);\n";
  m << "  end Joint;\n";
  m << "  annotation(uses(Modelica(version = \"4.0.0\")));\n";
  m << "end " << package << ";\n";
  return m.str();
}

nlohmann::ordered_json ExportJointJson(const ExportSource& s, const std::string& name) {
  const JointModel& j = s.joint;
  nlohmann::ordered_json out;
  out["camopt_version"] = s.camopt_version;
  out["study_sha256"] = s.study_sha256;
  out["study"] = s.study;
  out["name"] = s.name;
  out["exported_by_camopt_version"] = CamoptVersion();
  out["joint_name"] = name;
  out["ratio_input_per_output"] = j.ratio;
  out["rated_torque_Nm"] = j.rated_torque_Nm;
  out["stiffness_Nm_per_rad"] = j.stiffness_Nm_per_rad;
  out["stiffness_segments"] = {{"T1_Nm", j.T1_Nm},
                               {"T2_Nm", j.T2_Nm},
                               {"K1_Nm_per_rad", j.K1_Nm_per_rad},
                               {"K2_Nm_per_rad", j.K2_Nm_per_rad},
                               {"K3_Nm_per_rad", j.K3_Nm_per_rad}};
  nlohmann::ordered_json torque = nlohmann::ordered_json::array(), angle = nlohmann::ordered_json::array();
  for (const auto& [t, a] : j.torsion_curve) {
    torque.push_back(t);
    angle.push_back(a);
  }
  out["torsion_curve"] = {{"torque_Nm", torque}, {"angle_rad", angle}};
  out["backlash_rad"] = j.backlash_rad;
  out["lost_motion_rad"] = j.lost_motion_rad;
  out["lost_motion_percent"] = j.lost_motion_percent;
  out["reflected_inertia_kgm2"] = j.reflected_inertia_kgm2;
  out["inertia_includes"] = j.inertia_includes;
  out["damping_Nms_per_rad"] = j.damping_Nms_per_rad;
  out["damping_note"] = j.damping_note;
  out["friction_torque_Nm"] = j.friction_torque_Nm;
  out["friction_note"] = j.friction_note;
  out["efficiency_fraction"] = j.has_efficiency ? nlohmann::ordered_json(j.efficiency) : nlohmann::ordered_json();
  nlohmann::ordered_json table = nlohmann::ordered_json::array();
  for (const JointLossRow& r : j.loss_table)
    table.push_back({{"input_speed_rad_s", r.input_speed_rad_s},
                     {"efficiency_forward_fraction", r.efficiency_forward},
                     {"efficiency_backward_fraction", r.efficiency_backward},
                     {"friction_torque_input_Nm", r.friction_torque_input_Nm}});
  out["loss_table"] = table;
  out["tilt_stiffness_Nm_per_rad"] =
      j.tilt_stiffness_Nm_per_rad > 0 ? nlohmann::ordered_json(j.tilt_stiffness_Nm_per_rad) : nlohmann::ordered_json();
  out["tilt_note"] = j.tilt_note;
  return out;
}

ExportAnswer RunExport(const ExportRequest& request) {
  // The format first: a wrong --to is named before any file is read.
  const std::vector<std::string> formats = ExportFormats();
  if (std::find(formats.begin(), formats.end(), request.to) == formats.end()) {
    const std::string near = NearestName(request.to, formats);
    throw StudyError("--to: expected mujoco, modelica or json, found \"" + request.to + "\"" +
                     (near.empty() ? "" : " (did you mean \"" + near + "\"?)"));
  }
  if (request.result.empty()) throw StudyError("RESULT_DIR: expected the folder of a `camopt run` result, found nothing");
  std::error_code ec;
  const bool given_file = fs::is_regular_file(request.result, ec);
  const fs::path result_dir = given_file ? fs::path(request.result).parent_path() : fs::path(request.result);
  const std::string file = given_file ? request.result : (result_dir / "result.json").string();
  // A result.json of a long run is larger than a study: the cap is only against a device or a mistake.
  const nlohmann::json result = ParseStudyText(ReadFileCapped(file, size_t{1} << 30, "result"), file, 256);
  const ExportSource source = ParseExportSource(result, file);
  const std::string name = ExportJointName(request.name, result_dir.empty() ? "." : result_dir.string());

  const fs::path default_out = (result_dir.empty() ? fs::path(".") : result_dir) / "export";
  const std::string out_dir = request.out.empty() ? default_out.string() : request.out;
  CheckNotInside(file, out_dir, "result file");

  std::string file_name, text;
  if (request.to == "mujoco") {
    file_name = name + ".xml";
    text = ExportMujocoXml(source, name);
  } else if (request.to == "modelica") {
    file_name = ModelicaPackageName(name) + ".mo";
    text = ExportModelicaPackage(source, ModelicaPackageName(name));
  } else {
    file_name = "joint.json";
    text = ExportJointJson(source, name).dump(2) + "\n";
  }
  Outputs outputs;
  outputs.Add(file_name, text);
  // The other formats of an earlier export of this same result stay; anything else in the folder
  // (files of another result, this format under another name) goes with the swap. Only a folder
  // camopt may replace is read (its every file is one camopt wrote); any other is refused below.
  const auto same_format = [&](const std::string& f) {
    const std::string ext = fs::path(f).extension().string();
    return request.to == "mujoco" ? ext == ".xml" : request.to == "modelica" ? ext == ".mo" : f == "joint.json";
  };
  if (fs::is_directory(fs::symlink_status(out_dir, ec)) && NotReplaceable(out_dir).empty()) {
    for (const auto& entry : fs::directory_iterator(out_dir, ec)) {
      const std::string f = entry.path().filename().string();
      if (!entry.is_regular_file(ec) || f.empty() || f[0] == '.' || same_format(f)) continue;
      const std::string kept = ReadIfSmall(entry.path());
      if (kept.find(source.study_sha256) != std::string::npos && kept.find(source.camopt_version) != std::string::npos)
        outputs.Add(f, kept);
    }
  }
  OutputFolder folder(out_dir);
  // Before the swap: a listed folder that does not come to exist is harmless, an unlisted one
  // would keep the next `camopt run` from replacing RESULT_DIR.
  std::error_code same_ec;
  if (fs::weakly_canonical(fs::absolute(out_dir), same_ec) == fs::weakly_canonical(fs::absolute(default_out), same_ec))
    AddToManifest(default_out.parent_path().string(), "export/");
  folder.Commit(outputs);
  return {out_dir, (fs::path(out_dir) / file_name).string()};
}

}  // namespace camopt::studies
