#include "studies/bearing_life_io.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "model/common/life_modification.h"

#include "studies/format.h"

namespace camopt::studies {

std::optional<std::vector<OperatingLine>> ParseDutyCycle(const Node& root, const std::vector<DutyCycleLine>* given,
                                                         double output_torque_Nmm, std::string* why) {
  const bool speed = root.Has("load") && root["load"].Has("input_speed_rpm");
  const bool duty = given != nullptr;
  if (!speed && !duty) return std::nullopt;
  if (speed && duty)
    root["load"]["input_speed_rpm"].Fail("no input_speed_rpm when a \"duty_cycle\" is given (one or the other)");
  if (why) *why = speed ? "a life is asked: load.input_speed_rpm is given" : "a life is asked: duty_cycle is given";
  std::vector<OperatingLine> lines;
  if (speed) {
    lines.push_back({output_torque_Nmm, root["load"]["input_speed_rpm"].Positive(), 1.0});
    return lines;
  }
  // Each line's fields are checked as read (DutyCycleLineInput): what spans the lines follows.
  const Node dc = root["duty_cycle"];
  double share_sum = 0.0, speed_max = 0.0;
  for (const DutyCycleLine& in : *given) {
    lines.push_back({in.output_torque_Nm * 1000.0, in.input_speed_rpm, in.time_share});
    share_sum += in.time_share;
    speed_max = std::max(speed_max, in.input_speed_rpm);
  }
  if (!(std::abs(share_sum - 1.0) <= 1e-6))
    throw StudyError(dc.file() + ": " + dc.path() + ": expected time shares summing to 1 (within 1e-6), found " +
                         Format(share_sum, 10) + "; would fit: each time_share divided by " + Format(share_sum, 10),
                     dc.file(), dc.path(), "time shares summing to 1 (within 1e-6)", Format(share_sum, 10));
  if (!(speed_max > 0)) dc.Fail("at least one line with input_speed_rpm > 0 (no revolutions, no rating life)");
  for (OperatingLine& line : lines) line.time_share /= share_sum;  // exactly 1 for Palmgren–Miner
  return lines;
}

namespace {

[[noreturn]] void FailMissing(const Node& node, const std::string& key, const std::string& expected) {
  const std::string path = (node.path() == "/" ? std::string() : node.path()) + "/" + key;
  throw StudyError(node.file() + ": " + path + ": expected " + expected + ", found nothing", node.file(), path,
                   expected, "nothing");
}

}  // namespace

void FailMissingRating(const Node& node, const std::string& why) {
  FailMissing(node, "dynamic_rating_N", "the bearing's dynamic load rating C [N] > 0 (" + why + ")");
}

RollingBearingRating ParseRatingValues(const Node& node, BearingKind kind, const std::string& why) {
  RollingBearingRating b;
  b.kind = kind;
  if (!node.Has("dynamic_rating_N")) FailMissingRating(node, why);
  b.dynamic_N = node["dynamic_rating_N"].Positive();
  b.static_N = node.PositiveOr("static_rating_N", 0.0);
  b.modified = ParseModifiedLifeRating(node);
  return b;
}

std::optional<ModifiedLifeRating> ParseModifiedLifeRating(const Node& node) {
  const bool cu = node.Has("fatigue_load_limit_N"), dpw = node.Has("pitch_diameter_mm");
  if (cu && !dpw)
    FailMissing(node, "pitch_diameter_mm",
                "the bearing's pitch diameter D_pw [mm] > 0 beside fatigue_load_limit_N (the modified life a_ISO needs "
                "both: D_pw for the reference viscosity nu1, C_u for e_C C_u/P)");
  if (dpw && !cu)
    FailMissing(node, "fatigue_load_limit_N",
                "the bearing's fatigue load limit C_u [N] > 0 beside pitch_diameter_mm (the modified life a_ISO needs "
                "both: D_pw for the reference viscosity nu1, C_u for e_C C_u/P)");
  if (!cu) return std::nullopt;
  return ModifiedLifeRating{node["fatigue_load_limit_N"].Positive(), node["pitch_diameter_mm"].Positive()};
}

void CheckModifiedLifeInputs(const Node& root, const std::vector<Node>& rated) {
  const bool lubricant = root.Has("lubricant");
  const bool ec = lubricant && root["lubricant"].Has("contamination_factor");
  if (!rated.empty() && !lubricant)
    rated.front()["fatigue_load_limit_N"].FailWith(
        "the modified life a_ISO of this bearing needs the oil: a \"lubricant\" block (its viscosity at the "
        "operating temperature gives kappa = nu/nu1) with \"contamination_factor\" (e_C in [0, 1], ISO 281:2007 "
        "Table 13); give them, or remove fatigue_load_limit_N and pitch_diameter_mm");
  if (!rated.empty() && !ec)
    FailMissing(root["lubricant"], "contamination_factor",
                "the contamination factor e_C in [0, 1] (ISO 281:2007 Table 13; normal cleanliness 0.5-0.6 below "
                "D_pw 100 mm): " + rated.front().path() + " gives fatigue_load_limit_N for the modified life a_ISO");
  if (rated.empty() && ec)
    root["lubricant"]["contamination_factor"].FailWith(
        "contamination_factor is used by the modified life a_ISO of a bearing whose rating block gives "
        "fatigue_load_limit_N and pitch_diameter_mm, and none does: give them, or remove contamination_factor");
}

nlohmann::ordered_json ModifiedLifeSchemaRules(const std::vector<std::vector<std::string>>& rated_blocks) {
  using ojson = nlohmann::ordered_json;
  ojson any = ojson::array();
  for (const std::vector<std::string>& keys : rated_blocks) {
    ojson has = {{"required", {"fatigue_load_limit_N"}}};
    for (auto k = keys.rbegin(); k != keys.rend(); ++k) has = {{"required", {*k}}, {"properties", {{*k, has}}}};
    any.push_back(has);
  }
  const ojson ec = {{"required", {"lubricant"}}, {"properties", {{"lubricant", {{"required", {"contamination_factor"}}}}}}};
  return ojson::array({{{"if", {{"anyOf", any}}}, {"then", ec}}, {{"if", ec}, {"then", {{"anyOf", any}}}}});
}

double AddModifiedLife(LifeTableRow& row, BearingKind kind, const ModifiedLifeRating& rating,
                       const ModifiedLifeOil& oil, double mean_speed_rpm, double equivalent_load_N, double L10h) {
  row.mean_speed_rpm = mean_speed_rpm;
  row.pitch_diameter_mm = rating.pitch_diameter_mm;
  row.fatigue_load_limit_N = rating.fatigue_load_limit_N;
  row.contamination_factor = oil.contamination_factor;
  row.oil_temperature_C = oil.temperature_C;
  row.viscosity_mm2_s = oil.viscosity_mm2_s;
  row.reference_viscosity_mm2_s = row.kappa = row.a_ISO = row.L_nm_h = NAN;  // null until computed
  if (!oil.missing.empty()) {
    row.a_ISO_note = "not computed: no oil temperature (" + oil.missing + ")";
    return NAN;
  }
  if (!(mean_speed_rpm > 0)) {
    row.a_ISO_note = "not computed: the bearing does not turn (no reference viscosity nu1 at n = 0)";
    return NAN;
  }
  const double nu1 = ReferenceViscosity(mean_speed_rpm, rating.pitch_diameter_mm);
  const double kappa = oil.viscosity_mm2_s / nu1;
  row.reference_viscosity_mm2_s = nu1;
  row.kappa = kappa;
  // An unloaded bearing (P = 0) has e_C C_u / P = +inf: a_ISO is its cap.
  const double x = equivalent_load_N > 0 ? oil.contamination_factor * rating.fatigue_load_limit_N / equivalent_load_N
                                         : kInf;
  const LifeModification m = LifeModificationFactor(kind, kappa, x);
  if (!m.note.empty()) row.a_ISO_note = m.note;
  if (!m.computed) return NAN;
  const double l_nm = m.a_iso * L10h;  // a1 = 1 (90 % reliability)
  row.a_ISO = m.a_iso;
  row.L_nm_h = l_nm;
  return l_nm;
}

std::string ModifiedLifeModelText(bool computed) {
  if (!computed) return "the modified life (a1, a_ISO) is not modelled (docs/life.md)";
  return "the modified life L_nm = a1 a_ISO L10 (ISO 281:2007 9.3; a1 = 1, 90 % reliability) of the bearings given "
         "fatigue_load_limit_N and pitch_diameter_mm: a_ISO by eqs. 31-33 (ball) or 34-36 (roller) from kappa = nu/nu1 "
         "(nu the oil's at the lubricated operating point's temperature, nu1 by eq. 28 at the bearing's mean speed, "
         "kappa > 4 taken as 4, none below 0.1) and e_C C_u/P, at most 50 (docs/life.md)";
}

std::vector<DutyCycleEcho> DutyCycleEchoOf(const std::vector<OperatingLine>& lines) {
  std::vector<DutyCycleEcho> out;
  for (const OperatingLine& l : lines) out.push_back({l.output_torque_Nmm / 1000.0, l.input_speed_rpm, l.time_share});
  return out;
}

nlohmann::json DutyCycleJson(const std::vector<OperatingLine>& lines) {
  return nlohmann::json(ResultWriter::Value(DutyCycleEchoOf(lines), Field(), "/duty_cycle"));
}

LifeTableRow BearingLifeRow(const std::string& element, bool ball, double equivalent_load_N, double max_load_N,
                            double revolutions_per_input_revolution, double dynamic_rating_N, double static_rating_N,
                            double s0, double L10h, double life_h) {
  LifeTableRow e;
  e.element = element;
  e.kind = ball ? "ball" : "roller";
  e.equivalent_load_N = equivalent_load_N;
  e.max_load_N = max_load_N;
  e.revolutions_per_input_revolution = revolutions_per_input_revolution;
  e.dynamic_rating_N = dynamic_rating_N;
  e.L10h = L10h;
  if (static_rating_N > 0) {
    e.static_rating_N = static_rating_N;
    e.s0 = s0;
  }
  if (life_h > 0) e.pass = L10h >= life_h;
  return e;
}

}  // namespace camopt::studies
