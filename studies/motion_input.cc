#include "studies/motion_input.h"

#include <algorithm>
#include <array>
#include <optional>
#include <cmath>
#include <utility>

#include "studies/format.h"
#include "studies/writers.h"

namespace camopt::studies {
namespace {
constexpr double kDeg = kPi / 180.0;

// The study-file keys of a polynomial segment's boundary values for a follower unit ("mm", "deg"):
// position, then the derivatives per degree of cam angle.
std::array<std::string, 4> BoundaryKeys(const std::string& unit) {
  return {"position_" + unit, "velocity_" + unit + "_per_deg", "acceleration_" + unit + "_per_deg2",
          "jerk_" + unit + "_per_deg3"};
}

// Laws whose shape the segment carries (polynomial boundary values, B-spline control points): only
// where a kind allows them (MotionInputSpec::allow_polynomial).
bool Shaped(const std::string& law) {
  return law == motion::LawName(motion::MotionLaw::kPolynomial) || law == motion::LawName(motion::MotionLaw::kBSpline);
}

// The highest B-spline degree a study may ask for, and the default (lower when fewer points).
constexpr int kMaxSplineDegree = 7, kDefaultSplineDegree = 5;

// A polynomial segment's boundary as given in the file (file units), with its nodes for messages.
struct GivenEnd {
  std::vector<double> values;  // position, velocity, … as given
  std::vector<Node> nodes;
};
}  // namespace

std::vector<CrossFieldRule> MotionRules() {
  return {{{"motion"}, "the segments' cam angles sum to 360°", "segment durations sum to"},
          {{"motion"}, "the rises sum to 0: the follower returns to its start", "does not return"},
          {{"motion"}, "a B-spline segment has more control points than its degree", "needs at least"},
          {{"motion"},
           "a polynomial segment's boundary values continue the program (the position so far, the neighbours' "
           "derivatives)",
           "the motion is not continuous"}};
}

motion::MotionProgram<double> ParseMotionProgram(const Node& motion_node,
                                                 const MotionInputSpec& spec) {
  std::set<std::string> known = {"law", spec.rise_key, "cam_angle_deg"};
  if (!spec.misplaced_key.empty()) known.insert(spec.misplaced_key);
  std::string laws;
  for (const auto& n : motion::LawNames())
    if (spec.allow_polynomial || !Shaped(n)) laws += (laws.empty() ? "" : ", ") + n;
  const std::array<std::string, 4> keys = BoundaryKeys(spec.unit);
  // Model units per file unit of position, velocity, acceleration, jerk (per degree → per rad).
  const double scale[4] = {spec.rise_scale, spec.rise_scale / kDeg, spec.rise_scale / (kDeg * kDeg),
                           spec.rise_scale / (kDeg * kDeg * kDeg)};
  std::vector<motion::MotionSegment<double>> segments;
  std::vector<std::optional<std::pair<GivenEnd, GivenEnd>>> given;  // polynomial segments
  std::vector<std::optional<std::pair<Node, double>>> spline_start;  // B-splines: first point (file unit)
  const std::vector<Node> elements = motion_node.Elements();
  for (const Node& seg : elements) {
    const std::string law_name = seg["law"].String();
    const auto law = motion::LawFromName(law_name);
    if (!law || (Shaped(law_name) && !spec.allow_polynomial)) seg["law"].Fail("a motion law (" + laws + ")");
    const double duration = seg["cam_angle_deg"].Positive() * kDeg;
    spline_start.push_back(std::nullopt);
    if (*law == motion::MotionLaw::kBSpline) {
      const std::string points_key = "control_points_" + spec.unit;
      for (const std::string& k : {spec.rise_key, spec.misplaced_key})
        if (!k.empty() && seg.Has(k))
          seg[k].FailWith("a B-spline segment's rise is its last control point minus its first: remove " + k);
      seg.CheckKnownFields({"law", "cam_angle_deg", points_key, "degree"});
      const Node points = seg[points_key];
      std::vector<double> control;
      for (const Node& point : points.Elements()) control.push_back(point.Number() * scale[0]);
      if (control.size() < 2) points.Fail("an array of at least 2 control points");
      const int most = std::min(kMaxSplineDegree, int(control.size()) - 1);
      int degree = std::min(kDefaultSplineDegree, most);
      if (seg.Has("degree")) {
        degree = seg["degree"].Integer(1);
        if (degree > kMaxSplineDegree) seg["degree"].Fail("an integer in [1, " + std::to_string(kMaxSplineDegree) + "]");
        if (degree > most)
          seg["degree"].FailWith("a B-spline of degree " + std::to_string(degree) + " needs at least " +
                                 std::to_string(degree + 1) + " control points, found " +
                                 std::to_string(control.size()) + ": add points or use a degree of at most " +
                                 std::to_string(most));
      }
      spline_start.back() = std::pair{points[0], control.front() / scale[0]};
      segments.push_back(motion::BSplineThrough(control, degree, duration));
      given.push_back(std::nullopt);
      continue;
    }
    if (*law == motion::MotionLaw::kPolynomial) {
      std::set<std::string> poly_known = {"law", "cam_angle_deg", "boundary"};
      for (const std::string& k : {spec.rise_key, spec.misplaced_key})
        if (!k.empty() && seg.Has(k))
          seg[k].FailWith("a polynomial segment's rise is boundary.end minus boundary.start: remove " + k);
      seg.CheckKnownFields(poly_known);
      const Node boundary = seg["boundary"];
      boundary.CheckKnownFields({"start", "end"});
      std::pair<GivenEnd, GivenEnd> ends;
      motion::BoundaryState<double> states[2];
      for (int e = 0; e < 2; ++e) {
        const Node end = boundary[e == 0 ? "start" : "end"];
        end.CheckKnownFields({keys[0], keys[1], keys[2], keys[3]});
        GivenEnd& g = e == 0 ? ends.first : ends.second;
        for (int k = 0; k < 4; ++k) {
          if (k >= 2 && !end.Has(keys[k])) break;
          const Node v = end[keys[k]];  // position and velocity required: "missing field"
          g.values.push_back(v.Number());
          g.nodes.push_back(v);
        }
        if (g.values.size() < 3 && end.Has(keys[3]))  // a jerk without the acceleration
          end[keys[3]].FailWith("a jerk needs the acceleration at the same end (" + keys[2] + ")");
        states[e].position = g.values[0] * scale[0];
        for (size_t k = 1; k < g.values.size(); ++k) states[e].derivatives.push_back(g.values[k] * scale[k]);
      }
      segments.push_back(motion::PolynomialThrough(states[0], states[1], duration));
      given.push_back(std::move(ends));
      continue;
    }
    seg.CheckKnownFields(known);
    if (!spec.misplaced_key.empty() && seg.Has(spec.misplaced_key))
      seg[spec.misplaced_key].FailWith(spec.misplaced_hint);
    motion::MotionSegment<double> m;
    m.law = *law;
    m.duration = duration;
    if (*law == motion::MotionLaw::kDwell) {
      if (seg.Has(spec.rise_key) && seg[spec.rise_key].Number() != 0.0)
        seg[spec.rise_key].FailWith("a dwell has no rise");
    } else {
      const double rise = seg[spec.rise_key].Number();
      if (rise == 0.0) seg[spec.rise_key].Fail("a non-zero rise (use a dwell for no motion)");
      m.rise = rise * spec.rise_scale;
    }
    segments.push_back(m);
    given.push_back(std::nullopt);
  }
  // Continuity of every value a polynomial segment gives with the program around it: its start
  // position is where the program has brought the follower (0 at the start of the cycle), each
  // derivative equals the neighbour's at the joint (the segment before its start, the segment
  // after its end; the cycle wraps).
  const size_t n = segments.size();
  const char* quantity[4] = {"position", "velocity", "acceleration", "jerk"};
  auto units = [&](int k) {
    return k == 0 ? spec.unit : spec.unit + "/deg" + (k == 1 ? "" : k == 2 ? "²" : "³");
  };
  auto agree = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)}); };
  double s_start = 0.0;  // model units
  for (size_t i = 0; i < n; ++i) {
    if (spline_start[i] && !agree(s_start / scale[0], spline_start[i]->second))
      spline_start[i]->first.FailWith(
          "the motion is not continuous: " +
          (i == 0 ? std::string("the cycle starts on the base circle") : "segment " + std::to_string(i - 1) + " ends") +
          " with position " + Format(s_start / scale[0], 12) + " " + spec.unit + ", this control point gives " +
          Format(spline_start[i]->second, 12) + " " + spec.unit);
    if (given[i]) {
      for (int e = 0; e < 2; ++e) {
        const GivenEnd& g = e == 0 ? given[i]->first : given[i]->second;
        const size_t other = e == 0 ? (i + n - 1) % n : (i + 1) % n;
        const motion::Svaj<double> shape = motion::MotionSegmentShape(segments[other], e == 0 ? 1.0 : 0.0);
        const double b = segments[other].duration;
        const double actual[4] = {0.0, shape.v / b, shape.a / (b * b), shape.j / (b * b * b)};
        for (size_t k = 0; k < g.values.size(); ++k) {
          if (k == 0 && e == 1) continue;  // the end position sets the rise; the next start checks it
          // A value the next polynomial also gives at this joint: its start reports a mismatch.
          if (e == 1 && given[other] && k < given[other]->first.values.size()) continue;
          const double have = k == 0 ? s_start / scale[0] : actual[k] / scale[k];
          if (agree(have, g.values[k])) continue;
          const std::string where =
              k == 0 ? (i == 0 ? "the cycle starts on the base circle" : "segment " + std::to_string(i - 1) + " ends")
                     : (e == 0 ? "segment " + std::to_string(other) + " ends" : "segment " + std::to_string(other) + " starts");
          g.nodes[k].FailWith("the motion is not continuous: " + where + " with " + quantity[k] + " " +
                              Format(have, 12) + " " + units(int(k)) + ", this boundary gives " +
                              Format(g.values[k], 12) + " " + units(int(k)));
        }
      }
    }
    s_start += segments[i].rise;
  }
  motion::MotionProgram<double> program(segments);
  if (const auto issue = motion::CheckProgram(program, 2 * kPi, /*must_return=*/true, 1e-6)) {
    if (issue->segment < 0 && issue->message.find("does not return") != std::string::npos)
      motion_node.FailWith("the " + spec.subject + " does not return: rises sum to " +
                           Format(program.NetRise() / spec.rise_scale) + " " + spec.unit +
                           ", expected 0");
    if (issue->segment < 0) motion_node.FailWith(issue->message);
    const std::string field = issue->field == "rise" ? spec.rise_key : issue->field;
    motion_node[issue->segment][field].FailWith(issue->message);
  }
  return program;
}

