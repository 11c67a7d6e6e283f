// The paper's example design (§3; docs/papers.md §5), shared by tests and benchmarks:
// C = 45, R = 4, R_e = 22, m = 5, e = 1 (mm), β = 45°, φ_f = 20°, cam angles 60°/60°/135°/105°
// (rise, dwell, return, dwell), modified sine. The continuous parameters can be given as T so
// that gradients can be taken with respect to them.
#pragma once

#include "model/globoidal/globoidal.h"

namespace camopt::globoidal {

template <typename T>
GloboidalCam<T> PaperExampleCam(const T& c = T(45.0), const T& r = T(4.0), const T& re = T(22.0),
                                const T& beta = T(kPi / 4), const T& swing = T(kPi / 9)) {
  const double deg = kPi / 180.0;
  GloboidalCam<T> cam;
  cam.center_distance = c;
  cam.roller_radius = r;
  cam.pitch_radius = re;
  cam.roller_length = T(5.0);
  cam.clearance = T(1.0);
  cam.roller_angle = beta;
  cam.swing = swing;
  cam.direction = 1;
  cam.motion = RiseDwellReturnDwell(motion::MotionLaw::kModifiedSine, swing, T(60.0 * deg),
                                    T(60.0 * deg), T(135.0 * deg), T(105.0 * deg));
  return cam;
}

}  // namespace camopt::globoidal
