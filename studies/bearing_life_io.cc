#include "studies/bearing_life_io.h"

#include <algorithm>
#include <cmath>

#include "studies/format.h"

namespace camopt::studies {

std::optional<std::vector<OperatingLine>> ParseDutyCycle(const Node& root, double output_torque_Nmm,
                                                         std::string* why) {
  const bool speed = root.Has("load") && root["load"].Has("input_speed_rpm");
  const bool duty = root.Has("duty_cycle");
  if (!speed && !duty) return std::nullopt;
  if (speed && duty)
    root["load"]["input_speed_rpm"].Fail("no input_speed_rpm when a \"duty_cycle\" is given (one or the other)");
  if (why) *why = speed ? "a life is asked: load.input_speed_rpm is given" : "a life is asked: duty_cycle is given";
  std::vector<OperatingLine> lines;
  if (speed) {
    lines.push_back({output_torque_Nmm, root["load"]["input_speed_rpm"].Positive(), 1.0});
    return lines;
  }
  const Node dc = root["duty_cycle"];
  const std::vector<Node> items = dc.Elements();
  if (items.empty()) dc.Fail("a non-empty array of duty-cycle lines");
  double share_sum = 0.0, speed_max = 0.0;
  for (const Node& item : items) {
    item.CheckKnownFields({"output_torque_Nm", "input_speed_rpm", "time_share"});
    OperatingLine line;
    line.output_torque_Nmm = item["output_torque_Nm"].NonNegative() * 1000.0;
    line.input_speed_rpm = item["input_speed_rpm"].NonNegative();
    line.time_share = item["time_share"].Positive();
    if (line.time_share > 1.0) item["time_share"].Fail("a share in (0, 1]");
    share_sum += line.time_share;
    speed_max = std::max(speed_max, line.input_speed_rpm);
    lines.push_back(line);
  }
  if (!(std::abs(share_sum - 1.0) <= 1e-6))
    throw StudyError(dc.file() + ": " + dc.path() + ": expected time shares summing to 1 (within 1e-6), found " +
                         Format(share_sum, 10) + "; would fit: each time_share divided by " + Format(share_sum, 10),
                     dc.file(), dc.path(), "time shares summing to 1 (within 1e-6)", Format(share_sum, 10));
  if (!(speed_max > 0)) dc.Fail("at least one line with input_speed_rpm > 0 (no revolutions, no rating life)");
  for (OperatingLine& line : lines) line.time_share /= share_sum;  // exactly 1 for Palmgren–Miner
  return lines;
}

RollingBearingRating ParseBearingRating(const Node& node, bool with_kind, BearingKind kind, const std::string& why) {
  RollingBearingRating b;
  b.kind = kind;
  if (with_kind) {
    node.CheckKnownFields({"dynamic_rating_N", "static_rating_N", "kind"});
    const std::string k = node["kind"].String();
    if (k != "ball" && k != "roller") node["kind"].Fail("one of ball, roller");
    b.kind = k == "ball" ? BearingKind::kBall : BearingKind::kRoller;
  } else {
    node.CheckKnownFields({"dynamic_rating_N", "static_rating_N"});
  }
  return ParseRatingValues(node, b.kind, why);
}

RollingBearingRating ParseRatingValues(const Node& node, BearingKind kind, const std::string& why) {
  RollingBearingRating b;
  b.kind = kind;
  if (!node.Has("dynamic_rating_N")) {
    const std::string path = node.path() + "/dynamic_rating_N";
    const std::string expected = "the bearing's dynamic load rating C [N] > 0 (" + why + ")";
    throw StudyError(node.file() + ": " + path + ": expected " + expected + ", found nothing", node.file(), path,
                     expected, "nothing");
  }
  b.dynamic_N = node["dynamic_rating_N"].Positive();
  b.static_N = node.PositiveOr("static_rating_N", 0.0);
  return b;
}

nlohmann::json DutyCycleJson(const std::vector<OperatingLine>& lines) {
  nlohmann::json out = nlohmann::json::array();
  for (const OperatingLine& l : lines)
    out.push_back({{"output_torque_Nm", l.output_torque_Nmm / 1000.0},
                   {"input_speed_rpm", l.input_speed_rpm},
                   {"time_share", l.time_share}});
  return out;
}

nlohmann::json LifeTableRow(const std::string& element, bool ball, double equivalent_load_N, double max_load_N,
                            double revolutions_per_input_revolution, double dynamic_rating_N,
                            double static_rating_N, double s0, double L10h, double life_h) {
  auto finite = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  nlohmann::json e;
  e["element"] = element;
  e["kind"] = ball ? "ball" : "roller";
  e["equivalent_load_N"] = equivalent_load_N;
  e["max_load_N"] = max_load_N;
  e["revolutions_per_input_revolution"] = revolutions_per_input_revolution;
  e["dynamic_rating_N"] = dynamic_rating_N;
  e["L10h"] = finite(L10h);
  if (static_rating_N > 0) {
    e["static_rating_N"] = static_rating_N;
    e["s0"] = finite(s0);
  }
  e["pass"] = life_h > 0 ? nlohmann::json(L10h >= life_h) : nlohmann::json(nullptr);
  return e;
}

}  // namespace camopt::studies
