// The catalogue ratings of a reducer solved from its model (docs/ratings.md): rated torque for a
// rated life at a rated output speed, peak torque from the contact limits, momentary torque from
// the rated bearings' static capacity, the momentary peaks allowed. One solver for every kind: the
// kind gives what its model says at a torque (RatingPoint), the searches are here.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "studies/datasheet.h"
#include "studies/ratings_input.h"

namespace camopt::studies {

/// A rated bearing's static rating and its largest load at a torque (for s0 = C0 / P0max).
struct RatedStatic {
  std::string name;
  double static_rating_N = 0, max_load_N = 0;
};

/// What a kind's model says at one output torque (one analysis at that torque and the rated speed).
struct RatingPoint {
  double shortest_L10h = 0;   ///< the rated bearings' shortest L10 at the rated output speed
  std::string shortest;       ///< which
  double max_contact_stress_MPa = 0, max_roller_load_N = 0;
  std::vector<RatedStatic> statics;
};

/// The limits the peak torque is read from (the study's "limits"); absent: not a limit.
struct PeakLimits {
  std::optional<double> contact_stress_MPa, roller_load_N;
};

struct RatingsResult {
  double rated_torque_Nm = 0;
  std::string rated_by;            ///< the bearing whose L10 is the rated life at it
  double rated_L10h = 0;           ///< the shortest L10 at rated_torque_Nm
  std::optional<double> peak_torque_Nm;
  std::string peak_by, peak_note;
  std::optional<double> momentary_torque_Nm;
  std::string momentary_by, momentary_note;
  std::optional<double> momentary_peaks_allowed;
  int evaluations = 0;             ///< analyses at a torque
  /// Discretisation errors of the three torques (set by the kind when it estimates errors).
  std::optional<double> rated_error_Nm, peak_error_Nm, momentary_error_Nm;
  bool error_crank_estimated = false;
};

/// Solves the ratings: `at(T)` the model at output torque T [N·m] (asked once per torque: the
/// searches' repeats are remembered here), `ratio` input turns per output turn, `start_torque_Nm`
/// where the searches start. Each torque is the evaluated one closest to its target
/// (RatedTorqueForLife, model/common/catalogue_ratings.h).
/// @throws std::invalid_argument when a rating has no torque that reaches it (the message says why).
RatingsResult SolveRatings(const RatingsInput& in, const PeakLimits& limits,
                           const std::function<RatingPoint(double)>& at, double ratio, double start_torque_Nm);

/// result.json's top-level rated_torque_Nm, peak_torque_Nm, momentary_torque_Nm and "ratings" (the
/// details, `estimate_error`: its estimated_error block), or their nulls and {"error": why}.
void AddRatingsJson(const RatingsInput& in, const std::optional<RatingsResult>& g, const std::string& failed,
                    double ratio, bool estimate_error, nlohmann::json& j);

/// best.ratings of a sizing kind (SizingRatingsInput): the rated point asked for, the sized design's
/// shortest L10 there (the accurate model's check) and whether it reaches rated_life_h; with
/// `rated_torque_Nm` (a kind whose lives follow a closed form in the torque) the design's own rated
/// torque and its bearing, else `rated_torque_note` says where it is solved.
nlohmann::json SizedRatingsJson(const SizingRatingsInput& in, double ratio, double shortest_L10h,
                                const std::optional<double>& rated_torque_Nm, const std::string& rated_by,
                                const std::string& rated_torque_note);

/// The datasheet's "Ratings" and "Output bearing" sections (studies/datasheet.h).
std::vector<DatasheetSection> RatingsDatasheetSections();

}  // namespace camopt::studies
