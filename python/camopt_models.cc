// The models of the kinds' designs as Python objects: camopt.Lcr (an lcr_analysis study's reducer),
// camopt.CycloidDrive (a cycloid_ltca study's drive) and camopt.DiscCam (a disc_cam study's cam with
// a roller or knife-edge follower), evaluated at given angles as NumPy arrays
// without running the whole study. They parse the study with the kind's own Parse and call the
// model/ functions its Run calls (model/lcr/forces.h AnalyzeAngle, model/lcr/profile.h,
// model/cycloid/loaded_tca.h RunCycle, model/cycloid/unloaded_tca.h, tooth_profile.h,
// model/disc_cam/disc_cam.h EvaluateCam), so their
// numbers are the study's: the same at the study's own angles, bit for bit.
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "model/cycloid/loaded_tca.h"
#include "model/cycloid/tooth_profile.h"
#include "model/cycloid/unloaded_tca.h"
#include "model/disc_cam/disc_cam.h"
#include "model/lcr/forces.h"
#include "model/lcr/kinematics.h"
#include "model/lcr/profile.h"
#include "python/camopt_module.h"
#include "studies/cycloid_ltca_study.h"
#include "studies/disc_cam_study.h"
#include "studies/lcr_analysis_study.h"

namespace camopt::python {

namespace {

namespace st = camopt::studies;

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;

py::array_t<double> Vector(const std::vector<double>& v) {
  return py::array_t<double>(static_cast<py::ssize_t>(v.size()), v.data());
}

// rows × cols, row-major.
py::array_t<double> Matrix(const std::vector<double>& v, size_t rows, size_t cols) {
  py::array_t<double> a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)});
  std::copy(v.begin(), v.end(), a.mutable_data());
  return a;
}

std::vector<double> Angles(const py::object& angles) {
  const Array a = Array::ensure(angles);
  if (!a || a.ndim() > 1) throw py::value_error("expected a 1-D sequence of angles [rad]");
  std::vector<double> out(a.data(), a.data() + a.size());
  for (double x : out)
    if (!std::isfinite(x)) throw py::value_error("expected finite angles [rad], found " + std::to_string(x));
  return out;
}

// The kind's parsed study; a study of another kind is a StudyError at /study.
template <typename Parsed, typename ParseFn>
Parsed ParseKind(const StudyData& s, const std::string& kind, ParseFn parse) {
  try {
    if (s.kind() != kind)
      throw st::StudyError(s.file + ": /study: expected \"" + kind + "\" (this model's kind), found \"" + s.kind() + "\"");
    const st::Node root(&s.study, s.file, "");
    return parse(root);
  } catch (const st::StudyError& e) {
    RaiseStudyError(e, s.file);
  }
}

// ---- LCR ---------------------------------------------------------------------------------------

struct Lcr {
  st::lcr_analysis::Study study;

  const lcr::CamSide<double>& Side(const std::string& side) const {
    if (side == "input") return study.reducer.input;
    if (side == "output") return study.reducer.output;
    throw py::value_error("side: expected \"input\" or \"output\", found \"" + side + "\"");
  }

  // The cam profile (offset = the roller radius, the default), the pitch curve (offset 0) or a
  // cutter path (offset = roller − cutter radius), in the cam's frame [mm].
  py::tuple Profile(const std::string& side, int points, const py::object& offset) const {
    const lcr::CamSide<double>& c = Side(side);
    if (points < 3) throw py::value_error("points: expected at least 3");
    const double off = offset.is_none() ? c.roller_radius : offset.cast<double>();
    const auto pts = lcr::SampleCurve(c, study.reducer.eccentricity, off, points);
    std::vector<double> x, y;
    for (const auto& p : pts) x.push_back(p.x()), y.push_back(p.y());
    return py::make_tuple(Vector(x), Vector(y));
  }

