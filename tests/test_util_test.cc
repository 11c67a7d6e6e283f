// The shared Jacobian check (tests/test_util.h) can fail: a wrong entry is caught in every scale
// mode, a right one passes, and Scale::kBlockColumn scales each entry by its block's largest
// difference quotient in that column (a small row next to a large one in another block is judged
// on its own block's scale).
#include <cmath>
#include <vector>

#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include "tests/test_util.h"

namespace camopt::testing {
namespace test_util_test {

// y = (1e3 x0², 1e3 x0 x1 | 1e-3 x1³): two blocks of very different size.
std::vector<double> F(const std::vector<double>& x) {
  return {1e3 * x[0] * x[0], 1e3 * x[0] * x[1], 1e-3 * x[1] * x[1] * x[1]};
}
std::vector<double> Jac(const std::vector<double>& x) {
  return {2e3 * x[0], 0.0, 1e3 * x[1], 1e3 * x[0], 0.0, 3e-3 * x[1] * x[1]};
}

TEST(JacobianCheckHelper, RightPassesAndAWrongEntryFailsInEveryScaleMode) {
  const std::vector<double> x = {0.7, 1.3};
  for (JacobianCheck::Scale mode : {JacobianCheck::Scale::kEntry, JacobianCheck::Scale::kRow,
                                    JacobianCheck::Scale::kColumn, JacobianCheck::Scale::kBlockColumn}) {
    JacobianCheck c;
    c.scale = mode;
    c.row_blocks = {{0, 2}, {2, 1}};
    if (mode == JacobianCheck::Scale::kRow || mode == JacobianCheck::Scale::kColumn)
      c.rows = {0, 1};  // every checked row and column has a non-zero difference quotient
    EXPECT_GT(ExpectGivenJacobianMatchesCentralDifferences(F, x, F(x), Jac(x), c), 0);
    std::vector<double> wrong = Jac(x);
    wrong[2] *= 1.01;  // ∂y1/∂x0 off by 1 %
    EXPECT_NONFATAL_FAILURE(ExpectGivenJacobianMatchesCentralDifferences(F, x, F(x), wrong, c), "AD");
  }
}

TEST(JacobianCheckHelper, BlockColumnScaleJudgesASmallBlockOnItsOwnScale) {
  const std::vector<double> x = {0.7, 1.3};
  JacobianCheck c;
  c.scale = JacobianCheck::Scale::kBlockColumn;
  c.row_blocks = {{0, 2}, {2, 1}};
  c.rel_tol = 1e-6;
  c.abs_tol = 0.0;
  // ∂y2/∂x1 = 5.07e-3 off by 1e-6 of itself passes; off by 1e-3 of the large block's scale
  // (which a row or column scale would allow) fails here.
  std::vector<double> jac = Jac(x);
  jac[5] += 1e-7 * jac[5];
  EXPECT_EQ(ExpectGivenJacobianMatchesCentralDifferences(F, x, F(x), jac, c), 6);
  jac = Jac(x);
  jac[5] += 1e-3;
  EXPECT_NONFATAL_FAILURE(ExpectGivenJacobianMatchesCentralDifferences(F, x, F(x), jac, c), "AD");
}

}  // namespace test_util_test
}  // namespace camopt::testing
