#include "studies/studio_mechanism.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "model/common/geometry.h"
#include "model/cycloid/bearing_loads.h"
#include "model/contact/hertz.h"
#include "model/cycloid/tooth_profile.h"
#include "model/cycloid/unloaded_tca.h"
#include "model/disc_cam/disc_cam.h"
#include "model/disc_cam/flat_faced.h"
#include "model/disc_cam/oscillating_flat_faced.h"
#include "model/lcr/contact.h"
#include "model/lcr/forces.h"
#include "model/lcr/kinematics.h"
#include "model/lcr/profile.h"
#include "studies/cycloid_ltca_study.h"
#include "studies/disc_cam_study.h"
#include "studies/input.h"
#include "studies/kind.h"
#include "studies/lcr_analysis_study.h"
#include "studies/study.h"

namespace camopt::studies {

namespace {

double Round6(double v) { return std::round(v * 1e6) / 1e6; }

// The LCR at input angle θ. The conjugate cam turns about its centre C = e u(θ) by
// φ = (1 − n_A/m_A) θ (paper eq. 1), so a point X of the cam frame of model/lcr/profile.h is at
// C + R(φ) X in the fixed frame (the inverse of model/lcr/tolerance.h's x = R(−φ)(O − C)). The
// roller centres and their loads are model/lcr/forces.h's AnalyzeAngle (paper eqs. 20–33).
nlohmann::json LcrAt(const nlohmann::json& study, double theta_deg, int points) {
  const Node root(&study, "study", "");
  const lcr_analysis::Study s = lcr_analysis::Parse(root);
  const lcr::Reducer<double>& r = s.reducer;
  const double theta = theta_deg * kPi / 180.0;
  const double phi = lcr::CamSpeedRatio(r) * theta;
  const Vec2<double> centre = r.eccentricity * U(theta);
  lcr::AngleLoads<double> loads;
  bool have_loads = true;
  try {
    loads = lcr::AnalyzeAngle(r, s.material, s.load, theta, lcr::Stages{true, true, false});
  } catch (const std::domain_error&) {
    have_loads = false;  // no roller can carry load at this angle: geometry only
    loads.input.contacts = lcr::RollerContacts(r, lcr::Side::kInput, theta);
    loads.output.contacts = lcr::RollerContacts(r, lcr::Side::kOutput, theta);
  }
  nlohmann::json out = {{"kind", "lcr"},
                        {"supported", true},
                        {"input_angle_deg", theta_deg},
                        {"eccentricity_mm", r.eccentricity},
                        {"cam_centre_mm", {Round6(centre.x()), Round6(centre.y())}},
                        {"cam_rotation_deg", phi * 180.0 / kPi},
                        {"output_turret_rotation_deg", lcr::OutputSpeedRatio(r) * theta_deg},
                        {"loads", have_loads}};
  double max_stress = 0;
  nlohmann::json sides = nlohmann::json::array();
  for (const lcr::Side side : {lcr::Side::kInput, lcr::Side::kOutput}) {
    const lcr::CamSide<double>& c = r.side(side);
    const lcr::SideLoads<double>& l = side == lcr::Side::kInput ? loads.input : loads.output;
    nlohmann::json profile = nlohmann::json::array();
    for (const Vec2<double>& x : lcr::SampleCurve(c, r.eccentricity, c.roller_radius, points)) {
      const Vec2<double> p = centre + Rotate(x, phi);
      profile.push_back({Round6(p.x()), Round6(p.y())});
    }
    nlohmann::json rollers = nlohmann::json::array();
    for (size_t k = 0; k < l.contacts.size(); ++k) {
      const double force = have_loads && k < l.force.size() ? l.force[k] : 0.0;
      double stress = have_loads && k < l.stress.size() ? l.stress[k] : 0.0;
      if (!std::isfinite(stress)) stress = -1;  // an undercut contact: no finite Hertz stress
      max_stress = std::max(max_stress, stress);
      rollers.push_back({{"x", l.contacts[k].centre.x()},
                         {"y", l.contacts[k].centre.y()},
                         {"dx", l.contacts[k].direction.x()},
                         {"dy", l.contacts[k].direction.y()},
                         {"force_N", force},
                         {"stress_MPa", stress},
                         {"loaded", force > 0}});
    }
    sides.push_back({{"name", side == lcr::Side::kInput ? "input" : "output"},
                     {"lobes", c.lobes},
                     {"rollers", c.rollers},
                     {"turret_radius_mm", c.turret_radius},
                     {"roller_radius_mm", c.roller_radius},
                     {"profile_mm", profile},
                     {"rollers_at", rollers}});
  }
  out["sides"] = sides;
  out["max_stress_MPa"] = max_stress;
  return out;
}

// A disc cam with a roller (or knife-edge) follower at cam angle θ, model/disc_cam/disc_cam.h's
// EvaluateCam (Rzine et al. eqs. 1–12). Its frame is fixed on the cam, the follower turning with θ
// against the cam's rotation; drawn with the follower standing, every point is turned by −θ.
// A disc cam with a flat-faced follower at cam angle θ, drawn as the roller one (the follower
// standing, every point of the cam frame turned by −θ). Translating (model/disc_cam/flat_faced.h):
// the face is the line P · u(θ) = r_b + S, the contact A = (r_b + S) u + S' J u. On an arm
// (model/disc_cam/oscillating_flat_faced.h): the pivot O₃ = f u(θ), the face the line
// (P − O₃) · m = d with m = −n the unit normal from the arm toward the cam, the contact A at ℓ along
// the arm −u(α) from the foot O₃ + d m. The face is drawn over the contact's travel in the cycle
// (the profile's samples), or centred on the axis over face_width_mm for a translating face.
nlohmann::json FlatFaceAt(const disc_cam::Study& s, double theta_deg, int points) {
  namespace dc = camopt::disc_cam;
  const dc::DiscCam& cam = s.cam;
  const double theta = theta_deg * kPi / 180.0;
  const auto fixed = [&](const Vec2<double>& x) {
    const Vec2<double> p = Rotate(x, -theta);
    return nlohmann::json::array({Round6(p.x()), Round6(p.y())});
  };
  const bool oscillating = cam.follower == dc::FollowerType::kOscillatingRoller;
  dc::OscillatingFlatFaced arm;
  arm.base_radius = cam.base_radius;
  arm.pivot_distance = cam.pivot_distance;
  arm.face_offset = s.face_offset_mm;
  arm.motion = cam.motion;
  // The profile, and how far along the face the contact runs over the cycle.
  nlohmann::json profile = nlohmann::json::array();
  double lo = 0, hi = 0;
  for (int i = 0; i < points; ++i) {
    const double t = 2.0 * kPi * i / points;
    Vec2<double> a;
    double along;
    if (oscillating) {
      const dc::OscillatingFlatFacePoint q = dc::EvaluateOscillatingFlatFaced(arm, t);
      a = q.contact, along = q.contact_on_face;
    } else {
      const dc::FlatFacePoint<double> q = dc::EvaluateFlatFaced(cam.motion, cam.base_radius, t);
      a = q.contact, along = q.contact_offset;
    }
    profile.push_back(fixed(a));
    lo = i == 0 ? along : std::min(lo, along);
    hi = i == 0 ? along : std::max(hi, along);
  }
  nlohmann::json out = {{"kind", "disc_cam"},
                        {"supported", true},
                        {"input_angle_deg", theta_deg},
                        {"follower", s.in.follower.type},
                        {"oscillating", oscillating},
                        {"flat_face", true},
                        {"base_radius_mm", cam.base_radius},
                        {"roller_radius_mm", 0.0},
                        {"profile_mm", profile}};
  const double pad = 0.08 * std::max(hi - lo, 0.1 * cam.base_radius);
  if (oscillating) {
    const dc::OscillatingFlatFacePoint q = dc::EvaluateOscillatingFlatFaced(arm, theta);
    const Vec2<double> m = -q.normal, along = -U(q.theta - q.xi);  // toward the cam; along the arm
    const Vec2<double> foot = q.pivot + s.face_offset_mm * m;
    out["pivot_mm"] = fixed(q.pivot);
    out["face_foot_mm"] = fixed(foot);
    out["face_mm"] = {fixed(foot + (lo - pad) * along), fixed(foot + (hi + pad) * along)};
    out["contact_mm"] = fixed(q.contact);
    out["face_normal"] = {Rotate(m, -theta).x(), Rotate(m, -theta).y()};
    out["contact_on_face_mm"] = q.contact_on_face;
    out["lift"] = q.xi - dc::InitialArmAngle(arm);
    out["arm_angle_deg"] = q.xi * 180.0 / kPi;
    out["pressure_angle_deg"] = q.pressure_angle * 180.0 / kPi;
    out["radius_of_curvature_mm"] = q.radius_of_curvature;
    out["face_offset_mm"] = s.face_offset_mm;
  } else {
    const dc::FlatFacePoint<double> q = dc::EvaluateFlatFaced(cam.motion, cam.base_radius, theta);
    const Vec2<double> u = U(theta), centre = (cam.base_radius + q.s) * u;  // the face's foot on the axis
    const double w = s.follower_face_width_mm ? 0.5 * *s.follower_face_width_mm : 0.0;
    const double a0 = s.follower_face_width_mm ? -w : lo - pad, a1 = s.follower_face_width_mm ? w : hi + pad;
    out["face_mm"] = {fixed(centre + a0 * Perp(u)), fixed(centre + a1 * Perp(u))};
    out["face_foot_mm"] = fixed(centre);
    out["contact_mm"] = fixed(q.contact);
    out["face_normal"] = {1.0, 0.0};  // u(θ) turned by −θ: toward the follower
    out["follower_direction"] = {1.0, 0.0};
    out["contact_on_face_mm"] = q.contact_offset;
    out["lift"] = q.s;
    out["pressure_angle_deg"] = 0.0;
    out["radius_of_curvature_mm"] = q.radius_of_curvature;
  }
  return out;
}

nlohmann::json DiscCamAt(const nlohmann::json& study, double theta_deg, int points) {
  const Node root(&study, "study", "");
  const disc_cam::Study s = disc_cam::Parse(root);
  if (s.contact == disc_cam::Study::Contact::kFlatFaced) return FlatFaceAt(s, theta_deg, points);
  const camopt::disc_cam::DiscCam& cam = s.cam;
  const double theta = theta_deg * kPi / 180.0;
  const auto fixed = [&](const Vec2<double>& x) {
    const Vec2<double> p = Rotate(x, -theta);
    return nlohmann::json::array({Round6(p.x()), Round6(p.y())});
  };
  nlohmann::json profile = nlohmann::json::array();
  for (int i = 0; i < points; ++i)
    profile.push_back(fixed(camopt::disc_cam::EvaluateCam(cam, 2.0 * kPi * i / points).contact));
  const camopt::disc_cam::CamPoint<double> p = camopt::disc_cam::EvaluateCam(cam, theta);
  const bool oscillating = cam.follower == camopt::disc_cam::FollowerType::kOscillatingRoller;
  const Vec2<double> dir = Rotate(Vec2<double>(p.follower_dir / p.follower_dir.norm()), -theta);
  nlohmann::json out = {{"kind", "disc_cam"},
                        {"supported", true},
                        {"input_angle_deg", theta_deg},
                        {"follower", s.in.follower.type},
                        {"oscillating", oscillating},
                        {"base_radius_mm", cam.base_radius},
                        {"roller_radius_mm", cam.roller_radius},
                        {"profile_mm", profile},
                        {"roller_centre_mm", fixed(p.pitch)},
                        {"contact_mm", fixed(p.contact)},
                        {"follower_direction", {dir.x(), dir.y()}},
                        {"lift", p.s},
                        {"pressure_angle_deg", p.pressure_angle * 180.0 / kPi}};
  if (oscillating) {
    out["pivot_mm"] = fixed(camopt::disc_cam::FollowerPivot(cam, theta));
    out["arm_length_mm"] = cam.arm_length;
  }
  return out;
}

// A CSV's numeric columns by name (the writers' ToCsv: a header line, then one row per line).
// False (with why) for a text that is not such a table.
bool ReadCsvColumns(const std::string& text, std::vector<std::string>& names,
                    std::vector<std::vector<double>>& columns, std::string& why) {
  std::istringstream in(text);
  std::string line;
  if (!std::getline(in, line)) return why = "an empty file", false;
  names.clear();
  std::string cell;
  for (std::istringstream h(line); std::getline(h, cell, ',');) names.push_back(cell);
  columns.assign(names.size(), {});
  for (size_t row = 1; std::getline(in, line); ++row) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    size_t c = 0;
    for (std::istringstream r(line); std::getline(r, cell, ','); ++c) {
      char* end = nullptr;
      const double v = std::strtod(cell.c_str(), &end);
      if (c >= names.size() || cell.empty() || *end != '\0' || !std::isfinite(v))
        return why = "row " + std::to_string(row) + ", column " + std::to_string(c + 1) + ": not a number", false;
      columns[c].push_back(v);
    }
    if (c != names.size()) return why = "row " + std::to_string(row) + " has " + std::to_string(c) + " cells", false;
  }
  return true;
}

// A column by name, or null.
const std::vector<double>* Column(const std::vector<std::string>& names, const std::vector<std::vector<double>>& columns,
                                  const std::string& name) {
  const auto it = std::find(names.begin(), names.end(), name);
  return it == names.end() ? nullptr : &columns[size_t(it - names.begin())];
}

std::string Degrees(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// A cycloid drive at crank angle φ: the disc's tooth profile (model/cycloid/tooth_profile.h's
// ToothProfile, the load-distribution paper's eqs. 1–4, with the profile modification) in the disc
// frame, placed at its centre e u(φ) and turned by −φ/n2 (the inverse of RollerCentreInDisc), and
// the pins standing at a u(2πi/n1). Each pin's force is the rigid-disc load sharing of
// model/cycloid/bearing_loads.h's RigidRingPinLoads (F_i = T l_i / Σ l_k², Σ F_i l_i = T; Blanche &
// Yang 1989) at the disc's torque, and the Hertz pressure of that force on each pair: the nominal
// (unmodified) tooth's. With a run (LoadedRun), the pins' loads and pressures are instead the run's
// loaded contact analysis at φ (CycloidRunAt), the nominal ones kept beside them.
nlohmann::json CycloidAt(const nlohmann::json& study, double crank_deg, int points, const LoadedRun* run) {
  const Node root(&study, "study", "");
  const cycloid_ltca::Study s = cycloid_ltca::Parse(root);
  const cycloid::Drive& d = s.drive;
  const double crank = crank_deg * kPi / 180.0;
  const Vec2<double> centre = d.eccentricity_mm * U(crank);
  const double turn = -crank / d.teeth;
  const int n = std::min(4000, std::max(points, 48 * d.rollers));
  nlohmann::json profile = nlohmann::json::array();
  for (int j = 0; j < n; ++j) {
    const Vec2<double> p = centre + Rotate(cycloid::ToothProfile(d, 2.0 * kPi * j / n).point, turn);
    profile.push_back({Round6(p.x()), Round6(p.y())});
  }
  cycloid::Drive nominal = d;
  nominal.delta_position_mm = 0.0;
  nominal.delta_radius_mm = 0.0;
  const double torque = s.disc_torque_Nmm();
  std::vector<double> force(size_t(d.rollers), 0.0);
  for (const auto& [i, f] : cycloid::RigidRingPinLoads(nominal, torque, crank)) force[size_t(i)] = f;
  // Each loaded pair's Hertz line-contact peak pressure p0 = sqrt(F E* / (π B R')) (Johnson eq.
  // 4.45; model/contact/hertz.h), 1/R' = κ_tooth + 1/ρ at the nominal contact (the unloaded TCA's
  // pair, model/cycloid/unloaded_tca.h: the tooth's signed curvature there), over the face width B;
  // −1 where the pair is conformal (no Hertz contact). Needs the material: not for an unloaded-only study.
  const double e_star = s.loaded ? s.material.composite_modulus_MPa() : 0.0;
  double max_force = 0, max_pressure = 0;
  nlohmann::json pins = nlohmann::json::array();
  for (int i = 0; i < d.rollers; ++i) {
    const Vec2<double> o = d.roller_position_radius_mm * U(2.0 * kPi * i / d.rollers);
    const double f = force[size_t(i)];
    max_force = std::max(max_force, f);
    nlohmann::json pin = {{"x", o.x()}, {"y", o.y()}, {"force_N", f}, {"loaded", f > 0}};
    if (s.loaded) {
      double pressure = 0.0;
      if (f > 0) {
        const cycloid::PairGeometry<double> g = cycloid::SolvePair<double>(nominal, i, crank);
        const double curvature = g.profile_curvature + g.roller_curvature;  // 1/R'
        pressure = curvature > 0 ? contact::LineContactPeakPressure(f, nominal.face_width_mm, 1.0 / curvature, e_star) : -1.0;
        pin["effective_radius_mm"] = curvature > 0 ? nlohmann::json(1.0 / curvature) : nlohmann::json(nullptr);
      }
      pin["pressure_MPa"] = pressure;
      max_pressure = std::max(max_pressure, pressure);
    }
    pins.push_back(pin);
  }
  nlohmann::json out = {{"kind", "cycloid"},
                        {"supported", true},
                        {"input_angle_deg", crank_deg},
                        {"teeth", d.teeth},
                        {"rollers", d.rollers},
                        {"roller_position_radius_mm", d.roller_position_radius_mm},
                        {"roller_radius_mm", d.roller_radius_mm},
                        {"disc_centre_mm", {Round6(centre.x()), Round6(centre.y())}},
                        {"disc_rotation_deg", turn * 180.0 / kPi},
                        {"profile_mm", profile},
                        {"pins", pins},
                        {"disc_torque_Nmm", torque},
                        {"max_pin_force_N", max_force},
                        {"pin_forces",
                         "rigid disc, nominal (unmodified) tooth: F_i = T l_i / sum of l_k^2 over the loaded flank"}};
  if (s.loaded) {
    out["max_pressure_MPa"] = max_pressure;
    out["composite_modulus_MPa"] = e_star;
    out["pin_pressures"] =
        "Hertz line contact of each pin's force over the face width, 1/R' = tooth curvature + 1/pin radius at "
        "the nominal contact";
  }
  out["pin_source"] = "nominal";
  out["pin_source_label"] = "nominal rigid disc, no run";
  if (!run) return out;
  // The run's loaded tooth contact analysis (its per_angle.csv): the modified, crowned tooth's pair
  // loads and each pair's own peak pressure (cycloid load-distribution paper eqs. 15–26).
  const std::string file = run->folder + "/per_angle.csv";
  const auto note = [&](const std::string& why) {
    out["run_note"] = file + ": " + why + "; the pins show the nominal rigid disc";
    out["pin_source_label"] = "nominal rigid disc (" + why + ")";
    return out;
  };
  if (!s.loaded) return note("the study asks for the unloaded evaluation only");
  if (run->torque_Nm >= 0 && std::abs(run->torque_Nm - s.torque_Nm) > 1e-9 * std::max(1.0, std::abs(s.torque_Nm)))
    return note("the run's torque " + Degrees(run->torque_Nm) + " N m is not the study's " + Degrees(s.torque_Nm) +
                " N m: run the study again");
  nlohmann::json at = CycloidRunAt(run->per_angle_csv, d.rollers, crank_deg);
  if (at.contains("why")) return note(at["why"].get<std::string>());
  // The drive the run solved, against the study's: the unloaded transmission error β0 at the
  // first row used (model/cycloid/unloaded_tca.h, eq. 14) moves with every dimension and the
  // profile modification.
  if (at["unloaded_te_arcsec"].is_number()) {
    const double row_deg = at["angles_deg"][0], run_te = at["unloaded_te_arcsec"];
    const double te = cycloid::UnloadedTca<double>(d, row_deg * kPi / 180.0).rotation * 180.0 * 3600.0 / kPi;
    if (std::abs(te - run_te) > 1e-6 * std::max(1.0, std::abs(te)))
      return note("the run's unloaded transmission error at " + Degrees(row_deg) + "° (" + Degrees(run_te) +
                  " arcsec) is not the study's drive's (" + Degrees(te) + " arcsec): run the study again");
  }
  at.erase("unloaded_te_arcsec");
  const bool pressures = !at["pressure_MPa"].empty();
  double run_force = 0, run_pressure = 0;
  for (int i = 0; i < d.rollers; ++i) {
    nlohmann::json& pin = out["pins"][size_t(i)];
    pin["nominal_force_N"] = pin["force_N"];
    const double f = at["force_N"][size_t(i)];
    pin["force_N"] = f;
    pin["loaded"] = f > 0;
    pin.erase("effective_radius_mm");  // the nominal contact's
    if (pin.contains("pressure_MPa")) pin["nominal_pressure_MPa"] = pin["pressure_MPa"];
    pin.erase("pressure_MPa");
    if (pressures) {
      const double p = at["pressure_MPa"][size_t(i)];
      pin["pressure_MPa"] = p;
      run_pressure = std::max(run_pressure, p);
    }
    run_force = std::max(run_force, f);
  }
  out["max_pin_force_N"] = run_force;
  if (pressures) {
    out["max_pressure_MPa"] = run_pressure;
  } else {
    out.erase("max_pressure_MPa");
    out["run_note"] = file + ": no max_pressure_roller_i_MPa columns (a run of an earlier camopt): pins coloured by "
                             "the run's loads; run the study again for its pressures";
  }
  const double w = at["weight"];
  out["run"] = at;
  out["run"].erase("force_N");
  out["run"].erase("pressure_MPa");
  out["run"]["file"] = file;
  out["run"]["pressures"] = pressures;
  out["pin_source"] = "run";
  out["pin_forces"] = "the run's loaded tooth contact analysis (modified, crowned tooth): its pair loads";
  out["pin_pressures"] = "the run's own peak pressure of each pair's half-space contact solution";
  const std::string a0 = Degrees(at["angles_deg"][0].get<double>()), a1 = Degrees(at["angles_deg"][1].get<double>());
  out["pin_source_label"] = "loaded run " + file + ", crank angle " + Degrees(crank_deg) + "°" +
                            (w == 0 ? " (its row at " + a0 + "°)"
                                    : " (linear between its rows at " + a0 + "° and " + a1 + "°)");
  return out;
}

// One design of a sizing (an analysis study) drawn, or why it is not: a start outside the
// analysis kind's checks (an LCR start with too little roller room) is said, not an error.
nlohmann::json DrawnDesign(const nlohmann::json& analysis, double angle_deg, int points) {
  try {
    nlohmann::json d = MechanismAt(analysis, angle_deg, points);
    d["study"] = analysis;
    return d;
  } catch (const StudyError& e) {
    return {{"supported", false}, {"why", e.what()}, {"study", analysis}};
  }
}

// A sizing study: its start design and the optimum of its run, each as the analysis study of the
// same mechanism (the sizing kind's start_study and its run's best_….json) drawn at one angle.
nlohmann::json SizingAt(const KindDescriptor& kind, const nlohmann::json& study, const nlohmann::json& optimum,
                        double angle_deg, int points) {
  const nlohmann::json start = kind.start_study(Node(&study, "study", ""), optimum);
  nlohmann::json out = {{"kind", "sizing"},
                        {"sizing_kind", kind.name},
                        {"supported", true},
                        {"input_angle_deg", angle_deg},
                        {"analysis_kind", kind.sizing_of}};
  out["start"] = start.is_object() ? DrawnDesign(start, angle_deg, points)
                                   : nlohmann::json{{"supported", false}, {"why", start}};
  out["optimum"] = optimum.is_object() ? DrawnDesign(optimum, angle_deg, points) : nlohmann::json(nullptr);
  return out;
}

}  // namespace

std::string SizingAnalysisKind(const std::string& kind) {
  const KindDescriptor* k = FindKind(kind);
  return k ? k->sizing_of : "";
}

nlohmann::json LcrMechanismAt(const nlohmann::json& study, double input_angle_deg, int points, const LoadedRun*) {
  return LcrAt(study, input_angle_deg, points);
}
nlohmann::json DiscCamMechanismAt(const nlohmann::json& study, double input_angle_deg, int points, const LoadedRun*) {
  return DiscCamAt(study, input_angle_deg, points);
}
nlohmann::json CycloidMechanismAt(const nlohmann::json& study, double input_angle_deg, int points,
                                  const LoadedRun* run) {
  return CycloidAt(study, input_angle_deg, points, run);
}

std::string SizingOptimumFile(const std::string& kind) {
  const std::string a = SizingAnalysisKind(kind);
  return a.empty() ? a : "best_" + a + ".json";
}

nlohmann::json CycloidRunAt(const std::string& per_angle_csv, int rollers, double crank_deg) {
  std::vector<std::string> names;
  std::vector<std::vector<double>> columns;
  std::string why;
  if (!ReadCsvColumns(per_angle_csv, names, columns, why)) return {{"why", why}};
  const std::vector<double>* angles = Column(names, columns, "crank_angle_deg");
  if (!angles || angles->empty()) return {{"why", "no crank_angle_deg rows"}};
  if (Column(names, columns, "load_roller_" + std::to_string(rollers + 1) + "_N"))
    return {{"why", "the run has more than the study's " + std::to_string(rollers) + " pins"}};
  std::vector<const std::vector<double>*> load, pressure;
  for (int i = 1; i <= rollers; ++i) {
    load.push_back(Column(names, columns, "load_roller_" + std::to_string(i) + "_N"));
    if (!load.back()) return {{"why", "no load_roller_" + std::to_string(i) + "_N column (not a loaded run of this drive)"}};
    pressure.push_back(Column(names, columns, "max_pressure_roller_" + std::to_string(i) + "_MPa"));
  }
  const bool pressures = std::all_of(pressure.begin(), pressure.end(), [](const auto* c) { return c != nullptr; });
  const std::vector<double>& a = *angles;
  const size_t n = a.size();
  for (size_t k = 1; k < n; ++k)
    if (!(a[k] > a[k - 1])) return {{"why", "its crank angles are not increasing"}};
  // Two rows j0, j1 with pin shifts s0, s1 and the weight t of j1.
  const double tau = 360.0 / rollers, tol = 1e-6 + 1e-9 * std::abs(a.back());
  size_t j0 = 0, j1 = 0;
  long s0 = 0, s1 = 0;
  double t = 0;
  bool uniform = n >= 2;
  long periods = 0;
  if (uniform) {
    const double span = (a.back() - a.front()) * double(n) / double(n - 1);  // N h
    periods = std::lround(span / tau);
    uniform = periods >= 1 && std::abs(span - double(periods) * tau) <= 1e-6 * tau;
    for (size_t k = 0; uniform && k < n; ++k)
      uniform = std::abs(a[k] - a.front() - double(k) * periods * tau / double(n)) <= tol;
  }
  if (uniform) {
    const double span = double(periods) * tau, h = span / double(n);
    const double x = crank_deg - a.front();
    const double m = std::floor(x / span);
    double psi = (x - m * span) / h;  // in rows
    if (psi >= double(n)) psi = 0, s0 += periods;  // rounding at the top of the span
    j0 = size_t(std::floor(psi));
    t = psi - double(j0);
    if (t > 1 - 1e-9) t = 0, ++j0;  // a run's own angle: its row
    if (t < 1e-9) t = 0;
    s0 += long(m) * periods;
    if (j0 >= n) j0 -= n, s0 += periods;
    j1 = j0 + 1, s1 = s0;
    if (j1 == n) j1 = 0, s1 += periods;
  } else {
    double x = crank_deg - 360.0 * std::floor((crank_deg - a.front()) / 360.0);  // in [φ_0, φ_0 + 360)
    if (x > a.back() + tol && std::abs(x - 360.0 - a.front()) <= tol) x -= 360.0;
    if (x < a.front() - tol || x > a.back() + tol)
      return {{"why", "its crank angles " + Degrees(a.front()) + "° to " + Degrees(a.back()) + "° (" + std::to_string(n) +
                          ", not whole mesh periods of " + Degrees(tau) + "° uniformly) do not reach " +
                          Degrees(crank_deg) + "°"}};
    j0 = size_t(std::upper_bound(a.begin(), a.end(), x) - a.begin());
    j0 = j0 == 0 ? 0 : j0 - 1;
    if (j0 + 1 >= n) j0 = n >= 2 ? n - 2 : 0;
    j1 = std::min(j0 + 1, n - 1);
    t = j1 == j0 ? 0.0 : std::clamp((x - a[j0]) / (a[j1] - a[j0]), 0.0, 1.0);
    if (t < 1e-9) t = 0;
    if (t > 1 - 1e-9) t = 0, j0 = j1;
  }
  const auto pin = [&](int i, long shift) { return size_t(((i - shift) % rollers + rollers) % rollers); };
  nlohmann::json force = nlohmann::json::array(), press = nlohmann::json::array();
  for (int i = 0; i < rollers; ++i) {
    const double f0 = (*load[pin(i, s0)])[j0], f1 = (*load[pin(i, s1)])[j1];
    force.push_back(t == 0 ? f0 : (1 - t) * f0 + t * f1);
    if (pressures) {
      const double p0 = (*pressure[pin(i, s0)])[j0], p1 = (*pressure[pin(i, s1)])[j1];
      press.push_back(t == 0 ? p0 : (1 - t) * p0 + t * p1);
    }
  }
  const double a1 = a[j1] + (j1 < j0 || (j1 == j0 && s1 != s0) ? double(periods) * tau : 0.0);
  const std::vector<double>* te = Column(names, columns, "unloaded_te_arcsec");
  return {{"force_N", force},
          {"unloaded_te_arcsec", te ? nlohmann::json((*te)[j0]) : nlohmann::json(nullptr)},
          {"pressure_MPa", press},
          {"rows", {j0, t == 0 ? j0 : j1}},
          {"angles_deg", {a[j0], t == 0 ? a[j0] : a1}},
          {"weight", t},
          {"pin_shift", ((s0 % rollers) + rollers) % rollers},
          {"interpolation", t == 0 ? "the run's row" : "linear between the two rows"},
          {"uniform_mesh_periods", uniform ? periods : 0}};
}

nlohmann::json MechanismAt(const nlohmann::json& study, double input_angle_deg, int points,
                           const nlohmann::json& optimum, const LoadedRun* run) {
  points = std::clamp(points, 36, 4000);
  if (!std::isfinite(input_angle_deg) || std::abs(input_angle_deg) > 1e6)
    throw StudyError("angle: expected a finite input angle in degrees within ±1e6, found " +
                     std::to_string(input_angle_deg));
  const std::string kind = study.is_object() && study.contains("study") && study["study"].is_string()
                               ? study["study"].get<std::string>()
                               : std::string();
  const KindDescriptor* k = FindKind(kind);
  if (k && k->mechanism) return k->mechanism(study, input_angle_deg, points, run);
  if (k && k->start_study) return SizingAt(*k, study, optimum, input_angle_deg, points);
  return {{"kind", kind}, {"supported", false}};
}

}  // namespace camopt::studies
