// `camopt export` (studies/export.h, docs/export.md): the MJCF model loaded and simulated with the
// real MuJoCo (Debian's libmujoco-dev 2.2.2), the Modelica package read by a tokenizer and checked
// against hand-computed values, joint.json read back, and bad input refused by the CLI.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>
#include <nlohmann/json.hpp>

#include "studies/export.h"
#include "studies/input.h"
#include "studies/study.h"
#include "tests/test_util.h"

namespace export_test {

namespace fs = std::filesystem;
using camopt::testing::CliResult;
using camopt::testing::ReadFile;
using camopt::testing::RunCamopt;
using camopt::testing::SourcePath;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;

// A result.json written by hand against the joint_model contract: a 350 N m cycloid drive. The
// torsion curve is the three segments through the dead band ±b/2 = ±1.25e-4 rad:
// 1.25e-4 + 70/1.2e6 = 1.8333e-4, + 175/1.7e6 = 2.8627e-4, + 105/2.08e6 = 3.3675e-4 rad.
constexpr char kResult[] = R"({
  "study": "cycloid_ltca",
  "name": "A 350 N m cycloid drive -- by hand",
  "camopt_version": "0.1.0",
  "study_sha256": "7db5634c51b92eeb900d0202d26c5a6742fb944b9760c78a5d66a72ed31e2fed",
  "status": "limits_met",
  "torque_Nm": 350.0,
  "joint_model": {
    "ratio": 15.0,
    "rated_torque_Nm": 350.0,
    "stiffness_Nm_per_rad": 2.08e6,
    "stiffness_segments": {"T1_Nm": 70, "T2_Nm": 245, "K1_Nm_per_rad": 1.2e6, "K2_Nm_per_rad": 1.7e6,
                           "K3_Nm_per_rad": 2.08e6},
    "torsion_curve": [[-350, -3.3675e-4], [-245, -2.8627e-4], [-70, -1.8333e-4], [0, -1.25e-4],
                      [0, 1.25e-4], [70, 1.8333e-4], [245, 2.8627e-4], [350, 3.3675e-4]],
    "backlash_rad": 2.5e-4,
    "lost_motion_rad": 2.8e-4,
    "lost_motion_percent": 3,
    "reflected_inertia_kgm2": 0.012,
    "inertia_includes": "input shaft, eccentric bearings and both discs, reflected by ratio^2",
    "damping_Nms_per_rad": 0.5,
    "damping_note": "a \"typical\" value, not computed",
    "friction_torque_Nm": 1.5,
    "friction_note": "seal and bearing drag at 1000 rpm",
    "efficiency": 0.93,
    "loss_table": [
      {"input_speed_rad_s": 10.0, "efficiency_forward": 0.91, "efficiency_backward": 0.88,
       "friction_torque_input_Nm": 0.12},
      {"input_speed_rad_s": 100.0, "efficiency_forward": 0.93, "efficiency_backward": 0.9,
       "friction_torque_input_Nm": 0.15}
    ]
  }
})";

constexpr double kRatio = 15.0, kK = 2.08e6, kBacklash = 2.5e-4, kInertia = 0.012, kFriction = 1.5;
constexpr double kRated = 350.0;

nlohmann::json Fixture() { return nlohmann::json::parse(kResult); }

camopt::studies::ExportSource Source(const nlohmann::json& result = Fixture()) {
  return camopt::studies::ParseExportSource(result, "fixture/result.json");
}

// A result folder as `camopt run` leaves it: result.json and its list of what camopt wrote.
fs::path ResultDir(const std::string& tag, const nlohmann::json& result = Fixture()) {
  const fs::path dir = TempDir("export-" + tag) / "drive_350";
  fs::create_directories(dir);
  WriteFile(dir / "result.json", result.dump(2));
  camopt::studies::WriteManifest(dir.string(), {"result.json"});
  return dir;
}

// ---- MuJoCo ----------------------------------------------------------------------------------

std::string g_mujoco_warnings;
void CollectWarning(const char* text) { g_mujoco_warnings += std::string(text) + "\n"; }

struct Mj {
  mjModel* m = nullptr;
  mjData* d = nullptr;
  ~Mj() {
    if (d) mj_deleteData(d);
    if (m) mj_deleteModel(m);
  }
};

// Loads the exported MJCF from a file with mj_loadXML.
void Load(Mj& mj, const std::string& xml, const std::string& tag) {
  const fs::path file = TempDir("mjcf-" + tag) / "drive_350.xml";
  WriteFile(file, xml);
  char error[1000] = "";
  mju_user_warning = CollectWarning;
  mj.m = mj_loadXML(file.c_str(), nullptr, error, sizeof error);
  ASSERT_NE(mj.m, nullptr) << "mj_loadXML: " << error;
  EXPECT_STREQ(error, "") << "a warning while loading";
  mj.d = mj_makeData(mj.m);
}

int Id(const mjModel* m, int type, const std::string& name) {
  const int id = mj_name2id(m, type, name.c_str());
  EXPECT_GE(id, 0) << name;
  return id;
}

// The rotation about z of a body's world orientation [rad].
double AngleZ(const mjData* d, int body) {
  const mjtNum* q = d->xquat + 4 * body;
  return 2 * std::atan2(q[3], q[0]);
}

