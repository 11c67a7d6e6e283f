// The catalogue ratings of a reducer solved from its model (studies/ratings.h, docs/ratings.md).
#include "studies/ratings.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include "model/common/catalogue_ratings.h"
#include "model/common/scalar.h"
#include "studies/format.h"

namespace camopt::studies {

namespace {

/// The torque at which a ratio falling with the torque (a life over the rated life, a capacity over
/// its demand) is 1: RatedTorqueForLife (model/common/catalogue_ratings.h), its error named.
template <typename F>
double SolveTorqueForRatio(const F& ratio, double start_Nm, const std::string& what, double first_step = 2.0) {
  try {
    // A model's loads carry its solvers' tolerances (the LTCA: compatibility 1e-3, contact 1e-4; its
    // maxima jump where a cell or a pair enters the contact), and a rating its discretisation error
    // (1e-4 and more of the torque, estimated_error): a bracket of kRatingSearchRelTolerance · T is
    // inside both, and a narrower one only chases the solvers' noise (the cycloid catalogue's momentary
    // torque took 31 analyses to a 1e-9 bracket, 9 to 1e-6).
    return RatedTorqueForLife(ratio, 1.0, start_Nm, kRatingSearchRelTolerance, first_step);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(what + ": " + e.what());
  }
}

/// The smallest capacity / demand over the items given, and the item.
struct Capacity {
  double ratio = kInf;
  std::string by;
  void Add(double capacity, double demand, const std::string& name) {
    if (capacity > 0 && demand > 0 && capacity / demand < ratio) ratio = capacity / demand, by = name;
  }
};

}  // namespace

double ParabolicPeak(const std::vector<double>& f) {
  const size_t n = f.size();
  if (n < 3) return n ? *std::max_element(f.begin(), f.end()) : 0.0;
  const size_t k = size_t(std::max_element(f.begin(), f.end()) - f.begin());
  const double a = f[(k + n - 1) % n], b = f[k], c = f[(k + 1) % n];
  const double curvature = a - 2 * b + c;  // < 0 at a strict maximum
  if (!(curvature < 0)) return b;
  return b - (c - a) * (c - a) / (8 * curvature);  // b + (c − a)² / (8 (2b − a − c))
}

RatingsResult SolveRatings(const RatingsInput& in, const PeakLimits& limits,
                           const std::function<RatingPoint(double)>& at, double ratio, double start_torque_Nm,
                           const RatingsResult* near) {
  std::map<double, RatingPoint> memo;
  RatingsResult r;
  auto eval = [&](double t) -> const RatingPoint& {
    auto it = memo.find(t);
    if (it == memo.end()) {
      it = memo.emplace(t, at(t)).first;
      ++r.evaluations;
    }
    return it->second;
  };
  // Rated torque: the shortest L10 at the rated speed equals the rated life.
  // From `near`'s torque with a small first step (kNearRatingStep) when that rating is known.
  auto start = [&](const std::optional<double>& known, double otherwise) {
    return known && *known > 0 ? std::pair{*known, kNearRatingStep} : std::pair{otherwise, 2.0};
  };
  const auto [rated_start, rated_step] =
      start(near ? std::optional<double>(near->rated_torque_Nm) : std::nullopt, start_torque_Nm);
  r.rated_torque_Nm = SolveTorqueForRatio([&](double t) { return eval(t).shortest_L10h / in.rated_life_h; },
                                          rated_start, "the rated life", rated_step);
  r.rated_by = eval(r.rated_torque_Nm).shortest;
  r.rated_L10h = eval(r.rated_torque_Nm).shortest_L10h;
  // Peak (acceleration) torque: the contact limits, on the sampled maxima or (`vertex`) on their
  // parabolic vertices.
  auto peak = [&](double t, bool vertex = false) {
    const RatingPoint& p = eval(t);
    Capacity c;
    if (limits.contact_stress_MPa)
      c.Add(*limits.contact_stress_MPa, vertex ? p.max_contact_stress_vertex_MPa : p.max_contact_stress_MPa,
            "limits.contact_stress_MPa");
    if (limits.roller_load_N)
      c.Add(*limits.roller_load_N, vertex ? p.max_roller_load_vertex_N : p.max_roller_load_N, "limits.roller_load_N");
    return c;
  };
  if (limits.contact_stress_MPa || limits.roller_load_N) {
    const auto [peak_start, peak_step] = start(near ? near->peak_torque_Nm : std::nullopt, r.rated_torque_Nm);
    r.peak_torque_Nm = SolveTorqueForRatio([&](double t) { return peak(t).ratio; }, peak_start,
                                           "the peak torque's limits", peak_step);
    r.peak_by = peak(*r.peak_torque_Nm).by;
    // The sampled maxima lie below the true ones by up to the parabola's rise between samples: the
    // peak torque solved again on the vertex maxima gives the sampling's share of its error.
    const RatingPoint& at_peak = eval(*r.peak_torque_Nm);
    if (at_peak.max_contact_stress_vertex_MPa > 0 || at_peak.max_roller_load_vertex_N > 0) {
      r.peak_sampling_error_Nm = std::abs(
          *r.peak_torque_Nm - SolveTorqueForRatio([&](double t) { return peak(t, true).ratio; }, *r.peak_torque_Nm,
                                                  "the peak torque's limits between samples", kNearRatingStep));
    }
  } else {
    r.peak_note = "not computed: no limits.contact_stress_MPa or limits.roller_load_N";
  }
  // Momentary torque: every rated bearing keeps s0 = C0 / P0max >= momentary_static_safety.
  auto momentary = [&](double t) {
    Capacity c;
    for (const RatedStatic& b : eval(t).statics)
      c.Add(b.static_rating_N, in.momentary_static_safety * b.max_load_N, b.name + " (static rating)");
    return c;
  };
  bool any_static = false;
  for (const RatedStatic& b : eval(r.rated_torque_Nm).statics) any_static = any_static || b.static_rating_N > 0;
  if (any_static) {
    const auto [momentary_start, momentary_step] =
        start(near ? near->momentary_torque_Nm : std::nullopt, r.rated_torque_Nm);
    r.momentary_torque_Nm = SolveTorqueForRatio([&](double t) { return momentary(t).ratio; }, momentary_start,
                                                "the bearings' static ratings", momentary_step);
    r.momentary_by = momentary(*r.momentary_torque_Nm).by;
    if (in.momentary_peaks)
      r.momentary_peaks_allowed =
          AllowedMomentaryPeakCount(in.momentary_peaks->output_speed_rpm, in.momentary_peaks->duration_s, ratio);
  } else {
    r.momentary_note = "not computed: no rated bearing has a static rating (static_rating_N)";
  }
  return r;
}

void SolveAllowableSpeed(const std::function<double(double, double)>& loss_W, const HousingCooling& cooling,
                         double limit_C, double ratio, double guess_input_rpm, RatingsResult& g) {
  const double heat_path_W = cooling.conductance_W_per_K() * (limit_C - cooling.ambient_C);
  if (!(heat_path_W > 0)) {
    g.allowable_speed_note = "not computed: the oil's limit is not above the ambient (no heat path)";
    return;
  }
  int evaluations = 0;
  try {
    const double n_in = ThermalSpeedLimit(
        [&](double n) {
          ++evaluations;
          const double w = loss_W(n, limit_C);
          if (!std::isfinite(w) || w < 0)
            throw std::invalid_argument("the loss at " + Format(n, 6) + " rpm is not a finite number >= 0");
          return w;
        },
        heat_path_W, guess_input_rpm);
    g.allowable_output_speed_rpm = n_in / ratio;
    g.allowable_speed_note = "the output speed at which the housing's balance at the rated torque puts the oil at "
                             "lubricant.thermal.max_oil_temperature_C (" + Format(limit_C, 6) + " °C; heat path " +
                             Format(heat_path_W, 6) + " W); " + std::to_string(evaluations) +
                             " loss evaluations (docs/ratings.md)";
  } catch (const std::invalid_argument& e) {
    g.allowable_speed_note = std::string("not computed: ") + e.what();
  }
}

SizedRatingsBlock SizedRatingsOf(const SizingRatingsInput& in, double ratio, double shortest_L10h, bool met,
                                 const std::optional<double>& rated_torque_Nm, const std::string& rated_by,
                                 const std::string& rated_torque_note) {
  SizedRatingsBlock j;
  j.rated_torque_required_Nm = in.rated_torque_Nm;
  j.rated_life_h = in.rated_life_h;
  j.rated_output_speed_rpm = in.rated_output_speed_rpm;
  j.rated_input_speed_rpm = in.rated_output_speed_rpm * std::abs(ratio);
  j.L10h_at_required_torque = shortest_L10h;
  j.met = met;
  j.rated_torque_Nm = rated_torque_Nm;
  if (rated_torque_Nm) j.rated_by = rated_by;
  else j.rated_torque_note = rated_torque_note;
  j.definition = "the sized design reaches the rated torque when every rated bearing's L10 at it and the rated "
                 "output speed is at least rated_life_h (limits.life_h of the sizing, over that one line; "
                 "docs/ratings.md, Ratings as sizing limits)";
  return j;
}

void SizedRatingsBlock::SetMomentary(double required_Nm, double static_safety, double s0_at_required,
                                     const std::optional<double>& own_Nm, std::optional<std::string> by,
                                     std::optional<std::string> note, bool met_) {
  momentary_torque_required_Nm = required_Nm;
  momentary_static_safety = static_safety;
  s0_at_required_momentary_torque = s0_at_required;
  momentary_torque_Nm = own_Nm ? *own_Nm : std::numeric_limits<double>::quiet_NaN();
  momentary_by = std::move(by);
  momentary_torque_note = std::move(note);
  momentary_met = met_;
}

void RatingsKeys::Set(const RatingsInput& in, const std::optional<RatingsResult>& g, const std::string& failed,
                      double ratio, bool estimate_error) {
  const auto or_nan = [](const std::optional<double>& x) { return x ? *x : NAN; };
  if (!g) {
    rated_torque_Nm = peak_torque_Nm = momentary_torque_Nm = NAN;
    ratings = StageError{failed};
    return;
  }
  rated_torque_Nm = g->rated_torque_Nm;
  peak_torque_Nm = or_nan(g->peak_torque_Nm);
  momentary_torque_Nm = or_nan(g->momentary_torque_Nm);
  RatingsDetails d;
  d.rated_life_h = in.rated_life_h;
  d.rated_output_speed_rpm = in.rated_output_speed_rpm;
  d.rated_input_speed_rpm = in.rated_output_speed_rpm * ratio;
  d.rated_by = g->rated_by;
  d.L10h_at_rated_torque = g->rated_L10h;
  d.peak_limited_by = g->peak_torque_Nm ? g->peak_by : g->peak_note;
  d.momentary_static_safety = in.momentary_static_safety;
  d.momentary_limited_by = g->momentary_torque_Nm ? g->momentary_by : g->momentary_note;
  d.momentary_peaks_allowed = or_nan(g->momentary_peaks_allowed);
  d.allowable_output_speed_rpm = or_nan(g->allowable_output_speed_rpm);
  d.allowable_output_speed = g->allowable_speed_note;
  d.evaluations = g->evaluations;
  if (estimate_error)
    d.estimated_error = RatingsDetails::EstimatedError{
        or_nan(g->rated_error_Nm), or_nan(g->peak_error_Nm), or_nan(g->momentary_error_Nm),
        !g->error_method.empty() ? g->error_method
        : g->error_crank_estimated
            ? "the ratings on the refined crank angles (the study's and the half-step-shifted): |refined - the "
              "study's angles| + |the study's angles - coarser grid|, each rating solved again, + the search's "
              "bracket (1e-6 of the torque)"
            : "|fine - coarser grid|, each rating solved again (the angles' part not estimated), + the search's "
              "bracket (1e-6 of the torque)"};
  d.definitions =
      "rated torque: the output torque at which the rated bearings' shortest L10 at the rated output speed equals "
      "the rated life (one analysis per trial torque, solved, not scaled); peak torque: the largest torque within "
      "limits.contact_stress_MPa and limits.roller_load_N; momentary torque: the largest torque at which every "
      "rated bearing keeps s0 = C0/P0max >= momentary_static_safety; momentary peaks allowed: 1e4 / (2 (n R / 60) "
      "t), n the output speed at the peak, R the ratio, t its duration: the strain-wave catalogues' count of input "
      "revolutions under peak torque (docs/ratings.md)";
  if (in.momentary_peaks)
    d.momentary_peak = RatingsDetails::MomentaryPeak{in.momentary_peaks->output_speed_rpm, in.momentary_peaks->duration_s};
  ratings = d;
}

DatasheetSection StiffnessDatasheetSection() {
  return {"Torsional stiffness and lost motion (input held)",
          {{"T1", "/stiffness_segments/T1_Nm", "N·m"},
           {"T2", "/stiffness_segments/T2_Nm", "N·m"},
           {"K1 (0–T1)", "/stiffness_segments/K1_Nm_per_arcmin", "N·m/arcmin"},
           {"K2 (T1–T2)", "/stiffness_segments/K2_Nm_per_arcmin", "N·m/arcmin"},
           {"K3 (T2–rated)", "/stiffness_segments/K3_Nm_per_arcmin", "N·m/arcmin"},
           {"torsional stiffness (50–100% of rated)", "/torsional_stiffness_Nm_per_arcmin", "N·m/arcmin"},
           {"lost motion (±3% of rated)", "/lost_motion_arcmin", "arcmin"},
           {"lost motion at ± stiffness.lost_motion_percent", "/stiffness/lost_motion_at_percent_arcmin", "arcmin"},
           {"backlash", "/backlash_arcmin", "arcmin"},
           {"hysteresis loss", "/stiffness/hysteresis_width_arcmin", "arcmin"}}};
}

std::vector<Headline> RatingsHeadlines() {
  return {
      {"rated torque (rated life at rated speed)", "/rated_torque_Nm", "N m", "", NAN, true,
       "/ratings/estimated_error/rated_torque_Nm"},
      {"peak torque (contact limits)", "/peak_torque_Nm", "N m", "", NAN, true, "/ratings/estimated_error/peak_torque_Nm"},
      {"momentary torque (static ratings)", "/momentary_torque_Nm", "N m", "", NAN, true,
       "/ratings/estimated_error/momentary_torque_Nm"},
      {"allowable output speed (thermal, rated torque)", "/ratings/allowable_output_speed_rpm", "rpm"},
      {"output bearing life L10h", "/output_bearing/L10h", "h"},
      {"output bearing static safety f_s", "/output_bearing/static_safety", ""},
  };
}

std::vector<DatasheetSection> RatingsDatasheetSections() {
  return {{"Ratings",
           {{"rated torque", "/rated_torque_Nm", "N·m", 1.0, "/ratings/error"},
            {"rated torque, estimated discretisation error", "/ratings/estimated_error/rated_torque_Nm", "N·m"},
            {"rated output speed", "/ratings/rated_output_speed_rpm", "rpm"},
            {"rated life L10", "/ratings/rated_life_h", "h"},
            {"rated torque limited by", "/ratings/rated_by", ""},
            {"peak (acceleration) torque", "/peak_torque_Nm", "N·m", 1.0, "/ratings/peak_limited_by"},
            {"peak torque, estimated discretisation error", "/ratings/estimated_error/peak_torque_Nm", "N·m"},
            {"peak torque limited by", "/ratings/peak_limited_by", ""},
            {"momentary (emergency-stop) torque", "/momentary_torque_Nm", "N·m", 1.0, "/ratings/momentary_limited_by"},
            {"momentary torque, estimated discretisation error", "/ratings/estimated_error/momentary_torque_Nm", "N·m"},
            {"momentary torque limited by", "/ratings/momentary_limited_by", ""},
            {"momentary peaks allowed", "/ratings/momentary_peaks_allowed", ""},
            {"allowable output speed", "/ratings/allowable_output_speed_rpm", "rpm", 1.0,
             "/ratings/allowable_output_speed"}}},
          {"Output bearing",
           {{"type", "/output_bearing/type", ""},
            {"equivalent dynamic load P_C", "/output_bearing/P_C_N", "N"},
            {"L10", "/output_bearing/L10h", "h"},
            {"oscillating-motion life", "/output_bearing/L_OC_h", "h"},
            {"static equivalent load P_0", "/output_bearing/P0_N", "N"},
            {"static safety f_s", "/output_bearing/static_safety", ""},
            {"tilt under the largest moment", "/output_bearing/tilt_arcmin", "arcmin"}}}};
}

}  // namespace camopt::studies
