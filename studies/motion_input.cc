#include "studies/motion_input.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "studies/format.h"
#include "studies/writers.h"

namespace camopt::studies {
namespace {
constexpr double kDeg = kPi / 180.0;
}  // namespace

motion::MotionProgram<double> ParseMotionProgram(const Node& motion_node,
                                                 const MotionInputSpec& spec) {
  std::set<std::string> known = {"law", spec.rise_key, "cam_angle_deg"};
  if (!spec.misplaced_key.empty()) known.insert(spec.misplaced_key);
  std::string laws;
  for (const auto& n : motion::LawNames()) laws += (laws.empty() ? "" : ", ") + n;
  std::vector<motion::MotionSegment<double>> segments;
  for (const Node& seg : motion_node.Elements()) {
    seg.CheckKnownFields(known);
    if (!spec.misplaced_key.empty() && seg.Has(spec.misplaced_key))
      seg[spec.misplaced_key].FailWith(spec.misplaced_hint);
    const auto law = motion::LawFromName(seg["law"].String());
    if (!law) seg["law"].Fail("a motion law (" + laws + ")");
    motion::MotionSegment<double> m;
    m.law = *law;
    m.duration = seg["cam_angle_deg"].Positive() * kDeg;
    if (*law == motion::MotionLaw::kDwell) {
      if (seg.Has(spec.rise_key) && seg[spec.rise_key].Number() != 0.0)
        seg[spec.rise_key].FailWith("a dwell has no rise");
    } else {
      const double rise = seg[spec.rise_key].Number();
      if (rise == 0.0) seg[spec.rise_key].Fail("a non-zero rise (use a dwell for no motion)");
      m.rise = rise * spec.rise_scale;
    }
    segments.push_back(m);
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

nlohmann::json JointsJson(const std::vector<motion::JointContinuity>& joints) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& j : joints)
    out.push_back({{"after_segment", j.segment},
                   {"cam_angle_deg", j.cam_angle_rad / kDeg},
                   {"continuity", j.order < 0 ? std::string("discontinuous")
                                              : std::string("C").append(std::to_string(j.order))}});
  return out;
}

namespace {

// "acceleration_deg_per_rad2" → "acceleration [deg/rad²]": a CSV column name as an axis label.
std::string AxisLabel(const std::string& column) {
  size_t cut = std::string::npos;
  for (const char* unit : {"_deg", "_mm", "_rad"}) cut = std::min(cut, column.find(unit));
  if (cut == std::string::npos) return column;
  std::string quantity = column.substr(0, cut), unit = column.substr(cut + 1);
  for (char& c : quantity)
    if (c == '_') c = ' ';
  for (auto [from, to] : {std::pair<std::string, std::string>{"_per_", "/"}, {"rad2", "rad²"}, {"rad3", "rad³"}})
    for (size_t at = unit.find(from); at != std::string::npos; at = unit.find(from, at + to.size()))
      unit.replace(at, from.size(), to);
  if (quantity == "follower" || quantity == "swing") quantity += " displacement";
  return quantity + " [" + unit + "]";
}

}  // namespace

void AddSvajPlots(Outputs& out, const std::string& title_prefix,
                  const std::vector<double>& cam_angle_deg,
                  const std::array<std::string, 4>& y_labels,
                  const std::array<const std::vector<double>*, 4>& columns) {
  const char* names[4] = {"displacement", "velocity", "acceleration", "jerk"};
  for (int k = 0; k < 4; ++k) {
    PlotOptions o;
    o.title = title_prefix + " " + names[k];
    o.x_label = "cam angle [deg]";
    o.y_label = AxisLabel(y_labels[k]);
    out.Add(std::string("svaj_") + names[k] + ".svg",
            SvgLinePlot({Series{names[k], cam_angle_deg, *columns[k]}}, o));
  }
}

}  // namespace camopt::studies
