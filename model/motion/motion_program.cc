#include "model/motion/motion_program.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace camopt::motion {

std::vector<JointContinuity> CheckContinuity(const MotionProgram<double>& program,
                                             double rel_tol) {
  const auto& segs = program.segments();
  // Scales: the largest magnitudes of each derivative, sampled over every segment.
  double scale[4] = {0, 0, 0, 0};
  for (const auto& seg : segs) {
    for (int k = 0; k <= 64; ++k) {
      const Svaj<double> n = MotionSegmentShape(seg, k / 64.0);
      const double b = seg.duration;
      scale[0] = std::max(scale[0], std::max(std::abs(seg.rise), std::abs(n.s)));
      scale[1] = std::max(scale[1], std::abs(n.v / b));
      scale[2] = std::max(scale[2], std::abs(n.a / (b * b)));
      scale[3] = std::max(scale[3], std::abs(n.j / (b * b * b)));
    }
  }
  std::vector<JointContinuity> joints;
  double angle = 0.0, s_start = 0.0;
  for (size_t i = 0; i < segs.size(); ++i) {
    const auto& a = segs[i];
    const auto& b = segs[(i + 1) % segs.size()];
    const Svaj<double> end = MotionSegmentShape(a, 1.0);
    const Svaj<double> begin = MotionSegmentShape(b, 0.0);
    const double ba = a.duration, bb = b.duration;
    angle += ba;
    const double s_end = s_start + end.s;
    s_start += a.rise;
    // At the wrap-around joint the next cycle starts from the net rise (0 for a returning cam).
    const double s_next = (i + 1 == segs.size()) ? program.NetRise() : s_start;
    JointContinuity jc;
    jc.segment = static_cast<int>(i);
    jc.cam_angle_rad = angle;
    jc.jump_s = std::abs(s_next + begin.s - s_end);
    jc.jump_v = std::abs(begin.v / bb - end.v / ba);
    jc.jump_a = std::abs(begin.a / (bb * bb) - end.a / (ba * ba));
    jc.jump_j = std::abs(begin.j / (bb * bb * bb) - end.j / (ba * ba * ba));
    const double jumps[4] = {jc.jump_s, jc.jump_v, jc.jump_a, jc.jump_j};
    jc.order = -1;
    for (int k = 0; k < 4; ++k) {
      if (jumps[k] > rel_tol * std::max(scale[k], 1e-300)) break;
      jc.order = k;
    }
    joints.push_back(jc);
  }
  return joints;
}

std::optional<ProgramIssue> CheckProgram(const MotionProgram<double>& program, double period,
                                         bool must_return, double angle_tol, double rise_tol) {
  const auto& segs = program.segments();
  if (segs.empty()) return ProgramIssue{-1, "", "expected at least one motion segment"};
  double max_rise = 0.0;
  for (size_t i = 0; i < segs.size(); ++i) {
    const auto& s = segs[i];
    const int idx = static_cast<int>(i);
    if (!(s.duration > 0.0) || !std::isfinite(s.duration))
      return ProgramIssue{idx, "cam_angle_deg", "expected a segment duration > 0"};
    if (!std::isfinite(s.rise)) return ProgramIssue{idx, "rise", "expected a finite rise"};
    if (s.law == MotionLaw::kDwell && s.rise != 0.0)
      return ProgramIssue{idx, "rise", "a dwell has no rise"};
    if (s.law != MotionLaw::kDwell && s.law != MotionLaw::kPolynomial && s.law != MotionLaw::kBSpline &&
        s.rise == 0.0)
      return ProgramIssue{idx, "rise", "a moving segment needs a non-zero rise (use a dwell)"};
    max_rise = std::max(max_rise, std::abs(s.rise));
  }
  const double p = program.Period();
  if (std::abs(p - period) > angle_tol) {
    std::ostringstream m;
    m.precision(10);
    m << "segment durations sum to " << p * 180.0 / kPi << " deg, expected " << period * 180.0 / kPi
      << " deg";
    return ProgramIssue{-1, "", m.str()};
  }
  if (must_return && std::abs(program.NetRise()) > rise_tol * std::max(1.0, max_rise)) {
    std::ostringstream m;
    m.precision(10);
    m << "the follower does not return: rises sum to " << program.NetRise() << ", expected 0";
    return ProgramIssue{-1, "", m.str()};
  }
  return std::nullopt;
}

}  // namespace camopt::motion
