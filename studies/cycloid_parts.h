// The parts of a cycloid drive (docs/parts.md): every disc with its output-pin holes and bore at its
// own phase, the ring pins, the output pins (and their rollers), the crank's eccentrics and the
// ring-pin housing's outline, placed at a chosen crank angle for assembly.step.
//
// Frames. Disc k (k = 1..N) sits at crank angle φ + 2π(k − 1)/N (the model's convention for
// several discs, studies/cycloid_ltca_study.cc). Its part frame has its origin at the disc's centre
// (the bore's) and the output-pin holes at R_w u(2πj/Z_w); in it the tooth profile is the model's
// (model/cycloid/tooth_profile.h, disc frame) turned by γ_k = −2π(k − 1)/(N n2): every disc
// meshes the pins with its centre at e u(φ_k) and turns with the output by −φ/n2, so its model
// frame, at −φ_k/n2, is the part frame turned by γ_k (cycloid::DiscPhaseRotationRad,
// model/cycloid/parts.h, which the inspection points use too). Disc 1's part frame is the model's.
#pragma once

#include <optional>

#include "model/cycloid/output_mechanism.h"
#include "model/cycloid/parts.h"
#include "model/cycloid/tooth_profile.h"
#include "studies/geometry_files.h"
#include "studies/parts.h"

namespace camopt::studies::cycloid_common {

struct CycloidPartsInput {
  std::string design_name;
  cycloid::Drive drive;
  int discs = 1;
  double disc_spacing_mm = 0.0;           ///< mid-plane to mid-plane
  double bore_diameter_mm = 0.0;          ///< the discs' bore (the crank bearing's seat); 0: none
  std::optional<cycloid::OutputPins> pins;  ///< with the holes' radius; nullopt: no holes drawn
  double output_pin_length_mm = 0.0;
  double density_kg_m3 = 7850.0;
  std::string material = "steel";
  double crank_angle_rad = 0.0;           ///< the assembly's state
  std::string crank_bearing_designation;  ///< BOM (empty: none given)
  std::string pin_designation;            ///< the ring pins' (a pin as a rated roller), BOM
};

/// The parts from the disc's fitted profile (`tooth`: arcs of the model's profile, counter-clockwise,
/// its exact area, and the generating circle's centre path as the cutter path).
PartsSet CycloidParts(const CycloidPartsInput& in, const PlanarCamFit& tooth);

}  // namespace camopt::studies::cycloid_common
