// A follower displacement program: a sequence of motion-law segments over one cycle of the cam
// angle θ. Each segment scales a normalised law (motion_law.h) to a rise h over a duration β:
//   S(θ) = S₀ + h N(u), u = (θ − θ₀)/β, dS/dθ = h N'(u)/β, d²S/dθ² = h N''/β², d³S/dθ³ = h N'''/β³.
// The rise is in the follower's own unit (mm for a translating follower, rad for an oscillating
// one or a globoidal turret); angles are in rad. Independent of any cam type.
#pragma once

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "model/common/scalar.h"
#include "model/motion/motion_law.h"

namespace camopt::motion {

template <typename T>
struct MotionSegment {
  MotionLaw law = MotionLaw::kDwell;
  T rise = T(0.0);      ///< signed rise h over the segment (follower unit)
  T duration = T(0.0);  ///< cam angle β of the segment [rad], > 0
};

template <typename T>
class MotionProgram {
 public:
  MotionProgram() = default;
  explicit MotionProgram(std::vector<MotionSegment<T>> segments) : segments_(std::move(segments)) {}

  const std::vector<MotionSegment<T>>& segments() const { return segments_; }

  /// Cam angle of one cycle: the sum of the durations [rad].
  T Period() const {
    T p(0.0);
    for (const auto& s : segments_) p += s.duration;
    return p;
  }
  /// Net rise over one cycle (0 for a program that returns).
  T NetRise() const {
    T h(0.0);
    for (const auto& s : segments_) h += s.rise;
    return h;
  }

  /// S and its θ-derivatives at cam angle theta [rad]; theta is taken modulo the period, and
  /// for a program with a net rise each further cycle adds the net rise (an indexing motion).
  /// The segment is chosen on the value of θ; segments meet with continuous S, so the
  /// derivative of S with respect to the design is right at the joints.
  Svaj<T> Evaluate(const T& theta) const {
    const T period = Period();
    const double cycles = std::floor(Value(theta) / Value(period));
    T t = theta - T(cycles) * period;
    T start(0.0), s0 = T(cycles) * NetRise();
    for (size_t i = 0; i < segments_.size(); ++i) {
      const MotionSegment<T>& seg = segments_[i];
      const bool last = i + 1 == segments_.size();
      if (last || Value(t) < Value(start + seg.duration)) {
        const T u = (t - start) / seg.duration;
        const Svaj<T> n = NormalizedLaw(seg.law, u);
        const T b = seg.duration;
        return {s0 + seg.rise * n.s, seg.rise * n.v / b, seg.rise * n.a / (b * b),
                seg.rise * n.j / (b * b * b)};
      }
      start += seg.duration;
      s0 += seg.rise;
    }
    return {s0, T(0.0), T(0.0), T(0.0)};
  }

 private:
  std::vector<MotionSegment<T>> segments_;
};

/// Continuity of the program at one joint (the end of segment `segment`, the start of the next;
/// the last joint wraps to the start of the cycle).
struct JointContinuity {
  int segment = 0;
  double cam_angle_rad = 0.0;
  double jump_s = 0.0, jump_v = 0.0, jump_a = 0.0, jump_j = 0.0;  // absolute jumps
  /// Highest derivative order that is continuous: -1 (S jumps), 0, 1, 2 (C²) or 3.
  int order = -1;
};

/// The jumps of S, S', S'', S''' at every joint. A jump counts as continuous when it is below
/// rel_tol times the program's largest magnitude of that derivative (sampled).
std::vector<JointContinuity> CheckContinuity(const MotionProgram<double>& program,
                                             double rel_tol = 1e-9);

/// A problem with a program, naming the segment (-1 for the whole program).
struct ProgramIssue {
  int segment = -1;
  std::string field;  ///< "cam_angle_deg", "rise", or "" for the whole program
  std::string message;
};

/// Checks a program for a cam: at least one segment, positive durations, dwells without rise,
/// moving segments with a non-zero rise, durations summing to `period` (2π for a disc cam)
/// within `angle_tol` [rad], and, when `must_return`, a net rise of zero within `rise_tol`.
std::optional<ProgramIssue> CheckProgram(const MotionProgram<double>& program, double period,
                                         bool must_return, double angle_tol = 1e-9,
                                         double rise_tol = 1e-9);

}  // namespace camopt::motion
