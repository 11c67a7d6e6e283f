// Shared test helpers: AD-versus-central-difference gradient checks and running the CLI.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <ceres/jet.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

namespace camopt::testing {

// ---- AD Jacobians against central differences: the one numerical-gradient helper ----------------
//
// The tests of exact Jacobians (ceres::Jet, or an objectives::Evaluator's EvalWithJacobian)
// compare them here with central differences (f(x + h e_i) − f(x − h e_i)) / (2h). The default
// step h = ∛ε·max(1, |x_i|) balances truncation (~h²|f‴|) and rounding (~ε|f|/h) errors at about
// ε^(2/3) ≈ 4e-11 relative on a smooth function of order-one scale (Nocedal & Wright, Numerical
// Optimization, 2nd ed., §8.1). The default tolerances leave a margin of over 10^4 for curvature;
// models with iterative solves or kinks pass their own named tolerances.

/// Default relative tolerance of an AD-versus-central-difference entry.
inline constexpr double kJacobianRelTol = 1e-6;
/// Default absolute tolerance of an AD-versus-central-difference entry.
inline constexpr double kJacobianAbsTol = 1e-8;

/// The central-difference step of a variable at value x: h = ∛ε · max(1, |x|).
inline double CentralDifferenceStep(double x) {
  return std::cbrt(std::numeric_limits<double>::epsilon()) * std::max(1.0, std::abs(x));
}

/// How an AD Jacobian entry ad = ∂y_k/∂x_i is compared with its central difference fd. It passes when
///   |ad − fd| <= abs_tol · (abs_tol_scales_with_value ? max(1, |y_k|) : 1) + rel_tol · scale,
/// where scale is max(|ad|, |fd|) (Scale::kEntry), the largest |fd| of the checked entries of row k
/// (Scale::kRow) or of column i (Scale::kColumn), a row or column scale that must be positive, or
/// the largest |fd| of column i over the rows of k's block (Scale::kBlockColumn, blocks in
/// row_blocks: an optimization problem's output blocks, whose rows share a scale).
struct JacobianCheck {
  enum class Scale { kEntry, kRow, kColumn, kBlockColumn };
  double rel_tol = kJacobianRelTol;
  double abs_tol = kJacobianAbsTol;
  Scale scale = Scale::kEntry;
  bool abs_tol_scales_with_value = false;
  std::vector<double> steps;                ///< a step per variable; empty: CentralDifferenceStep(x_i)
  std::vector<int> rows;                    ///< the outputs checked; empty: all
  std::vector<int> variables;               ///< the variables checked (and differenced); empty: all
  std::vector<std::string> output_names;    ///< for messages; empty: "output k"
  std::vector<std::string> variable_names;  ///< for messages; empty: "xi"
  std::vector<std::pair<int, int>> row_blocks;  ///< Scale::kBlockColumn: (first row, rows) per block
};

/// Checks a given Jacobian jac (row-major, jac[k n + i] = ∂y_k/∂x_i, n = x.size(), with the
/// values y = f(x)) against central differences of f: std::vector<double> -> std::vector<double>.
/// Returns the number of entries checked.
template <typename F>
int ExpectGivenJacobianMatchesCentralDifferences(const F& f, const std::vector<double>& x,
                                                 const std::vector<double>& y, const std::vector<double>& jac,
                                                 const JacobianCheck& check = {}) {
  const size_t n = x.size(), m = y.size();
  const bool steps_ok = check.steps.empty() || check.steps.size() == n;
  EXPECT_EQ(jac.size(), m * n) << "the Jacobian is m x n, row-major";
  EXPECT_TRUE(steps_ok) << "a step per variable";
  if (jac.size() != m * n || !steps_ok) return 0;
  auto all = [](size_t count) {
    std::vector<int> v(count);
    for (size_t i = 0; i < count; ++i) v[i] = int(i);
    return v;
  };
  const std::vector<int> rows = check.rows.empty() ? all(m) : check.rows;
  const std::vector<int> vars = check.variables.empty() ? all(n) : check.variables;
  auto output_name = [&](int k) {
    return check.output_names.empty() ? "output " + std::to_string(k) : check.output_names[size_t(k)];
  };
  auto variable_name = [&](int i) {
    return check.variable_names.empty() ? "x" + std::to_string(i) : check.variable_names[size_t(i)];
  };
  std::vector<double> fd(jac.size(), 0.0);
  for (int i : vars) {
    const double h = check.steps.empty() ? CentralDifferenceStep(x[size_t(i)]) : check.steps[size_t(i)];
    std::vector<double> xp = x, xm = x;
    xp[size_t(i)] += h;
    xm[size_t(i)] -= h;
    const std::vector<double> yp = f(xp), ym = f(xm);
    EXPECT_EQ(yp.size(), m);
    EXPECT_EQ(ym.size(), m);
    if (yp.size() != m || ym.size() != m) return 0;
    for (int k : rows) fd[size_t(k) * n + size_t(i)] = (yp[size_t(k)] - ym[size_t(k)]) / (2 * h);
  }
  std::vector<double> row_scale(m, 0.0), column_scale(n, 0.0);
  for (int k : rows)
    for (int i : vars) {
      const double a = std::abs(fd[size_t(k) * n + size_t(i)]);
      row_scale[size_t(k)] = std::max(row_scale[size_t(k)], a);
      column_scale[size_t(i)] = std::max(column_scale[size_t(i)], a);
    }
  if (check.scale == JacobianCheck::Scale::kRow) {
    for (int k : rows) EXPECT_GT(row_scale[size_t(k)], 0.0) << output_name(k) << " has no central difference";
  }
  if (check.scale == JacobianCheck::Scale::kColumn) {
    for (int i : vars) EXPECT_GT(column_scale[size_t(i)], 0.0) << variable_name(i) << " has no central difference";
  }
  // Scale::kBlockColumn: the block of each row, and per block and column the largest |fd|.
  std::vector<int> block_of(m, -1);
  for (size_t b = 0; b < check.row_blocks.size(); ++b)
    for (int k = check.row_blocks[b].first; k < check.row_blocks[b].first + check.row_blocks[b].second; ++k)
      if (k >= 0 && size_t(k) < m) block_of[size_t(k)] = int(b);
  std::vector<double> block_scale(check.row_blocks.size() * n, 0.0);
  for (int k : rows)
    if (block_of[size_t(k)] >= 0)
      for (int i : vars) {
        double& b = block_scale[size_t(block_of[size_t(k)]) * n + size_t(i)];
        b = std::max(b, std::abs(fd[size_t(k) * n + size_t(i)]));
      }
  if (check.scale == JacobianCheck::Scale::kBlockColumn) {
    for (int k : rows) EXPECT_GE(block_of[size_t(k)], 0) << output_name(k) << " is in no block";
  }
  int checked = 0;
  for (int k : rows)
    for (int i : vars) {
      const double ad = jac[size_t(k) * n + size_t(i)], d = fd[size_t(k) * n + size_t(i)];
      EXPECT_TRUE(std::isfinite(ad)) << output_name(k) << " d/d" << variable_name(i);
      const double scale =
          check.scale == JacobianCheck::Scale::kRow      ? row_scale[size_t(k)]
          : check.scale == JacobianCheck::Scale::kColumn ? column_scale[size_t(i)]
          : check.scale == JacobianCheck::Scale::kBlockColumn
              ? (block_of[size_t(k)] >= 0 ? block_scale[size_t(block_of[size_t(k)]) * n + size_t(i)] : 0.0)
              : std::max(std::abs(ad), std::abs(d));
      const double abs_tol =
          check.abs_tol * (check.abs_tol_scales_with_value ? std::max(1.0, std::abs(y[size_t(k)])) : 1.0);
      EXPECT_LE(std::abs(ad - d), abs_tol + check.rel_tol * scale)
          << output_name(k) << " d/d" << variable_name(i) << ": AD " << ad << " vs central difference " << d;
      ++checked;
    }
  return checked;
}

/// Checks the Jacobian of f by ceres::Jet against central differences (JacobianCheck with
/// Scale::kEntry: |ad − fd| <= abs_tol + rel_tol · max(|ad|, |fd|)), and the Jet's values against
/// f's double values. f is a generic callable: std::array<T, N> -> std::vector<T>.
template <int N, typename F>
void ExpectJacobianMatchesCentralDifferences(const F& f, const std::array<double, N>& x,
                                             double rel_tol = kJacobianRelTol, double abs_tol = kJacobianAbsTol) {
  using J = ceres::Jet<double, N>;
  std::array<J, N> xj;
  for (int i = 0; i < N; ++i) xj[i] = J(x[i], i);
  const std::vector<J> yj = f(xj);
  const std::vector<double> y0 = f(x);
  ASSERT_EQ(yj.size(), y0.size());
  std::vector<double> y(y0.size()), jac(y0.size() * N);
  for (size_t k = 0; k < y0.size(); ++k) {
    EXPECT_NEAR(yj[k].a, y0[k], 1e-12 * std::max(1.0, std::abs(y0[k]))) << "output " << k;
    y[k] = yj[k].a;
    for (int i = 0; i < N; ++i) jac[k * N + i] = yj[k].v[i];
  }
  auto f_of_vector = [&f](const std::vector<double>& z) {
    std::array<double, N> a;
    std::copy(z.begin(), z.end(), a.begin());
    return f(a);
  };
  JacobianCheck check;
  check.rel_tol = rel_tol;
  check.abs_tol = abs_tol;
  ExpectGivenJacobianMatchesCentralDifferences(f_of_vector, std::vector<double>(x.begin(), x.end()), y, jac, check);
}

/// Checks an objectives::Evaluator's Jacobian (EvalWithJacobian) at x against central differences
/// of its Eval, and its values against Eval's; outputs are named by their blocks in messages.
/// Returns the number of entries checked.
template <typename Evaluator>
int ExpectEvaluatorJacobianMatchesCentralDifferences(const Evaluator& ev, const std::vector<double>& x,
                                                     JacobianCheck check = {}) {
  const size_t n = size_t(ev.num_vars()), m = size_t(ev.num_outputs());
  EXPECT_EQ(x.size(), n);
  if (x.size() != n) return 0;
  std::vector<double> y(m), jac(m * n), y0(m);
  ev.EvalWithJacobian(x, y, jac);
  ev.Eval(x, y0);
  for (size_t k = 0; k < m; ++k) EXPECT_NEAR(y[k], y0[k], 1e-12 * std::max(1.0, std::abs(y0[k]))) << "output " << k;
  if (check.output_names.empty()) {
    check.output_names.resize(m);
    for (const auto& b : ev.blocks())
      for (int k = b.offset; k < b.offset + b.size; ++k)
        check.output_names[size_t(k)] = b.name + "[" + std::to_string(k - b.offset) + "]";
  }
  auto eval = [&ev, m](const std::vector<double>& z) {
    std::vector<double> out(m);
    ev.Eval(z, out);
    return out;
  };
  return ExpectGivenJacobianMatchesCentralDifferences(eval, x, y, jac, check);
}

struct CliResult {
  int exit_code;
  std::string stderr_text;
};

/// Runs the built camopt binary with arguments; captures stderr.
inline CliResult RunCamopt(const std::string& args) {
  // Unique per process and call: ctest runs tests in parallel processes.
  static int calls = 0;
  const auto err = std::filesystem::temp_directory_path() /
                   ("camopt-test-stderr-" + std::to_string(::getpid()) + "-" + std::to_string(++calls));
  const std::string cmd = std::string(CAMOPT_BINARY) + " " + args + " 2> " + err.string();
  const int status = std::system(cmd.c_str());
  std::ifstream in(err);
  std::stringstream ss;
  ss << in.rdbuf();
  std::filesystem::remove(err);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, ss.str()};
}

