// Inspection points and measured parts (model/common/profile_deviation.h, studies/measured_profile.h)
// on the cycloid disc: the inspection CSV against an independent projection onto the exact tooth
// profile (dense sampling and golden-section refinement here, not the code under test), and
// synthetic measured discs — the nominal profile plus a known normal deviation — whose ISO 1101
// deviation is computed here from the known deviation and whose transmission error is the
// existing tolerance model's (a uniform offset is its `profile` δn) or the first-order prediction
// of TE1 (model/cycloid/transmission_error.h): pair i closes at β_i − d(t_i)/l_i.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/common/profile_deviation.h"
#include "model/cycloid/parts.h"
#include "model/cycloid/tooth_profile.h"
#include "model/cycloid/transmission_error.h"
#include "model/cycloid/unloaded_tca.h"
#include "model/cycloid/loaded_tca.h"
#include "studies/cycloid_life.h"
#include "studies/cycloid_ltca_study.h"
#include "studies/lcr_analysis_study.h"
#include "studies/disc_cam_study.h"
#include "model/disc_cam/disc_cam.h"
#include "model/disc_cam/flat_faced.h"
#include "model/lcr/profile.h"
#include "model/lcr/transmission_error.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt {
namespace measured_profile_test {

namespace fs = std::filesystem;
namespace ltca = studies::cycloid_ltca;
using camopt::testing::CycloidNnm;
using camopt::testing::ReadFile;
using camopt::testing::RunCamopt;
using camopt::testing::TempDir;
using camopt::testing::WriteFile;
using nlohmann::json;

constexpr double kArcsec = 180.0 / kPi * 3600.0;

// A kind's declared "measured" block as result.json has it (null: none).
template <typename T>
json MeasuredJson(const std::optional<T>& m) {
  return m ? studies::WriteResult(*m) : json();
}

// The NNM drive as an unloaded cycloid_ltca study (rigid output), `discs` discs.
json DiscStudy(int discs) {
  return json::parse(R"({"study": "cycloid_ltca", "name": "NNM disc",
    "drive": {"teeth": 15, "rollers": 16, "roller_position_radius_mm": 90, "roller_radius_mm": 7.2,
              "eccentricity_mm": 4.5, "face_width_mm": 17},
    "modification": {"delta_position_um": -16, "delta_radius_um": -8},
    "analysis": {"evaluate": ["unloaded"], "crank_angles_per_mesh_period": 4}, "discs": )" +
                     std::to_string(discs) + "}");
}

// The tooth profile of disc k in its part frame, as the test builds it: ToothProfile turned by
// −2π(k − 1)/(N n2) (the frames decided for the discs' parts).
Vec2<double> PartPoint(const cycloid::Drive& d, int k, int discs, double t) {
  const double g = -2.0 * kPi * (k - 1) / (discs * d.teeth);
  return Rotate(cycloid::ToothProfile<double>(d, t).point, g);
}

// Independent closest point: the nearest of 200 000 samples, then golden section on the distance
// over the two neighbouring intervals. Returns the distance and the parameter.
struct Near {
  double distance, t;
};
class DenseProfile {
 public:
  DenseProfile(const cycloid::Drive& d, int k, int discs) : d_(d), k_(k), discs_(discs) {
    for (int i = 0; i < kN; ++i) pts_.push_back(PartPoint(d, k, discs, 2 * kPi * i / kN));
  }
  Near Closest(const Vec2<double>& q) const {
    int best = 0;
    for (int i = 1; i < kN; ++i)
      if ((pts_[i] - q).squaredNorm() < (pts_[best] - q).squaredNorm()) best = i;
    const double h = 2 * kPi / kN, r = 0.5 * (std::sqrt(5.0) - 1);
    double a = 2 * kPi * best / kN - h, b = a + 2 * h;
    auto f = [&](double t) { return (PartPoint(d_, k_, discs_, t) - q).norm(); };
    for (int it = 0; it < 100; ++it) {
      const double c = b - r * (b - a), e = a + r * (b - a);
      if (f(c) < f(e)) b = e; else a = c;
    }
    return {f(0.5 * (a + b)), 0.5 * (a + b)};
  }
  // Winding number of the sampled polygon around q (0: outside).
  int Winding(const Vec2<double>& q) const {
    double w = 0;
    for (int i = 0; i < kN; ++i) {
      const Vec2<double> a = pts_[i] - q, b = pts_[(i + 1) % kN] - q;
      w += std::atan2(Cross(a, b), a.dot(b));
    }
    return int(std::lround(w / (2 * kPi)));
  }
  double Length() const {
    double l = 0;
    for (int i = 0; i < kN; ++i) l += (pts_[(i + 1) % kN] - pts_[i]).norm();
    return l;
  }
  static constexpr int kN = 200000;

 private:
  cycloid::Drive d_;
  int k_, discs_;
  std::vector<Vec2<double>> pts_;
};

struct CsvRows {
  std::vector<std::string> comments, header;
  std::vector<std::vector<double>> rows;
};
CsvRows ParseCsv(const std::string& text) {
  CsvRows c;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("#", 0) == 0) {
      c.comments.push_back(line);
      continue;
    }
    std::vector<std::string> cells;
    std::string cell;
    std::istringstream l(line);
    while (std::getline(l, cell, ',')) cells.push_back(cell);
    if (c.header.empty()) {
      c.header = cells;
      continue;
    }
    std::vector<double> v;
    for (const auto& s : cells) v.push_back(std::stod(s));
    c.rows.push_back(v);
  }
  return c;
}

// Inspection points of both discs of a two-disc drive: on the exact profile of each disc's part
// frame within 0.1 µm (independent projection), unit outward normals perpendicular to the
// profile, arcs <= the spacing, the ISO 1101 zone ± t/2, and the same bytes on a second run.
TEST(MeasuredProfile, CycloidInspectionPointsOnTheExactProfile) {
  const auto dir = TempDir("inspection-cycloid");
  json study = DiscStudy(2);
  study["inspection"] = {{"spacing_mm", 0.5}, {"tolerance_um", 8}};
  WriteFile(dir / "study.json", study.dump());
  for (const char* out : {"a", "b"}) {
    const auto r = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " + (dir / out).string());
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  }
  const json result = json::parse(ReadFile(dir / "a" / "result.json"));
  const cycloid::Drive d = CycloidNnm();
  for (int k = 1; k <= 2; ++k) {
    SCOPED_TRACE(k);
    const std::string name = "disc_" + std::to_string(k);
    const std::string text = ReadFile(dir / "a" / "inspection" / (name + ".csv"));
    EXPECT_EQ(text, ReadFile(dir / "b" / "inspection" / (name + ".csv"))) << "byte-identical rerun";
    const CsvRows c = ParseCsv(text);
    ASSERT_EQ(c.header, (std::vector<std::string>{"x_mm", "y_mm", "nx", "ny", "nominal_mm", "upper_mm", "lower_mm"}));
    EXPECT_EQ(result["inspection"]["parts"][name]["points"].get<size_t>(), c.rows.size());
    std::string comments;
    for (const auto& l : c.comments) comments += l + "\n";
    EXPECT_NE(comments.find("ISO 1101"), std::string::npos);
    EXPECT_NE(comments.find("datum"), std::string::npos);
    const DenseProfile exact(d, k, 2);
    // n = ceil(L / s) points: at least the polyline's length over the spacing.
    EXPECT_GE(double(c.rows.size()), exact.Length() / 0.5);
    EXPECT_LE(double(c.rows.size()), exact.Length() / 0.5 + 2.0);
    double worst_distance = 0, worst_unit = 0, worst_perp = 0, worst_chord = 0;
    for (size_t i = 0; i < c.rows.size(); ++i) {
      const auto& v = c.rows[i];
      const Vec2<double> p(v[0], v[1]), n(v[2], v[3]);
      const Near near = exact.Closest(p);
      worst_distance = std::max(worst_distance, near.distance);
      worst_unit = std::max(worst_unit, std::abs(n.norm() - 1.0));
      const double h = 1e-6;
      const Vec2<double> tangent =
          (PartPoint(d, k, 2, near.t + h) - PartPoint(d, k, 2, near.t - h)).normalized();
      worst_perp = std::max(worst_perp, std::abs(n.dot(tangent)));
      const auto& w = c.rows[(i + 1) % c.rows.size()];
      worst_chord = std::max(worst_chord, (Vec2<double>(w[0], w[1]) - p).norm());
      if (i % 97 == 0) {
        EXPECT_EQ(exact.Winding(p + 0.01 * n), 0) << "outward normal at row " << i;
        EXPECT_NE(exact.Winding(p - 0.01 * n), 0) << "inward at row " << i;
      }
      EXPECT_EQ(v[4], 0.0);
      EXPECT_EQ(v[5], 0.004);
      EXPECT_EQ(v[6], -0.004);
    }
    EXPECT_LE(worst_distance, 1e-4) << "mm";
    EXPECT_LE(worst_unit, 1e-9);
    EXPECT_LE(worst_perp, 1e-7);
    EXPECT_LE(worst_chord, 0.5);
  }
}