nlohmann::ordered_json FollowerRiseRule(const MotionInputSpec& spec, const MotionInputSpec& other,
                                        const std::vector<std::string>& types) {
  using oj = nlohmann::ordered_json;
  oj moving = oj::array();
  for (const std::string& law : motion::LawNames())
    if (!Shaped(law) && law != motion::LawName(motion::MotionLaw::kDwell)) moving.push_back(law);
  oj other_state = oj::object();
  for (const std::string& k : BoundaryKeys(other.unit)) other_state[k] = false;
  const oj item = {
      {"allOf",
       oj::array({{{"properties", {{other.rise_key, false},
                                   {"control_points_" + other.unit, false},
                                   {"boundary", {{"properties", {{"start", {{"properties", other_state}}},
                                                                 {"end", {{"properties", other_state}}}}}}}}}},
                  {{"if", {{"required", {"law"}}, {"properties", {{"law", {{"enum", moving}}}}}}},
                   {"then", {{"required", {spec.rise_key}}, {"properties", {{spec.rise_key, {{"not", {{"const", 0}}}}}}}}}},
                  {{"if", {{"required", {"law"}},
                           {"properties", {{"law", {{"const", motion::LawName(motion::MotionLaw::kDwell)}}}}}}},
                   {"then", {{"properties", {{spec.rise_key, {{"const", 0}}}}}}}}})}};
  return {{"if", {{"required", {"follower"}}, {"properties", {{"follower", {{"required", {"type"}}, {"properties", {{"type", {{"enum", types}}}}}}}}}}},
          {"then", {{"properties", {{"motion", {{"items", item}}}}}}}};
}

