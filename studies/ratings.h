// The catalogue ratings of a reducer solved from its model (docs/ratings.md): rated torque for a
// rated life at a rated output speed, peak torque from the contact limits, momentary torque from
// the rated bearings' static capacity, the momentary peaks allowed. One solver for every kind: the
// kind gives what its model says at a torque (RatingPoint), the searches are here.
#pragma once

#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/common/thermal.h"
#include "studies/archive.h"
#include "studies/datasheet.h"
#include "studies/report.h"
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
  /// The two maxima refined between samples (the vertex of the parabola through the largest sample
  /// and its neighbours), for the peak torque's sampling error; 0: the kind gives none.
  double max_contact_stress_vertex_MPa = 0, max_roller_load_vertex_N = 0;
  std::vector<RatedStatic> statics;
};

/// The vertex of the parabola through a periodic series' largest sample and its two neighbours:
/// the maximum between samples to second order (the series itself when it has fewer than 3 samples
/// or is not concave there).
double ParabolicPeak(const std::vector<double>& periodic_series);

/// The relative width of the bracket at which the rating searches stop (SolveRatings): each
/// torque is within it of a crossing of the model's computed ratio, and the kinds add it to the
/// ratings' estimated errors.
inline constexpr double kRatingSearchRelTolerance = 1e-6;
/// The first bracket factor of a rating search that starts from a torque known to be near its
/// answer (the same rating of a neighbouring model: SolveRatings' `near`; the peak torque on its
/// vertex maxima from the sampled one): 1 %, about the discretisation errors of the ratings, so the
/// answer is bracketed in one or two runs (the factor squares while it is not: 1.01, 1.02, 1.04, …).
inline constexpr double kNearRatingStep = 1.01;

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
  /// With the kind's vertex maxima: |peak torque on the sampled maxima − on the vertex maxima|, the
  /// sampling's share of the peak torque's error (SolveRatings; the kind adds it to peak_error_Nm).
  std::optional<double> peak_sampling_error_Nm;
  bool error_crank_estimated = false;
  /// How the kind estimated them (result.json ratings.estimated_error.method); empty: the cycloid's.
  std::string error_method;
  /// The thermal allowable output speed at the rated torque (SolveAllowableSpeed); absent: `note` why.
  std::optional<double> allowable_output_speed_rpm;
  std::string allowable_speed_note =
      "not computed: no lubricant (the allowable speed is the thermal limit of the lubricated losses; "
      "docs/lubrication.md)";
};

/// RatingsResult's allowable output speed: the output speed at which the housing's balance at the
/// rated torque puts the oil at `limit_C` (ThermalSpeedLimit, model/common/catalogue_ratings.h).
/// `loss_W(input_rpm, oil_C)` the kind's lubricated loss at the rated torque; `ratio` input turns per
/// output turn; `guess_input_rpm` where the search starts. A speed that cannot be solved leaves the speed absent and says why in the note.
void SolveAllowableSpeed(const std::function<double(double, double)>& loss_W, const HousingCooling& cooling,
                         double limit_C, double ratio, double guess_input_rpm, RatingsResult& g);

/// Solves the ratings: `at(T)` the model at output torque T [N·m] (asked once per torque: the
/// searches' repeats are remembered here), `ratio` input turns per output turn, `start_torque_Nm`
/// where the searches start; with `near` (the ratings of a neighbouring model: the same drive on
/// fewer crank angles or a coarser grid, for their errors) each search starts at its rating there
/// with the bracket factor kNearRatingStep. Each torque is the evaluated one closest to its target
/// (RatedTorqueForLife, model/common/catalogue_ratings.h).
/// @throws std::invalid_argument when a rating has no torque that reaches it (the message says why).
RatingsResult SolveRatings(const RatingsInput& in, const PeakLimits& limits,
                           const std::function<RatingPoint(double)>& at, double ratio, double start_torque_Nm,
                           const RatingsResult* near = nullptr);

