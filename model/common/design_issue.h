// One design check result for every model family (disc cam, globoidal cam, lobe-cam reducer,
// cycloid drive): a design the model cannot build or run, named by the model parameter it is
// attributed to, with the numbers and what would fit. A study maps `field` to the JSON path of its
// input in one place (studies/design_issue_paths.h) and refuses the study (exit 2).
#pragma once

#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace camopt {

struct DesignIssue {
  DesignIssue() = default;
  DesignIssue(std::string field_, std::string message_, double value_ = std::numeric_limits<double>::quiet_NaN(),
              double limit_ = std::numeric_limits<double>::quiet_NaN(),
              std::optional<double> cam_angle_rad_ = std::nullopt)
      : field(std::move(field_)), message(std::move(message_)), value(value_), limit(limit_),
        cam_angle_rad(cam_angle_rad_) {}

  /// The parameter the issue is attributed to, relative to the model's parameters: a name, or
  /// names joined by '.' for nested ones ("offset", "input.rollers", "motion").
  std::string field;
  /// What is wrong, with the numbers (in the study's units: mm and deg), and what would fit.
  std::string message;
  /// The value found and the limit it breaks, in the model's units (mm, rad); NaN where the issue
  /// has no single number.
  double value = std::numeric_limits<double>::quiet_NaN();
  double limit = std::numeric_limits<double>::quiet_NaN();
  /// Where over the cycle it is first met (cycle checks) [rad].
  std::optional<double> cam_angle_rad;
};

using DesignIssues = std::vector<DesignIssue>;

/// A number in a design issue's message: printf's %g with `significant_digits` digits.
inline std::string IssueNumber(double v, int significant_digits = 6) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", significant_digits, v);
  return buf;
}

}  // namespace camopt
