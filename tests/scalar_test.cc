// IfThenElse of model/common/scalar.h: every comparison on values, mixed double/Jet operands, and
// the derivative of the chosen branch.
#include <gtest/gtest.h>

#include "model/common/scalar.h"

namespace camopt {
namespace scalar_test {

TEST(Scalar, IfThenElseComparesValues) {
  struct Case {
    Compare op;
    bool less, equal, greater;  // the outcome for 1 op 2, 2 op 2, 3 op 2
  };
  for (const Case& c : {Case{Compare::kLess, true, false, false}, Case{Compare::kLessEqual, true, true, false},
                        Case{Compare::kGreater, false, false, true},
                        Case{Compare::kGreaterEqual, false, true, true},
                        Case{Compare::kEqual, false, true, false}, Case{Compare::kNotEqual, true, false, true}}) {
    EXPECT_EQ(IfThenElse(c.op, 1.0, 2.0, 10.0, 20.0), c.less ? 10.0 : 20.0);
    EXPECT_EQ(IfThenElse(c.op, 2.0, 2.0, 10.0, 20.0), c.equal ? 10.0 : 20.0);
    EXPECT_EQ(IfThenElse(c.op, 3.0, 2.0, 10.0, 20.0), c.greater ? 10.0 : 20.0);
  }
}

TEST(Scalar, IfThenElseKeepsTheChosenBranchsDerivative) {
  using J = ceres::Jet<double, 1>;
  const J x(3.0, 0);
  // max(x, 2) at x = 3: the branch x, derivative 1; min(x, 2): the constant, derivative 0.
  const J hi = IfThenElse(Compare::kGreater, x, 2.0, x, J(2.0));
  const J lo = IfThenElse(Compare::kLess, x, J(2.0), x, J(2.0));
  EXPECT_EQ(hi.a, 3.0);
  EXPECT_EQ(hi.v[0], 1.0);
  EXPECT_EQ(lo.a, 2.0);
  EXPECT_EQ(lo.v[0], 0.0);
  // The comparison looks at the value only: a Jet with a large derivative part (1e8) compares as
  // its value 3, on either side of the comparison, and the chosen branch carries that derivative.
  J steep(3.0);
  steep.v[0] = 1e8;
  EXPECT_EQ(IfThenElse(Compare::kEqual, steep, 3.0, 1.0, 0.0), 1.0);
  EXPECT_EQ(IfThenElse(Compare::kLess, steep, 3.0 + 1e-9, 1.0, 0.0), 1.0);
  EXPECT_EQ(IfThenElse(Compare::kGreater, 3.0 + 1e-9, steep, 1.0, 0.0), 1.0);
  // d/dv (2 steep) = 2e8 through the then branch; the else branch's derivative 0 is not mixed in.
  const J chosen = IfThenElse(Compare::kLessEqual, steep, 3.0, 2.0 * steep, J(0.0));
  EXPECT_EQ(chosen.a, 6.0);
  EXPECT_EQ(chosen.v[0], 2e8);
}

}  // namespace scalar_test
}  // namespace camopt
