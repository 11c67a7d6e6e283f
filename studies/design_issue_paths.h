// The one place where a model's design issues (camopt::DesignIssue, model/common/design_issue.h)
// become refusals of a study: the issue's field, named relative to the model's parameters, is
// mapped to the JSON path of the input it came from, and the study is refused there with the
// issue's message ("FILE: PATH: MESSAGE", exit 2). Each kind supplies where its model's
// parameters sit (IssuePaths): a prefix, and the fields whose names differ in the study.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "model/common/design_issue.h"
#include "studies/input.h"

namespace camopt::studies {

/// Where a model family's parameters sit in a study, relative to the node given to FailOn.
struct IssuePaths {
  /// The JSON path of the model's parameters ("drive", or "" when they are the node itself).
  std::string prefix;
  /// Model field → JSON path, for the fields whose name or place in the study differs
  /// ("offset" → "follower/offset_mm").
  std::map<std::string, std::string> fields;
};

/// The disc cam's fields (model/disc_cam/check.h) in a disc_cam study.
const IssuePaths& DiscCamIssuePaths();
/// The globoidal cam's fields (model/globoidal/check.h) in a globoidal_cam study.
const IssuePaths& GloboidalIssuePaths();
/// The lobe-cam reducer's fields (model/lcr/reducer.h) under a study's reducer object.
const IssuePaths& LcrIssuePaths();
/// The cycloid drive's fields (model/cycloid/tooth_profile.h) in a cycloid study ("drive",
/// "modification" in µm).
const IssuePaths& CycloidIssuePaths();

/// The JSON path of an issue's field, relative to the node given to FailOn: its entry in
/// paths.fields, else prefix/field with '.' read as '/' ("input.rollers" → "input/rollers").
std::string IssuePath(const DesignIssue& issue, const IssuePaths& paths);

/// Refuses the study at the issue's JSON path under `at` with the issue's message (StudyError,
/// exit 2). A field the file leaves out (a default) is named at its path all the same.
[[noreturn]] void FailOn(const DesignIssue& issue, const Node& at, const IssuePaths& paths);

/// FailOn the first issue; nothing when there is none.
void FailOnFirst(const std::vector<DesignIssue>& issues, const Node& at, const IssuePaths& paths);

}  // namespace camopt::studies
