// Benchmarks of the optimization layer: the LCR sizing evaluator (values and exact Jacobian), one
// combination solved by each backend in both constraint forms, and the whole ratio −90 study.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "objectives/lcr_sizing.h"
#include "optimizers/solver.h"
#include "studies/lcr_min_size_study.h"
#include "studies/study.h"
#include "tests/reference_designs.h"

namespace optim_bench {

using camopt::objectives::LcrConstraintForm;

// The LCR II sizing duty on the −90 optimum's lobe/roller counts.
camopt::objectives::LcrSizingSpec Spec(LcrConstraintForm form) {
  return camopt::testing::LcrIISizingSpec(form, 25, 26, 35, 36);
}

void BM_LcrSizingValues(benchmark::State& state) {
  const auto p = camopt::objectives::MakeLcrSizingProblem(Spec(LcrConstraintForm::kAggregate));
  std::vector<double> x = {0.66, 32.8, 32.8, 4.1, 34.8}, y(p.evaluator->num_outputs());
  for (auto _ : state) {
    p.evaluator->Eval(x, y);
    benchmark::DoNotOptimize(y.data());
  }
}
BENCHMARK(BM_LcrSizingValues)->Unit(benchmark::kMicrosecond);

void BM_LcrSizingJacobian(benchmark::State& state) {
  const auto p = camopt::objectives::MakeLcrSizingProblem(Spec(LcrConstraintForm::kAggregate));
  std::vector<double> x = {0.66, 32.8, 32.8, 4.1, 34.8}, y(p.evaluator->num_outputs()),
                      j(y.size() * x.size());
  for (auto _ : state) {
    p.evaluator->EvalWithJacobian(x, y, j);
    benchmark::DoNotOptimize(j.data());
  }
}
BENCHMARK(BM_LcrSizingJacobian)->Unit(benchmark::kMicrosecond);

// One combination (25/26 + 35/36), one start. Arg 0: backend index; arg 1: 0 aggregate, 1 samples.
void BM_SolveOneCombination(benchmark::State& state) {
  const char* backends[] = {"ipopt", "slsqp", "mma", "cobyla"};
  const auto form = state.range(1) ? LcrConstraintForm::kSamples : LcrConstraintForm::kAggregate;
  const auto p = camopt::objectives::MakeLcrSizingProblem(Spec(form));
  camopt::optimizers::SolverOptions o;
  o.backend = *camopt::optimizers::BackendFromName(backends[state.range(0)]);
  o.max_seconds = 20;
  camopt::optimizers::SolverResult r;
  for (auto _ : state) r = camopt::optimizers::Solve(p, o);
  state.SetLabel(std::string(camopt::optimizers::ToString(o.backend)) + (state.range(1) ? " samples" : " aggregate") + " " +
                 camopt::optimizers::ToString(r.status));
  state.counters["OD_mm"] = r.objective;
  state.counters["value_evals"] = r.value_evaluations;
  state.counters["gradient_evals"] = r.gradient_evaluations;
}
BENCHMARK(BM_SolveOneCombination)
    ->Args({0, 0})->Args({1, 0})->Args({2, 0})->Args({3, 0})
    ->Args({0, 1})->Args({1, 1})->Args({3, 1})
    ->Unit(benchmark::kMillisecond);

// The whole ratio −90 study of studies/examples/lcr_min_size.json through the C++ entry point
// (parse, 4 combinations × 3 starts, smooth phase, polish, dense checks, limit sensitivity).
// Arg 0: backend index; arg 1: smooth-phase form 0 aggregate, 1 samples; arg 2: polish 1/0.
// Counters: the best outer diameter and the model runs.
void BM_LcrMinSizeStudy(benchmark::State& state) {
  std::ifstream in(std::filesystem::path(CAMOPT_SOURCE_DIR) / "studies" / "examples" / "lcr_min_size.json");
  std::stringstream ss;
  ss << in.rdbuf();
  nlohmann::json study = nlohmann::json::parse(ss.str());
  const char* backends[] = {"ipopt", "slsqp", "mma", "cobyla"};
  study["optimizer"]["backend"] = backends[state.range(0)];
  study["optimizer"]["constraints"] = state.range(1) ? "samples" : "aggregate";
  study["optimizer"]["polish"] = state.range(2) != 0;
  const camopt::studies::Node root(&study, "lcr_min_size.json", "");
  const auto s = camopt::studies::lcr_min_size::Parse(root);
  camopt::studies::RunContext ctx;
  ctx.quiet = true;
  camopt::studies::lcr_min_size::Result r;
  for (auto _ : state) r = camopt::studies::lcr_min_size::Run(s, ctx);
  state.SetLabel(std::string(backends[state.range(0)]) + (state.range(1) ? " samples" : " aggregate") +
                 (state.range(2) ? " +polish" : " smooth only"));
  state.counters["OD_mm"] = r.best >= 0 ? r.candidates[r.best].outcome.check->outer_diameter_mm : 0.0;
  state.counters["value_evals"] = r.value_evaluations;
  state.counters["gradient_evals"] = r.gradient_evaluations;
}
BENCHMARK(BM_LcrMinSizeStudy)
    ->Args({0, 0, 1})->Args({1, 0, 1})->Args({2, 0, 1})->Args({3, 0, 1})
    ->Args({0, 1, 1})->Args({1, 1, 1})
    ->Args({0, 0, 0})->Args({1, 0, 0})->Args({1, 1, 0})
    ->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace optim_bench