  // The rigid model's loads at the input angles θ [rad]: the columns of series.csv under the same
  // names, and each roller's force (angles × rollers).
  py::dict Loads(const py::object& angles_rad) const {
    if (study.load_model != lcr::LoadModel::kRigid)
      throw py::value_error("loads(): the study's analysis.load_model is not \"rigid\"; the compliant model "
                            "solves the whole revolution at once (run the study)");
    const std::vector<double> theta = Angles(angles_rad);
    const lcr::Stages stages{true, study.evaluate.stress, study.evaluate.efficiency};
    const size_t n = theta.size();
    std::vector<double> deg, act_a, act_b, fa, fb, sa, sb, ta, tb, ft, fr, tin, eta, rf_a, rf_b;
    for (double t : theta) {
      lcr::AngleLoads<double> a;
      try {
        a = lcr::AnalyzeAngle(study.reducer, study.material, study.load, t, stages);
      } catch (const std::domain_error& e) {
        throw py::value_error(std::string("infeasible geometry: ") + e.what());
      }
      deg.push_back(t * 180 / kPi);
      act_a.push_back(a.input.actuating);
      act_b.push_back(a.output.actuating);
      fa.push_back(a.input.max_force);
      fb.push_back(a.output.max_force);
      sa.push_back(a.input.max_stress);
      sb.push_back(a.output.max_stress);
      ta.push_back(a.input.turret_torque / 1000);
      tb.push_back(a.output.turret_torque / 1000);
      ft.push_back(a.tangential_force);
      fr.push_back(a.radial_force);
      tin.push_back(a.input_torque / 1000);
      eta.push_back(a.efficiency);
      rf_a.insert(rf_a.end(), a.input.force.begin(), a.input.force.end());
      rf_b.insert(rf_b.end(), a.output.force.begin(), a.output.force.end());
    }
    py::dict d;
    d["input_angle_deg"] = Vector(deg);
    d["input_actuating_rollers"] = Vector(act_a);
    d["output_actuating_rollers"] = Vector(act_b);
    d["input_max_roller_force_N"] = Vector(fa);
    d["output_max_roller_force_N"] = Vector(fb);
    if (stages.stress) {
      d["input_max_contact_stress_MPa"] = Vector(sa);
      d["output_max_contact_stress_MPa"] = Vector(sb);
    }
    d["fixed_turret_torque_Nm"] = Vector(ta);
    d["output_torque_Nm"] = Vector(tb);
    if (stages.efficiency) {
      d["eccentric_tangential_force_N"] = Vector(ft);
      d["eccentric_radial_force_N"] = Vector(fr);
      d["input_torque_Nm"] = Vector(tin);
      d["efficiency"] = Vector(eta);
    }
    d["input_roller_force_N"] = Matrix(rf_a, n, size_t(study.reducer.input.rollers));
    d["output_roller_force_N"] = Matrix(rf_b, n, size_t(study.reducer.output.rollers));
    return d;
  }

  // The study's own input angles, θ_i = 2π i / angle_steps (model/lcr/cycle.cc).
  py::array_t<double> StudyAngles() const {
    std::vector<double> t;
    for (int i = 0; i < study.angle_steps; ++i) t.push_back(2 * kPi * i / study.angle_steps);
    return Vector(t);
  }
};

// ---- Cycloid drive -----------------------------------------------------------------------------

struct CycloidDrive {
  st::cycloid_ltca::Study study;

  py::tuple Profile(int points) const {
    if (points < 3) throw py::value_error("points: expected at least 3");
    std::vector<double> x, y;
    for (int k = 0; k < points; ++k) {
      const auto p = cycloid::ToothProfile<double>(study.drive, 2.0 * kPi * k / points).point;
      x.push_back(p.x());
      y.push_back(p.y());
    }
    return py::make_tuple(Vector(x), Vector(y));
  }

  py::tuple RollerCentres(double crank_rad) const {
    std::vector<double> x, y;
    for (int i = 0; i < study.drive.rollers; ++i) {
      const auto c = cycloid::RollerCentreInDisc<double>(study.drive, i, crank_rad, 0.0);
      x.push_back(c.x());
      y.push_back(c.y());
    }
    return py::make_tuple(Vector(x), Vector(y));
  }