TEST(ExportMujoco, TheModelLoadsWithTheJointModelsParameters) {
  Mj mj;
  Load(mj, camopt::studies::ExportMujocoXml(Source(), "drive_350"), "parameters");
  const mjModel* m = mj.m;
  EXPECT_EQ(mj_version(), 222) << "the version the MJCF is written for (Debian 12's)";
  ASSERT_EQ(m->njnt, 3);
  ASSERT_EQ(m->nu, 1);
  const int motor = Id(m, mjOBJ_JOINT, "drive_350_motor_side"), play = Id(m, mjOBJ_JOINT, "drive_350_backlash"),
            spring = Id(m, mjOBJ_JOINT, "drive_350_elastic");
  for (int j : {motor, play, spring}) {
    EXPECT_EQ(m->jnt_type[j], mjJNT_HINGE);
    EXPECT_EQ(m->jnt_axis[3 * j + 2], 1.0);
  }
  // Every number read back exactly: the file writes the shortest text of each double.
  EXPECT_EQ(m->dof_armature[m->jnt_dofadr[motor]], kInertia);
  EXPECT_EQ(m->dof_frictionloss[m->jnt_dofadr[motor]], kFriction);
  EXPECT_EQ(m->dof_damping[m->jnt_dofadr[motor]], 0.5);
  EXPECT_EQ(m->jnt_limited[play], 1);
  EXPECT_EQ(m->jnt_range[2 * play], -kBacklash / 2);
  EXPECT_EQ(m->jnt_range[2 * play + 1], kBacklash / 2);
  EXPECT_EQ(m->jnt_limited[spring], 0);
  EXPECT_EQ(m->jnt_stiffness[spring], kK);
  EXPECT_EQ(m->qpos_spring[m->jnt_qposadr[spring]], 0.0);
  EXPECT_EQ(m->actuator_gear[0], kRatio);
  EXPECT_EQ(m->actuator_trnid[0], motor);
  // The motor torque at the input, times the ratio, on the motor side.
  mj.d->ctrl[0] = 2.0;
  mj_forward(m, mj.d);
  EXPECT_DOUBLE_EQ(mj.d->qfrc_actuator[m->jnt_dofadr[motor]], 2.0 * kRatio);
  EXPECT_EQ(g_mujoco_warnings, "");
}

// The static state under a torque T on the output body, the motor side held.
struct Rest {
  double rotation = 0.0;          ///< output body relative to the motor-side body [rad]
  double motor_drift = 0.0;       ///< the held motor side's own rotation [rad]
  double max_speed = 0.0;         ///< the largest |qvel| at the end [rad/s]
  double limit_yield = 0.0;       ///< predicted penetration of the soft limit [rad]
  bool limit_free_inside = true;  ///< no limit force while |backlash joint| < b/2
};

// Simulates the exported model with a step torque T on the output body for `seconds`. The motor
// side is held by the model's own motor: ctrl = -T/ratio, so that the actuator (gear = ratio)
// takes the reaction -T; with `flywheel` > 1 the motor side's armature is multiplied by it as well,
// so that the transient does not turn it either (1e6: 12 000 kg m2). Not more: MuJoCo scales its
// solver's tolerance by the mean inertia, and at 1e9 the solver stops early and the limit chatters.
// The only other change is a damping on the elastic joint (the export has none), critical for the
// output on the spring, so that the model comes to rest; the static answer does not depend on it.
// The joint a model is exported from: the fixture's, or a run's (ExportMujoco.ARunOfTheCatalogue…).
struct Joint {
  std::string xml, name = "drive_350";
  double stiffness = kK, ratio = kRatio, inertia = kInertia;
};

Rest SimulateToRest(double torque, double flywheel, double seconds = 0.3, const Joint* joint = nullptr) {
  Joint fixture;
  if (!joint) {
    fixture.xml = camopt::studies::ExportMujocoXml(Source(), "drive_350");
    joint = &fixture;
  }
  const std::string& name = joint->name;
  const double stiffness = joint->stiffness, ratio = joint->ratio, inertia = joint->inertia;
  Mj mj;
  Load(mj, joint->xml, "rest");
  mjModel* m = mj.m;
  mjData* d = mj.d;
  if (!m) return {};
  const int motor_dof = m->jnt_dofadr[Id(m, mjOBJ_JOINT, name + "_motor_side")];
  const int play = Id(m, mjOBJ_JOINT, name + "_backlash");
  const int spring_dof = m->jnt_dofadr[Id(m, mjOBJ_JOINT, name + "_elastic")];
  const int motor_body = Id(m, mjOBJ_BODY, name + "_motor_side"), out = Id(m, mjOBJ_BODY, name + "_output");
  m->dof_armature[motor_dof] *= flywheel;
  const double i_out = 0.1 * inertia;  // the export's stand-in inertia of the output body
  m->dof_damping[spring_dof] = 2 * std::sqrt(stiffness * i_out);
  mj_setConst(m, d);  // invweight0 with the flywheel
  d->xfrc_applied[6 * out + 5] = torque;  // a torque about z on the output body, world frame
  d->ctrl[0] = -torque / ratio;
  const int steps = static_cast<int>(seconds / m->opt.timestep);
  Rest r;
  for (int s = 0; s < steps; ++s) {
    // The constraints of a step are those of the state it starts from.
    const double q = d->qpos[m->jnt_qposadr[play]];
    mj_step(m, d);
    if (std::abs(q) < kBacklash / 2 * 0.999)
      for (int i = 0; i < d->nefc; ++i)
        if (d->efc_type[i] == mjCNSTR_LIMIT_JOINT && d->efc_force[i] != 0) r.limit_free_inside = false;
  }
  mj_forward(m, d);
  r.rotation = AngleZ(d, out) - AngleZ(d, motor_body);
  r.motor_drift = AngleZ(d, motor_body);
  for (int i = 0; i < m->nv; ++i) r.max_speed = std::max(r.max_speed, std::abs(d->qvel[i]));
  // The soft limit at rest. MuJoCo's constraint force f solves (A + R) f = a_ref - a0; at rest the
  // acceleration a0 + A f is 0, so R f = a_ref, with R = (1 - imp)/imp * invweight0 and
  // a_ref = -imp r / (dmax^2 tc^2 dampratio^2); imp = dmax = 0.9999 (solimplimit flat): the limit
  // yields r = (1 - imp) tc^2 dampratio^2 invweight0 |T| beyond b/2.
  const double tc = std::max(m->jnt_solref[mjNREF * play], 2 * m->opt.timestep);
  const double imp = m->jnt_solimp[mjNIMP * play], zeta = m->jnt_solref[mjNREF * play + 1];
  r.limit_yield = (1 - imp) * tc * tc * zeta * zeta * m->dof_invweight0[m->jnt_dofadr[play]] * std::abs(torque);
  for (int w = 0; w < mjNWARNING; ++w) EXPECT_EQ(d->warning[w].number, 0) << "MuJoCo warning " << w;
  return r;
}

