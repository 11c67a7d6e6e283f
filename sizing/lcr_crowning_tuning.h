// Tuning the logarithmic roller crowning of a given LCR ("lcr_crowning_tuning"): per cam,
// the coefficient f (effective length Le fixed) that minimises the largest contact pressure over a
// revolution at the design torque, worst over a set of misalignments, subject to the pressure
// staying off the contact's ends at an overload torque (at every misalignment). The two cams are
// independent (each cam's pressures depend only on its own rollers' crowning).
//
// Method: the slices model over the cycle (model/lcr/contact3d_cycle.h) on a geometric scan of f
// (the stress-versus-coefficient curve), then golden-section refinement in ln f between the scan
// neighbours of the best feasible point (feasible = off the ends at overload). Double only: a
// one-variable problem per cam whose value evaluations are cheap; the sizing problem with crowning
// variables uses the slices model's exact gradients instead.
#pragma once

#include <array>
#include <functional>
#include <vector>

#include "model/lcr/contact3d_cycle.h"

namespace camopt::sizing {

struct LcrCrowningTuningSpec {
  lcr::Reducer<double> reducer;
  lcr::Material material;
  lcr::LoadCase design_load;
  double overload_torque_Nmm = 0;
  std::vector<double> misalignments_rad = {0.0};
  std::array<double, 2> effective_length_mm{0, 0};  // Le per cam ([0] input, [1] output), > roller length
  std::array<double, 2> coefficient_range_mm{1e-4, 0.05};
  int angle_steps = 360;
  int slices = 40;
  int curve_points = 12;
  int refine_iterations = 8;
  std::function<void(double)> progress;  // fraction done, now and then (may be empty)
};

/// One cam's pressures at one crowning: per misalignment, at design and overload torque.
struct LcrCrowningCheck {
  std::vector<double> design_MPa, overload_MPa;
  std::vector<char> design_edge, overload_edge;
  double worst_design_MPa = 0;
  bool edge_free_at_overload = true;
};

struct LcrCrowningSideResult {
  double coefficient_mm = 0;  // tuned f
  bool feasible = false;      // some f of the range keeps the pressure off the ends at overload
  std::vector<double> curve_coefficient_mm, curve_worst_design_MPa;
  std::vector<char> curve_edge_free_at_overload;
  LcrCrowningCheck tuned, uncrowned;
  int evaluations = 0;
};

/// @throws std::invalid_argument for Le <= roller length or a bad range.
std::array<LcrCrowningSideResult, 2> TuneLcrCrowning(const LcrCrowningTuningSpec& spec);

/// The check of one cam (details: the cycle result per misalignment, design then overload)'s crowning with the given contact model (slices or half_space).
LcrCrowningCheck CheckLcrCrowning(const LcrCrowningTuningSpec& spec, lcr::Side side,
                                  const lcr::RollerCrowning<double>& crowning, lcr::ContactModel model,
                                  std::vector<lcr::Contact3DCycleSide>* details = nullptr, int grid_nx = 48,
                                  int grid_ny = 256);

}  // namespace camopt::sizing
