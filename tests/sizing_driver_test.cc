// The sizing loop shared by lcr_min_size and cycloid_min_size (sizing/sizing_driver.h).
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "sizing/sizing_driver.h"

namespace camopt::sizing {
namespace sizing_driver_test {

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

// Candidates solved in steps (the LCR 3D polish rounds): each step's optimum, the last one the
// candidate's size (a step adds constraints: the optima do not fall); the size after its
// verification (empty: the verification fails).
struct Stepped {
  std::vector<std::vector<double>> steps;
  std::vector<bool> fits;                        // feasible on the fast model when solved to the end
  std::vector<std::optional<double>> verified_size;
  std::vector<size_t> done;
  std::vector<bool> checked;
  std::vector<int> verified, calls;
  SizingCandidates Hooks(bool prune) {
    done.assign(steps.size(), 0);
    checked.assign(steps.size(), false);
    verified.clear();
    calls.clear();
    SizingCandidates c;
    c.count = int(steps.size());
    if (prune)
      c.solve_within = [this](int i, double bound) -> std::optional<double> {
        calls.push_back(i);
        const std::vector<double>& s = steps[size_t(i)];
        for (;;) {  // at least one step per call
          const double value = s[done[size_t(i)]++];
          if (done[size_t(i)] == s.size()) return std::nullopt;
          if (value > bound) return value;
        }
      };
    else
      c.solve = [this](int i) {
        calls.push_back(i);
        done[size_t(i)] = steps[size_t(i)].size();
      };
    c.feasible_size = [this](int i) -> std::optional<double> {
      EXPECT_EQ(done[size_t(i)], steps[size_t(i)].size()) << "the size of a candidate not solved to the end";
      if (!fits[size_t(i)]) return std::nullopt;
      return checked[size_t(i)] ? verified_size[size_t(i)] : steps[size_t(i)].back();
    };
    c.verify = [this](int i) {
      verified.push_back(i);
      checked[size_t(i)] = true;
    };
    return c;
  }
};

// The crowned LCR example's polish rounds (outer diameters [mm], rounded): the best (20/26) is
// solved to the end, the others stop at the first round above its 103.32 mm.
TEST(SizingDriver, BranchAndBoundStopsCandidatesWhoseLowerBoundExceedsTheBest) {
  Stepped f{{{97.18, 104.27, 104.99}, {101.56, 103.03, 103.29, 103.32}, {103.09, 104.52, 104.88, 104.88, 104.88},
             {104.63, 105.66, 105.97}},
            {true, true, true, true},
            {105.0, 103.64, 104.9, 106.0},
            {}, {}, {}, {}};
  std::vector<double> fractions;
  const SizingDriverResult r = RunSizingDriver(f.Hooks(true), [&](double x, const std::string&) { fractions.push_back(x); });
  EXPECT_EQ(r.best, 1);
  EXPECT_EQ(f.verified, (std::vector<int>{1}));
  EXPECT_EQ(f.done, (std::vector<size_t>{2, 4, 2, 1}));  // 9 steps of 15
  ASSERT_EQ(r.pruned.size(), 4u);
  EXPECT_EQ(r.pruned[0], 104.27);
  EXPECT_FALSE(r.pruned[1]);
  EXPECT_EQ(r.pruned[2], 104.52);
  EXPECT_EQ(r.pruned[3], 104.63);
  // Every candidate is started (one step each) before any continues; the smallest bound goes next.
  EXPECT_EQ(f.calls, (std::vector<int>{0, 1, 2, 3, 0, 1, 2, 1}));
  EXPECT_EQ(r.calls, (std::vector<int>{2, 3, 2, 1}));
  EXPECT_DOUBLE_EQ(fractions.front(), 0.0);
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  // The same answer without pruning.
  Stepped g = f;
  const SizingDriverResult all = RunSizingDriver(g.Hooks(false));
  EXPECT_EQ(all.best, r.best);
  EXPECT_EQ(g.verified, f.verified);
}

TEST(SizingDriver, APrunedCandidateIsContinuedWhenTheVerificationRaisesOrFailsTheBest) {
  const std::vector<std::vector<double>> steps = {{97.0, 104.3, 105.0}, {101.0, 103.0, 103.3}, {103.1, 104.5, 104.9},
                                                  {104.6, 105.7, 106.0}};
  // The verification raises the best above the first candidate's lower bound (104.3): that one is
  // continued, ends at 105.0, and the raised best (104.4) stays the answer.
  Stepped raised{steps, {true, true, true, true}, {105.0, 104.4, 104.9, 106.0}, {}, {}, {}, {}};
  SizingDriverResult r = RunSizingDriver(raised.Hooks(true));
  EXPECT_EQ(r.best, 1);
  EXPECT_EQ(raised.done, (std::vector<size_t>{3, 3, 2, 1}));
  EXPECT_FALSE(r.pruned[0]);
  EXPECT_EQ(r.pruned[2], 104.5);
  // The best fails its verification: the pruned candidates are continued in the order of their
  // bounds until one solved to the end is smaller than every bound left (104.9 < 105.7).
  Stepped failed{steps, {true, true, true, true}, {105.0, std::nullopt, 104.9, 106.0}, {}, {}, {}, {}};
  r = RunSizingDriver(failed.Hooks(true));
  EXPECT_EQ(r.best, 2);
  EXPECT_EQ(failed.verified, (std::vector<int>{1, 2}));
  EXPECT_EQ(failed.done, (std::vector<size_t>{3, 3, 3, 2}));
  EXPECT_EQ(r.pruned[3], 105.7);
  Stepped reference{steps, {true, true, true, true}, {105.0, std::nullopt, 104.9, 106.0}, {}, {}, {}, {}};
  EXPECT_EQ(RunSizingDriver(reference.Hooks(false)).best, 2);
  EXPECT_EQ(reference.verified, failed.verified);
}

// Random candidates (whole-number optima, so that ties occur; some infeasible; verifications that
// hold, raise the size or fail): branch and bound verifies the same candidates in the same order
// and gives the same answer as the loop that solves every candidate to the end.
TEST(SizingDriver, BranchAndBoundAgreesWithSolvingEveryCandidate) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> count(1, 7), nsteps(1, 5), value(0, 12), rise(0, 3), kind(0, 5);
  int pruned = 0, continued = 0;
  for (int trial = 0; trial < 500; ++trial) {
    Stepped f;
    const int n = count(rng);
    for (int i = 0; i < n; ++i) {
      std::vector<double> s;
      double v = value(rng);
      for (int k = nsteps(rng); k > 0; --k, v += rise(rng)) s.push_back(v);
      f.steps.push_back(s);
      const int k = kind(rng);
      f.fits.push_back(k != 0);
      f.verified_size.push_back(k == 1 ? std::nullopt : std::optional<double>(s.back() + (k == 2 ? rise(rng) : 0)));
    }
    Stepped g = f;
    const SizingDriverResult a = RunSizingDriver(f.Hooks(true));
    const SizingDriverResult b = RunSizingDriver(g.Hooks(false));
    ASSERT_EQ(a.best, b.best) << "trial " << trial;
    ASSERT_EQ(f.verified, g.verified) << "trial " << trial;
    for (int i = 0; i < n; ++i) {
      pruned += a.pruned[size_t(i)].has_value();
      continued += a.calls[size_t(i)] > 1 && !a.pruned[size_t(i)];
      // A candidate left pruned has its bound above the answer's size.
      if (a.pruned[size_t(i)]) {
        ASSERT_GE(a.best, 0) << "trial " << trial;
        ASSERT_GT(*a.pruned[size_t(i)], *f.verified_size[size_t(a.best)]) << "trial " << trial;
      }
    }
  }
  EXPECT_GT(pruned, 100);     // the trials do prune
  EXPECT_GT(continued, 100);  // and continue pruned candidates
}

TEST(SizingDriver, MissingHooksAreRefused) {
  SizingCandidates c;
  c.count = 1;
  EXPECT_THROW(RunSizingDriver(c), std::invalid_argument);
}

}  // namespace sizing_driver_test
}  // namespace camopt::sizing