// The output turns by backlash/2 + T/K under a torque T, the motor side held, for two torques and
// both signs: with the flywheel (the motor side held: it turns by < 1e-6 of the rotation), and in
// the model as exported (only the damping added: the actuator balances the motor side, which then
// moves in the transient, ~1e-4 rad; the rotation is taken relative to it). Tolerance:
// the soft limit's own yield, predicted from the model's constants above (about 2.4e-11 rad per
// N m here: 8.2e-9 rad at 350 N m, 2.8e-5 of the rotation), plus 1e-12 rad for the solver; the
// deviation must also be that yield (within 1 %): the model is understood, not just close.
TEST(ExportMujoco, StaticRotationIsHalfTheBacklashPlusTorqueOverStiffness) {
  for (double flywheel : {1.0, 1e6})
    for (double torque : {0.5 * kRated, kRated, -0.5 * kRated, -kRated}) {
      SCOPED_TRACE("T = " + std::to_string(torque) + " N m, flywheel x" + std::to_string(flywheel));
      const Rest r = SimulateToRest(torque, flywheel);
      const double expected = std::copysign(kBacklash / 2, torque) + torque / kK;
      std::printf("[ export   ] flywheel x%g, T = %+6.1f N m: rotation %.10e rad, b/2 + T/K %.10e rad, "
                  "difference %+.4e rad, predicted limit yield %.4e rad, motor side %+.1e rad, max |qvel| %.0e rad/s\n",
                  flywheel, torque, r.rotation, expected, r.rotation - expected, r.limit_yield, r.motor_drift,
                  r.max_speed);
      EXPECT_LT(r.max_speed, 1e-9) << "at rest";
      if (flywheel > 1) {
        EXPECT_LT(std::abs(r.motor_drift), 1e-6 * std::abs(expected)) << "the motor side held";
      }
      EXPECT_NEAR(r.rotation, expected, r.limit_yield + 1e-12);
      EXPECT_NEAR(std::abs(r.rotation) - std::abs(expected), r.limit_yield, 0.01 * r.limit_yield + 1e-13);
      EXPECT_LT(r.limit_yield, 1e-4 * std::abs(expected)) << "the limit is far stiffer than the spring";
    }
}

// The dead band the model has is the backlash: a tiny torque (1e-4 of the rated) takes the output
// across to +b/2 and, reversed, to -b/2 with no limit force inside the band; the band measured
// between the two rests, less the spring's 2 T/K, equals the fixture's backlash within the two
// rests' limit yields (8e-13 rad each) and 1e-12 rad.
TEST(ExportMujoco, TinyTorquesCrossTheDeadBandFreely) {
  const double tiny = 1e-4 * kRated;
  const Rest up = SimulateToRest(tiny, 1e6), down = SimulateToRest(-tiny, 1e6);
  const double band = up.rotation - down.rotation - 2 * tiny / kK;
  std::printf("[ export   ] T = +/-%.3f N m: rests at %+.12e and %+.12e rad; band less 2T/K %.12e rad "
              "(backlash %.3e rad, difference %+.1e rad)\n",
              tiny, up.rotation, down.rotation, band, kBacklash, band - kBacklash);
  EXPECT_TRUE(up.limit_free_inside);
  EXPECT_TRUE(down.limit_free_inside);
  EXPECT_LT(up.max_speed, 1e-9);
  EXPECT_LT(down.max_speed, 1e-9);
  EXPECT_NEAR(band, kBacklash, up.limit_yield + down.limit_yield + 1e-12);
  EXPECT_NEAR(up.rotation, kBacklash / 2 + tiny / kK, up.limit_yield + 1e-12);
  EXPECT_NEAR(down.rotation, -kBacklash / 2 - tiny / kK, down.limit_yield + 1e-12);
}