nlohmann::ordered_json MotionSchema(const std::vector<MotionInputSpec>& specs,
                                    const std::vector<std::string>& rise_notes, bool rise_rules) {
  using oj = nlohmann::ordered_json;
  const bool polynomial = specs.front().allow_polynomial;
  oj laws = oj::array(), moving = oj::array();
  for (const std::string& law : motion::LawNames()) {
    if (!polynomial && Shaped(law)) continue;
    laws.push_back(law);
    if (!Shaped(law) && law != motion::LawName(motion::MotionLaw::kDwell)) moving.push_back(law);
  }
  oj props = oj::object();
  props["law"] = {{"description", "the motion law of the segment"}, {"enum", laws}};
  for (size_t i = 0; i < specs.size(); ++i)
    props[specs[i].rise_key] = {{"description", "the " + specs[i].subject + "'s rise over the segment, " +
                                                    rise_notes[i] + " (none or 0 for a dwell) [" + specs[i].unit + "]"},
                                {"type", "number"}};
  props["cam_angle_deg"] = {{"description", "the cam angle the segment spans [deg]"}, {"type", "number"}, {"exclusiveMinimum", 0}};
  oj items = {{"type", "object"}};
  if (polynomial) {
    // A polynomial segment's boundary state (docs/disc_cam.md "Polynomial segments"): the keys of
    // BoundaryKeys for each unit, position and velocity required, a jerk with the acceleration.
    oj state = {{"type", "object"}}, sprops = oj::object(), any = oj::array(), dependent = oj::object();
    for (const MotionInputSpec& spec : specs) {
      const std::array<std::string, 4> k = BoundaryKeys(spec.unit);
      sprops[k[0]] = {{"type", "number"},
                      {"description", spec.subject + " displacement S [" + spec.unit + "] (absolute: 0 on the base circle)"}};
      sprops[k[1]] = {{"type", "number"}, {"description", "dS/dθ [" + spec.unit + " per degree of cam angle]"}};
      sprops[k[2]] = {{"type", "number"}, {"description", "d²S/dθ² (optional: with it the degree is 5)"}};
      sprops[k[3]] = {{"type", "number"}, {"description", "d³S/dθ³ (optional, needs the acceleration: degree 7)"}};
      any.push_back({{"required", {k[0], k[1]}}});
      dependent[k[3]] = {k[2]};
    }
    state["properties"] = sprops;
    if (any.size() == 1) state["required"] = any[0]["required"];
    else state["anyOf"] = any;
    state["dependentRequired"] = dependent;
    state["additionalProperties"] = false;
    props["boundary"] = {{"type", "object"},
                         {"description", "law polynomial only: the " + specs.front().subject +
                                             " at the segment's start and end (docs/disc_cam.md 'Polynomial segments')"},
                         {"properties", {{"start", state}, {"end", state}}},
                         {"required", {"start", "end"}},
                         {"additionalProperties", false}};
    props["boundary"]["properties"]["start"]["description"] = "the segment's start";
    props["boundary"]["properties"]["end"]["description"] = "the segment's end";
    for (const MotionInputSpec& spec : specs)
      props["control_points_" + spec.unit] = {
          {"type", "array"},
          {"items", {{"type", "number"}}},
          {"minItems", 2},
          {"description", "law bspline only: the " + spec.subject + "'s B-spline control points [" + spec.unit +
                              "] (absolute; the first is where the segment starts, the last where it ends; "
                              "repeat the first or last k + 1 for k zero derivatives there; docs/disc_cam.md "
                              "'B-spline segments')"}};
    props["degree"] = {{"type", "integer"},
                       {"minimum", 1},
                       {"maximum", kMaxSplineDegree},
                       {"description", "law bspline only: the B-spline's degree, at most the control points less 1 "
                                       "(absent: 5, or that when fewer points)"}};
  }
  items["properties"] = props;
  items["required"] = {"law", "cam_angle_deg"};
  items["additionalProperties"] = false;
  if (polynomial) {
    oj rise_given = oj::array();
    for (const MotionInputSpec& spec : specs) rise_given.push_back({{"required", {spec.rise_key}}});
    items["if"] = {{"properties", {{"law", {{"const", motion::LawName(motion::MotionLaw::kPolynomial)}}}}},
                   {"required", {"law"}}};
    items["then"] = {{"required", {"boundary"}},
                     {"not", rise_given.size() == 1 ? rise_given[0] : oj{{"anyOf", rise_given}}}};
    items["else"] = {{"not", {{"required", {"boundary"}}}}};
    // A B-spline segment: its control points, no rise; other laws take neither points nor degree.
    oj points_given = oj::array();
    for (const MotionInputSpec& spec : specs) points_given.push_back({{"required", {"control_points_" + spec.unit}}});
    const oj any_points = points_given.size() == 1 ? points_given[0] : oj{{"anyOf", points_given}};
    oj spline = {{"if", {{"properties", {{"law", {{"const", motion::LawName(motion::MotionLaw::kBSpline)}}}}},
                         {"required", {"law"}}}},
                 {"then", {{"allOf", oj::array({any_points, {{"not", rise_given.size() == 1 ? rise_given[0]
                                                                                            : oj{{"anyOf", rise_given}}}}})}}},
                 {"else", {{"not", {{"anyOf", oj::array({any_points, {{"required", {"degree"}}}})}}}}}};
    items["allOf"] = oj::array({spline});
  }
  if (rise_rules) {
    const std::string& key = specs.front().rise_key;
    if (!items.contains("allOf")) items["allOf"] = oj::array();
    for (oj rule : oj::array({
        {{"$comment", "a moving law has a non-zero rise"},
         {"if", {{"properties", {{"law", {{"enum", moving}}}}}, {"required", {"law"}}}},
         {"then", {{"required", {key}}, {"properties", {{key, {{"not", {{"const", 0}}}}}}}}}},
        {{"$comment", "a dwell has no rise (0 when given)"},
         {"if", {{"properties", {{"law", {{"const", motion::LawName(motion::MotionLaw::kDwell)}}}}}, {"required", {"law"}}}},
         {"then", {{"properties", {{key, {{"const", 0}}}}}}}}}))
      items["allOf"].push_back(rule);
  }
  return {{"type", "array"}, {"minItems", 1}, {"items", items}};
}