// A synthetic measurement: rows of the nominal disc_k profile plus a known deviation, written as
// the test's own CSV of the given kind.
struct Synthetic {
  std::vector<double> t, d;               // parameter and known normal deviation of each row
  std::vector<Vec2<double>> nominal, normal;
};
Synthetic Sample(const cycloid::Drive& d, int k, int discs, int n, const std::function<double(double, Vec2<double>)>& dev) {
  Synthetic s;
  const double g = -2.0 * kPi * (k - 1) / (discs * d.teeth);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * kPi * (i + 0.25) / n;
    const cycloid::ProfilePoint<double> p = cycloid::ToothProfile<double>(d, t);
    s.t.push_back(t);
    s.nominal.push_back(Rotate(p.point, g));
    s.normal.push_back(Rotate(p.normal, g));
    s.d.push_back(dev(t, s.normal.back()));
  }
  return s;
}
std::string Csv(const Synthetic& s, const std::string& kind, double translate_x = 0, double translate_y = 0) {
  std::ostringstream o;
  o.precision(17);
  if (kind == "points") {
    o << "# synthetic measurement\nx_mm,y_mm\n";
    for (size_t i = 0; i < s.t.size(); ++i) {
      if (translate_x != 0 || translate_y != 0)
        o << s.nominal[i].x() + translate_x << "," << s.nominal[i].y() + translate_y << "\n";
      else
        o << s.nominal[i].x() + s.d[i] * s.normal[i].x() << "," << s.nominal[i].y() + s.d[i] * s.normal[i].y() << "\n";
    }
  } else {
    o << "x_mm,y_mm,nx,ny,deviation_mm\n";
    for (size_t i = 0; i < s.t.size(); ++i)
      o << s.nominal[i].x() << "," << s.nominal[i].y() << "," << s.normal[i].x() << "," << s.normal[i].y() << ","
        << s.d[i] << "\n";
  }
  return o.str();
}

struct Measured {
  ltca::Study study;
  json measured;
};
Measured RunMeasured(const std::string& tag, int discs, int k, const std::string& kind, const std::string& csv) {
  const auto dir = TempDir("measured-" + tag);
  WriteFile(dir / "points.csv", csv);
  json j = DiscStudy(discs);
  j["measured_profile"] = {{"part", "disc_" + std::to_string(k)}, {"file", "points.csv"}, {"kind", kind}};
  const std::string file = (dir / "study.json").string();
  Measured m{ltca::Parse(studies::Node(&j, file, "")), json()};
  const ltca::Result r = ltca::Run(m.study, studies::RunContext{file, true});
  m.measured = MeasuredJson(r.measured);
  return m;
}

// The study's crank angles for disc k (64 per mesh period over one output revolution, the disc's own).
std::vector<double> DiscAngles(const cycloid::Drive& d, int k, int discs) {
  std::vector<double> a;
  const int n = 64 * d.rollers * d.teeth;
  for (int i = 0; i < n; ++i) a.push_back(2 * kPi * d.teeth * i / n + 2 * kPi * (k - 1) / discs);
  return a;
}

// First order (TE1): TE(φ) = min_i (β_i − d(t_i)/l_i) − β0 over the loaded flank's pairs of the
// nominal drive, d the known deviation at the pair's nominal contact.
std::pair<double, double> FirstOrderTeRange(const cycloid::Drive& d, const std::vector<double>& angles,
                                            const std::function<double(double)>& dev_of_t) {
  double lo = INFINITY, hi = -INFINITY;
  for (double phi : angles) {
    const cycloid::UnloadedMesh<double> u = cycloid::UnloadedTca<double>(d, phi);
    double best = INFINITY;
    for (const auto& g : u.pairs)
      if (g.loaded_flank) best = std::min(best, g.contact_rotation - dev_of_t(g.parameter) / g.arm_mm);
    lo = std::min(lo, best - u.rotation);
    hi = std::max(hi, best - u.rotation);
  }
  return {lo, hi};
}

// A uniform offset δ: ISO 1101 deviation 2δ, and the transmission error of the existing tolerance
// model with profile = δ (ExactTransmissionError, same angles) to 1e-9 arcsec; to first order −δ/l.
// Both kinds of file give the same.
TEST(MeasuredProfile, CycloidUniformOffsetIsTheToleranceModelsProfileOffset) {
  const cycloid::Drive d = CycloidNnm();
  const double delta = 0.002;
  const Synthetic s = Sample(d, 2, 2, 2400, [&](double, Vec2<double>) { return delta; });
  std::vector<double> angles = DiscAngles(d, 2, 2);
  cycloid::Deviations<double> dev;
  dev.profile = delta;
  const std::vector<double> te = cycloid::ExactTransmissionError(d, nullptr, dev, angles);
  const auto [te_lo, te_hi] = std::minmax_element(te.begin(), te.end());
  const auto [p_lo, p_hi] = FirstOrderTeRange(d, angles, [&](double) { return delta; });
  for (const std::string kind : {"points", "normal_deviation"}) {
    SCOPED_TRACE(kind);
    const Measured m = RunMeasured("uniform-" + kind, 2, 2, kind, Csv(s, kind));
    const json& j = m.measured;
    EXPECT_NEAR(j["iso1101_profile_deviation_um"].get<double>(), 2 * delta * 1e3, 1e-6);
    EXPECT_NEAR(j["mean_deviation_um"].get<double>(), delta * 1e3, 1e-6);
    EXPECT_NEAR(j["rms_deviation_um"].get<double>(), delta * 1e3, 1e-6);
    const json& k = j["kinematic"];
    EXPECT_NEAR(k["transmission_error_max_arcsec"].get<double>(), *te_hi * kArcsec, 1e-6);
    EXPECT_NEAR(k["transmission_error_min_arcsec"].get<double>(), *te_lo * kArcsec, 1e-6);
    // −δ/l, about −6 arcsec: the second order is δ/(its scale) smaller.
    EXPECT_NEAR(k["transmission_error_max_arcsec"].get<double>(), p_hi * kArcsec, 0.01 * std::abs(p_hi * kArcsec));
    EXPECT_NEAR(k["transmission_error_min_arcsec"].get<double>(), p_lo * kArcsec, 0.01 * std::abs(p_lo * kArcsec));
    EXPECT_LT(p_hi * kArcsec, -5.0);
    std::printf("uniform %s: zone %.9f um; TE %.9f..%.9f arcsec, tolerance model %.9f..%.9f, first order %.6f..%.6f\n",
                kind.c_str(), j["iso1101_profile_deviation_um"].get<double>(),
                k["transmission_error_min_arcsec"].get<double>(), k["transmission_error_max_arcsec"].get<double>(),
                *te_lo * kArcsec, *te_hi * kArcsec, p_lo * kArcsec, p_hi * kArcsec);
  }
}