// A joint exported from a real run, not a fixture: the catalogue example (coarse) run by the CLI
// and exported by the CLI; MuJoCo loads it with the run's stiffness, dead band and inertia, and a
// step of the rated torque turns the output by backlash/2 + T/K (K the catalogue slope the joint
// takes) within the limit's predicted yield.
TEST(ExportMujoco, ARunOfTheCatalogueExampleLoadsAndDeflectsAsItsResultSays) {
  nlohmann::json study = nlohmann::json::parse(ReadFile(SourcePath("studies/examples/cycloid_catalogue.json")));
  study["analysis"]["grid"] = {16, 16};
  study["analysis"]["crank_angles_per_mesh_period"] = 4;
  study["analysis"]["estimate_error"] = false;
  study["geometry_files"] = false;
  study.erase("ratings");
  study.erase("output_bearing");
  study.erase("external_loads");
  const fs::path dir = TempDir("export-real-run");
  WriteFile(dir / "study.json", study.dump());
  const CliResult run = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " + (dir / "out").string());
  ASSERT_EQ(run.exit_code, 0) << run.stderr_text;
  const CliResult exported = RunCamopt("export " + (dir / "out").string() + " --to mujoco --name drive");
  ASSERT_EQ(exported.exit_code, 0) << exported.stderr_text;
  const nlohmann::json r = nlohmann::json::parse(ReadFile(dir / "out" / "result.json"));
  const nlohmann::json& j = r["joint_model"];
  Joint joint;
  joint.name = "drive";
  joint.xml = ReadFile(dir / "out" / "export" / "drive.xml");
  joint.stiffness = j["stiffness_Nm_per_rad"].get<double>();
  joint.ratio = j["ratio"].get<double>();
  joint.inertia = j["reflected_inertia_kgm2"].get<double>();
  const double backlash = j["backlash_rad"].get<double>();
  // The numbers the run's report gives, in the joint's units.
  const double arcmin = 60.0 * 180.0 / M_PI;
  EXPECT_NEAR(joint.stiffness, r["torsional_stiffness_Nm_per_arcmin"].get<double>() * arcmin, 1e-9 * joint.stiffness);
  EXPECT_NEAR(backlash * arcmin, r["backlash_arcmin"].get<double>(), 1e-12);
  Mj mj;
  Load(mj, joint.xml, "real");
  ASSERT_NE(mj.m, nullptr);
  const int play = Id(mj.m, mjOBJ_JOINT, "drive_backlash"), spring = Id(mj.m, mjOBJ_JOINT, "drive_elastic");
  EXPECT_DOUBLE_EQ(mj.m->jnt_stiffness[spring], joint.stiffness);
  EXPECT_DOUBLE_EQ(mj.m->jnt_range[2 * play + 1] - mj.m->jnt_range[2 * play], backlash);
  const double t = 350.0;
  const Rest rest = SimulateToRest(t, 1e6, 0.3, &joint);
  const double expected = backlash / 2 + t / joint.stiffness;
  std::printf("[ export   ] cycloid_catalogue run: T = %.0f N m, rotation %.10e rad, b/2 + T/K %.10e rad, yield %.2e\n",
              t, rest.rotation, expected, rest.limit_yield);
  EXPECT_LT(rest.max_speed, 1e-9);
  EXPECT_NEAR(rest.rotation, expected, rest.limit_yield + 1e-12);
}

TEST(ExportMujoco, NoBacklashNoDeadBandJoint) {
  nlohmann::json result = Fixture();
  result["joint_model"]["backlash_rad"] = 0.0;
  Mj mj;
  Load(mj, camopt::studies::ExportMujocoXml(Source(result), "drive_350"), "no-backlash");
  ASSERT_NE(mj.m, nullptr);
  EXPECT_EQ(mj.m->njnt, 2);
  EXPECT_EQ(mj_name2id(mj.m, mjOBJ_JOINT, "drive_350_backlash"), -1);
}

// The output bearing's moment stiffness K_B (joint_model.tilt_stiffness_Nm_per_rad, SHA32A-SG's
// 100e4 N m/rad): two hinges on the output body about x and y, each with stiffness K_B. A moment
// M about x on the output body, at rest (critical damping added to the tilt hinges, as the elastic
// one above), tilts it by M/K_B about x and not about y or z; the hinges add no torsional
// compliance (a torque about z still turns it by b/2 + T/K). Without the field there is no tilt
// hinge (NoBacklashNoDeadBandJoint's count).
TEST(ExportMujoco, OutputBearingTiltStiffnessTiltsTheOutputByMomentOverKb) {
  constexpr double kKb = 1.0e6, kMoment = 300.0;
  nlohmann::json result = Fixture();
  result["joint_model"]["tilt_stiffness_Nm_per_rad"] = kKb;
  result["joint_model"]["tilt_note"] = "catalogue K_B";
  const std::string xml = camopt::studies::ExportMujocoXml(Source(result), "drive_350");
  Mj mj;
  Load(mj, xml, "tilt");
  ASSERT_NE(mj.m, nullptr);
  mjModel* m = mj.m;
  mjData* d = mj.d;
  EXPECT_EQ(m->njnt, 5);
  const int tx = Id(m, mjOBJ_JOINT, "drive_350_tilt_x"), ty = Id(m, mjOBJ_JOINT, "drive_350_tilt_y");
  const int out = Id(m, mjOBJ_BODY, "drive_350_output");
  EXPECT_EQ(m->jnt_stiffness[tx], kKb);
  EXPECT_EQ(m->jnt_stiffness[ty], kKb);
  const double i_tilt = 0.6 * 0.1 * kInertia;  // the output body's stand-in inertia about x and y
  // The tilt mode on K_B is the stiffest: the time step is a quarter of its stability bound.
  EXPECT_LE(m->opt.timestep, 0.5 / std::sqrt(kKb / i_tilt));
  for (int j : {tx, ty}) m->dof_damping[m->jnt_dofadr[j]] = 2 * std::sqrt(kKb * i_tilt);
  d->xfrc_applied[6 * out + 3] = kMoment;  // a moment about x on the output body, world frame
  const int steps = static_cast<int>(0.05 / m->opt.timestep);
  for (int k = 0; k < steps; ++k) mj_step(m, d);
  mj_forward(m, d);
  const double qx = d->qpos[m->jnt_qposadr[tx]], qy = d->qpos[m->jnt_qposadr[ty]];
  std::printf("[ export   ] tilt under %.0f N m: %.10e rad, M/K_B %.10e rad, about y %.1e rad\n", kMoment, qx,
              kMoment / kKb, qy);
  EXPECT_NEAR(qx, kMoment / kKb, 1e-9 * kMoment / kKb);
  EXPECT_NEAR(qy, 0.0, 1e-12);
  const mjtNum* q = d->xquat + 4 * out;  // the body's world orientation: a rotation about x only
  EXPECT_NEAR(2 * std::atan2(q[1], q[0]), kMoment / kKb, 1e-9 * kMoment / kKb);
  for (int w = 0; w < mjNWARNING; ++w) EXPECT_EQ(d->warning[w].number, 0) << "MuJoCo warning " << w;
  // The same model turns by b/2 + T/K under a torque about z.
  Joint joint;
  joint.xml = xml;
  const Rest r = SimulateToRest(kRated, 1e6, 0.3, &joint);
  EXPECT_NEAR(r.rotation, kBacklash / 2 + kRated / kK, r.limit_yield + 1e-12);
  // joint.json and the Modelica package carry it too.
  EXPECT_EQ(camopt::studies::ExportJointJson(Source(result), "drive_350")["tilt_stiffness_Nm_per_rad"], kKb);
  EXPECT_TRUE(camopt::studies::ExportJointJson(Source(), "drive_350")["tilt_stiffness_Nm_per_rad"].is_null());
  EXPECT_NE(camopt::studies::ExportModelicaPackage(Source(result), "Drive350").find("tiltStiffness = 1000000"),
            std::string::npos);
}