  // The unloaded TCA (model/cycloid/unloaded_tca.h): the transmission error and each roller's
  // backlash (-1 where its flank is not loaded, as backlash.csv) [arcsec].
  py::dict Unloaded(const py::object& angles_rad) const {
    const std::vector<double> phi = Angles(angles_rad);
    const size_t n1 = size_t(study.drive.rollers);
    std::vector<double> deg, te, backlash(phi.size() * n1, -1.0);
    for (size_t k = 0; k < phi.size(); ++k) {
      const auto u = cycloid::UnloadedTca<double>(study.drive, phi[k]);
      deg.push_back(phi[k] * 180.0 / kPi);
      te.push_back(u.rotation * cycloid::kArcsecPerRad);
      for (const auto& g : u.pairs)
        if (g.loaded_flank) backlash[k * n1 + size_t(g.roller)] = g.backlash * cycloid::kArcsecPerRad;
    }
    py::dict d;
    d["crank_angle_deg"] = Vector(deg);
    d["unloaded_te_arcsec"] = Vector(te);
    d["backlash_arcsec"] = Matrix(backlash, phi.size(), n1);
    return d;
  }

  // The loaded TCA under the study's torque per disc at the crank angles [rad] (in order, each
  // warm-started from the one before, as the study's RunCycle): the columns of per_angle.csv.
  py::dict Loads(const py::object& angles_rad, const py::object& progress) const {
    if (!study.loaded) throw py::value_error("loads(): the study asks for the unloaded evaluation only");
    const std::vector<double> phi = Angles(angles_rad);
    cycloid::CycleResult c;
    RunInterruptibly(
        [&] {
          const cycloid::LoadedTca tca(study.drive, study.crowning, study.material, study.options);
          st::Progress p("cycloid loads", true);
          c = cycloid::RunCycle(tca, study.disc_torque_Nmm(), phi, [&](double f) { p.Update(f); });
        },
        progress);
    const size_t n1 = size_t(study.drive.rollers);
    std::vector<double> deg, ute, p, pairs, load(phi.size() * n1, 0.0), peak(phi.size() * n1, 0.0);
    for (size_t k = 0; k < c.meshes.size(); ++k) {
      const cycloid::MeshLoad& m = c.meshes[k];
      deg.push_back(phi[k] * 180.0 / kPi);
      ute.push_back(m.unloaded_rotation_rad * cycloid::kArcsecPerRad);
      p.push_back(m.max_pressure_MPa);
      pairs.push_back(m.pairs_in_contact);
      for (const cycloid::PairLoad& q : m.pairs) {
        load[k * n1 + size_t(q.roller)] = q.load_N;
        peak[k * n1 + size_t(q.roller)] = q.max_pressure_MPa;
      }
    }
    py::dict d;
    d["crank_angle_deg"] = Vector(deg);
    d["lte_arcsec"] = Vector(c.lte_arcsec);
    d["unloaded_te_arcsec"] = Vector(ute);
    d["gear_ratio"] = Vector(c.gear_ratio);
    d["max_contact_stress_MPa"] = Vector(p);
    d["pairs_in_contact"] = Vector(pairs);
    d["roller_load_N"] = Matrix(load, phi.size(), n1);
    d["roller_max_pressure_MPa"] = Matrix(peak, phi.size(), n1);
    d["converged"] = c.converged;
    return d;
  }
};

// ---- Disc cam ----------------------------------------------------------------------------------

struct DiscCam {
  st::disc_cam::Study study;

  void RequireRoller() const {
    if (study.contact == st::disc_cam::Study::Contact::kFlatFaced)
      throw py::value_error("the study's follower is flat-faced; DiscCam evaluates roller and knife-edge "
                            "followers (model/disc_cam/disc_cam.h)");
  }
  bool Oscillating() const { return study.cam.follower == disc_cam::FollowerType::kOscillatingRoller; }