/// The folders TempDir made in this process, removed when it exits unless a test failed (kept to
/// be looked at) or CAMOPT_KEEP_TEST_DIRS is set. Removal is best effort: it never throws.
class TempDirRegistry {
 public:
  static TempDirRegistry& Get() {
    static TempDirRegistry registry;
    return registry;
  }
  void Add(const std::filesystem::path& dir) { dirs_.push_back(dir); }
  ~TempDirRegistry() {
    if (::getpid() != owner_ || std::getenv("CAMOPT_KEEP_TEST_DIRS") != nullptr) return;
    if (::testing::UnitTest::GetInstance()->Failed()) return;
    for (const auto& dir : dirs_) {
      std::error_code ec;
      std::filesystem::permissions(dir, std::filesystem::perms::owner_all,
                                   std::filesystem::perm_options::add, ec);
      std::filesystem::remove_all(dir, ec);
    }
  }

 private:
  TempDirRegistry() = default;
  pid_t owner_ = ::getpid();
  std::vector<std::filesystem::path> dirs_;
};

/// A fresh temporary folder for one test, removed when the test process ends (TempDirRegistry).
inline std::filesystem::path TempDir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("camopt-test-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  TempDirRegistry::Get().Add(dir);
  return dir;
}

inline void WriteFile(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path) << text;
}