// ---- Modelica --------------------------------------------------------------------------------

struct Token {
  enum Kind { kIdent, kNumber, kString, kSymbol } kind;
  std::string text;
};

// Modelica 3 lexical structure: identifiers, unsigned numbers, strings with \ escapes, // and /* */
// comments, one- and two-character symbols. Fails the test on a character outside it.
std::vector<Token> Tokenize(const std::string& s) {
  std::vector<Token> out;
  size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (s.compare(i, 2, "//") == 0) {
      i = s.find('\n', i);
      if (i == std::string::npos) i = s.size();
    } else if (s.compare(i, 2, "/*") == 0) {
      const size_t end = s.find("*/", i + 2);
      EXPECT_NE(end, std::string::npos) << "unterminated comment";
      i = end == std::string::npos ? s.size() : end + 2;
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      size_t j = i;
      while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
      out.push_back({Token::kIdent, s.substr(i, j - i)});
      i = j;
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      size_t j = i;
      while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
      if (j < s.size() && s[j] == '.') ++j;
      while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
      if (j < s.size() && (s[j] == 'e' || s[j] == 'E')) {
        ++j;
        if (j < s.size() && (s[j] == '+' || s[j] == '-')) ++j;
        const size_t digits = j;
        while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j]))) ++j;
        EXPECT_GT(j, digits) << "exponent without digits at " << i;
      }
      out.push_back({Token::kNumber, s.substr(i, j - i)});
      i = j;
    } else if (c == '"') {
      size_t j = i + 1;
      while (j < s.size() && s[j] != '"') j += s[j] == '\\' ? 2 : 1;
      EXPECT_LT(j, s.size()) << "unterminated string";
      out.push_back({Token::kString, s.substr(i + 1, j - i - 1)});
      i = j + 1;
    } else if (std::string("()[]{};,=.:+-*/^<>").find(c) != std::string::npos) {
      out.push_back({Token::kSymbol, std::string(1, c)});
      ++i;
    } else {
      ADD_FAILURE() << "a character outside Modelica's tokens: '" << c << "' at " << i;
      ++i;
    }
  }
  return out;
}

// The structure a Modelica parser checks first: (), [] and {} balanced and properly nested; every
// class (package, model, …) closed by `end NAME;` with its own name; `;` only at statement level or
// between matrix rows inside []; the file one class, `package_name`. Returns the classes seen.
std::vector<std::string> CheckStructure(const std::vector<Token>& t, const std::string& package_name) {
  static const std::set<std::string> class_words = {"package", "model", "block", "connector", "record",
                                                    "function", "type", "class"};
  std::vector<std::string> classes, open;
  std::string brackets;
  for (size_t i = 0; i < t.size(); ++i) {
    const Token& k = t[i];
    if (k.kind == Token::kSymbol && (k.text == "(" || k.text == "[" || k.text == "{")) brackets += k.text;
    if (k.kind == Token::kSymbol && (k.text == ")" || k.text == "]" || k.text == "}")) {
      const char want = k.text == ")" ? '(' : k.text == "]" ? '[' : '{';
      EXPECT_TRUE(!brackets.empty() && brackets.back() == want) << "unbalanced " << k.text << " at token " << i;
      if (!brackets.empty()) brackets.pop_back();
    }
    if (k.kind == Token::kSymbol && k.text == ";") {
      EXPECT_TRUE(brackets.empty() || brackets.back() == '[') << "; inside " << brackets << " at token " << i;
    }
    if (k.kind == Token::kIdent && class_words.count(k.text) && (i == 0 || t[i - 1].text != "end")) {
      EXPECT_TRUE(brackets.empty()) << k.text << " inside brackets";
      if (i + 1 >= t.size()) {
        ADD_FAILURE() << k.text << " at the end of the file";
        break;
      }
      EXPECT_EQ(t[i + 1].kind, Token::kIdent) << k.text << " without a name";
      open.push_back(t[i + 1].text);
      classes.push_back(t[i + 1].text);
    }
    if (k.kind == Token::kIdent && k.text == "end") {
      if (i + 2 >= t.size() || open.empty()) {
        ADD_FAILURE() << "end at token " << i << " without a class or at the end of the file";
        break;
      }
      EXPECT_EQ(t[i + 1].text, open.back()) << "end of the wrong class";
      EXPECT_EQ(t[i + 2].text, ";") << "end " << t[i + 1].text << " without ;";
      open.pop_back();
    }
  }
  EXPECT_TRUE(brackets.empty()) << "unclosed " << brackets;
  EXPECT_TRUE(open.empty()) << "unclosed class " << (open.empty() ? "" : open.back());
  EXPECT_FALSE(t.empty());
  if (t.size() >= 2) {
    EXPECT_EQ(t[0].text, "package");
    EXPECT_EQ(t[1].text, package_name);
    EXPECT_EQ(t.back().text, ";");
  }
  return classes;
}

