// The solver adapters on shared reference problems with known optima, their statuses on problems
// that cannot converge, and the Ceres least-squares adapter on fits with known answers.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <unistd.h>

#include "model/lcr/cycle.h"
#include "model/lcr/profile.h"
#include "optimizers/cancel.h"
#include "optimizers/ceres_fit.h"
#include "optimizers/mumps_save_size.h"
#include "optimizers/solver.h"
#include "tests/optim_reference_problems.h"

namespace camopt {
namespace optimizers_test {

using optimizers::SolverOptions;
using optimizers::SolverStatus;

class EveryBackend : public ::testing::TestWithParam<std::string> {};

// A converged result at the known optimum: objective within 1e-5 of f*, x within x_tol of x*,
// feasible within the solver's constraint tolerance.
void ExpectKnownOptimum(const optimizers::SolverResult& r, double f_star, const std::vector<double>& x_star,
                        double x_tol, double constraint_tolerance) {
  ASSERT_EQ(r.status, SolverStatus::kConverged) << r.message;
  EXPECT_NEAR(r.objective, f_star, 1e-5);
  ASSERT_EQ(r.x.size(), x_star.size());
  for (size_t i = 0; i < x_star.size(); ++i) EXPECT_NEAR(r.x[i], x_star[i], x_tol) << "x" << i + 1;
  EXPECT_LE(r.max_violation, constraint_tolerance);
}

TEST_P(EveryBackend, Hs71ReachesTheKnownOptimum) {
  SolverOptions opt;
  opt.backend = *optimizers::BackendFromName(GetParam());
  ExpectKnownOptimum(optimizers::Solve(testing::Hs71(), opt), testing::kHs71Optimum,
                     {1.0, 4.7429994, 3.8211503, 1.3794082}, 1e-3, opt.constraint_tolerance);
}

TEST_P(EveryBackend, ScalingIsTranslated) {
  // Same problem with variables in a unit 1000 times smaller: the optimum must scale exactly.
  SolverOptions opt;
  opt.backend = *optimizers::BackendFromName(GetParam());
  const auto r = optimizers::Solve(testing::Hs71(1000.0), opt);
  ASSERT_EQ(r.status, SolverStatus::kConverged) << r.message;
  EXPECT_NEAR(r.objective, testing::kHs71Optimum, 1e-5);
  EXPECT_NEAR(r.x[1], 4742.9994, 1.0);
}

TEST_P(EveryBackend, RosenbrockOnDiskWithInfiniteBounds) {
  SolverOptions opt;
  opt.backend = *optimizers::BackendFromName(GetParam());
  const auto [t, f] = testing::RosenbrockOnDiskOptimum();
  const auto r = optimizers::Solve(testing::RosenbrockOnDisk(), opt);
  ASSERT_EQ(r.status, SolverStatus::kConverged) << r.message;
  EXPECT_NEAR(r.objective, f, 1e-6);
  EXPECT_NEAR(r.x[0], std::cos(t), 1e-4);
  EXPECT_NEAR(r.x[1], std::sin(t), 1e-4);
  ASSERT_EQ(r.active.size(), 1u);
  EXPECT_EQ(r.active[0], "r2");
}

TEST_P(EveryBackend, InfeasibleProblemIsReportedAsSuch) {
  // x >= 2 through a constraint while the bound says x <= 1.
  objectives::Problem p;
  p.variables = {{"x", -1.0, 1.0, 0.0, 1.0}, {"y", -1.0, 1.0, 0.0, 1.0}};
  p.evaluator = objectives::MakeEvaluator<2>(2, {{"f", 0, 1}, {"g", 1, 1}}, [](auto x, auto y) {
    y[0] = x[0] * x[0] + x[1] * x[1];
    y[1] = x[0] + 0.0 * x[1];
  });
  p.objective = "f";
  p.constraints = {{"g", 2.0, kInf, 1.0}};
  SolverOptions opt;
  opt.backend = *optimizers::BackendFromName(GetParam());
  opt.max_evaluations = 500;
  const auto r = optimizers::Solve(p, opt);
  EXPECT_NE(r.status, SolverStatus::kConverged) << r.message;
  if (!r.x.empty()) {
    for (double v : r.x) EXPECT_TRUE(std::isfinite(v));
    EXPECT_GT(r.max_violation, opt.constraint_tolerance);
    ASSERT_FALSE(r.violated.empty());
  }
}

TEST_P(EveryBackend, IterationLimitIsReported) {
  SolverOptions opt;
  opt.backend = *optimizers::BackendFromName(GetParam());
  opt.max_evaluations = 2;
  const auto r = optimizers::Solve(testing::RosenbrockOnDisk(), opt);
  EXPECT_EQ(r.status, SolverStatus::kIterationLimit) << r.message;
}

// A cancellation (optimizers/cancel.h) stops the backend at its next evaluation or iteration and
// is thrown as Cancelled, not reported as a failed solve; cleared, the same solve runs again.
TEST_P(EveryBackend, ACancellationIsThrownNotReportedAsAFailure) {
  SolverOptions opt;
  opt.backend = *optimizers::BackendFromName(GetParam());
  optimizers::RequestCancel();
  EXPECT_THROW(optimizers::Solve(testing::RosenbrockOnDisk(), opt), optimizers::Cancelled);
  optimizers::ClearCancel();
  EXPECT_FALSE(optimizers::CancelRequested());
  // Cleared, the same solve runs to the optimum again.
  const auto [t, f] = testing::RosenbrockOnDiskOptimum();
  const auto r = optimizers::Solve(testing::RosenbrockOnDisk(), opt);
  EXPECT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(r.objective, f, 1e-4);
  EXPECT_NEAR(r.x[0], std::cos(t), 1e-2);
}

TEST_P(EveryBackend, NonFiniteModelGivesNoDesign) {
  objectives::Problem p;
  p.variables = {{"x", 0.0, 1.0, 0.5, 1.0}};
  p.evaluator = objectives::MakeEvaluator<1>(1, {{"f", 0, 1}}, [](auto x, auto y) {
    using std::sqrt;
    y[0] = sqrt(x[0] - 2.0);  // NaN everywhere in the bounds
  });
  p.objective = "f";
  SolverOptions opt;
  opt.backend = *optimizers::BackendFromName(GetParam());
  const auto r = optimizers::Solve(p, opt);
  EXPECT_EQ(r.status, SolverStatus::kFailed);
  EXPECT_TRUE(r.x.empty());
}

TEST_P(EveryBackend, QpReachesTheHandComputedKktPoint) {
  // x* = (1.75, 0.25), f* = 4.625 with x + y <= 2 and y <= 0.25 active (KKT derivation in
  // tests/optim_reference_problems.h).
  SolverOptions opt;
  opt.backend = *optimizers::BackendFromName(GetParam());
  const auto r = optimizers::Solve(testing::QpWithActiveConstraintAndBound(), opt);
  ExpectKnownOptimum(r, testing::kQpOptimum, {testing::kQpOptimumX, testing::kQpOptimumY}, 1e-4,
                     opt.constraint_tolerance);
  for (const char* a : {"sum", "y upper bound"})
    EXPECT_NE(std::find(r.active.begin(), r.active.end(), a), r.active.end()) << a;
}

// The LCR sizing reference problem has no closed-form optimum: every backend reaches the design of
// another backend (Ipopt's; for Ipopt itself SLSQP's, so that no backend is compared with its own
// answer), and it satisfies every limit in the dense check of the pipeline (3600 angles).
TEST_P(EveryBackend, LcrIISizingAgreesAcrossBackends) {
  const auto spec = testing::LcrIISizingSpec();
  SolverOptions opt;
  opt.backend = GetParam() == "ipopt" ? optimizers::Backend::kSlsqp : optimizers::Backend::kIpopt;
  const auto reference = optimizers::Solve(objectives::MakeLcrSizingProblem(spec), opt);
  ASSERT_TRUE(reference.ok()) << reference.message;
  opt.backend = *optimizers::BackendFromName(GetParam());
  const auto r = optimizers::Solve(objectives::MakeLcrSizingProblem(spec), opt);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_NEAR(r.objective, reference.objective, 1e-4 * reference.objective);
  for (size_t i = 0; i < r.x.size(); ++i) EXPECT_NEAR(r.x[i], reference.x[i], 1e-3 * std::abs(reference.x[i]));
  const lcr::Reducer<double> d = objectives::LcrDesign(spec, r.x);
  EXPECT_TRUE(lcr::CheckDesign(d).empty());
  const auto cycle = lcr::AnalyzeCycle(d, spec.material, {spec.output_torque_Nmm, 0.0, 0.0}, 3600, {});
  for (const auto* side : {&cycle.input, &cycle.output}) {
    EXPECT_LE(*std::max_element(side->max_stress_MPa.begin(), side->max_stress_MPa.end()), 1500.0);
    EXPECT_LE(*std::max_element(side->max_force_N.begin(), side->max_force_N.end()), 1050.0);
  }
  EXPECT_GE(lcr::UndercutMargin(d.input, d.eccentricity), 0.5 - 1e-6);
  EXPECT_GE(lcr::UndercutMargin(d.output, d.eccentricity), 0.5 - 1e-6);
  EXPECT_GE(lcr::RollerGap(d.input), 1.0 - 1e-6);
  EXPECT_GE(lcr::RollerGap(d.output), 1.0 - 1e-6);
}

// One constraint row per sample: the same optimum from the backends that handle many rows well
// (MMA's dual subproblem has one variable per row and is left out: see docs/optimization.md).
// Fit statistics against hand-computed values for a 2x2 covariance [[4, 3], [3, 9]]:
// correlation 3 / sqrt(4·9) = 0.5; q = 2 x0 − x1 has variance 4·4 − 2·2·3 + 9 = 13.
TEST(CeresFit, CorrelationAndPropagatedStandardDeviation) {
  optimizers::FitResult fit;
  fit.x = {1.0, 2.0};
  fit.covariance = {4.0, 3.0, 3.0, 9.0};
  EXPECT_DOUBLE_EQ(fit.Correlation(0, 1), 0.5);
  EXPECT_DOUBLE_EQ(fit.Correlation(1, 0), 0.5);
  EXPECT_DOUBLE_EQ(fit.Correlation(0, 0), 1.0);
  EXPECT_NEAR(fit.PropagatedStandardDeviation({2.0, -1.0}), std::sqrt(13.0), 1e-14);
  EXPECT_DOUBLE_EQ(fit.PropagatedStandardDeviation({0.0, 1.0}), 3.0);
}

TEST(Optimizers, LcrIISizingPerSampleConstraints) {
  const auto spec = testing::LcrIISizingSpec(objectives::LcrConstraintForm::kSamples);
  SolverOptions opt;
  opt.backend = optimizers::Backend::kSlsqp;
  const auto slsqp = optimizers::Solve(objectives::MakeLcrSizingProblem(spec), opt);
  opt.backend = optimizers::Backend::kIpopt;
  const auto ipopt = optimizers::Solve(objectives::MakeLcrSizingProblem(spec), opt);
  ASSERT_TRUE(slsqp.ok() && ipopt.ok()) << slsqp.message << " / " << ipopt.message;
  EXPECT_NEAR(slsqp.objective, ipopt.objective, 1e-4 * ipopt.objective);
  // Per-sample rows are exact at the samples, the aggregate is conservative: never larger.
  opt.backend = optimizers::Backend::kSlsqp;
  const auto aggregate = optimizers::Solve(objectives::MakeLcrSizingProblem(testing::LcrIISizingSpec()), opt);
  ASSERT_TRUE(aggregate.ok());
  EXPECT_LE(slsqp.objective, aggregate.objective);
}

INSTANTIATE_TEST_SUITE_P(Optimizers, EveryBackend,
                         ::testing::Values("ipopt", "slsqp", "mma", "cobyla"));

TEST(Optimizers, GradientBackendsUseFarFewerEvaluationsThanCobyla) {
  SolverOptions opt;
  opt.backend = optimizers::Backend::kIpopt;
  const auto ipopt = optimizers::Solve(testing::Hs71(), opt);
  opt.backend = optimizers::Backend::kCobyla;
  const auto cobyla = optimizers::Solve(testing::Hs71(), opt);
  ASSERT_TRUE(ipopt.ok() && cobyla.ok());
  EXPECT_GT(ipopt.gradient_evaluations, 0);
  EXPECT_EQ(cobyla.gradient_evaluations, 0);
  EXPECT_LT(ipopt.value_evaluations + ipopt.gradient_evaluations, cobyla.value_evaluations);
}

// MUMPS 5.3–5.x under Ipopt: its after-every-call size-of-a-save bookkeeping is replaced by the
// program's no-op, bound for libdmumps too (optimizers/mumps_save_size.cc); Ipopt still solves.
TEST(Optimizers, MumpsSaveSizeBookkeepingIsSkippedWhereConfigured) {
#ifdef CAMOPT_EXPECT_MUMPS_SAVE_SIZE_OFF
  EXPECT_TRUE(optimizers::MumpsSaveSizeSkipped());
#else
  EXPECT_FALSE(optimizers::MumpsSaveSizeSkipped());
#endif
  optimizers::SolverOptions opt;
  opt.backend = optimizers::Backend::kIpopt;
  EXPECT_NEAR(optimizers::Solve(testing::Hs71(), opt).objective, testing::kHs71Optimum, 1e-6);
}

// Ipopt reads ./ipopt.opt when it is initialised without a file name, and its options override the
// program's: camopt's answers must not depend on such a file where it runs.
TEST(Optimizers, AnIpoptOptionsFileInTheWorkingFolderIsIgnored) {
  const std::filesystem::path before = std::filesystem::current_path();
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("camopt_ipopt_opt_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "ipopt.opt") << "max_iter 1\ntol 0.5\n";
  std::filesystem::current_path(folder);
  optimizers::SolverOptions opt;
  opt.backend = optimizers::Backend::kIpopt;
  const optimizers::SolverResult r = optimizers::Solve(testing::Hs71(), opt);
  std::filesystem::current_path(before);
  std::filesystem::remove_all(folder);
  EXPECT_EQ(r.status, SolverStatus::kConverged) << r.message;
  EXPECT_GT(r.iterations, 1);
  EXPECT_NEAR(r.objective, testing::kHs71Optimum, 1e-6);
}

// One spelling per backend; the old "nlopt_" spellings still name their backend, flagged deprecated.
TEST(Optimizers, EachBackendHasOneSpellingAndTheOldOnesAreDeprecated) {
  const std::map<std::string, optimizers::Backend> current = {{"ipopt", optimizers::Backend::kIpopt},
                                                              {"slsqp", optimizers::Backend::kSlsqp},
                                                              {"mma", optimizers::Backend::kMma},
                                                              {"cobyla", optimizers::Backend::kCobyla}};
  ASSERT_EQ(optimizers::Backends().size(), current.size());
  for (const auto& [name, backend] : current) {
    bool deprecated = true;
    EXPECT_EQ(optimizers::BackendFromName(name, &deprecated), backend) << name;
    EXPECT_FALSE(deprecated) << name;
    EXPECT_EQ(optimizers::ToString(backend), name);
    if (backend == optimizers::Backend::kIpopt) continue;
    EXPECT_EQ(optimizers::BackendFromName("nlopt_" + name, &deprecated), backend) << name;
    EXPECT_TRUE(deprecated) << name;
  }
  for (const char* unknown : {"simplex", "nlopt_ipopt", "SLSQP", ""})
    EXPECT_FALSE(optimizers::BackendFromName(unknown).has_value()) << unknown;
}

TEST(Optimizers, InvalidProblemIsAnError) {
  auto p = testing::Hs71();
  p.variables[0].lower = 6.0;  // lower > upper
  EXPECT_THROW(optimizers::Solve(p, SolverOptions{}), std::invalid_argument);
  auto q = testing::Hs71();
  q.objective = "nothing";
  EXPECT_THROW(optimizers::Solve(q, SolverOptions{}), std::out_of_range);
}

// y = a exp(b t) + c sampled without noise: the fit recovers a, b, c.
TEST(CeresFit, RecoversKnownCurveParameters) {
  const double a = 2.5, b = -0.7, c = 0.3;
  std::vector<double> t, y;
  for (int i = 0; i < 20; ++i) {
    t.push_back(0.25 * i);
    y.push_back(a * std::exp(b * t.back()) + c);
  }
  optimizers::LeastSquaresProblem p;
  p.variables = {{"a", 0.0, 10.0, 1.0, 1.0}, {"b", -5.0, 0.0, -0.1, 1.0}, {"c", -kInf, kInf, 0.0, 1.0}};
  const int m = static_cast<int>(t.size());
  p.evaluator = objectives::MakeEvaluator<3>(3, {{"r", 0, m}}, [t, y](auto x, auto r) {
    using std::exp;
    for (size_t i = 0; i < t.size(); ++i) r[i] = x[0] * exp(x[1] * t[i]) + x[2] - y[i];
  });
  p.residuals = "r";
  const auto fit = optimizers::SolveLeastSquares(p);
  ASSERT_EQ(fit.status, SolverStatus::kConverged) << fit.message;
  EXPECT_NEAR(fit.x[0], a, 1e-8);
  EXPECT_NEAR(fit.x[1], b, 1e-8);
  EXPECT_NEAR(fit.x[2], c, 1e-8);
  EXPECT_LT(fit.cost, 1e-20);
}

// Weighted straight line: the parameter covariance has the closed form (X^T W X)^-1.
TEST(CeresFit, CovarianceMatchesLinearRegressionClosedForm) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::vector<double> t, y, sd;
  for (int i = 0; i < 12; ++i) {
    t.push_back(i);
    sd.push_back(0.1 + 0.05 * i);
    y.push_back(1.0 + 0.5 * i + sd.back() * noise(rng));
  }
  optimizers::LeastSquaresProblem p;
  p.variables = {{"a", -kInf, kInf, 0.0, 1.0}, {"b", -kInf, kInf, 0.0, 1.0}};
  const int m = static_cast<int>(t.size());
  p.evaluator = objectives::MakeEvaluator<2>(2, {{"r", 0, m}}, [t, y, sd](auto x, auto r) {
    for (size_t i = 0; i < t.size(); ++i) r[i] = (x[0] + x[1] * t[i] - y[i]) / sd[i];
  });
  p.residuals = "r";
  const auto fit = optimizers::SolveLeastSquares(p);
  ASSERT_EQ(fit.status, SolverStatus::kConverged) << fit.message;
  // Normal equations of weighted least squares.
  double s0 = 0, s1 = 0, s2 = 0, sy = 0, sty = 0;
  for (int i = 0; i < m; ++i) {
    const double w = 1 / (sd[i] * sd[i]);
    s0 += w, s1 += w * t[i], s2 += w * t[i] * t[i], sy += w * y[i], sty += w * t[i] * y[i];
  }
  const double det = s0 * s2 - s1 * s1;
  EXPECT_NEAR(fit.x[0], (s2 * sy - s1 * sty) / det, 1e-7);
  EXPECT_NEAR(fit.x[1], (s0 * sty - s1 * sy) / det, 1e-7);
  ASSERT_EQ(fit.covariance.size(), 4u);
  EXPECT_NEAR(fit.covariance[0], s2 / det, 1e-9 * s2 / det);
  EXPECT_NEAR(fit.covariance[1], -s1 / det, 1e-9 * std::abs(s1 / det));
  EXPECT_NEAR(fit.covariance[3], s0 / det, 1e-9 * s0 / det);
}

TEST(CeresFit, RankDeficientFitHasNoCovariance) {
  // Only a + b is determined by the data.
  optimizers::LeastSquaresProblem p;
  p.variables = {{"a", -kInf, kInf, 0.0, 1.0}, {"b", -kInf, kInf, 0.0, 1.0}};
  p.evaluator = objectives::MakeEvaluator<2>(2, {{"r", 0, 3}}, [](auto x, auto r) {
    for (int i = 0; i < 3; ++i) r[i] = x[0] + x[1] - 1.0 - 0.01 * i;
  });
  p.residuals = "r";
  const auto fit = optimizers::SolveLeastSquares(p);
  ASSERT_FALSE(fit.x.empty());
  EXPECT_NEAR(fit.x[0] + fit.x[1], 1.01, 1e-9);
  EXPECT_TRUE(fit.covariance.empty());
}

}  // namespace optimizers_test
}  // namespace camopt