inline std::string ReadFile(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// The columns of a CSV with a header line, by name; every other cell read as a number.
inline std::map<std::string, std::vector<double>> ReadCsv(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  {
    std::istringstream h(line);
    std::string n;
    while (std::getline(h, n, ',')) names.push_back(n);
  }
  std::map<std::string, std::vector<double>> cols;
  while (std::getline(in, line)) {
    std::istringstream r(line);
    std::string v;
    for (size_t i = 0; i < names.size() && std::getline(r, v, ','); ++i)
      cols[names[i]].push_back(std::stod(v));
  }
  return cols;
}

inline std::string SourcePath(const std::string& relative) {
  return std::string(CAMOPT_SOURCE_DIR) + "/" + relative;
}

/// Runs a study that must be rejected as bad input: exit code 2, one line on stderr naming the
/// study file and ": PATH: " and containing `words`, and nothing written.
inline void ExpectStudyRejected(const nlohmann::json& study, const std::string& tag,
                                const std::string& path, const std::string& words) {
  const auto dir = TempDir("bad-" + tag);
  const auto file = dir / "study.json";
  WriteFile(file, study.dump());
  const CliResult res = RunCamopt("run " + file.string() + " --quiet --out " + (dir / "out").string());
  EXPECT_EQ(res.exit_code, 2) << res.stderr_text;
  EXPECT_NE(res.stderr_text.find(file.string() + ": "), std::string::npos) << res.stderr_text;
  EXPECT_NE(res.stderr_text.find(": " + path + ": "), std::string::npos) << res.stderr_text;
  EXPECT_NE(res.stderr_text.find(words), std::string::npos) << res.stderr_text;
  EXPECT_EQ(std::count(res.stderr_text.begin(), res.stderr_text.end(), '\n'), 1) << res.stderr_text;
  EXPECT_FALSE(std::filesystem::exists(dir / "out")) << "nothing is written for a bad study";
}

/// A result.json without what every run adds to the kind's ToJson (studies/study.cc):
/// "camopt_version", "study_sha256", and "warnings" when it is empty. Tests that check that the
/// CLI writes what Parse → Run → ToJson gives compare through it; the added fields have their own
/// tests (tests/provenance_test.cc).
inline nlohmann::json WithoutRunStamp(nlohmann::json result) {
  result.erase("camopt_version");
  result.erase("study_sha256");
  result.erase("status");  // the runner's one status of the answer (studies/status.h)
  result.erase("status_reason");
  if (result.contains("warnings") && result["warnings"].is_array() && result["warnings"].empty())
    result.erase("warnings");
  return result;
}

/// |actual − expected| <= rel·|expected|.
inline void ExpectRel(double actual, double expected, double rel) {
  EXPECT_NEAR(actual, expected, rel * std::abs(expected)) << "expected " << expected;
}

/// Runs f and checks it throws std::invalid_argument whose message contains `quantity`.
template <typename F>
void ExpectRejects(const F& f, const std::string& quantity) {
  try {
    f();
    ADD_FAILURE() << "no exception; expected one naming " << quantity;
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(quantity), std::string::npos) << "message: " << e.what();
  }
}

/// A study from studies/examples/, parsed.
inline nlohmann::json Example(const std::string& name) {
  return nlohmann::json::parse(ReadFile(SourcePath("studies/examples/" + name)));
}

/// A lubricated sizing `study` run without its efficiency limit in a housing too small to give off
/// the sized design's loss (0.001 m²): expects exit 3 naming the lubricated losses and the balance's
/// own reason, and returns result.json.
inline nlohmann::json RunSizingWithoutThermalEquilibrium(nlohmann::json study, const std::string& tag) {
  study["limits"].erase("min_efficiency");
  study["lubricant"]["thermal"]["housing_area_m2"] = 0.001;
  const auto dir = TempDir(tag);
  WriteFile(dir / "study.json", study.dump());
  const CliResult r = RunCamopt("run " + (dir / "study.json").string() + " --quiet --out " + (dir / "out").string());
  EXPECT_EQ(r.exit_code, 3) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("lubricated losses"), std::string::npos) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("no equilibrium below the oil's limit"), std::string::npos) << r.stderr_text;
  return nlohmann::json::parse(ReadFile(dir / "out" / "result.json"));
}

}  // namespace camopt::testing
