// Tests of RunCycle's reuse of the drive's roller-pitch symmetry (LoadedOptions::
// reuse_symmetric_angles): the state at φ + m·2π/n1 is the state at φ with roller i renamed
// i + m (mod n1). The expected values come from solving every angle (the option off, or Solve
// itself), never from the reuse.
#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include <gtest/gtest.h>

#include "model/cycloid/loaded_tca.h"
#include "tests/reference_designs.h"

namespace camopt::cycloid {
namespace cycloid_symmetry_test {

constexpr double kTorque = 350.0e3;  // N·mm, the reference drive's torque
constexpr int kRollers = 16;
// Two solves of one state from different starts agree within the compatibility tolerance
// (LoadedOptions::tolerance = 1e-3, relative), the half-space solves within solver_tolerance
// (1e-4): loads and deflection within 3e-3 relative (as CycloidLtca.ASolveDependsOnItsInputsOnly),
// the peak pressure (∝ √F) within half of that.
constexpr double kLoadTol = 3e-3, kDeflectionTol = 3e-3, kPressureTol = 2e-3;

LoadedOptions Options(bool reuse) {
  LoadedOptions o;
  o.profile_cells = 12;
  o.axial_cells = 12;
  o.reuse_symmetric_angles = reuse;
  return o;
}

Crowning Log(double f) { return testing::LogCrowning(f); }

std::map<int, const PairLoad*> ByRoller(const MeshLoad& m) {
  std::map<int, const PairLoad*> r;
  for (const PairLoad& p : m.pairs) r[p.roller] = &p;
  return r;
}

double MaxLoad(const MeshLoad& m) {
  double f = 0;
  for (const PairLoad& p : m.pairs) f = std::max(f, p.load_N);
  return f;
}

// The pairs of `b` are those of `a` with roller i renamed i + shift: a pair in one and not in the
// other may only be one barely loaded (its load within the tolerance of the largest).
void ExpectRelabelled(const MeshLoad& a, const MeshLoad& b, int shift) {
  const double fmax = MaxLoad(a);
  const auto pb = ByRoller(b);
  int matched = 0;
  for (const PairLoad& p : a.pairs) {
    const int r = (p.roller + shift) % kRollers;
    const auto it = pb.find(r);
    if (it == pb.end()) {
      EXPECT_LT(p.load_N, kLoadTol * fmax) << "roller " << p.roller << " -> " << r;
      continue;
    }
    ++matched;
    const PairLoad& q = *it->second;
    EXPECT_NEAR(q.load_N, p.load_N, kLoadTol * fmax) << "roller " << p.roller << " -> " << r;
    EXPECT_NEAR(q.max_pressure_MPa, p.max_pressure_MPa, kPressureTol * a.max_pressure_MPa);
    EXPECT_NEAR(q.arm_mm, p.arm_mm, 1e-9 * std::abs(p.arm_mm));
    EXPECT_NEAR(q.backlash_rad, p.backlash_rad, 1e-11);
  }
  EXPECT_GE(matched, int(b.pairs.size()) - 1);
  EXPECT_GE(matched, 2);
  EXPECT_NEAR(b.unloaded_rotation_rad, a.unloaded_rotation_rad, 1e-11);
  EXPECT_NEAR(b.deflection_rad, a.deflection_rad, kDeflectionTol * a.deflection_rad);
  EXPECT_NEAR(b.rotation_rad, a.rotation_rad, kDeflectionTol * a.deflection_rad);
  EXPECT_NEAR(b.max_pressure_MPa, a.max_pressure_MPa, kPressureTol * a.max_pressure_MPa);
}

TEST(CycloidSymmetry, OneRollerPitchOfCrankRenamesRollerIIntoIPlusOne) {
  // Independent of RunCycle: two cold solves one and three roller pitches apart.
  const LoadedTca tca(testing::CycloidNnm(), Log(0.005), Material{}, Options(false));
  const double pitch = 2 * kPi / kRollers, phi = 0.37;
  const MeshLoad a = tca.Solve(kTorque, phi);
  for (int m : {1, 3, -2}) {
    SCOPED_TRACE(m);
    const MeshLoad b = tca.Solve(kTorque, phi + m * pitch);
    ASSERT_TRUE(a.converged && b.converged);
    ExpectRelabelled(a, b, (m + kRollers) % kRollers);
    EXPECT_NEAR(b.rotation_slope, a.rotation_slope, 1e-3 * std::abs(a.rotation_slope) + 1e-9);
  }
  // The other direction would put the loaded pairs elsewhere: the rollers in contact are not
  // those renamed i − 1.
  const MeshLoad b = tca.Solve(kTorque, phi + pitch);
  const auto pb = ByRoller(b);
  int wrong = 0;
  for (const PairLoad& p : a.pairs) wrong += pb.count((p.roller - 1 + kRollers) % kRollers) ? 0 : 1;
  EXPECT_GT(wrong, 0);
}

TEST(CycloidSymmetry, SixtyAnglesReuseFifteenPhasesWithTheAnswersOfSolvingEveryAngle) {
  const std::vector<double> angles = UniformCrankAngles(60, 2 * kPi);
  const Drive d = testing::CycloidNnm();
  const LoadedTca reuse(d, Log(0.005), Material{}, Options(true));
  const LoadedTca every(d, Log(0.005), Material{}, Options(false));
  const CycleResult r = RunCycle(reuse, kTorque, angles);
  const CycleResult e = RunCycle(every, kTorque, angles);
  ASSERT_TRUE(r.converged && e.converged);
  // 6k degrees mod 22.5°: 15 phases, met first at k = 0..14; k is a copy of k mod 15, shifted by
  // the 4 roller pitches of 90° per 15 angles.
  int solved = 0;
  for (size_t k = 0; k < angles.size(); ++k) {
    SCOPED_TRACE(k);
    const MeshLoad& m = r.meshes[k];
    EXPECT_EQ(m.crank_angle_rad, angles[k]);
    EXPECT_EQ(e.meshes[k].symmetric_source, -1);
    if (k < 15) {
      EXPECT_EQ(m.symmetric_source, -1);
      EXPECT_GT(m.contact_solves, 0);
      ++solved;
    } else {
      EXPECT_EQ(m.symmetric_source, int(k % 15));
      EXPECT_EQ(m.roller_shift, int(4 * (k / 15)) % kRollers);
      EXPECT_EQ(m.contact_solves, 0);
    }
    // Against the angle solved on its own: the same rollers loaded, loads, pressures, LTE.
    ExpectRelabelled(e.meshes[k], m, 0);
    // The pairs in roller order, as a solve gives them.
    for (size_t i = 1; i < m.pairs.size(); ++i) EXPECT_LT(m.pairs[i - 1].roller, m.pairs[i].roller);
    EXPECT_NEAR(r.lte_arcsec[k], e.lte_arcsec[k], kDeflectionTol * e.meshes[k].deflection_rad * kArcsecPerRad);
    ASSERT_EQ(r.gear_ratio.size(), e.gear_ratio.size());
    // GR = 1/(1/n2 + s): a slope error ds (crank_slope_tolerance 1e-4 on top of the state's)
    // moves it by GR² ds; the slopes are compared at 1e-3 of their size plus 1e-7.
    const double ds = 1e-3 * std::abs(e.meshes[k].rotation_slope) + 1e-7;
    EXPECT_NEAR(r.gear_ratio[k], e.gear_ratio[k], e.gear_ratio[k] * e.gear_ratio[k] * ds);
  }
  EXPECT_EQ(solved, 15);
  EXPECT_LT(r.contact_solves, e.contact_solves / 3);
  // Cycle values.
  EXPECT_NEAR(r.max_pressure_MPa, e.max_pressure_MPa, kPressureTol * e.max_pressure_MPa);
  EXPECT_NEAR(r.max_pair_load_N, e.max_pair_load_N, kLoadTol * e.max_pair_load_N);
  double dmax = 0;
  for (const MeshLoad& m : e.meshes) dmax = std::max(dmax, m.deflection_rad);
  EXPECT_NEAR(r.lte_peak_to_peak_arcsec, e.lte_peak_to_peak_arcsec, 2 * kDeflectionTol * dmax * kArcsecPerRad);
  EXPECT_EQ(r.max_pairs_in_contact, e.max_pairs_in_contact);
}

TEST(CycloidSymmetry, EndDistanceOfTheCycleIsUnchanged) {
  LoadedOptions o = Options(true);
  o.edge_margin = true;
  const std::vector<double> angles = UniformCrankAngles(24, 2 * kPi);  // 15° steps: 3 phases
  const LoadedTca reuse(testing::CycloidNnm(), Log(0.002), Material{}, o);
  o.reuse_symmetric_angles = false;
  const LoadedTca every(testing::CycloidNnm(), Log(0.002), Material{}, o);
  const CycleResult r = RunCycle(reuse, kTorque, angles), e = RunCycle(every, kTorque, angles);
  int copies = 0;
  for (const MeshLoad& m : r.meshes) copies += m.symmetric_source >= 0;
  EXPECT_EQ(copies, 21);
  // The end located within a cell (B / q) from the pressures: at the solver's tolerance it moves by
  // a small fraction of a cell.
  const double cell = testing::CycloidNnm().face_width_mm / o.axial_cells;
  EXPECT_NEAR(r.end_distance_mm, e.end_distance_mm, 0.02 * cell);
  EXPECT_NEAR(r.edge_margin_mm, e.edge_margin_mm, 1e-3 * std::abs(e.edge_margin_mm) + 1e-6);
}

TEST(CycloidSymmetry, AnglesOnDistinctPhasesOrTheOptionOffSolveEveryAngle) {
  const LoadedTca tca(testing::CycloidNnm(), Log(0.005), Material{}, Options(true));
  const double pitch = 2 * kPi / kRollers;
  // One mesh period: every phase distinct, the same bits as with the option off.
  const std::vector<double> period = UniformCrankAngles(8, pitch);
  const CycleResult a = RunCycle(tca, kTorque, period);
  const CycleResult b = RunCycle(LoadedTca(testing::CycloidNnm(), Log(0.005), Material{}, Options(false)),
                                 kTorque, period);
  for (size_t k = 0; k < period.size(); ++k) {
    EXPECT_EQ(a.meshes[k].symmetric_source, -1);
    EXPECT_EQ(a.meshes[k].rotation_rad, b.meshes[k].rotation_rad);
    EXPECT_EQ(a.meshes[k].max_pressure_MPa, b.meshes[k].max_pressure_MPa);
  }
  EXPECT_EQ(a.contact_solves, b.contact_solves);
  // Off by more than the phase tolerance (1e-9 rad): solved.
  const CycleResult c = RunCycle(tca, kTorque, {0.3, 0.3 + pitch + 1e-7, 0.3 + 2 * pitch + 1e-12});
  EXPECT_EQ(c.meshes[1].symmetric_source, -1);
  EXPECT_EQ(c.meshes[2].symmetric_source, 0);
  EXPECT_EQ(c.meshes[2].roller_shift, 2);
  // Negative and large angles find their phase too.
  const CycleResult n = RunCycle(tca, kTorque, {0.3, 0.3 - 5 * pitch, 0.3 + 40 * pitch});
  EXPECT_EQ(n.meshes[1].symmetric_source, 0);
  EXPECT_EQ(n.meshes[1].roller_shift, kRollers - 5);
  EXPECT_EQ(n.meshes[2].symmetric_source, 0);
  EXPECT_EQ(n.meshes[2].roller_shift, 40 % kRollers);
  // The option off: every angle solved.
  const CycleResult f = RunCycle(LoadedTca(testing::CycloidNnm(), Log(0.005), Material{}, Options(false)),
                                 kTorque, {0.3, 0.3 + pitch, 0.3 + 2 * pitch});
  for (const MeshLoad& m : f.meshes) {
    EXPECT_EQ(m.symmetric_source, -1);
    EXPECT_GT(m.contact_solves, 0);
  }
}

TEST(CycloidSymmetry, CycleDerivativesAtCopiesAreTheirSourcesRelabelled) {
  const std::vector<double> angles = UniformCrankAngles(24, 2 * kPi);
  const std::vector<std::string> params = {"coefficient_mm", "delta_position_mm", "crank_angle_rad"};
  const LoadedTca tca(testing::CycloidNnm(), Log(0.005), Material{}, Options(true));
  const CycleResult r = RunCycle(tca, kTorque, angles);
  const std::vector<CycleDerivative> reused = DifferentiateCycle(tca, r, params, 2.0);
  // The same states with the copies' marks removed: every angle differentiated at its own state.
  CycleResult unmarked = r;
  for (MeshLoad& m : unmarked.meshes) m.symmetric_source = -1;
  const std::vector<CycleDerivative> direct = DifferentiateCycle(tca, unmarked, params, 2.0);
  EXPECT_LT(reused.front().cg_iterations, direct.front().cg_iterations / 4);
  for (size_t j = 0; j < params.size(); ++j) {
    SCOPED_TRACE(params[j]);
    const CycleDerivative &a = reused[j], &b = direct[j];
    auto close = [](double x, double y) { return std::abs(x - y) <= 1e-6 * std::abs(y) + 1e-12; };
    for (size_t k = 0; k < angles.size(); ++k) {
      SCOPED_TRACE(k);
      EXPECT_TRUE(close(a.rotation_rad[k], b.rotation_rad[k])) << a.rotation_rad[k] << " " << b.rotation_rad[k];
      EXPECT_TRUE(close(a.max_pressure_per_angle_MPa[k], b.max_pressure_per_angle_MPa[k]));
      ASSERT_EQ(a.pair_load_N[k].size(), b.pair_load_N[k].size());
      for (size_t i = 0; i < a.pair_load_N[k].size(); ++i) {
        EXPECT_TRUE(close(a.pair_load_N[k][i], b.pair_load_N[k][i])) << a.pair_load_N[k][i] << " " << b.pair_load_N[k][i];
        EXPECT_TRUE(close(a.pair_max_pressure_MPa[k][i], b.pair_max_pressure_MPa[k][i]));
      }
    }
    EXPECT_TRUE(close(a.smooth_peak_MPa, b.smooth_peak_MPa)) << a.smooth_peak_MPa << " " << b.smooth_peak_MPa;
    EXPECT_TRUE(close(a.max_pressure_MPa, b.max_pressure_MPa));
    EXPECT_TRUE(close(a.lte_peak_to_peak_arcsec, b.lte_peak_to_peak_arcsec));
    EXPECT_TRUE(close(a.max_pair_load_N, b.max_pair_load_N));
  }
}

}  // namespace cycloid_symmetry_test
}  // namespace camopt::cycloid