// An eccentric profile (translated by ε in the part frame): d = ε·n to first order, the ISO 1101
// deviation 2 max|ε·n| (≈ 2|ε|), the transmission error TE1's with d(t) = ε·n(t).
TEST(MeasuredProfile, CycloidEccentricProfile) {
  const cycloid::Drive d = CycloidNnm();
  const Vec2<double> eps(0.003, -0.004);
  const Synthetic s = Sample(d, 1, 1, 3000, [&](double, Vec2<double> n) { return eps.dot(n); });
  const Measured m = RunMeasured("eccentric", 1, 1, "points", Csv(s, "points", eps.x(), eps.y()));
  double expected = 0;
  for (double v : s.d) expected = std::max(expected, 2 * std::abs(v));
  EXPECT_NEAR(m.measured["iso1101_profile_deviation_um"].get<double>(), expected * 1e3, 0.005);
  EXPECT_NEAR(expected, 2 * eps.norm(), 2e-4);
  const auto [p_lo, p_hi] = FirstOrderTeRange(d, DiscAngles(d, 1, 1), [&](double t) {
    return eps.dot(cycloid::ToothProfile<double>(d, t).normal);
  });
  const json& k = m.measured["kinematic"];
  const double range = (p_hi - p_lo) * kArcsec;
  EXPECT_GT(range, 1.0);
  EXPECT_NEAR(k["transmission_error_max_arcsec"].get<double>(), p_hi * kArcsec, 0.02 * range);
  EXPECT_NEAR(k["transmission_error_min_arcsec"].get<double>(), p_lo * kArcsec, 0.02 * range);
  std::printf("eccentric: zone %.6f um (2 max|eps.n| %.6f); TE %.6f..%.6f arcsec, first order %.6f..%.6f\n",
              m.measured["iso1101_profile_deviation_um"].get<double>(), expected * 1e3,
              k["transmission_error_min_arcsec"].get<double>(), k["transmission_error_max_arcsec"].get<double>(),
              p_lo * kArcsec, p_hi * kArcsec);
}

// A single cos² bump of height h over w = 4 mm of arc on the flank the first contact uses at crank
// 0: ISO 1101 deviation 2h, and the transmission error TE1's with the bump.
TEST(MeasuredProfile, CycloidSingleBump) {
  const cycloid::Drive d = CycloidNnm();
  const double h = 0.003, w = 4.0;
  const cycloid::UnloadedMesh<double> u = cycloid::UnloadedTca<double>(d, 0.0);
  const double tb = u.pairs[u.first_contact].parameter;
  // Arc length from tb by the test's own quadrature (1e-6 steps of t).
  auto arc = [&](double t) {
    const int n = 2000;
    double s = 0;
    Vec2<double> prev = cycloid::ToothProfile<double>(d, tb).point;
    for (int i = 1; i <= n; ++i) {
      const Vec2<double> p = cycloid::ToothProfile<double>(d, tb + (t - tb) * i / n).point;
      s += (p - prev).norm();
      prev = p;
    }
    return t >= tb ? s : -s;
  };
  auto bump = [&](double t) {
    double dt = std::remainder(t - tb, 2 * kPi);
    if (std::abs(dt) > 0.2) return 0.0;
    const double s = arc(tb + dt);
    return std::abs(s) < w / 2 ? h * std::pow(std::cos(kPi * s / w), 2) : 0.0;
  };
  // Rows every 2π/6000 (about 0.1 mm), one at the bump's crest.
  Synthetic s;
  const int n = 6000;
  for (int i = 0; i < n; ++i) {
    const double t = tb + 2 * kPi * i / n;
    const cycloid::ProfilePoint<double> p = cycloid::ToothProfile<double>(d, t);
    s.t.push_back(t), s.nominal.push_back(p.point), s.normal.push_back(p.normal), s.d.push_back(bump(t));
  }
  const Measured m = RunMeasured("bump", 1, 1, "normal_deviation", Csv(s, "normal_deviation"));
  EXPECT_NEAR(m.measured["iso1101_profile_deviation_um"].get<double>(), 2 * h * 1e3, 1e-9);
  EXPECT_NEAR(m.measured["max_deviation_um"].get<double>(), h * 1e3, 1e-9);
  EXPECT_NEAR(m.measured["min_deviation_um"].get<double>(), 0.0, 1e-9);
  const auto [p_lo, p_hi] = FirstOrderTeRange(d, DiscAngles(d, 1, 1), bump);
  const json& k = m.measured["kinematic"];
  EXPECT_LT(p_lo * kArcsec, -1.0) << "the bump is met by the first contact";
  EXPECT_NEAR(k["transmission_error_min_arcsec"].get<double>(), p_lo * kArcsec, 0.02 * std::abs(p_lo * kArcsec));
  EXPECT_NEAR(k["transmission_error_max_arcsec"].get<double>(), p_hi * kArcsec, 0.02 * std::abs(p_lo * kArcsec));
  std::printf("bump: zone %.9f um; TE %.6f..%.6f arcsec, first order %.6f..%.6f\n",
              m.measured["iso1101_profile_deviation_um"].get<double>(), k["transmission_error_min_arcsec"].get<double>(),
              k["transmission_error_max_arcsec"].get<double>(), p_lo * kArcsec, p_hi * kArcsec);
}

