// The parts of a cycloid stage as a shop makes and checks them: the frames of the discs.
//
// Disc k (k = 1 … N) of N identical discs sits at crank angle φ + 2π(k − 1)/N, so its kinematic
// angle −(φ + 2π(k − 1)/N)/n2 differs from disc 1's by γ_k = −2π(k − 1)/(N n2), while the output
// pins (one flange) are common. In the part frame of disc k — origin at the disc's centre (its
// bore), the output-pin holes at R_w u(2πj/Z_w) — its tooth profile is ToothProfile's (disc frame,
// model/cycloid/tooth_profile.h) turned by γ_k. Disc 1's part frame is the model's disc frame.
#pragma once

#include <cmath>

#include "model/common/geometry.h"
#include "model/common/profile_deviation.h"
#include "model/common/scalar.h"
#include "model/cycloid/tooth_profile.h"

namespace camopt::cycloid {

/// γ_k = −2π(k − 1)/(N n2) [rad]: the turn of disc k's tooth profile in its part frame from the
/// model's disc frame. @param k 1-based disc number, @param discs N, @param teeth n2.
inline double DiscPhaseRotationRad(int k, int discs, int teeth) {
  return -2.0 * kPi * double(k - 1) / (double(discs) * double(teeth));
}

/// The (modified) tooth profile of disc k in its part frame as a closed curve of the parameter t
/// of ToothProfile, t ∈ [0, 2π): unit tangent of the roller-centre curve (the inner offset keeps
/// its direction where the tooth is not undercut), speed |X'|(1 − ρ' κ_X), curvature of the tooth.
/// @pre CheckDrive(d) is empty (no undercut).
inline profile::Curve DiscPartProfile(const Drive& d, int k, int discs) {
  const double gamma = DiscPhaseRotationRad(k, discs, d.teeth);
  return [d, gamma](double t) {
    const ProfilePoint<double> p = ToothProfile(d, t);
    const double rho = d.roller_radius_mm + d.delta_radius_mm;
    profile::CurvePoint c;
    c.point = Rotate(p.point, gamma);
    c.tangent = Rotate(p.tangent, gamma);
    c.speed = p.speed * (1.0 - rho * p.centre_curvature);
    c.curvature = p.curvature;
    return c;
  };
}

}  // namespace camopt::cycloid
