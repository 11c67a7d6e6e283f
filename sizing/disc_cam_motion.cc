#include "sizing/disc_cam_motion.h"

#include "sizing/stage_clock.h"

#include <algorithm>
#include <cmath>

namespace camopt::sizing {
namespace {

namespace dc = camopt::disc_cam;
using objectives::VerifiedLimit;
// The fast limits start this share inside the study's (the solvers meet rows to ~1e-7 of scale).
constexpr double kTightenMargin = 2e-7;

objectives::Verification VerificationOf(const objectives::MotionAccurate& a, int max_rounds) {
  objectives::Verification v;
  v.accurate_model = a.model;
  v.checks = a.checks;
  v.max_rounds = max_rounds;
  v.ran = true;
  return v;
}

}  // namespace

std::vector<motion::MotionLaw> NamedLaws() {
  using L = motion::MotionLaw;
  return {L::kCycloidal,       L::kSimpleHarmonic, L::kModifiedSine, L::kModifiedTrapezoid,
          L::kPolynomial345,   L::kPolynomial4567, L::kQuadraticParabola};
}

DiscCamMotionOutcome SolveDiscCamMotion(const objectives::DiscCamMotionSpec& spec, const DiscCamMotionOptions& options,
                                        const dc::DiscCam& study_design) {
  DiscCamMotionOutcome out;
  objectives::MotionFastLimits fast;
  fast.pressure_angle_deg = spec.pressure_angle_deg * (1 - kTightenMargin);
  if (spec.stroke_mm) fast.stroke_inset_mm = kTightenMargin * *spec.stroke_mm;
  if (spec.contact_stress_MPa) fast.contact_stress_MPa = *spec.contact_stress_MPa * (1 - kTightenMargin);
  if (spec.follower) fast.separation_margin_N = kTightenMargin * std::max(1.0, std::abs(spec.follower->Hold()));
  std::vector<double> start;  // all variables (t included), from the last solve
  std::vector<objectives::TighteningStep> history;
  for (int round = 0;; ++round) {
    objectives::Problem p = objectives::DiscCamMotionProblem(spec, fast);
    optimizers::SolverOptions so = options.solver;
    so.ipopt_extended_low_rank = true;  // a few free controls, rows at every sampled angle (solver.h)
    if (!start.empty()) {
      // t from the objective at the last design (the rows change with the limits, not t's meaning).
      so.initial = start;
    }
    optimizers::SolverResult r = optimizers::Solve(p, so);
    const int gv = out.result.value_evaluations + r.value_evaluations;
    const int gg = out.result.gradient_evaluations + r.gradient_evaluations;
    out.result = r;
    out.result.value_evaluations = gv, out.result.gradient_evaluations = gg;
    out.rounds = round;
    out.fast = fast;
    if (r.x.empty()) break;
    out.x.assign(r.x.begin(), r.x.end() - 1);
    out.cam = objectives::MotionDesign(spec, out.x);
    out.converged = r.ok();
    out.check = [&] {
      const StageClock::Scope stage("verification");
      return objectives::CheckMotionDesign(spec, out.cam);
    }();
    start = r.x;
    bool all = true, moved = false;
    for (const VerifiedLimit& c : out.check.checks) {
      if (c.holds()) continue;
      all = false;
      if (round >= options.verify_rounds) continue;
      const double ex = std::isfinite(c.excess()) ? c.excess() : std::max(1.0, std::abs(c.limit_value) * 0.05);
      objectives::TighteningStep st;
      st.round = round + 1, st.limit = c.limit, st.where = c.where;
      st.accurate_value = c.accurate_value, st.limit_value = c.limit_value;
      if (c.limit == "pressure_angle_deg") {
        // The fast rows hold |φ| within [−p, p]: an excess as large as p itself leaves no band to
        // tighten to, and the design stays over the limit (not verified) instead of a problem
        // whose bounds cross.
        const double next = fast.pressure_angle_deg - (ex + kTightenMargin * spec.pressure_angle_deg);
        if (!(next > 0)) continue;
        st.fast_limit_before = fast.pressure_angle_deg;
        fast.pressure_angle_deg = next;
        st.fast_limit_after = fast.pressure_angle_deg;
      } else if (c.limit == "radius_margin_mm") {
        st.fast_limit_before = fast.radius_margin_extra_mm;
        fast.radius_margin_extra_mm += ex + 1e-7;
        st.fast_limit_after = fast.radius_margin_extra_mm;
      } else if (c.limit == "contact_stress_MPa") {
        st.fast_limit_before = fast.contact_stress_MPa;
        fast.contact_stress_MPa -= ex + kTightenMargin * *spec.contact_stress_MPa;
        st.fast_limit_after = fast.contact_stress_MPa;
      } else if (c.limit == "stroke_mm") {
        st.fast_limit_before = fast.stroke_inset_mm;
        fast.stroke_inset_mm += ex + 1e-7;
        st.fast_limit_after = fast.stroke_inset_mm;
      } else if (c.limit == "no_separation_up_to_rpm") {
        // The weakest speed joins the fast rows (once), and the margin grows by the excess.
        const double rpm = out.check.weakest_contact_rpm;
        if (rpm > 0 && std::find(fast.extra_separation_rpm.begin(), fast.extra_separation_rpm.end(), rpm) ==
                           fast.extra_separation_rpm.end())
          fast.extra_separation_rpm.push_back(rpm);
        st.fast_limit_before = fast.separation_margin_N;
        // A separation at a force the held-on model puts at 0 is the two models' difference
        // (RK4 against CVODE, ~1e-5 of the loads): step by at least 1e-4 of the hold-down load.
        const double hold = std::max(1.0, std::abs(spec.follower->Hold()));
        fast.separation_margin_N += std::max(ex + 1e-6 * hold, out.check.lowest_separation_rpm > 0 ? 1e-4 * hold : 0.0);
        st.fast_limit_after = fast.separation_margin_N;
      }
      history.push_back(st);
      moved = true;
    }
    if (all || !moved) break;
  }
  out.verification = VerificationOf(out.check, options.verify_rounds);
  out.verification.history = history;
  out.verification.ran = !out.x.empty();
  // An objective the accurate model cannot evaluate (the follower leaves the cam in the dwell) is
  // not verified, whatever the limits say.
  out.verified = out.verification.verified() && std::isfinite(out.check.objective);
  // The study's own law(s) and every named law in place of each optimized segment, accurate: their
  // objective alone (what they are compared by; the start's limits are not reported).
  out.start = objectives::CheckMotionDesign(spec, study_design, /*objective_only=*/true);
  if (spec.objective == objectives::MotionObjective::kPeakJerk)
    for (const objectives::OptimizedSegment& o : spec.segments) {
      const auto ch = motion::Characteristics(study_design.motion.segments()[size_t(o.segment)].law);
      if (ch && !std::isfinite(ch->cj)) out.start.objective = kInf, out.start.objective_error = 0.0;
    }
  const dc::DiscCam base = out.x.empty() ? study_design : out.cam;
  for (const objectives::OptimizedSegment& o : spec.segments)
    for (motion::MotionLaw law : NamedLaws()) {
      dc::DiscCam c = base;
      std::vector<motion::MotionSegment<double>> segs = c.motion.segments();
      const auto& s = study_design.motion.segments()[size_t(o.segment)];
      segs[size_t(o.segment)] = motion::MotionSegment<double>(law, s.rise, s.duration);
      c.motion = motion::MotionProgram<double>(std::move(segs));
      // A law whose acceleration jumps (inside it or against a dwell) has an infinite jerk there
      // (its characteristic value c_j, motion_law.h): the sampled jerk would miss the jump.
      const auto ch = motion::Characteristics(law);
      if (spec.objective == objectives::MotionObjective::kPeakJerk && ch && !std::isfinite(ch->cj)) {
        out.named_laws.push_back({o.segment, motion::LawName(law), kInf, 0.0});
        continue;
      }
      const objectives::MotionAccurate a = objectives::CheckMotionDesign(spec, c, /*objective_only=*/true);
      out.named_laws.push_back({o.segment, motion::LawName(law), a.objective, a.objective_error});
    }
  return out;
}

}  // namespace camopt::sizing