  // The columns of series.csv of a roller or knife-edge follower (jerk and errors left out) at the
  // cam angles [rad], computed as the study does (EvaluateCam; a follower in deg when oscillating).
  py::dict Evaluate(const py::object& angles_rad) const {
    RequireRoller();
    const std::vector<double> theta = Angles(angles_rad);
    constexpr double kDeg = kPi / 180.0;
    const double unit = Oscillating() ? 1.0 / kDeg : 1.0;
    const std::string fu = Oscillating() ? "deg" : "mm";
    std::vector<double> deg, sv, v, a, pa, sa, rd, cx, cy, px, py_, q, k;
    for (double t : theta) {
      const disc_cam::CamPoint<double> p = disc_cam::EvaluateCam(study.cam, t);
      deg.push_back(t / kDeg);
      sv.push_back(p.s * unit);
      v.push_back(p.ds * unit);
      a.push_back(p.d2s * unit);
      pa.push_back(p.pressure_angle / kDeg);
      sa.push_back(p.shift_angle / kDeg);
      rd.push_back(p.radial_dimension);
      cx.push_back(p.contact.x());
      cy.push_back(p.contact.y());
      px.push_back(p.pitch.x());
      py_.push_back(p.pitch.y());
      q.push_back(p.q);
      k.push_back(p.pitch_curvature);
    }
    py::dict d;
    d["cam_angle_deg"] = Vector(deg);
    d[py::str("follower_" + fu)] = Vector(sv);
    d[py::str("velocity_" + fu + "_per_rad")] = Vector(v);
    d[py::str("acceleration_" + fu + "_per_rad2")] = Vector(a);
    d["pressure_angle_deg"] = Vector(pa);
    d["shift_angle_deg"] = Vector(sa);
    d["radial_dimension_mm"] = Vector(rd);
    d["contact_x_mm"] = Vector(cx);
    d["contact_y_mm"] = Vector(cy);
    d["pitch_x_mm"] = Vector(px);
    d["pitch_y_mm"] = Vector(py_);
    d["q_mm"] = Vector(q);
    d["pitch_curvature_per_mm"] = Vector(k);
    return d;
  }

  py::tuple Profile(int points) const {
    RequireRoller();
    if (points < 3) throw py::value_error("points: expected at least 3");
    std::vector<double> x, y;
    for (int i = 0; i < points; ++i) {
      const auto p = disc_cam::EvaluateCam(study.cam, 2 * kPi * i / points).contact;
      x.push_back(p.x());
      y.push_back(p.y());
    }
    return py::make_tuple(Vector(x), Vector(y));
  }

  py::array_t<double> StudyAngles() const {
    std::vector<double> t;
    for (int i = 0; i < study.in.analysis.angle_steps; ++i) t.push_back(2 * kPi * i / study.in.analysis.angle_steps);
    return Vector(t);
  }
};

}  // namespace