// The loaded TCA of a measured disc with a uniform offset δ: the tooth moved by δ along its
// normal is exactly the tooth cut with ρ' − δ (an offset of an offset), so its cycle is the LTCA of
// the drive with delta_radius_mm − δ on the same crank angles (8 per mesh period over one output
// revolution), run here with the study's grid.
TEST(MeasuredProfile, CycloidLoadedUniformOffsetIsTheToothCutWithSmallerRho) {
  const cycloid::Drive d = CycloidNnm();
  const double delta = 0.001;
  const Synthetic s = Sample(d, 1, 1, 2400, [&](double, Vec2<double>) { return delta; });
  const auto dir = TempDir("measured-loaded");
  WriteFile(dir / "points.csv", Csv(s, "points"));
  json j = DiscStudy(1);
  j["analysis"] = {{"crank_angles_per_mesh_period", 4}, {"grid", {12, 12}}, {"estimate_error", false}};
  j["material"] = {{"youngs_modulus_GPa", 206}, {"poisson_ratio", 0.3}};
  j["load"] = {{"torque_Nm", 350}};
  j["measured_profile"] = {{"part", "disc_1"}, {"file", "points.csv"}, {"kind", "points"}};
  const std::string file = (dir / "study.json").string();
  const ltca::Study st = ltca::Parse(studies::Node(&j, file, ""));
  const json m = MeasuredJson(ltca::Run(st, studies::RunContext{file, true}).measured);
  ASSERT_TRUE(m.contains("loaded")) << m.dump();
  std::vector<double> angles;
  const int n = 8 * d.rollers * d.teeth;
  for (int i = 0; i < n; ++i) angles.push_back(2 * kPi * d.teeth * i / n);
  cycloid::LoadedOptions o;
  o.profile_cells = o.axial_cells = 12;
  o.crank_slope = false;
  cycloid::Drive cut = d;
  cut.delta_radius_mm -= delta;
  const cycloid::Material mat;
  const cycloid::CycleResult nominal = cycloid::RunCycle(cycloid::LoadedTca(d, st.crowning, mat, o), 350000.0, angles);
  // Every angle solved in turn, warm-started from the one before, as the measured disc's (its
  // iterations stop within the compatibility tolerance 1e-3: the same path gives the same stop).
  o.reuse_symmetric_angles = false;
  const cycloid::CycleResult expected = cycloid::RunCycle(cycloid::LoadedTca(cut, st.crowning, mat, o), 350000.0, angles);
  const json& l = m["loaded"];
  EXPECT_NEAR(l["max_contact_stress_MPa"]["measured"].get<double>(), expected.max_pressure_MPa,
              1e-4 * expected.max_pressure_MPa);
  EXPECT_NEAR(l["max_pair_load_N"]["measured"].get<double>(), expected.max_pair_load_N, 1e-4 * expected.max_pair_load_N);
  EXPECT_NEAR(l["lte_peak_to_peak_arcsec"]["measured"].get<double>(), expected.lte_peak_to_peak_arcsec,
              1e-3 * expected.lte_peak_to_peak_arcsec);
  EXPECT_NEAR(l["max_contact_stress_MPa"]["nominal"].get<double>(), nominal.max_pressure_MPa, 1e-9);
  std::printf("loaded uniform: max stress %.6f MPa (cut with rho' - delta %.6f; nominal %.6f), max load %.6f N (%.6f), "
              "LTE p2p %.6f arcsec (%.6f)\n",
              l["max_contact_stress_MPa"]["measured"].get<double>(), expected.max_pressure_MPa, nominal.max_pressure_MPa,
              l["max_pair_load_N"]["measured"].get<double>(), expected.max_pair_load_N,
              l["lte_peak_to_peak_arcsec"]["measured"].get<double>(), expected.lte_peak_to_peak_arcsec);
}

// The lives as made: a disc measured 1 µm fuller everywhere carries its duty cycle as the tooth cut
// with ρ' − 1 µm does (the same equivalence as the stress above), so the measured crank-bearing and
// pin lives are those of the cut tooth's cycle on the same angles, and differ from the nominal's.
TEST(MeasuredProfile, CycloidLivesAsMadeAreTheToothCutWithSmallerRhos) {
  const cycloid::Drive d = CycloidNnm();
  const double delta = 0.001;
  const Synthetic s = Sample(d, 1, 1, 2400, [&](double, Vec2<double>) { return delta; });
  const auto dir = TempDir("measured-life");
  WriteFile(dir / "points.csv", Csv(s, "points"));
  json j = DiscStudy(1);
  j["analysis"] = {{"crank_angles_per_mesh_period", 4}, {"grid", {10, 10}}, {"estimate_error", false}};
  j["material"] = {{"youngs_modulus_GPa", 206}, {"poisson_ratio", 0.3}};
  j["load"] = {{"torque_Nm", 350}, {"input_speed_rpm", 1500}};
  j["crank_bearing"] = {{"kind", "roller"}, {"dynamic_rating_N", 60000}};
  j["pins"] = {{"dynamic_rating_N", 9000}};
  j["output_mechanism"] = {{"pins", 8}, {"pin_circle_radius_mm", 50}};
  j["measured_profile"] = {{"part", "disc_1"}, {"file", "points.csv"}, {"kind", "points"}};
  const std::string file = (dir / "study.json").string();
  const ltca::Study st = ltca::Parse(studies::Node(&j, file, ""));
  ASSERT_TRUE(st.life.has_value());
  const json m = MeasuredJson(ltca::Run(st, studies::RunContext{file, true}).measured);
  ASSERT_TRUE(m["loaded"].contains("life")) << m.dump().substr(0, 400);
  std::vector<double> angles;
  const int n = 8 * d.rollers * d.teeth;
  for (int i = 0; i < n; ++i) angles.push_back(2 * kPi * d.teeth * i / n);
  cycloid::LoadedOptions o;
  o.profile_cells = o.axial_cells = 10;
  o.crank_slope = false;
  o.reuse_symmetric_angles = false;
  cycloid::Drive cut = d;
  cut.delta_radius_mm -= delta;
  const cycloid::Material mat;
  const cycloid::LoadedTca tca(cut, st.crowning, mat, o);
  const studies::cycloid_common::LifeResult expected = studies::cycloid_common::RunLife(*st.life, tca, angles);
  const json& life = m["loaded"]["life"];
  ASSERT_EQ(expected.elements.size(), 2u);
  for (const auto& e : expected.elements) {
    const double got = life["L10h"][e.name]["measured"], nominal = life["L10h"][e.name]["nominal"];
    std::printf("life as made, %s: %.6f h (tooth cut with rho' - 1 um: %.6f h; nominal %.6f h)\n", e.name.c_str(), got,
                e.life.L10h, nominal);
    EXPECT_NEAR(got, e.life.L10h, 1e-3 * e.life.L10h) << e.name;
    EXPECT_GT(std::abs(got - nominal), 10 * std::abs(got - e.life.L10h)) << e.name << ": the measured disc changes it";
  }
  EXPECT_NEAR(life["shortest_L10h"]["measured"].get<double>(), expected.shortest_L10h, 1e-3 * expected.shortest_L10h);
}

