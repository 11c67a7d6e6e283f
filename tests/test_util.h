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
#include <sstream>
#include <string>
#include <vector>

#include <ceres/jet.h>
#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

namespace camopt::testing {

/// Checks the Jacobian of f by ceres::Jet against central differences with the step
/// h = cbrt(eps) * max(1, |x|). f is a generic callable: std::array<T, N> -> std::vector<T>.
/// An entry passes when |ad - fd| <= abs_tol + rel_tol * max(|ad|, |fd|).
template <int N, typename F>
void ExpectJacobianMatchesCentralDifferences(const F& f, const std::array<double, N>& x,
                                             double rel_tol = 1e-6, double abs_tol = 1e-8) {
  using J = ceres::Jet<double, N>;
  std::array<J, N> xj;
  for (int i = 0; i < N; ++i) xj[i] = J(x[i], i);
  const std::vector<J> yj = f(xj);
  const std::vector<double> y0 = f(x);
  ASSERT_EQ(yj.size(), y0.size());
  for (size_t k = 0; k < y0.size(); ++k) {
    EXPECT_NEAR(yj[k].a, y0[k], 1e-12 * std::max(1.0, std::abs(y0[k]))) << "output " << k;
  }
  const double cbrt_eps = std::cbrt(std::numeric_limits<double>::epsilon());
  for (int i = 0; i < N; ++i) {
    const double h = cbrt_eps * std::max(1.0, std::abs(x[i]));
    auto xp = x, xm = x;
    xp[i] += h;
    xm[i] -= h;
    const std::vector<double> yp = f(xp), ym = f(xm);
    for (size_t k = 0; k < y0.size(); ++k) {
      const double fd = (yp[k] - ym[k]) / (2 * h);
      const double ad = yj[k].v[i];
      ASSERT_TRUE(std::isfinite(ad)) << "output " << k << " variable " << i;
      EXPECT_LE(std::abs(ad - fd), abs_tol + rel_tol * std::max(std::abs(ad), std::abs(fd)))
          << "output " << k << " d/dx" << i << ": AD " << ad << " vs central difference " << fd;
    }
  }
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

/// A fresh temporary folder for one test.
inline std::filesystem::path TempDir(const std::string& name) {
  auto dir = std::filesystem::temp_directory_path() /
             ("camopt-test-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
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

/// A result.json without what every run adds to the kind's ToJson (studies/study.cc, issue 17):
/// "camopt_version", "study_sha256", and "warnings" when it is empty. Tests that check that the
/// CLI writes what Parse → Run → ToJson gives compare through it; the added fields have their own
/// tests (tests/provenance_test.cc).
inline nlohmann::json WithoutRunStamp(nlohmann::json result) {
  result.erase("camopt_version");
  result.erase("study_sha256");
  if (result.contains("warnings") && result["warnings"].is_array() && result["warnings"].empty())
    result.erase("warnings");
  return result;
}

/// A study from studies/examples/, parsed.
inline nlohmann::json Example(const std::string& name) {
  return nlohmann::json::parse(ReadFile(SourcePath("studies/examples/" + name)));
}

}  // namespace camopt::testing
