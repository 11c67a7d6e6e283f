// Crowning tuning of LCR II at 80 N·m : uncrowned versus tuned logarithmic
// crowning at 0 and 1 mrad, off the ends at 120 N·m, each with the half_space check. The numbers
// behind docs/validation.md "Crowned rollers and 3D contact"; printed, asserted with margins.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include "sizing/lcr_crowning_tuning.h"
#include "tests/reference_designs.h"

namespace camopt::sizing {
namespace lcr_crowning_tuning_test {

TEST(LcrCrowningTuning, LcrIIAt80NmUncrownedVersusTuned) {
  LcrCrowningTuningSpec spec;
  spec.reducer = testing::LcrII();
  spec.material = testing::Steel();
  spec.design_load = {80000.0, 0.05, 0.0};
  spec.overload_torque_Nmm = 120000.0;
  spec.misalignments_rad = {0.0, 1e-3};
  spec.effective_length_mm = {10.5, 10.5};
  spec.coefficient_range_mm = {1e-3, 0.05};
  spec.curve_points = 10;
  spec.refine_iterations = 6;
  const auto res = TuneLcrCrowning(spec);
  for (lcr::Side side : {lcr::Side::kInput, lcr::Side::kOutput}) {
    const auto& r = res[side == lcr::Side::kInput ? 0 : 1];
    const char* name = side == lcr::Side::kInput ? "input" : "output";
    std::printf("%s cam: tuned f = %.5f mm (Le 10.5 mm), %d evaluations; curve:", name, r.coefficient_mm, r.evaluations);
    for (size_t i = 0; i < r.curve_coefficient_mm.size(); ++i)
      std::printf(" %.4f:%.0f%s", r.curve_coefficient_mm[i], r.curve_worst_design_MPa[i],
                  r.curve_edge_free_at_overload[i] ? "" : "(edge)");
    std::printf("\n");
    ASSERT_TRUE(r.feasible);
    std::vector<lcr::Contact3DCycleSide> hs_tuned, hs_flat;
    lcr::RollerCrowning<double> crown;
    crown.type = contact::CrowningType::kLogarithmic;
    crown.coefficient = r.coefficient_mm;
    crown.effective_length = 10.5;
    const auto check_tuned = CheckLcrCrowning(spec, side, crown, lcr::ContactModel::kHalfSpace, &hs_tuned);
    const auto check_flat = CheckLcrCrowning(spec, side, {}, lcr::ContactModel::kHalfSpace, &hs_flat);
    for (size_t g = 0; g < spec.misalignments_rad.size(); ++g) {
      const auto& ht = hs_tuned[2 * g];
      const auto& hf = hs_flat[2 * g];
      std::printf("  %.0f mrad: uncrowned %.1f MPa (edge %d; half_space %.1f, dy %.4f mm) | tuned %.1f MPa (edge %d, "
                  "overload %.1f edge %d; half_space %.1f, %+.2f%%)\n",
                  spec.misalignments_rad[g] * 1e3, r.uncrowned.design_MPa[g], r.uncrowned.design_edge[g],
                  check_flat.design_MPa[g], hf.cell_dy_mm, r.tuned.design_MPa[g], r.tuned.design_edge[g],
                  r.tuned.overload_MPa[g], r.tuned.overload_edge[g], check_tuned.design_MPa[g],
                  100 * (ht.slices_peak_at_worst_MPa / check_tuned.design_MPa[g] - 1));
      EXPECT_TRUE(r.uncrowned.design_edge[g]);
      EXPECT_FALSE(r.tuned.design_edge[g]);
      EXPECT_FALSE(r.tuned.overload_edge[g]);
      // The slices model at the half_space's worst contact within 3% of it (a crowned, converged case).
      EXPECT_LT(std::abs(ht.slices_peak_at_worst_MPa / check_tuned.design_MPa[g] - 1), 0.03);
      EXPECT_FALSE(check_tuned.design_edge[g]);
    }
    // At 1 mrad the straight roller's end peak exceeds the tuned crown's peak (both models).
    EXPECT_GT(r.uncrowned.design_MPa[1], r.tuned.design_MPa[1]);
    EXPECT_GT(check_flat.design_MPa[1], check_tuned.design_MPa[1]);
  }
}

}  // namespace lcr_crowning_tuning_test
}  // namespace camopt::sizing