// The model pieces on a closed form: an ellipse's projection and the periodic spline of a
// trigonometric function.
TEST(MeasuredProfile, ProjectionAndSplineOnClosedForms) {
  const double a = 30, b = 20;
  profile::Curve ellipse = [&](double t) {
    profile::CurvePoint c;
    c.point = Vec2<double>(a * std::cos(t), b * std::sin(t));
    const Vec2<double> dp(-a * std::sin(t), b * std::cos(t)), ddp(-a * std::cos(t), -b * std::sin(t));
    c.speed = dp.norm();
    c.tangent = dp / c.speed;
    c.curvature = Cross(dp, ddp) / std::pow(c.speed, 3);
    return c;
  };
  const profile::ClosedProfile p(ellipse, 0.0, 2 * kPi, 256);
  // Ramanujan's second approximation of the perimeter (relative error ~1e-10 at this ratio).
  const double hh = std::pow((a - b) / (a + b), 2);
  EXPECT_NEAR(p.length_mm(), kPi * (a + b) * (1 + 3 * hh / (10 + std::sqrt(4 - 3 * hh))), 1e-7);
  // A point on the normal at distance δ projects back to its foot with deviation δ.
  for (double t : {0.1, 1.3, 2.9, 4.4, 6.2}) {
    const Vec2<double> foot(a * std::cos(t), b * std::sin(t));
    const Vec2<double> n = Vec2<double>(b * std::cos(t), a * std::sin(t)).normalized();  // outward
    for (double delta : {-0.7, 0.003, 0.9}) {
      const auto pr = p.Project(foot + delta * n);
      EXPECT_NEAR(pr.deviation_mm, delta, 1e-12);
      EXPECT_NEAR((pr.foot - foot).norm(), 0.0, 1e-10);
    }
  }
  // The spline of sin(t) + 0.5 cos(3t) on 64 uneven knots: within the cubic spline's error bounds
  // (Hall & Meyer 1976) (5/384) h⁴ |f⁗| for the value and (1/24) h³ |f⁗| for the slope, h the
  // largest knot interval, |f⁗| <= 1 + 0.5·81.
  std::vector<double> t, v;
  double hmax = 0;
  for (int i = 0; i < 64; ++i) {
    const double x = 2 * kPi * (i + 0.3 * std::sin(i)) / 64;
    if (!t.empty()) hmax = std::max(hmax, x - t.back());
    t.push_back(x), v.push_back(std::sin(x) + 0.5 * std::cos(3 * x));
  }
  hmax = std::max(hmax, t[0] + 2 * kPi - t.back());
  const double f4 = 1 + 0.5 * 81;
  const profile::PeriodicSpline sp(t, v, 2 * kPi);
  for (int i = 0; i < 500; ++i) {
    const double x = -3 + 0.05 * i;
    double slope;
    EXPECT_NEAR(sp(x, &slope), std::sin(x) + 0.5 * std::cos(3 * x), 5.0 / 384 * std::pow(hmax, 4) * f4) << x;
    EXPECT_NEAR(slope, std::cos(x) - 1.5 * std::sin(3 * x), std::pow(hmax, 3) * f4 / 24) << x;
  }
  for (size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(sp(t[i] + 2 * kPi), v[i], 1e-12);
}

// The command line: a study with a measured disc runs (exit 0, "measured" in result.json); a file
// that is missing, a NaN, a point 2 mm off the profile, too few points are bad input (exit 2)
// naming the study file, /measured_profile/file, and what was expected.
TEST(MeasuredProfile, CycloidCommandLine) {
  const cycloid::Drive d = CycloidNnm();
  const Synthetic s = Sample(d, 1, 1, 1200, [&](double, Vec2<double>) { return 0.001; });
  const auto dir = TempDir("measured-cli");
  WriteFile(dir / "m.csv", Csv(s, "points"));
  json study = DiscStudy(1);
  study["measured_profile"] = {{"part", "disc_1"}, {"file", "m.csv"}, {"kind", "points"}};
  study["inspection"] = {{"spacing_mm", 1}, {"tolerance_um", 5}};
  WriteFile(dir / "study.json", study.dump());
  const auto r = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " + (dir / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  const json result = json::parse(ReadFile(dir / "out" / "result.json"));
  ASSERT_TRUE(result.contains("measured"));
  EXPECT_NEAR(result["measured"]["iso1101_profile_deviation_um"].get<double>(), 2.0, 1e-6);
  EXPECT_TRUE(result["measured"]["kinematic"].contains("backlash_max_arcmin"));
  EXPECT_TRUE(fs::exists(dir / "out" / "inspection" / "disc_1.csv"));

  auto bad = [&](const std::string& tag, const std::string& csv, const std::string& words, const std::string& part = "disc_1") {
    const auto bdir = TempDir("measured-bad-" + tag);
    if (!csv.empty()) WriteFile(bdir / "m.csv", csv);
    json b = DiscStudy(1);
    b["measured_profile"] = {{"part", part}, {"file", (bdir / "m.csv").string()}, {"kind", "points"}};
    camopt::testing::ExpectStudyRejected(b, "measured-" + tag, part == "disc_1" ? "/measured_profile/file" : "/measured_profile/part", words);
  };
  bad("missing", "", "expected a readable CSV file");
  std::string nan = Csv(s, "points");
  nan.replace(nan.find('\n', nan.find("x_mm")) + 1, 0, "nan,3\n");
  bad("nan", nan, "expected a finite number in column x_mm");
  std::string far = Csv(s, "points");
  far += "200,0\n";
  bad("far", far, "within 1 mm of the exact profile");
  bad("columns", "u,v\n1,2\n", "a header line with the columns x_mm,y_mm");
  std::string few = "x_mm,y_mm\n";
  for (int i = 0; i < 100; ++i) few += std::to_string(s.nominal[i].x()) + "," + std::to_string(s.nominal[i].y()) + "\n";
  bad("gap", few, "points covering the whole profile");
  bad("part", Csv(s, "points"), "a disc of the drive, disc_1 to disc_1", "disc_2");
}

// ---------------------------------------------------------------------------------------------
// LCR: LCR II (the paper's) at 80 N·m, compliant load sharing, as studies/examples/lcr_ii_tolerances.json.

json LcrStudy() {
  return json::parse(R"({"study": "lcr_analysis", "name": "LCR II",
    "reducer": {"eccentricity_mm": 2,
                "input": {"lobes": 12, "rollers": 13, "turret_radius_mm": 37, "roller_diameter_mm": 12,
                          "roller_length_mm": 10, "cam_thickness_mm": 8},
                "output": {"lobes": 14, "rollers": 15, "turret_radius_mm": 42, "roller_diameter_mm": 12,
                           "roller_length_mm": 10, "cam_thickness_mm": 8}},
    "material": {"youngs_modulus_GPa": 206, "poisson_ratio": 0.3},
    "load": {"output_torque_Nm": 80, "friction_coefficient": 0.05},
    "analysis": {"angle_steps": 36, "load_model": "compliant", "evaluate": ["forces"]}})");
}

// Nominal rows of a cam profile from the model's OffsetPoint (the cam frame of its DXF) with
// their outward normals (−InwardNormal), and a known deviation.
Synthetic CamSample(const lcr::CamSide<double>& c, double e, int n, const std::function<double(double, Vec2<double>)>& dev) {
  Synthetic s;
  for (int i = 0; i < n; ++i) {
    const double psi = 2 * kPi * (i + 0.5) / n;
    s.t.push_back(psi);
    s.nominal.push_back(lcr::OffsetPoint(c, e, psi, c.roller_radius));
    s.normal.push_back(-lcr::InwardNormal(c, e, psi));
    s.d.push_back(dev(psi, s.normal.back()));
  }
  return s;
}

json RunLcrMeasured(const std::string& tag, const std::string& part, const std::string& kind, const std::string& csv) {
  const auto dir = TempDir("lcr-measured-" + tag);
  WriteFile(dir / "points.csv", csv);
  json j = LcrStudy();
  j["measured_profile"] = {{"part", part}, {"file", "points.csv"}, {"kind", kind}};
  const std::string file = (dir / "study.json").string();
  const studies::lcr_analysis::Study st = studies::lcr_analysis::Parse(studies::Node(&j, file, ""));
  return MeasuredJson(studies::lcr_analysis::Run(st, studies::RunContext{file, true}).measured);
}