// The text of a component's modifier: the tokens between "NAME(" and its ")".
std::vector<Token> Modifier(const std::vector<Token>& t, const std::string& type, const std::string& name) {
  for (size_t i = 0; i + 2 < t.size(); ++i) {
    if (t[i].text != name || t[i + 1].text != "(" || i < 1 || t[i - 1].text != type) continue;
    int depth = 0;
    for (size_t j = i + 1; j < t.size(); ++j) {
      depth += t[j].text == "(" ? 1 : t[j].text == ")" ? -1 : 0;
      if (depth == 0) return std::vector<Token>(t.begin() + long(i) + 2, t.begin() + long(j));
    }
  }
  ADD_FAILURE() << "no component " << type << " " << name << "(...)";
  return {};
}

// A scalar modification "key = NUMBER" (with an optional minus) in a modifier.
double ScalarIn(const std::vector<Token>& mod, const std::string& key) {
  for (size_t i = 0; i + 2 < mod.size(); ++i)
    if (mod[i].text == key && mod[i + 1].text == "=") {
      const bool minus = mod[i + 2].text == "-";
      return (minus ? -1 : 1) * std::stod(mod[i + 2 + (minus ? 1 : 0)].text);
    }
  ADD_FAILURE() << "no " << key << " = number";
  return NAN;
}

// The rows of "key = [a, b; c, d]" in a modifier.
std::vector<std::vector<double>> MatrixIn(const std::vector<Token>& mod, const std::string& key) {
  std::vector<std::vector<double>> rows;
  for (size_t i = 0; i + 2 < mod.size(); ++i) {
    if (mod[i].text != key || mod[i + 1].text != "=" || mod[i + 2].text != "[") continue;
    rows.emplace_back();
    double sign = 1;
    for (size_t j = i + 3; j < mod.size() && mod[j].text != "]"; ++j) {
      if (mod[j].text == ";") {
        rows.emplace_back();
      } else if (mod[j].text == "-") {
        sign = -1;
      } else if (mod[j].kind == Token::kNumber) {
        rows.back().push_back(sign * std::stod(mod[j].text));
        sign = 1;
      } else {
        EXPECT_EQ(mod[j].text, ",");
      }
    }
    return rows;
  }
  ADD_FAILURE() << "no " << key << " = [...]";
  return rows;
}

const char kLossyGear[] = "LossyGear", kElastoBacklash[] = "ElastoBacklash";

// The package parses as Modelica's structure, and its gear and elasticity carry the joint model's
// values, computed here by hand from the fixture: the loss table's first row [10 rad/s, 0.91,
// 0.88, 0.12 N m, 0.12 N m]; c = 2.08e6 N m/rad, b = 2.5e-4 rad; J at the input 0.012/15^2.
TEST(ExportModelica, PackageParsesAndCarriesTheLossTableStiffnessAndBacklash) {
  const std::string text = camopt::studies::ExportModelicaPackage(Source(), "Drive350");
  const std::vector<Token> t = Tokenize(text);
  const std::vector<std::string> classes = CheckStructure(t, "Drive350");
  EXPECT_EQ(classes, (std::vector<std::string>{"Drive350", "Joint"}));
  // MSL 4.0 class names, each component by its full name.
  for (const char* name : {"Modelica.Mechanics.Rotational.Components.LossyGear gear(",
                           "Modelica.Mechanics.Rotational.Components.ElastoBacklash elastoBacklash(",
                           "Modelica.Mechanics.Rotational.Components.Inertia inputInertia(",
                           "Modelica.Mechanics.Rotational.Interfaces.Flange_a flange_a",
                           "Modelica.Mechanics.Rotational.Interfaces.Flange_b flange_b",
                           "annotation(uses(Modelica(version = \"4.0.0\")))"})
    EXPECT_NE(text.find(name), std::string::npos) << name;
  const auto gear = Modifier(t, kLossyGear, "gear");
  EXPECT_EQ(ScalarIn(gear, "ratio"), 15.0);
  const auto loss = MatrixIn(gear, "lossTable");
  ASSERT_EQ(loss.size(), 2u);
  EXPECT_EQ(loss[0], (std::vector<double>{10.0, 0.91, 0.88, 0.12, 0.12}));
  EXPECT_EQ(loss[1], (std::vector<double>{100.0, 0.93, 0.9, 0.15, 0.15}));
  const auto elastic = Modifier(t, kElastoBacklash, "elastoBacklash");
  EXPECT_EQ(ScalarIn(elastic, "c"), 2.08e6);
  EXPECT_EQ(ScalarIn(elastic, "b"), 2.5e-4);
  EXPECT_EQ(ScalarIn(elastic, "d"), 0.5);
  EXPECT_DOUBLE_EQ(ScalarIn(Modifier(t, "Inertia", "inputInertia"), "J"), 0.012 / 225);
  // The torsion curve as {angle, torque} rows by ascending angle, the dead band its two rows at 0.
  std::vector<std::vector<double>> curve;
  for (size_t i = 0; i + 1 < t.size(); ++i)
    if (t[i].text == "torsionCurve" && t[i + 1].text == "[") {
      std::vector<Token> rest(t.begin() + long(i), t.end());
      rest.erase(rest.begin() + 1, rest.begin() + 6);  // "[", ":", ",", "2", "]"
      curve = MatrixIn(rest, "torsionCurve");
    }
  ASSERT_EQ(curve.size(), 8u);
  EXPECT_EQ(curve[3], (std::vector<double>{-1.25e-4, 0.0}));
  EXPECT_EQ(curve[4], (std::vector<double>{1.25e-4, 0.0}));
  EXPECT_EQ(curve[7], (std::vector<double>{3.3675e-4, 350.0}));
  // Provenance as comments.
  EXPECT_NE(text.find("// study_sha256: 7db5634c51b92eeb900d0202d26c5a6742fb944b9760c78a5d66a72ed31e2fed"),
            std::string::npos);
  EXPECT_NE(text.find("// camopt_version: 0.1.0"), std::string::npos);
}

