// The sizing loop shared by lcr_min_size and cycloid_min_size (objectives/sizing_driver.h).
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "objectives/sizing_driver.h"

namespace camopt::objectives {
namespace {

// Candidates with a size each (empty: infeasible) and whether their verification would hold.
struct Fake {
  std::vector<std::optional<double>> size;
  std::vector<bool> holds;
  std::vector<int> solved, verified;
  std::vector<bool> failed;
  SizingCandidates Hooks() {
    failed.assign(size.size(), false);
    SizingCandidates c;
    c.count = int(size.size());
    c.solve = [this](int i) { solved.push_back(i); };
    c.feasible_size = [this](int i) -> std::optional<double> {
      if (failed[size_t(i)]) return std::nullopt;
      return size[size_t(i)];
    };
    c.verify = [this](int i) {
      verified.push_back(i);
      if (!holds[size_t(i)]) failed[size_t(i)] = true;
    };
    return c;
  }
};

TEST(SizingDriver, EveryCandidateIsSolvedOnceInOrderAndTheSmallestThatHoldsIsTheAnswer) {
  Fake f{{40.0, 30.0, std::nullopt, 35.0, 32.0}, {true, false, true, true, false}, {}, {}, {}};
  std::vector<double> fractions;
  const SizingDriverResult r = RunSizingDriver(f.Hooks(), [&](double x, const std::string&) { fractions.push_back(x); });
  EXPECT_EQ(f.solved, (std::vector<int>{0, 1, 2, 3, 4}));
  // 30 fails its verification, then 32 fails, then 35 holds.
  EXPECT_EQ(f.verified, (std::vector<int>{1, 4, 3}));
  EXPECT_EQ(r.verified, f.verified);
  EXPECT_EQ(r.best, 3);
  ASSERT_EQ(fractions.size(), 6u);
  EXPECT_DOUBLE_EQ(fractions.front(), 0.0);
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
}

TEST(SizingDriver, NothingFeasibleOrEveryVerificationFailingGivesNoBest) {
  Fake none{{std::nullopt, std::nullopt}, {true, true}, {}, {}, {}};
  EXPECT_EQ(RunSizingDriver(none.Hooks()).best, -1);
  EXPECT_TRUE(none.verified.empty());
  Fake failing{{10.0, 12.0}, {false, false}, {}, {}, {}};
  const SizingDriverResult r = RunSizingDriver(failing.Hooks());
  EXPECT_EQ(r.best, -1);
  EXPECT_EQ(failing.verified, (std::vector<int>{0, 1}));
}

TEST(SizingDriver, MissingHooksAreRefused) {
  SizingCandidates c;
  c.count = 1;
  EXPECT_THROW(RunSizingDriver(c), std::invalid_argument);
}

}  // namespace
}  // namespace camopt::objectives