// A uniform offset δ of the output cam: ISO 1101 deviation 2δ, and the transmission error of the
// existing tolerance model with the cam's `profile` offset δ (lcr::ExactTransmissionError at the
// same 720 angles), both kinds of file.
TEST(MeasuredProfile, LcrUniformOffsetIsTheToleranceModelsProfileOffset) {
  const lcr::Reducer<double> r = camopt::testing::LcrII();
  const double delta = 0.002;
  const Synthetic s = CamSample(r.output, r.eccentricity, 1500, [&](double, Vec2<double>) { return delta; });
  lcr::Material mat;
  mat.youngs_modulus_MPa = 206000;
  mat.poisson_ratio = 0.3;
  lcr::Deviations<double> dev;
  dev.profile[1] = delta;
  std::vector<double> theta;
  for (int i = 0; i < 720; ++i) theta.push_back(2 * kPi * i / 720);
  const std::vector<double> te = lcr::ExactTransmissionError(r, mat, dev, 80000.0, theta);
  const auto [lo, hi] = std::minmax_element(te.begin(), te.end());
  for (const std::string kind : {"points", "normal_deviation"}) {
    SCOPED_TRACE(kind);
    const json m = RunLcrMeasured("uniform-" + kind, "output_cam", kind, Csv(s, kind));
    EXPECT_NEAR(m["iso1101_profile_deviation_um"].get<double>(), 2 * delta * 1e3, 1e-6);
    const json& c = m["compliant"];
    EXPECT_NEAR(c["transmission_error_max_arcsec"].get<double>(), *hi * kArcsec, 1e-6);
    EXPECT_NEAR(c["transmission_error_min_arcsec"].get<double>(), *lo * kArcsec, 1e-6);
    EXPECT_LT(*hi * kArcsec, -1.0);
    if (kind == "points") {
      // The Hertz stress on the moved profile: an offset of the pitch curve by r_r − δ, curvature
      // κ/(1 − (r_r − δ)κ), with the tolerance model's roller forces; E* = E/(2(1 − ν²)).
      const double e_star = 206000.0 / (2 * (1 - 0.3 * 0.3)), rr = r.output.roller_radius;
      const double t = lcr::LoadedArmSign(r, lcr::Side::kOutput) * 80000.0;
      double expected = 0;
      for (double th : theta) {
        const auto eq = lcr::CompliantAtAngle<double>(r, mat, th, t, &dev);
        const auto contacts = lcr::RollerContacts(r, lcr::Side::kOutput, th);
        for (size_t k = 0; k < contacts.size(); ++k) {
          const double kap = contacts[k].curvature, f = eq.force_output[k];
          if (f > 0)
            expected = std::max(expected, std::sqrt(f * e_star * (1 / rr + kap / (1 - (rr - delta) * kap)) /
                                                    (kPi * r.output.contact_length())));
        }
      }
      const double ours = c["max_contact_stress_MPa"]["measured"].get<double>();
      EXPECT_NEAR(ours, expected, 1e-6 * expected);
      std::printf("lcr uniform stress: %.6f MPa (closed form %.6f, nominal %.6f)\n", ours, expected,
                  c["max_contact_stress_MPa"]["nominal"].get<double>());
    }
    std::printf("lcr uniform %s: zone %.9f um; TE %.9f..%.9f arcsec, tolerance model %.9f..%.9f\n", kind.c_str(),
                m["iso1101_profile_deviation_um"].get<double>(), c["transmission_error_min_arcsec"].get<double>(),
                c["transmission_error_max_arcsec"].get<double>(), *lo * kArcsec, *hi * kArcsec);
  }
}

// The input cam's profile translated by ε in its frame: to first order d = ε·n; exactly, the input
// cam's centre moved by R(φ)ε in the fixed frame (φ the cam's turn): the existing model's gaps
// with that centre shift on the input side only (RollerGaps' bearing shift; the output cam stays),
// in the compliant equilibrium as CompliantAtAngle solves it (the turrets' springs).
TEST(MeasuredProfile, LcrEccentricCamIsACentreShift) {
  const lcr::Reducer<double> r = camopt::testing::LcrII();
  const Vec2<double> eps(0.002, 0.0015);
  const Synthetic s = CamSample(r.input, r.eccentricity, 2000, [&](double, Vec2<double> n) { return eps.dot(n); });
  const json m = RunLcrMeasured("eccentric", "input_cam", "points", Csv(s, "points", eps.x(), eps.y()));
  double zone = 0;
  for (double v : s.d) zone = std::max(zone, 2 * std::abs(v));
  EXPECT_NEAR(m["iso1101_profile_deviation_um"].get<double>(), zone * 1e3, 0.005);
  lcr::Material mat;
  mat.youngs_modulus_MPa = 206000;
  mat.poisson_ratio = 0.3;
  double lo = INFINITY, hi = -INFINITY;
  const double t = lcr::LoadedArmSign(r, lcr::Side::kOutput) * 80000.0;
  const double rho = rigidity::FixedTurretTorqueRatio(r);
  for (int i = 0; i < 720; ++i) {
    const double th = 2 * kPi * i / 720, phi = lcr::CamSpeedRatio(r) * th;
    rigidity::TurretSpring<double> a{{}, r.input.contact_length(), mat.composite_modulus_MPa(), 0.0, 0.0};
    rigidity::TurretSpring<double> b{{}, r.output.contact_length(), mat.composite_modulus_MPa(), 0.0, 0.0};
    for (const auto& c : lcr::RollerContacts(r, lcr::Side::kInput, th)) a.arms.push_back(c.arm);
    for (const auto& c : lcr::RollerContacts(r, lcr::Side::kOutput, th)) b.arms.push_back(c.arm);
    a.gaps = lcr::RollerGaps(r, lcr::Side::kInput, lcr::Deviations<double>{}, th, Vec2<double>(Rotate(eps, phi)));
    b.gaps = lcr::RollerGaps(r, lcr::Side::kOutput, lcr::Deviations<double>{}, th, Vec2<double>(0.0, 0.0));
    const double rot = b.Rotation(t) - rho * a.Rotation(-rho * t);
    const double te = rot - lcr::CompliantAtAngle<double>(r, mat, th, t, nullptr).output_rotation;
    lo = std::min(lo, te), hi = std::max(hi, te);
  }
  const json& c = m["compliant"];
  const double range = (hi - lo) * kArcsec;
  EXPECT_GT(range, 1.0);
  EXPECT_NEAR(c["transmission_error_max_arcsec"].get<double>(), hi * kArcsec, 0.02 * range);
  EXPECT_NEAR(c["transmission_error_min_arcsec"].get<double>(), lo * kArcsec, 0.02 * range);
  std::printf("lcr eccentric: zone %.6f um (2 max|eps.n| %.6f); TE %.6f..%.6f arcsec, centre shift %.6f..%.6f\n",
              m["iso1101_profile_deviation_um"].get<double>(), zone * 1e3,
              c["transmission_error_min_arcsec"].get<double>(), c["transmission_error_max_arcsec"].get<double>(),
              lo * kArcsec, hi * kArcsec);
}

// The command line for lcr_analysis: a measured cam runs (exit 0, "measured"), inspection files of
// both cams; a missing file is exit 2.
TEST(MeasuredProfile, LcrCommandLine) {
  const lcr::Reducer<double> r = camopt::testing::LcrII();
  const Synthetic s = CamSample(r.output, r.eccentricity, 800, [&](double, Vec2<double>) { return 0.001; });
  const auto dir = TempDir("lcr-measured-cli");
  WriteFile(dir / "m.csv", Csv(s, "normal_deviation"));
  json study = LcrStudy();
  study["measured_profile"] = {{"part", "output_cam"}, {"file", "m.csv"}, {"kind", "normal_deviation"}};
  study["inspection"] = {{"spacing_mm", 1}, {"tolerance_um", 5}};
  WriteFile(dir / "study.json", study.dump());
  const auto res = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " + (dir / "out").string());
  ASSERT_EQ(res.exit_code, 0) << res.stderr_text;
  const json result = json::parse(ReadFile(dir / "out" / "result.json"));
  ASSERT_TRUE(result.contains("measured"));
  EXPECT_NEAR(result["measured"]["iso1101_profile_deviation_um"].get<double>(), 2.0, 1e-6);
  EXPECT_TRUE(fs::exists(dir / "out" / "inspection" / "input_cam.csv"));
  EXPECT_TRUE(fs::exists(dir / "out" / "inspection" / "output_cam.csv"));
  json b = LcrStudy();
  b["measured_profile"] = {{"part", "input_cam"}, {"file", (dir / "none.csv").string()}, {"kind", "points"}};
  camopt::testing::ExpectStudyRejected(b, "lcr-measured-missing", "/measured_profile/file", "expected a readable CSV file");
}

// ---------------------------------------------------------------------------------------------
// Disc cam: Rzine et al.'s translating roller example (studies/examples/disc_cam_translating.json:
// r_b 40, r_f 10, offset e 12 mm, cycloidal rise 24 mm over 120°, dwell 50°, return 120°, dwell 70°).

json DiscCamStudy() {
  json j = camopt::testing::Example("disc_cam_translating.json");
  j["analysis"] = {{"angle_steps", 3600}, {"monte_carlo", false}};
  return j;
}