// Without a loss table the one row comes from the efficiency and the no-load running torque
// referred to the input: [0, 0.93, 0.93, 1.5/15 = 0.1, 0.1]; without an efficiency, a lossless
// mesh with that torque; with neither, Modelica's lossless [0, 1, 1, 0, 0].
TEST(ExportModelica, OneLossRowFromTheEfficiencyOrLossless) {
  nlohmann::json result = Fixture();
  result["joint_model"]["loss_table"] = nlohmann::json::array();
  auto rows = [&] {
    const std::vector<Token> t = Tokenize(camopt::studies::ExportModelicaPackage(Source(result), "Drive350"));
    CheckStructure(t, "Drive350");
    return MatrixIn(Modifier(t, kLossyGear, "gear"), "lossTable");
  };
  EXPECT_EQ(rows(), (std::vector<std::vector<double>>{{0.0, 0.93, 0.93, 0.1, 0.1}}));
  result["joint_model"]["efficiency"] = nullptr;
  EXPECT_EQ(rows(), (std::vector<std::vector<double>>{{0.0, 1.0, 1.0, 0.1, 0.1}}));
  result["joint_model"]["friction_torque_Nm"] = 0;
  EXPECT_EQ(rows(), (std::vector<std::vector<double>>{{0.0, 1.0, 1.0, 0.0, 0.0}}));
}

TEST(ExportModelica, NamesAreModelicaIdentifiers) {
  EXPECT_EQ(camopt::studies::ModelicaPackageName("cycloid_datasheet_nnm"), "CycloidDatasheetNnm");
  EXPECT_EQ(camopt::studies::ModelicaPackageName("real"), "RealReducer");
  EXPECT_EQ(camopt::studies::ExportJointName("", "/tmp/x/lcr ii-2/"), "lcr_ii_2");
  EXPECT_EQ(camopt::studies::ExportJointName("", "/tmp/x/2024_run"), "joint_2024_run");
  EXPECT_THROW(camopt::studies::ExportJointName("my joint", "."), camopt::studies::StudyError);
}

// ---- joint.json and the command line ---------------------------------------------------------

// joint.json holds every number of joint_model exactly (and the provenance), under keys with units.
TEST(ExportJson, EveryNumberEqualsTheResults) {
  const fs::path dir = ResultDir("json");
  const auto r = RunCamopt("export " + dir.string() + " --to json");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const nlohmann::json out = nlohmann::json::parse(ReadFile(dir / "export" / "joint.json"));
  const nlohmann::json in = Fixture(), &j = in["joint_model"];
  EXPECT_EQ(out["camopt_version"], in["camopt_version"]);
  EXPECT_EQ(out["study_sha256"], in["study_sha256"]);
  EXPECT_EQ(out["study"], in["study"]);
  EXPECT_EQ(out["name"], in["name"]);
  // Every number of joint_model, where joint.json has it.
  int compared = 0;
  auto same = [&](const nlohmann::json& a, const nlohmann::json& b, const std::string& what) {
    ASSERT_TRUE(a.is_number()) << what;
    EXPECT_EQ(a.get<double>(), b.get<double>()) << what;
    ++compared;
  };
  const std::map<std::string, std::string> renamed = {{"ratio", "ratio_input_per_output"},
                                                      {"efficiency", "efficiency_fraction"}};
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string key = renamed.count(it.key()) ? renamed.at(it.key()) : it.key();
    ASSERT_TRUE(out.contains(key)) << key;
    if (it->is_number()) {
      same(out[key], *it, key);
    } else if (it->is_string()) {
      EXPECT_EQ(out[key], *it) << key;
    }
  }
  for (auto it = j["stiffness_segments"].begin(); it != j["stiffness_segments"].end(); ++it)
    same(out["stiffness_segments"][it.key()], *it, it.key());
  const auto& curve = j["torsion_curve"];
  ASSERT_EQ(out["torsion_curve"]["torque_Nm"].size(), curve.size());
  ASSERT_EQ(out["torsion_curve"]["angle_rad"].size(), curve.size());
  for (size_t i = 0; i < curve.size(); ++i) {
    same(out["torsion_curve"]["torque_Nm"][i], curve[i][0], "torque " + std::to_string(i));
    same(out["torsion_curve"]["angle_rad"][i], curve[i][1], "angle " + std::to_string(i));
  }
  const std::map<std::string, std::string> row_keys = {{"input_speed_rad_s", "input_speed_rad_s"},
                                                       {"efficiency_forward", "efficiency_forward_fraction"},
                                                       {"efficiency_backward", "efficiency_backward_fraction"},
                                                       {"friction_torque_input_Nm", "friction_torque_input_Nm"}};
  ASSERT_EQ(out["loss_table"].size(), j["loss_table"].size());
  for (size_t i = 0; i < j["loss_table"].size(); ++i)
    for (const auto& [from, to] : row_keys) same(out["loss_table"][i][to], j["loss_table"][i][from], to);
  // 10 scalars + 5 segments + 16 curve + 8 loss-table numbers: all of joint_model's.
  EXPECT_EQ(compared, 39);
  // And joint.json has no other number: its numbers are exactly those.
  int numbers = 0;
  std::function<void(const nlohmann::json&)> count = [&](const nlohmann::json& v) {
    if (v.is_number()) ++numbers;
    if (v.is_structured())
      for (const auto& e : v) count(e);
  };
  count(out);
  EXPECT_EQ(numbers, compared);
  // A null efficiency stays null.
  nlohmann::json none = Fixture();
  none["joint_model"]["efficiency"] = nullptr;
  EXPECT_TRUE(camopt::studies::ExportJointJson(Source(none), "x")["efficiency_fraction"].is_null());
}

