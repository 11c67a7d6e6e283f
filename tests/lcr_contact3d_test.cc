// The LCR finite-length contact: the contact/crowning input of lcr_analysis (exit 2 for
// what the line model ignores), the slices/half_space cycle numbers on LCR II, and AD derivatives
// of the LCR roller contact's slices peak through the reducer geometry against central differences.
#include <algorithm>
#include <array>
#include <tuple>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/lcr/contact.h"
#include "model/lcr/contact3d.h"
#include "model/lcr/contact3d_cycle.h"
#include "model/lcr/cycle.h"
#include "studies/lcr_analysis_study.h"
#include "studies/lcr_crowning_tuning_study.h"
#include "studies/work_limits.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt {
namespace lcr_contact3d_test {

using camopt::testing::ReadFile;
using camopt::testing::SourcePath;
using nlohmann::json;

json Example(const std::string& name) { return json::parse(ReadFile(SourcePath("studies/examples/" + name))); }

studies::lcr_analysis::Result RunAnalysis(const json& study) {
  const studies::Node root(&study, "lcr.json", "");
  return studies::lcr_analysis::Run(studies::lcr_analysis::Parse(root), {"lcr.json", true});
}

std::string ParseError(const json& study) {
  const studies::Node root(&study, "lcr.json", "");
  try {
    studies::lcr_analysis::Parse(root);
  } catch (const studies::StudyError& e) {
    return e.what();
  }
  return "";
}

TEST(LcrContact3DInput, WhatTheLineModelIgnoresIsABadStudy) {
  json s = Example("lcr_ii_crowned.json");
  s["contact"]["model"] = "line";
  s["contact"].erase("misalignment_mrad");
  EXPECT_EQ(ParseError(s),
            "lcr.json: /contact/model: expected slices or half_space with crowned rollers (the line model "
            "ignores crowning), found a string \"line\"");
  s.erase("contact");
  EXPECT_NE(ParseError(s).find("crowned rollers need"), std::string::npos);
  json t = Example("lcr_ii.json");
  t["contact"] = {{"misalignment_mrad", 1.0}};
  EXPECT_NE(ParseError(t).find("misalignment_mrad (the line model ignores it)"), std::string::npos) << ParseError(t);
  json u = Example("lcr_ii_crowned.json");
  u["reducer"]["input"]["crowning"]["effective_length_mm"] = 10.0;  // = roller length
  EXPECT_NE(ParseError(u).find("/reducer/input/crowning: effective length must exceed the roller length"),
            std::string::npos)
      << ParseError(u);
  u = Example("lcr_ii_crowned.json");
  u["reducer"]["output"]["crowning"]["type"] = "parabolic";
  EXPECT_NE(ParseError(u).find("/reducer/output/crowning/type"), std::string::npos);
  u = Example("lcr_ii.json");
  u["reducer"]["input"]["crowning"] = {{"type", "none"}};
  u["contact"] = {{"model", "line"}};
  EXPECT_EQ(ParseError(u), "");
}

TEST(LcrCrowningTuningStudy, ParseRejectsAnUnboundedDropAndReadsTheExample) {
  json s = Example("lcr_crowning_tuning.json");
  const auto parse = [](const json& j) {
    const studies::Node root(&j, "t.json", "");
    return studies::lcr_crowning_tuning::Parse(root);
  };
  const auto st = parse(s);
  EXPECT_EQ(st.spec.misalignments_rad, (std::vector<double>{0.0, 1e-3}));
  EXPECT_DOUBLE_EQ(st.spec.overload_torque_Nmm, 120000.0);
  s["tuning"]["effective_length_mm"] = 10.0;
  try {
    parse(s);
    ADD_FAILURE() << "accepted Le = roller length";
  } catch (const studies::StudyError& e) {
    EXPECT_NE(std::string(e.what()).find("t.json: /tuning/effective_length_mm: expected an effective length above"),
              std::string::npos)
        << e.what();
  }
}

TEST(LcrCrowningTuningStudy, WorkLimitRefusesAHugeScanUpFront) {
  json s = Example("lcr_crowning_tuning.json");
  EXPECT_NO_THROW(studies::CheckWorkLimits(s, "t.json", 1.0));
  s["tuning"]["slices"] = 200;
  s["tuning"]["curve_points"] = 60;
  try {
    studies::CheckWorkLimits(s, "t.json", 1.0);
    ADD_FAILURE() << "accepted";
  } catch (const studies::StudyError& e) {
    EXPECT_NE(std::string(e.what()).find("t.json: /tuning/curve_points: the study needs about"), std::string::npos)
        << e.what();
  }
}

TEST(LcrContact3DInput, CliExitsTwoWithOneLineForCrowningUnderTheLineModel) {
  const auto dir = testing::TempDir("lcr-contact3d-cli");
  json s = Example("lcr_ii_crowned.json");
  s["contact"] = {{"model", "line"}};
  testing::WriteFile(dir / "s.json", s.dump());
  const auto r = testing::RunCamopt("run " + (dir / "s.json").string() + " --quiet --out " + (dir / "o").string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n'), 1) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("/contact/model: expected slices or half_space with crowned rollers"), std::string::npos)
      << r.stderr_text;
  EXPECT_FALSE(std::filesystem::exists(dir / "o" / "result.json"));
}

TEST(LcrContact3DInput, ExplicitLineModelGivesTheLineStress) {
  json s = Example("lcr_ii.json");
  s["analysis"]["angle_steps"] = 360;
  const auto base = RunAnalysis(s);
  s["contact"] = {{"model", "line"}};
  const auto line = RunAnalysis(s);
  EXPECT_EQ(line.input_cam.max_contact_stress_MPa, base.input_cam.max_contact_stress_MPa);
  EXPECT_EQ(line.output_cam.max_contact_stress_MPa, base.output_cam.max_contact_stress_MPa);
  ASSERT_TRUE(line.contact_output);
  // The force and R' of the contact setting each angle's maximum reproduce that maximum.
  const auto& c = *line.contact_output;
  for (size_t i = 0; i < c.max_stress_MPa.size(); i += 37) {
    const double p = contact::LineContactPeakPressure(c.stress_force_N[i], 8.0, c.stress_radius_mm[i],
                                                      Material{}.composite_modulus_MPa());
    EXPECT_NEAR(p, line.series.output.max_stress_MPa[i], 1e-9 * p);
  }
}

TEST(LcrContact3D, LcrIIStraightVersusCrownedRollers) {
  // LCR II at 80 N·m, slices model (40 slices, w = 0.2 mm): straight rollers peak at the contact's
  // ends (edge loaded, above the line value, growing with the slice count); the example's
  // logarithmic crown (f = 0.01 mm, Le = 10.5 mm) keeps the pressure off the ends at 0.5 mrad,
  // where straight rollers carry a far higher edge peak.
  json s = Example("lcr_ii_crowned.json");
  s["analysis"]["angle_steps"] = 360;
  const auto crowned = RunAnalysis(s);
  json straight = s;
  for (const char* side : {"input", "output"}) straight["reducer"][side].erase("crowning");
  const auto tilted = RunAnalysis(straight);
  straight["contact"]["misalignment_mrad"] = 0.0;
  const auto flat = RunAnalysis(straight);
  straight["contact"] = {{"model", "line"}};
  const auto line = RunAnalysis(straight);
  for (auto [name, cr, ti, fl, li] :
       {std::tuple{"input", &crowned.contact_input, &tilted.contact_input, &flat.contact_input, &line.input_cam},
        std::tuple{"output", &crowned.contact_output, &tilted.contact_output, &flat.contact_output, &line.output_cam}}) {
    ASSERT_TRUE(*cr && *fl && *ti);
    std::printf("%s: line %.1f | straight 0 mrad %.1f (edge %d, w %.3f mm) | straight 0.5 mrad %.1f | crowned "
                "0.5 mrad %.1f (edge %d, interpolation error %.2f)\n",
                name, li->max_contact_stress_MPa, (*fl)->max_contact_stress_MPa, (*fl)->edge_loaded,
                (*fl)->slice_width_mm, (*ti)->max_contact_stress_MPa, (*cr)->max_contact_stress_MPa,
                (*cr)->edge_loaded, (*cr)->interpolation_error_MPa);
    EXPECT_TRUE((*fl)->edge_loaded);
    EXPECT_TRUE((*ti)->edge_loaded);
    EXPECT_GT((*fl)->max_contact_stress_MPa, li->max_contact_stress_MPa);
    EXPECT_GT((*ti)->max_contact_stress_MPa, (*cr)->max_contact_stress_MPa);
    EXPECT_FALSE((*cr)->edge_loaded);
    EXPECT_LT((*cr)->interpolation_error_MPa, 0.01 * (*cr)->max_contact_stress_MPa);
    EXPECT_LT((*ti)->interpolation_error_MPa, 0.01 * (*ti)->max_contact_stress_MPa);
    ASSERT_EQ((*cr)->worst_pressure_MPa.size(), 40u);
    // The series (interpolated, exact at the worst contacts) peaks at the reported maximum within
    // the interpolation error.
    EXPECT_NEAR(*std::max_element((*cr)->max_stress_MPa.begin(), (*cr)->max_stress_MPa.end()),
                (*cr)->max_contact_stress_MPa, (*cr)->interpolation_error_MPa + 1e-9);
  }
}

// The cycle's curvatures (AnalyzeCycle's array kernel) are RollerContacts' bit for bit.
TEST(LcrContact3D, CycleCurvaturesAreRollerContactsBitForBit) {
  for (const lcr::Reducer<double>& r : {testing::LcrI(), testing::LcrII(), testing::LcrIII()})
    for (const lcr::Side side : {lcr::Side::kInput, lcr::Side::kOutput}) {
      std::vector<double> theta;
      for (int i = 0; i < 720; ++i) theta.push_back(2 * kPi * i / 720);
      const std::vector<double> kappa = lcr::CycleCurvatures(r, side, theta);
      const size_t n = size_t(r.side(side).rollers);
      ASSERT_EQ(kappa.size(), theta.size() * n);
      for (size_t i = 0; i < theta.size(); ++i) {
        const auto rc = lcr::RollerContacts(r, side, theta[i]);
        ASSERT_EQ(rc.size(), n);
        for (size_t k = 0; k < n; ++k) ASSERT_EQ(kappa[i * n + k], rc[k].curvature) << i << " " << k;
      }
    }
}

// The half_space cycle on two grids at once: started cold it gives bit for bit what two separate
// AnalyzeCycleContact3D calls give; with the starts (the previous contact's pressure on the same
// grid, the coarser grid's for a grid's first contact) the same contacts and peaks to within the
// solver's tolerance (relative pressure change 1e-8 per iteration; 1e-6 allows for the distance
// to the exact solution that a small last step leaves).
TEST(LcrContact3D, HalfSpaceCycleStartsChangeTheIterationsNotTheAnswer) {
  constexpr double kStartRelTol = 1e-6;
  const lcr::Reducer<double> r = testing::LcrII();
  const lcr::Material m = testing::Steel();
  const double e_star = m.composite_modulus_MPa();
  const auto series = lcr::AnalyzeCycle(r, m, lcr::LoadCase{80e3, 0, 0}, 360, lcr::Stages{true, false, false});
  lcr::RollerCrowning<double> crown;
  crown.type = contact::CrowningType::kLogarithmic;
  crown.coefficient = 0.01, crown.effective_length = 10.5;
  lcr::ContactModelOptions o;
  o.model = lcr::ContactModel::kHalfSpace;
  o.slices = 20;
  o.misalignment_rad = 1e-3;
  const std::vector<std::array<int, 2>> grids = {{24, 64}, {48, 128}};
  for (const lcr::Side side : {lcr::Side::kInput, lcr::Side::kOutput}) {
    const auto cold = lcr::AnalyzeCycleContact3DOnGrids(r, side, series, e_star, crown, o, grids, {});
    lcr::HalfSpaceStarts starts;
    starts.from_coarser_grid = starts.from_previous_contact = true;
    const auto warm = lcr::AnalyzeCycleContact3DOnGrids(r, side, series, e_star, crown, o, grids, starts);
    ASSERT_EQ(cold.size(), 2u);
    ASSERT_EQ(warm.size(), 2u);
    for (int g = 0; g < 2; ++g) {
      lcr::ContactModelOptions one = o;
      one.grid_nx = grids[g][0], one.grid_ny = grids[g][1];
      const auto single = lcr::AnalyzeCycleContact3D(r, side, series, e_star, crown, one);
      EXPECT_EQ(cold[g].max_contact_stress_MPa, single.max_contact_stress_MPa) << g;
      EXPECT_EQ(cold[g].worst_angle, single.worst_angle) << g;
      EXPECT_EQ(cold[g].worst_pressure_MPa, single.worst_pressure_MPa) << g;
      EXPECT_EQ(cold[g].max_stress_MPa, single.max_stress_MPa) << g;
      EXPECT_EQ(cold[g].half_space_iterations, single.half_space_iterations) << g;
      EXPECT_TRUE(warm[g].converged) << g;
      EXPECT_EQ(warm[g].worst_angle, cold[g].worst_angle) << g;
      EXPECT_EQ(warm[g].worst_roller, cold[g].worst_roller) << g;
      EXPECT_EQ(warm[g].edge_loaded, cold[g].edge_loaded) << g;
      EXPECT_NEAR(warm[g].max_contact_stress_MPa, cold[g].max_contact_stress_MPa,
                  kStartRelTol * cold[g].max_contact_stress_MPa) << g;
      ASSERT_EQ(warm[g].worst_pressure_MPa.size(), cold[g].worst_pressure_MPa.size());
      for (size_t i = 0; i < cold[g].worst_pressure_MPa.size(); ++i)
        EXPECT_NEAR(warm[g].worst_pressure_MPa[i], cold[g].worst_pressure_MPa[i],
                    kStartRelTol * cold[g].max_contact_stress_MPa) << g << " " << i;
      std::printf("%s cam, %dx%d: peak %.6f MPa, CG iterations cold %d, with starts %d\n",
                  side == lcr::Side::kInput ? "input" : "output", grids[g][0], grids[g][1],
                  warm[g].max_contact_stress_MPa, cold[g].half_space_iterations, warm[g].half_space_iterations);
    }
  }
}

TEST(LcrContact3D, SlicesPeakGradientThroughTheReducerMatchesCentralDifferences) {
  // x = (e, r_r, f, γ [mrad], T_o-scaled force): the slices peak of output roller 3 of LCR II at
  // input angle 0.3 rad, with R' from the pitch curvature.
  auto fn = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    const auto [r, r_eff] = testing::LcrIIOutputRoller3(x[0], x[1]);
    lcr::RollerCrowning<T> c;
    c.type = contact::CrowningType::kLogarithmic;
    c.coefficient = x[2];
    c.effective_length = T(10.5);
    const auto s = lcr::RollerContactSlices<T>(x[4], r_eff, r.output.contact_length(),
                                               Material{}.composite_modulus_MPa(), c, x[3] * T(1e-3), 24);
    return std::vector<T>{s.peak_pressure, s.approach * T(1000.0)};
  };
  testing::ExpectJacobianMatchesCentralDifferences<5>(fn, {2.0, 6.0, 0.002, 0.5, 800.0}, 1e-5, 1e-6);
}

}  // namespace lcr_contact3d_test
}  // namespace camopt