/// result.json's "ratings" of the kinds that rate a design (cycloid_ltca, lcr_analysis): the rated
/// point, what limits each torque, the allowable speed, the torques' estimated errors.
struct RatingsDetails {
  /// The three torques' discretisation errors (with the kind's error estimates).
  struct EstimatedError {
    double rated_torque_Nm = NAN, peak_torque_Nm = NAN, momentary_torque_Nm = NAN;  ///< NaN: null
    std::string method;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("rated_torque_Nm", &rated_torque_Nm, Field().NullWhenNotFinite().Unit("N·m"));
      a->Visit("peak_torque_Nm", &peak_torque_Nm, Field().NullWhenNotFinite().Unit("N·m"));
      a->Visit("momentary_torque_Nm", &momentary_torque_Nm, Field().NullWhenNotFinite().Unit("N·m"));
      a->Visit("method", &method, Field().Desc("how the errors were estimated"));
    }
  };
  struct MomentaryPeak {
    double output_speed_rpm = 0, duration_s = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("output_speed_rpm", &output_speed_rpm, Field().Unit("rpm").Desc("the output speed at the peak"));
      a->Visit("duration_s", &duration_s, Field().Unit("s").Desc("its duration"));
    }
  };
  double rated_life_h = 0, rated_output_speed_rpm = 0, rated_input_speed_rpm = 0;
  std::string rated_by;
  double L10h_at_rated_torque = NAN;  ///< NaN: null
  std::string peak_limited_by;
  double momentary_static_safety = 0;
  std::string momentary_limited_by;
  double momentary_peaks_allowed = NAN, allowable_output_speed_rpm = NAN;  ///< NaN: null
  std::string allowable_output_speed;
  int evaluations = 0;
  std::optional<EstimatedError> estimated_error;
  std::string definitions;
  std::optional<MomentaryPeak> momentary_peak;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("rated_life_h", &rated_life_h, Field().Unit("h").Desc("ratings.rated_life_h"));
    a->Visit("rated_output_speed_rpm", &rated_output_speed_rpm, Field().Unit("rpm").Desc("ratings.rated_output_speed_rpm"));
    a->Visit("rated_input_speed_rpm", &rated_input_speed_rpm, Field().Unit("rpm").Desc("the rated output speed times the ratio"));
    a->Visit("rated_by", &rated_by, Field().Desc("the bearing whose L10 is the rated life at the rated torque"));
    a->Visit("L10h_at_rated_torque", &L10h_at_rated_torque,
             Field().NullWhenNotFinite().Unit("h").Desc("the shortest L10 at the rated torque (null: unlimited)"));
    a->Visit("peak_limited_by", &peak_limited_by, Field().Desc("the limit that sets the peak torque, or why there is none"));
    a->Visit("momentary_static_safety", &momentary_static_safety, Field().Desc("ratings.momentary_static_safety"));
    a->Visit("momentary_limited_by", &momentary_limited_by,
             Field().Desc("the bearing that sets the momentary torque, or why there is none"));
    a->Visit("momentary_peaks_allowed", &momentary_peaks_allowed,
             Field().NullWhenNotFinite().Desc("the momentary peaks allowed (with ratings.momentary_peak; else null)"));
    a->Visit("allowable_output_speed_rpm", &allowable_output_speed_rpm,
             Field().NullWhenNotFinite().Unit("rpm").Desc("the thermal allowable output speed at the rated torque "
                                                          "(null: not computed)"));
    a->Visit("allowable_output_speed", &allowable_output_speed, Field().Desc("how it was found, or why not"));
    a->Visit("evaluations", &evaluations, Field().Desc("analyses at a torque"));
    a->Visit("estimated_error", &estimated_error,
             Field().NullWhenAbsent().Desc("the torques' estimated discretisation errors (null: not estimated)"));
    a->Visit("definitions", &definitions, Field().Desc("what each rating means"));
    a->Visit("momentary_peak", &momentary_peak, Field().Desc("with ratings.momentary_peak: that peak"));
  }
};

/// result.json's top-level rated_torque_Nm, peak_torque_Nm, momentary_torque_Nm and "ratings" of the
/// kinds that rate a design (cycloid_ltca, lcr_analysis): a member of their result serialized flat
/// into it (RatingsKeys::Serialize), every key absent without "ratings".
struct RatingsKeys {
  /// Each torque (NaN: null, not solved or none); "ratings": the details, or {"error": why} when
  /// `failed` says why there are none.
  std::optional<double> rated_torque_Nm, peak_torque_Nm, momentary_torque_Nm;
  std::optional<OrError<RatingsDetails>> ratings;
  void Set(const RatingsInput& in, const std::optional<RatingsResult>& g, const std::string& failed, double ratio,
           bool estimate_error);
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("rated_torque_Nm", &rated_torque_Nm,
             Field().NullWhenNotFinite().Unit("N·m").Desc("rated life at the rated speed (with ratings; null: not solved)"));
    a->Visit("peak_torque_Nm", &peak_torque_Nm,
             Field().NullWhenNotFinite().Unit("N·m").Desc("within the contact limits (with ratings; null: none)"));
    a->Visit("momentary_torque_Nm", &momentary_torque_Nm,
             Field().NullWhenNotFinite().Unit("N·m").Desc("within the static ratings (with ratings; null: none)"));
    a->Visit("ratings", &ratings, Field().Desc("the catalogue's ratings (with ratings; docs/ratings.md)"));
  }
};