// All three formats into RESULT_DIR/export: each export keeps the others of the same result, the
// folder is on the result's list (the next `camopt run` may replace the result folder), and an
// export of another result into the same folder drops them.
TEST(ExportCli, FormatsShareTheExportFolderAndTheResultStaysReplaceable) {
  const fs::path dir = ResultDir("cli");
  for (const char* to : {"mujoco", "modelica", "json"}) {
    const auto r = RunCamopt("export " + dir.string() + " --to " + to);
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  }
  EXPECT_TRUE(fs::is_regular_file(dir / "export" / "drive_350.xml"));
  EXPECT_TRUE(fs::is_regular_file(dir / "export" / "Drive350.mo"));
  EXPECT_TRUE(fs::is_regular_file(dir / "export" / "joint.json"));
  EXPECT_EQ(camopt::studies::NotReplaceable(dir), "");
  EXPECT_NE(ReadFile(dir / ".camopt_manifest").find("export/"), std::string::npos);
  // The result's own file as RESULT_DIR, and --name.
  auto r = RunCamopt("export " + (dir / "result.json").string() + " --to mujoco --name arm_joint_2");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_TRUE(fs::is_regular_file(dir / "export" / "arm_joint_2.xml"));
  EXPECT_FALSE(fs::exists(dir / "export" / "drive_350.xml")) << "the same format under another name goes";
  EXPECT_TRUE(fs::is_regular_file(dir / "export" / "Drive350.mo"));
  // Another result into the same folder: the first result's files go.
  nlohmann::json other = Fixture();
  other["study_sha256"] = std::string(64, 'a');
  const fs::path dir2 = ResultDir("cli-other", other);
  r = RunCamopt("export " + dir2.string() + " --to json --out " + (dir / "export").string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  EXPECT_TRUE(fs::is_regular_file(dir / "export" / "joint.json"));
  EXPECT_FALSE(fs::exists(dir / "export" / "Drive350.mo"));
  EXPECT_FALSE(fs::exists(dir / "export" / "arm_joint_2.xml"));
}

// Bad input: exit 2, one line naming the file and the JSON path, what was expected and found, and
// nothing written.
TEST(ExportCli, BadInputExitsTwoNamingThePath) {
  struct Case {
    std::string tag, args_after_dir, expect;
    std::function<void(nlohmann::json&)> change;
    std::string raw;  // instead of the JSON: this text as result.json
  };
  const std::vector<Case> cases = {
      {"no-joint-model", "--to mujoco",
       "/result.json: /joint_model: expected the joint model of a cycloid_ltca or lcr_analysis result, found none: "
       "a disc_cam result has no joint to export",
       [](nlohmann::json& r) { r.erase("joint_model"); r["study"] = "disc_cam"; }, ""},
      {"null-stiffness", "--to modelica",
       "/result.json: /joint_model/stiffness_Nm_per_rad: expected a number > 0, found null",
       [](nlohmann::json& r) { r["joint_model"]["stiffness_Nm_per_rad"] = nullptr; }, ""},
      {"missing-backlash", "--to json", "/result.json: /joint_model/backlash_rad: missing required field",
       [](nlohmann::json& r) { r["joint_model"].erase("backlash_rad"); }, ""},
      {"curve-point", "--to json",
       "/result.json: /joint_model/torsion_curve/2/0: expected a torque >= the previous point's -245.0 N m",
       [](nlohmann::json& r) { r["joint_model"]["torsion_curve"][2][0] = -300; }, ""},
      {"nan-literal", "--to mujoco", "/result.json: ", nullptr,
       R"({"study": "cycloid_ltca", "joint_model": {"ratio": NaN}})"},
      {"unknown-to", "--to mujocco",
       "camopt: error: --to: expected mujoco, modelica or json, found \"mujocco\" (did you mean \"mujoco\"?)\n",
       [](nlohmann::json&) {}, ""},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.tag);
    nlohmann::json result = Fixture();
    if (c.change) c.change(result);
    const fs::path dir = ResultDir("bad-" + c.tag, result);
    if (!c.raw.empty()) WriteFile(dir / "result.json", c.raw);
    const auto r = RunCamopt("export " + dir.string() + " " + c.args_after_dir);
    EXPECT_EQ(r.exit_code, 2) << r.stderr_text;
    if (c.tag != "unknown-to") {
      EXPECT_NE(r.stderr_text.find((dir / "result.json").string() + ": "), std::string::npos) << r.stderr_text;
    }
    EXPECT_NE(r.stderr_text.find(c.expect), std::string::npos) << r.stderr_text;
    EXPECT_EQ(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n'), 1) << r.stderr_text;
    EXPECT_FALSE(fs::exists(dir / "export")) << "nothing written";
  }
  // No result folder at all.
  const fs::path none = TempDir("export-none") / "nope";
  const auto r = RunCamopt("export " + none.string() + " --to json");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.stderr_text, "camopt: error: " + (none / "result.json").string() +
                               ": cannot read the result: No such file or directory\n");
  // The result folder itself as --out would be replaced by the export: refused.
  const fs::path dir = ResultDir("out-is-result");
  const auto same = RunCamopt("export " + dir.string() + " --to json --out " + dir.string());
  EXPECT_EQ(same.exit_code, 2) << same.stderr_text;
  EXPECT_TRUE(fs::is_regular_file(dir / "result.json"));
}

}  // namespace export_test
