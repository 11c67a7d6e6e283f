// The motion program optimized (objectives/disc_cam_motion.h): solve on the fast rows, check the
// answer on the accurate model, tighten a fast limit by the accurate excess and solve again from
// the last design until every limit holds on the accurate model or verify_rounds are spent
// (objectives/verification.h, as sizing/disc_cam_min_size.h); then the objective of the study's
// own start law and of every named law of the library (motion_law.h) on each optimized segment,
// by the same accurate model, for comparison.
#pragma once

#include <string>
#include <vector>

#include "objectives/disc_cam_motion.h"
#include "optimizers/solver.h"

namespace camopt::sizing {

struct DiscCamMotionOptions {
  optimizers::SolverOptions solver;
  int verify_rounds = 4;
};

/// The accurate objective of one named law in place of an optimized segment.
struct NamedLawValue {
  int segment = 0;
  std::string law;
  double value = 0.0, error = 0.0;
};

struct DiscCamMotionOutcome {
  bool converged = false, verified = false;
  std::vector<double> x;  ///< free control values (empty: no design)
  camopt::disc_cam::DiscCam cam;
  optimizers::SolverResult result;
  objectives::MotionAccurate check;  ///< at the reported design
  objectives::Verification verification;
  objectives::MotionFastLimits fast;
  int rounds = 0;
  objectives::MotionAccurate start;  ///< the study's own law(s): the objective, accurate (no limit checks)
  std::vector<NamedLawValue> named_laws;
};

DiscCamMotionOutcome SolveDiscCamMotion(const objectives::DiscCamMotionSpec& spec,
                                        const DiscCamMotionOptions& options,
                                        const camopt::disc_cam::DiscCam& study_design);

/// The named laws compared (every rest-in-rest law of motion_law.h).
std::vector<motion::MotionLaw> NamedLaws();

}  // namespace camopt::sizing
