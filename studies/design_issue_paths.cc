#include "studies/design_issue_paths.h"

#include <sstream>

namespace camopt::studies {

const IssuePaths& DiscCamIssuePaths() {
  static const IssuePaths p{"",
                            {{"offset", "follower/offset_mm"},
                             {"arm_length", "follower/arm_length_mm"},
                             {"motion", "motion"}}};
  return p;
}

const IssuePaths& GloboidalIssuePaths() {
  static const IssuePaths p{"",
                            {{"roller_length", "cam/roller_length_mm"},
                             {"center_distance", "cam/center_distance_mm"},
                             {"roller_angle", "cam/roller_angle_deg"},
                             {"motion", "motion"},
                             {"contact_arm_mm", "contact/contact_arm_mm"}}};
  return p;
}

const IssuePaths& LcrIssuePaths() {
  static const IssuePaths p{"", {}};
  return p;
}

const IssuePaths& CycloidIssuePaths() {
  static const IssuePaths p{"drive",
                            {{"delta_position_mm", "modification/delta_position_um"},
                             {"delta_radius_mm", "modification/delta_radius_um"}}};
  return p;
}

std::string IssuePath(const DesignIssue& issue, const IssuePaths& paths) {
  if (const auto it = paths.fields.find(issue.field); it != paths.fields.end()) return it->second;
  std::string field = issue.field;
  for (char& ch : field)
    if (ch == '.') ch = '/';
  return paths.prefix.empty() ? field : paths.prefix + "/" + field;
}

void FailOn(const DesignIssue& issue, const Node& at, const IssuePaths& paths) {
  const std::string path = IssuePath(issue, paths);
  Node n = at;
  std::istringstream parts(path);
  std::string key;
  while (std::getline(parts, key, '/')) {
    if (key.empty()) continue;
    if (!n.json().is_object() || !n.Has(key)) {
      static const nlohmann::json absent;
      Node(&absent, at.file(), at.path() + "/" + path).FailWith(issue.message);
    }
    n = n[key];
  }
  n.FailWith(issue.message);
}

void FailOnFirst(const std::vector<DesignIssue>& issues, const Node& at, const IssuePaths& paths) {
  if (!issues.empty()) FailOn(issues.front(), at, paths);
}

}  // namespace camopt::studies