void AddModels(py::module_& m) {
  py::class_<Lcr>(m, "Lcr",
                  "The reducer of an lcr_analysis study (model/lcr): its cam profiles and its loads at given "
                  "input angles, as the study computes them.")
      .def_static(
          "from_study",
          [](const py::object& s) {
            const StudyData d = ToStudy(s);
            return Lcr{ParseKind<st::lcr_analysis::Study>(d, "lcr_analysis",
                                                          [](const st::Node& n) { return st::lcr_analysis::Parse(n); })};
          },
          py::arg("study"), "From a camopt.Study, a dict or a path of kind lcr_analysis.")
      .def_property_readonly("eccentricity_mm", [](const Lcr& l) { return l.study.reducer.eccentricity; })
      .def_property_readonly("speed_ratio", [](const Lcr& l) { return lcr::SpeedReductionRatio(l.study.reducer); })
      .def_property_readonly("angles_rad", &Lcr::StudyAngles,
                             "The study's input angles 2*pi*i/angle_steps (those of series.csv).")
      .def(
          "profile", [](const Lcr& l, const std::string& side, const py::object& points, const py::object& offset) {
            return l.Profile(side, points.is_none() ? l.study.profile_points : points.cast<int>(), offset);
          },
          py::arg("side") = "input", py::arg("points") = py::none(), py::arg("offset_mm") = py::none(),
          "(x, y) [mm] of a cam's curve in its own frame at psi = 2*pi*i/points: the cam profile (offset_mm\n"
          "None: the roller radius), the pitch curve (0) or any inward offset.")
      .def("loads", &Lcr::Loads, py::arg("angles_rad"),
           "The rigid model's loads at the input angles [rad] as arrays: the columns of series.csv by name\n"
           "(line-contact Hertz stress), plus input_/output_roller_force_N (angles x rollers).");

  py::class_<CycloidDrive>(m, "CycloidDrive",
                           "The drive of a cycloid_ltca study (model/cycloid): tooth profile, unloaded and loaded "
                           "tooth contact at given crank angles, as the study computes them.")
      .def_static(
          "from_study",
          [](const py::object& s) {
            const StudyData d = ToStudy(s);
            return CycloidDrive{ParseKind<st::cycloid_ltca::Study>(
                d, "cycloid_ltca", [](const st::Node& n) { return st::cycloid_ltca::Parse(n); })};
          },
          py::arg("study"), "From a camopt.Study, a dict or a path of kind cycloid_ltca.")
      .def_property_readonly("teeth", [](const CycloidDrive& c) { return c.study.drive.teeth; })
      .def_property_readonly("rollers", [](const CycloidDrive& c) { return c.study.drive.rollers; })
      .def_property_readonly("crank_angles_rad",
                             [](const CycloidDrive& c) { return Vector(c.study.crank_angles_rad); },
                             "The study's crank angles (those of per_angle.csv without the error estimate).")
      .def_property_readonly("disc_torque_Nm", [](const CycloidDrive& c) { return c.study.disc_torque_Nmm() / 1000; })
      .def("profile", &CycloidDrive::Profile, py::arg("points") = 3600,
           "(x, y) [mm] of the (modified) tooth profile in the disc frame at t = 2*pi*k/points.")
      .def("roller_centres", &CycloidDrive::RollerCentres, py::arg("crank_angle_rad") = 0.0,
           "(x, y) [mm] of the rollers' centres in the disc frame at a crank angle (unloaded).")
      .def("unloaded", &CycloidDrive::Unloaded, py::arg("angles_rad"),
           "Unloaded TCA at the crank angles [rad]: crank_angle_deg, unloaded_te_arcsec, backlash_arcsec\n"
           "(angles x rollers; -1 where the roller's flank is not loaded).")
      .def("loads", &CycloidDrive::Loads, py::arg("angles_rad"), py::arg("progress") = py::none(),
           "Loaded TCA under the study's torque per disc at the crank angles [rad] (in order): crank_angle_deg,\n"
           "lte_arcsec, unloaded_te_arcsec, gear_ratio, max_contact_stress_MPa, pairs_in_contact,\n"
           "roller_load_N and roller_max_pressure_MPa (each pair's own peak; angles x rollers), converged.\n"
           "Ctrl-C raises KeyboardInterrupt.");

  py::class_<DiscCam>(m, "DiscCam",
                      "The cam of a disc_cam study with a roller or knife-edge follower (model/disc_cam): its profile "
                      "and follower motion, pressure angle and curvature at given cam angles.")
      .def_static(
          "from_study",
          [](const py::object& s) {
            const StudyData d = ToStudy(s);
            return DiscCam{ParseKind<st::disc_cam::Study>(d, "disc_cam",
                                                          [](const st::Node& n) { return st::disc_cam::Parse(n); })};
          },
          py::arg("study"), "From a camopt.Study, a dict or a path of kind disc_cam.")
      .def_property_readonly("angles_rad", &DiscCam::StudyAngles,
                             "The study's cam angles 2*pi*i/angle_steps (those of series.csv).")
      .def_property_readonly("oscillating", &DiscCam::Oscillating)
      .def("evaluate", &DiscCam::Evaluate, py::arg("angles_rad"),
           "At the cam angles [rad]: the columns of series.csv by name (follower in mm, or deg when\n"
           "oscillating; pressure and shift angles; contact and pitch points; q; pitch curvature).")
      .def("profile", &DiscCam::Profile, py::arg("points") = 3600,
           "(x, y) [mm] of the cam profile (the contact points) at theta = 2*pi*i/points.");
}

}  // namespace camopt::python