// The pressure angle in closed form: tan φ = (S' − e)/(s0 + S), s0 = sqrt((r_b + r_f)² − e²)
// (Rzine et al. eqs. 3–5), with the cycloidal law S = h (x − sin 2πx / 2π) written out here.
double PressureAngle(double th) {
  const double h = 24, beta = 120 * kPi / 180, e = 12, s0 = std::sqrt(50.0 * 50.0 - e * e);
  const double deg = th * 180 / kPi;
  double S = 0, dS = 0;
  if (deg < 120) {
    const double x = th / beta;
    S = h * (x - std::sin(2 * kPi * x) / (2 * kPi)), dS = h / beta * (1 - std::cos(2 * kPi * x));
  } else if (deg < 170) {
    S = h;
  } else if (deg < 290) {
    const double x = (th - 170 * kPi / 180) / beta;
    S = h - h * (x - std::sin(2 * kPi * x) / (2 * kPi)), dS = -h / beta * (1 - std::cos(2 * kPi * x));
  }
  return std::atan((dS - e) / (s0 + S));
}

json RunDiscCamMeasured(const std::string& tag, const std::string& kind, const std::string& csv) {
  const auto dir = TempDir("disc-cam-measured-" + tag);
  WriteFile(dir / "points.csv", csv);
  json j = DiscCamStudy();
  j["measured_profile"] = {{"part", "profile"}, {"file", "points.csv"}, {"kind", kind}};
  const std::string file = (dir / "study.json").string();
  const studies::disc_cam::Study st = studies::disc_cam::Parse(studies::Node(&j, file, ""));
  return MeasuredJson(studies::disc_cam::Run(st, studies::RunContext{file, true}).measured);
}

Synthetic DiscCamSample(int n, const std::function<double(double)>& dev) {
  json j = DiscCamStudy();
  const studies::disc_cam::Study st = studies::disc_cam::Parse(studies::Node(&j, "s.json", ""));
  Synthetic s;
  for (int i = 0; i < n; ++i) {
    const double th = 2 * kPi * i / n;
    const disc_cam::CamPoint<double> p = disc_cam::EvaluateCam(st.cam, th);
    s.t.push_back(th), s.nominal.push_back(p.contact), s.normal.push_back(p.normal), s.d.push_back(dev(th));
  }
  return s;
}

// A uniform offset δ: ISO 1101 deviation 2δ and the follower's error δ/cos φ (Rzine et al. eq. 17)
// with φ in closed form here, largest and smallest over the 3600 angles; both kinds.
TEST(MeasuredProfile, DiscCamUniformOffsetMovesTheFollowerByDeltaOverCosPhi) {
  const double delta = 0.002;
  const Synthetic s = DiscCamSample(2000, [&](double) { return delta; });
  double lo = INFINITY, hi = -INFINITY;
  for (int i = 0; i < 3600; ++i) {
    const double e = delta / std::cos(PressureAngle(2 * kPi * i / 3600));
    lo = std::min(lo, e), hi = std::max(hi, e);
  }
  for (const std::string kind : {"points", "normal_deviation"}) {
    SCOPED_TRACE(kind);
    const json m = RunDiscCamMeasured("uniform-" + kind, kind, Csv(s, kind));
    EXPECT_NEAR(m["iso1101_profile_deviation_um"].get<double>(), 2 * delta * 1e3, 1e-6);
    EXPECT_NEAR(m["follower"]["displacement_error_max_um"].get<double>(), hi * 1e3, 1e-6);
    EXPECT_NEAR(m["follower"]["displacement_error_min_um"].get<double>(), lo * 1e3, 1e-6);
    std::printf("disc cam uniform %s: zone %.9f um; follower error %.9f..%.9f um, closed form %.9f..%.9f\n",
                kind.c_str(), m["iso1101_profile_deviation_um"].get<double>(),
                m["follower"]["displacement_error_min_um"].get<double>(),
                m["follower"]["displacement_error_max_um"].get<double>(), lo * 1e3, hi * 1e3);
  }
}

// A cos² bump of height h over ±10° of cam angle on the rise (centred at 60°): ISO 1101 deviation
// 2h and the follower's error h/cos φ(60°) at 60°, closed form.
TEST(MeasuredProfile, DiscCamBumpOnTheRise) {
  const double h = 0.003, c = 60 * kPi / 180, w = 20 * kPi / 180;
  auto bump = [&](double th) {
    const double x = std::remainder(th - c, 2 * kPi);
    return std::abs(x) < w / 2 ? h * std::pow(std::cos(kPi * x / w), 2) : 0.0;
  };
  const Synthetic s = DiscCamSample(3600, bump);
  const json m = RunDiscCamMeasured("bump", "normal_deviation", Csv(s, "normal_deviation"));
  EXPECT_NEAR(m["iso1101_profile_deviation_um"].get<double>(), 2 * h * 1e3, 1e-9);
  double hi = -INFINITY, at = 0;
  for (int i = 0; i < 3600; ++i) {
    const double th = 2 * kPi * i / 3600, e = bump(th) / std::cos(PressureAngle(th));
    if (e > hi) hi = e, at = th;
  }
  EXPECT_NEAR(m["follower"]["displacement_error_max_um"].get<double>(), hi * 1e3, 1e-3 * hi * 1e3);
  EXPECT_NEAR(m["follower"]["displacement_error_max_at_cam_angle_deg"].get<double>(), at * 180 / kPi, 0.5);
  EXPECT_NEAR(m["follower"]["displacement_error_min_um"].get<double>(), 0.0, 1e-3 * h * 1e3);
  std::printf("disc cam bump: zone %.9f um; follower error max %.6f um at %.1f deg, closed form %.6f at %.1f\n",
              m["iso1101_profile_deviation_um"].get<double>(), m["follower"]["displacement_error_max_um"].get<double>(),
              m["follower"]["displacement_error_max_at_cam_angle_deg"].get<double>(), hi * 1e3, at * 180 / kPi);
}

// The contact stress of a measured roller cam with a uniform offset δ (disc_cam_dynamics.json at
// 250 rpm): the moved profile is the pitch curve's offset by r_f − δ, of curvature κ/(1 − (r_f − δ)κ)
// (κ the pitch curve's), so the Hertz line-contact stress is sqrt(F E* (1/r_f + that)/(π w)) with
// the nominal contact force F, E* = E/(2(1 − ν²)).
TEST(MeasuredProfile, DiscCamContactStressOfAUniformOffset) {
  const double delta = 0.3;  // large enough to move the stress well beyond the check's tolerance
  json j = camopt::testing::Example("disc_cam_dynamics.json");
  const auto nominal_study = studies::disc_cam::Parse(studies::Node(&j, "s.json", ""));
  Synthetic s;
  for (int i = 0; i < 2400; ++i) {
    const double th = 2 * kPi * i / 2400;
    const disc_cam::CamPoint<double> p = disc_cam::EvaluateCam(nominal_study.cam, th);
    s.t.push_back(th), s.nominal.push_back(p.contact), s.normal.push_back(p.normal), s.d.push_back(delta);
  }
  const auto dir = TempDir("disc-cam-measured-stress");
  WriteFile(dir / "points.csv", Csv(s, "points"));
  j["measured_profile"] = {{"part", "profile"}, {"file", "points.csv"}, {"kind", "points"}};
  const std::string file = (dir / "study.json").string();
  const auto st = studies::disc_cam::Parse(studies::Node(&j, file, ""));
  const auto r = studies::disc_cam::Run(st, studies::RunContext{file, true});
  ASSERT_TRUE(r.loads.has_value());
  const json measured = MeasuredJson(r.measured);
  ASSERT_TRUE(measured.contains("contact")) << measured.dump();
  const double e_star = 206000.0 / (2 * (1 - 0.3 * 0.3)), rf = 10.0, w = 12.0;
  double expected = 0;
  for (int i = 0; i < 3600; ++i) {
    const double k = disc_cam::EvaluateCam(st.cam, 2 * kPi * i / 3600).pitch_curvature;
    const double f = r.loads->contact_force_N[size_t(i)];
    if (f > 0) expected = std::max(expected, std::sqrt(f * e_star * (1 / rf + k / (1 - (rf - delta) * k)) / (kPi * w)));
  }
  const double ours = measured["contact"]["max_contact_stress_MPa"]["measured"].get<double>();
  EXPECT_NEAR(ours, expected, 1e-7 * expected);  // the finite-difference curvature: ~1e-8
  EXPECT_GT(std::abs(ours - measured["contact"]["max_contact_stress_MPa"]["nominal"].get<double>()), 1e-5 * expected);  // 1.5e-4 at 0.3 mm
  std::printf("disc cam uniform stress: %.6f MPa (closed form %.6f, nominal %.6f)\n", ours, expected,
              measured["contact"]["max_contact_stress_MPa"]["nominal"].get<double>());
}