/// best.ratings of a sizing kind (SizingRatingsInput): the rated point asked for, the sized design's
/// shortest L10 there (the accurate model's check) and `met` (the verification's verdict on it); with
/// `rated_torque_Nm` (a kind whose lives follow a closed form in the torque) the design's own rated
/// torque and its bearing, else `rated_torque_note` says where it is solved. With
/// ratings.momentary_torque_Nm also the static check at it (SetMomentary).
struct SizedRatingsBlock {
  double rated_torque_required_Nm = 0, rated_life_h = 0, rated_output_speed_rpm = 0, rated_input_speed_rpm = 0;
  double L10h_at_required_torque = 0;
  bool met = false;
  std::optional<double> rated_torque_Nm;
  std::optional<std::string> rated_by, rated_torque_note;
  std::string definition;
  std::optional<double> momentary_torque_required_Nm, momentary_static_safety, s0_at_required_momentary_torque,
      momentary_torque_Nm;
  std::optional<std::string> momentary_by, momentary_torque_note;
  std::optional<bool> momentary_met;

  /// The momentary part: the torque and s0 asked for, the smallest s0 at that torque (not finite:
  /// null), the design's own momentary torque (absent: null) and what limits it or where it is solved.
  void SetMomentary(double required_Nm, double static_safety, double s0_at_required, const std::optional<double>& own_Nm,
                    std::optional<std::string> by, std::optional<std::string> note, bool met_);

  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("rated_torque_required_Nm", &rated_torque_required_Nm, Field().Unit("N·m").Desc("ratings.rated_torque_Nm"));
    a->Visit("rated_life_h", &rated_life_h, Field().Unit("h").Desc("ratings.rated_life_h"));
    a->Visit("rated_output_speed_rpm", &rated_output_speed_rpm, Field().Unit("rpm").Desc("ratings.rated_output_speed_rpm"));
    a->Visit("rated_input_speed_rpm", &rated_input_speed_rpm,
             Field().Unit("rpm").Desc("the rated output speed times the ratio"));
    a->Visit("L10h_at_required_torque", &L10h_at_required_torque,
             Field().NullWhenNotFinite().Unit("h").Desc(
                 "the shortest L10h at the rated torque and speed, accurate model (null: unlimited)"));
    a->Visit("met", &met, Field().Desc("the life (and the momentary torque's s0) holds as the verification holds it"));
    a->Visit("rated_torque_Nm", &rated_torque_Nm,
             Field().NullWhenAbsent().Unit("N·m").Desc(
                 "the sized design's own rated torque (null: none reached, or solved by the analysis kind: "
                 "rated_torque_note)"));
    a->Visit("rated_by", &rated_by, Field().Desc("with rated_torque_Nm: the bearing that sets it"));
    a->Visit("rated_torque_note", &rated_torque_note, Field().Desc("without it: where the design's own comes from"));
    a->Visit("definition", &definition, Field().Desc("what reaching the rated torque means"));
    a->Visit("momentary_torque_required_Nm", &momentary_torque_required_Nm,
             Field().Unit("N·m").Desc("with ratings.momentary_torque_Nm: that torque"));
    a->Visit("momentary_static_safety", &momentary_static_safety, Field().Desc("with it: the s0 asked for"));
    a->Visit("s0_at_required_momentary_torque", &s0_at_required_momentary_torque,
             Field().NullWhenNotFinite().Desc("with it: the smallest s0 at it, accurate model (null: unlimited)"));
    a->Visit("momentary_torque_Nm", &momentary_torque_Nm,
             Field().NullWhenNotFinite().Unit("N·m").Desc(
                 "with it: the design's own momentary torque (null: none, or solved by the analysis kind)"));
    a->Visit("momentary_by", &momentary_by, Field().Desc("with it and the design's own: the bearing that sets it"));
    a->Visit("momentary_torque_note", &momentary_torque_note,
             Field().Desc("with it, solved by the analysis kind: where it comes from"));
    a->Visit("momentary_met", &momentary_met, Field().Desc("with it: s0 holds as the verification holds it"));
  }
};
SizedRatingsBlock SizedRatingsOf(const SizingRatingsInput& in, double ratio, double shortest_L10h, bool met,
                                 const std::optional<double>& rated_torque_Nm, const std::string& rated_by,
                                 const std::string& rated_torque_note);

/// The datasheet's "Ratings" and "Output bearing" sections (studies/datasheet.h).
std::vector<DatasheetSection> RatingsDatasheetSections();

/// The datasheet's "Torsional stiffness and lost motion (input held)" section: the stiffness block
/// of the rating kinds (stiffness_segments, torsional_stiffness_Nm_per_arcmin, lost_motion_arcmin,
/// backlash_arcmin, stiffness).
DatasheetSection StiffnessDatasheetSection();

/// report.html's headlines of RatingsKeys and the output bearing: the rated, peak and momentary
/// torques with their error estimates, the allowable speed, the output bearing's life and safety.
std::vector<Headline> RatingsHeadlines();


}  // namespace camopt::studies