std::vector<motion::Svaj<double>> SampleMotion(const motion::MotionProgram<double>& program,
                                               int n) {
  std::vector<motion::Svaj<double>> out(n);
  for (int i = 0; i < n; ++i) out[i] = program.Evaluate(2 * kPi * i / n);
  return out;
}

MotionPeaks PeakDerivatives(const std::vector<motion::Svaj<double>>& samples) {
  MotionPeaks p;
  for (const auto& s : samples) {
    p.velocity = std::max(p.velocity, std::abs(s.v));
    p.acceleration = std::max(p.acceleration, std::abs(s.a));
    p.jerk = std::max(p.jerk, std::abs(s.j));
  }
  return p;
}

std::vector<JointRow> JointRows(const std::vector<motion::JointContinuity>& joints) {
  std::vector<JointRow> out;
  for (const auto& j : joints)
    out.push_back({j.segment, j.cam_angle_rad / kDeg,
                   j.order < 0 ? std::string("discontinuous") : std::string("C").append(std::to_string(j.order))});
  return out;
}

void AddSvajPlots(Outputs& out, const std::string& title, const std::string& unit,
                  const std::vector<double>& cam_angle_deg,
                  const std::array<const std::vector<double>*, 4>& per_rad, double speed_rpm) {
  const char* names[4] = {"displacement", "velocity", "acceleration", "jerk"};
  const char* powers[4] = {"", "", "²", "³"};
  // d/dθ per degree = d/dθ per radian × (π/180)^k; d/dt = d/dθ × ω^k (ω in rad/s).
  auto stacked = [&](const std::string& plot_title, const std::vector<double>& x, const std::string& x_label,
                     double factor, const std::string& per) {
    std::vector<Panel> panels;
    double scale = 1.0;
    for (int k = 0; k < 4; ++k) {
      Panel p;
      p.options.title = k == 0 ? plot_title : names[k];
      p.options.height = 260;
      p.options.x_label = x_label;
      p.options.y_label = std::string(names[k]) + " [" + unit + (k ? "/" + per + powers[k] : "") + "]";
      std::vector<double> y(per_rad[k]->size());
      for (size_t i = 0; i < y.size(); ++i) y[i] = (*per_rad[k])[i] * scale;
      p.series.push_back(Series{names[k], x, y});
      panels.push_back(std::move(p));
      scale *= factor;
    }
    return SvgStackedPlots(panels);
  };
  out.Add("svaj.svg", stacked(title + " displacement, velocity, acceleration, jerk per degree of cam", cam_angle_deg,
                              "cam angle [deg]", kDeg, "deg"));
  if (speed_rpm > 0.0) {
    const double omega = speed_rpm * 2 * kPi / 60.0;
    std::vector<double> t_ms(cam_angle_deg.size());
    for (size_t i = 0; i < t_ms.size(); ++i) t_ms[i] = cam_angle_deg[i] * kDeg / omega * 1e3;
    out.Add("svaj_time.svg", stacked(title + " over time at " + Format(speed_rpm) + " rpm", t_ms, "time [ms]",
                                     omega, "s"));
  }
}

}  // namespace camopt::studies