// The command line for disc_cam: a measured cam runs (exit 0, "measured", inspection/profile.csv);
// a NaN in the file is exit 2.
TEST(MeasuredProfile, DiscCamCommandLine) {
  const Synthetic s = DiscCamSample(1000, [&](double) { return 0.001; });
  const auto dir = TempDir("disc-cam-measured-cli");
  WriteFile(dir / "m.csv", Csv(s, "points"));
  json study = DiscCamStudy();
  study["measured_profile"] = {{"part", "profile"}, {"file", "m.csv"}, {"kind", "points"}};
  study["inspection"] = {{"spacing_mm", 1}, {"tolerance_um", 5}};
  WriteFile(dir / "study.json", study.dump());
  const auto res = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " + (dir / "out").string());
  ASSERT_EQ(res.exit_code, 0) << res.stderr_text;
  const json result = json::parse(ReadFile(dir / "out" / "result.json"));
  ASSERT_TRUE(result.contains("measured"));
  EXPECT_NEAR(result["measured"]["iso1101_profile_deviation_um"].get<double>(), 2.0, 1e-6);
  EXPECT_TRUE(fs::exists(dir / "out" / "inspection" / "profile.csv"));
  std::string nan = Csv(s, "points");
  nan += "1,nan\n";
  WriteFile(dir / "nan.csv", nan);
  json b = DiscCamStudy();
  b["measured_profile"] = {{"part", "profile"}, {"file", (dir / "nan.csv").string()}, {"kind", "points"}};
  camopt::testing::ExpectStudyRejected(b, "disc-cam-measured-nan", "/measured_profile/file",
                                       "expected a finite number in column y_mm");
}

// Inspection points of the cams (LCR II's two cams; the disc cam with a translating roller and with
// a translating flat face, whose profile is the envelope of the face lines) against an independent
// projection onto the model's point function: within 0.1 µm, unit normals perpendicular to the
// profile and outward, arcs <= the spacing.
void CheckInspection(const std::string& csv, const std::function<Vec2<double>(double)>& f, double spacing) {
  const int n = 200000;
  std::vector<Vec2<double>> pts;
  for (int i = 0; i < n; ++i) pts.push_back(f(2 * kPi * i / n));
  auto winding = [&](const Vec2<double>& q) {
    double w = 0;
    for (int i = 0; i < n; ++i) {
      const Vec2<double> a = pts[i] - q, b = pts[(i + 1) % n] - q;
      w += std::atan2(Cross(a, b), a.dot(b));
    }
    return int(std::lround(w / (2 * kPi)));
  };
  const CsvRows c = ParseCsv(csv);
  ASSERT_GT(c.rows.size(), 10u);
  double worst = 0, worst_perp = 0, worst_chord = 0, worst_unit = 0;
  for (size_t r = 0; r < c.rows.size(); ++r) {
    const Vec2<double> p(c.rows[r][0], c.rows[r][1]), nn(c.rows[r][2], c.rows[r][3]);
    int best = 0;
    for (int i = 1; i < n; ++i)
      if ((pts[i] - p).squaredNorm() < (pts[best] - p).squaredNorm()) best = i;
    const double h = 2 * kPi / n, g = 0.5 * (std::sqrt(5.0) - 1);
    double a = 2 * kPi * best / n - h, b = a + 2 * h;
    for (int it = 0; it < 100; ++it) {
      const double x = b - g * (b - a), y = a + g * (b - a);
      if ((f(x) - p).norm() < (f(y) - p).norm()) b = y; else a = x;
    }
    const double t = 0.5 * (a + b);
    worst = std::max(worst, (f(t) - p).norm());
    const Vec2<double> tangent = (f(t + 1e-6) - f(t - 1e-6)).normalized();
    worst_perp = std::max(worst_perp, std::abs(nn.dot(tangent)));
    worst_unit = std::max(worst_unit, std::abs(nn.norm() - 1));
    const auto& w = c.rows[(r + 1) % c.rows.size()];
    worst_chord = std::max(worst_chord, (Vec2<double>(w[0], w[1]) - p).norm());
    if (r % 53 == 0) {
      EXPECT_EQ(winding(p + 0.01 * nn), 0) << "outward at row " << r;
      EXPECT_NE(winding(p - 0.01 * nn), 0) << "inward at row " << r;
    }
  }
  EXPECT_LE(worst, 1e-4);
  EXPECT_LE(worst_unit, 1e-9);
  EXPECT_LE(worst_perp, 2e-6);  // the test's own central difference at a motion law's junction
  EXPECT_LE(worst_chord, spacing);
}

TEST(MeasuredProfile, CamInspectionPointsOnTheExactProfile) {
  {
    json j = LcrStudy();
    j["inspection"] = {{"spacing_mm", 0.7}, {"tolerance_um", 10}};
    const auto st = studies::lcr_analysis::Parse(studies::Node(&j, "s.json", ""));
    const auto r = studies::lcr_analysis::Run(st, studies::RunContext{"", true});
    ASSERT_EQ(r.inspection_files.size(), 2u);
    const lcr::Reducer<double> red = camopt::testing::LcrII();
    for (int k = 0; k < 2; ++k) {
      SCOPED_TRACE(r.inspection_files[k].first);
      const lcr::CamSide<double> c = k == 0 ? red.input : red.output;
      CheckInspection(r.inspection_files[k].second,
                      [&](double psi) { return lcr::OffsetPoint(c, red.eccentricity, psi, c.roller_radius); }, 0.7);
    }
  }
  for (const char* example : {"disc_cam_translating.json", "disc_cam_flat_faced.json"}) {
    SCOPED_TRACE(example);
    json j = camopt::testing::Example(example);
    j["inspection"] = {{"spacing_mm", 0.7}, {"tolerance_um", 10}};
    j["analysis"]["monte_carlo"] = false;
    const auto st = studies::disc_cam::Parse(studies::Node(&j, "s.json", ""));
    const auto r = studies::disc_cam::Run(st, studies::RunContext{"", true});
    ASSERT_EQ(r.inspection_files.size(), 1u);
    if (st.contact == studies::disc_cam::Study::Contact::kFlatFaced)
      CheckInspection(r.inspection_files[0].second,
                      [&](double th) { return disc_cam::EvaluateFlatFaced(st.cam.motion, st.cam.base_radius, th).contact; },
                      0.7);
    else
      CheckInspection(r.inspection_files[0].second, [&](double th) { return disc_cam::EvaluateCam(st.cam, th).contact; },
                      0.7);
  }
}

}  // namespace measured_profile_test
}  // namespace camopt
