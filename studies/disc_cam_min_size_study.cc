#include "studies/disc_cam_min_size_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <tuple>

#include "studies/format.h"
#include "studies/kind.h"
#include "studies/report.h"
#include "studies/verification_json.h"
#include "studies/work_limits.h"
#include "studies/writers.h"
#include "studies/archive.h"

namespace camopt::studies::disc_cam_min_size {
namespace {

namespace dc = camopt::disc_cam;
using sizing::DiscCamSizingVariable;
constexpr double kDeg = kPi / 180.0;

// The unit of a limit key, for the costs ("mm per deg").
std::string LimitUnit(const std::string& key) {
  if (key == "pressure_angle_deg") return "deg";
  if (key == "contact_stress_MPa") return "MPa";
  return "mm";
}

double LimitValue(const Study& s, const sizing::DiscCamMinSizeOutcome& o, const std::string& key) {
  if (key == "pressure_angle_deg") return s.spec.limits.pressure_angle_deg;
  if (key == "contact_stress_MPa") return s.spec.limits.contact_stress_MPa;
  return sizing::RadiusMarginOf(s.spec, o.cam);
}

std::string DesignWords(const Study& s, const sizing::DiscCamMinSizeOutcome& o) {
  std::string w = "base circle " + Format(o.cam.base_radius, 6) + " mm";
  for (size_t k = 1; k < s.spec.which.size(); ++k)
    w += ", " + sizing::DiscCamSizingVariableName(s.spec.which[k]) + " " + Format(o.x[k], 6);
  return w;
}

// Why the answer is not what was asked (exit 3), or "" when it is: the limit that blocks, its
// accurate value at the closest design, and what would help.
std::string BlockingMessage(const Study& s, const sizing::DiscCamMinSizeOutcome& o) {
  if (o.x.empty())
    return "no design meets the limits: the optimizer ended without a design (" +
           (o.result.message.empty() ? std::string(optimizers::ToString(o.result.status)) : o.result.message) +
           "); widen the variables' ranges or relax the limits";
  if (o.verified && o.converged) return "";
  // The check that breaks its limit by the largest share of the limit.
  const objectives::VerifiedLimit* w = nullptr;
  double share = 0;
  for (const objectives::VerifiedLimit& c : o.check.checks) {
    const double miss = !std::isfinite(c.accurate_value) ? kInf
                        : c.upper                        ? c.accurate_value - c.limit_value
                                                         : c.limit_value - c.accurate_value;
    if (!(miss > 0)) continue;
    const double part = miss / std::max(std::abs(c.limit_value), 1e-9);
    if (!w || part > share) w = &c, share = part;
  }
  const std::string at = "at the closest design (" + DesignWords(s, o) + ")";
  if (w) {
    const std::string head = o.converged ? "the optimum of the sampled angles is not verified after " +
                                               std::to_string(o.rounds) + " tightening rounds: "
                                         : "no design in the variables' ranges meets the limits (optimizer status " +
                                               std::string(optimizers::ToString(o.result.status)) + "): ";
    return head + w->limit + " (" + w->where + ") blocks; " + at + " it is " + Format(w->accurate_value, 6) +
           " against the limit " + Format(w->limit_value, 6) +
           (w->upper ? "; widen the ranges (a larger base circle, another offset or roller) or raise the limit"
                     : "; widen the ranges or lower the margin");
  }
  return "the optimizer ended with status " + std::string(optimizers::ToString(o.result.status)) + " " + at +
         " although the accurate model meets every limit there: it is not known to be the smallest (" +
         o.result.message + "); give more optimizer.max_evaluations";
}

Result::Cycle CycleOf(const sizing::DiscCamCycleValues& v) {
  Result::Cycle c;
  c.pressure_angle_deg.max_rise = v.max_pressure_rise_deg;
  c.pressure_angle_deg.at_max_rise_cam_angle_deg = v.at_rise_deg;
  if (v.has_return) {
    c.pressure_angle_deg.max_return = v.max_pressure_return_deg;
    c.pressure_angle_deg.at_max_return_cam_angle_deg = v.at_return_deg;
  }
  c.min_radius_of_curvature_mm = v.min_radius_of_curvature_mm;  // null: +inf, no convex part
  c.at_min_radius_of_curvature_cam_angle_deg = v.at_curvature_deg;
  c.max_radial_dimension_mm = v.max_radial_dimension_mm;
  if (v.stress_evaluated) {
    c.max_contact_stress_MPa = v.max_contact_stress_MPa;
    c.at_max_contact_stress_cam_angle_deg = v.at_stress_deg;
  }
  return c;
}

// result.json's members (Result's Serialize) from the sizing's outcome.
void FillResult(const Study& s, Result& r) {
  const sizing::DiscCamMinSizeOutcome& o = r.outcome;
  r.name = s.name;
  r.follower = s.base.in.follower.type;
  for (const objectives::Variable& v : s.spec.variables) r.variables.push_back({v.name, v.lower, v.upper, v.initial});
  if (s.base.limits.pressure_angle_default) r.limits.defaults.push_back("pressure_angle_deg");
  if (s.base.limits.radius_margin_default) r.limits.defaults.push_back("radius_margin_mm");
  r.limits.pressure_angle_deg = s.spec.limits.pressure_angle_deg;
  if (s.spec.limits.radius_margin_is_roller) {
    r.limits.radius_margin_mm = o.x.empty() ? s.spec.cam.roller_radius : o.cam.roller_radius;
    r.limits.radius_margin_follows = "roller_radius_mm";
  } else {
    r.limits.radius_margin_mm = s.spec.limits.radius_margin_mm;
  }
  if (std::isfinite(s.spec.limits.contact_stress_MPa)) r.limits.contact_stress_MPa = s.spec.limits.contact_stress_MPa;
  r.verification = VerificationBlock::Of(o.verification);
  // Verified: the accurate values themselves within the limits (RunStudy writes it again from the
  // status, studies/status.h: feasible_verified when the optimizer did not converge).
  r.verified = o.verified;
  if (!o.x.empty()) {
    Result::Best& b = r.best.emplace();
    b.base_circle_radius_mm = o.cam.base_radius;
    if (s.spec.cam.follower == dc::FollowerType::kOscillatingRoller) {
      b.pivot_distance_mm = o.cam.pivot_distance;
      b.arm_length_mm = o.cam.arm_length;
    } else if (!s.spec.flat_face) {
      b.offset_mm = o.cam.offset;
    }
    if (!s.spec.flat_face) {
      b.roller_radius_mm = o.cam.roller_radius;
      b.prime_circle_radius_mm = o.cam.base_radius + o.cam.roller_radius;
    }
    for (size_t k = 0; k < s.spec.variables.size(); ++k) {
      const objectives::Variable& v = s.spec.variables[k];
      const double tol = 1e-6 * std::max(1.0, v.upper - v.lower);
      if (v.upper > v.lower && o.x[k] <= v.lower + tol)
        b.variables_at_bounds.push_back({v.name, "lower", v.lower});
      else if (v.upper > v.lower && o.x[k] >= v.upper - tol)
        b.variables_at_bounds.push_back({v.name, "upper", v.upper});
    }
    b.accurate = CycleOf(o.check.accurate);
    b.fast = CycleOf(o.check.fast);
    // The accurate values' own error estimate, and the fast (sampled) model's error: accurate − fast.
    const sizing::DiscCamCycleValues &a = o.check.accurate, &d = o.check.dense, &f = o.check.fast;
    Result::CycleError &err = b.estimated_error, &fast_err = b.fast_model_error;
    err.pressure_angle_rise_deg = a.max_pressure_rise_deg - d.max_pressure_rise_deg;
    fast_err.pressure_angle_rise_deg = a.max_pressure_rise_deg - f.max_pressure_rise_deg;
    if (a.has_return) {
      err.pressure_angle_return_deg = a.max_pressure_return_deg - d.max_pressure_return_deg;
      fast_err.pressure_angle_return_deg = a.max_pressure_return_deg - f.max_pressure_return_deg;
    }
    err.min_radius_of_curvature_mm = d.min_radius_of_curvature_mm - a.min_radius_of_curvature_mm;
    fast_err.min_radius_of_curvature_mm = a.min_radius_of_curvature_mm - f.min_radius_of_curvature_mm;
    if (a.stress_evaluated) {
      err.max_contact_stress_MPa = a.max_contact_stress_MPa - d.max_contact_stress_MPa;
      fast_err.max_contact_stress_MPa = a.max_contact_stress_MPa - f.max_contact_stress_MPa;
    }
    b.accurate_model = o.check.model;
  }
  r.binding = o.binding;
  for (const auto& [key, cost] : o.limit_cost) {
    // The cost is itself the re-solve slope here: the same number, with its sides.
    r.binding_limits.push_back({key, LimitValue(s, o, key), cost, "mm of base circle per " + LimitUnit(key),
                                MakeLimitSlopeResult(o.limit_slope.count(key) ? &o.limit_slope.at(key) : nullptr)});
  }
  Result::Optimizer& opt = r.optimizer;
  for (const optimizers::SolverResult& st : o.starts)
    opt.start_outcomes.push_back({optimizers::ToString(st.status),
                                  st.x.empty() ? std::nullopt : std::optional<double>(st.objective), st.max_violation,
                                  st.first_order_residual});
  opt.Set(s.backend, o.converged, o.result, s.options.solver.max_evaluations, s.options.verify_rounds,
          o.result.value_evaluations, o.result.gradient_evaluations);
  opt.max_violation = o.result.max_violation;
  opt.binding_rows = o.result.active;
  opt.rounds = o.rounds;
  r.analysis = {s.spec.angle_steps, s.spec.accurate_factor, s.spec.angle_steps * s.spec.accurate_factor};
  if (!r.blocking_message.empty()) r.notes = std::vector<std::string>{r.blocking_message};
}

}  // namespace

// The checks that span fields (the design by disc_cam::Parse, the follower's type, the ranges'
// order) and the sizing problem.
nlohmann::ordered_json Input::SchemaRules() {
  using oj = nlohmann::ordered_json;
  auto not_sized = [](const std::vector<std::string>& fields) {
    oj refused = oj::array();
    for (const std::string& f : fields) refused.push_back(disc_cam::Refuse(f));
    return oj{{"properties", {{"variables", {{"allOf", refused}}}}}};
  };
  // The follower's own variables: an offset (translating roller or knife edge), pivot and arm
  // (oscillating), a roller's radius (a roller); a translating flat face the base circle only.
  oj all = disc_cam::DesignSchemaRules();
  all.push_back({{"if", disc_cam::FollowerTypeIs(
                             {"oscillating_roller", "oscillating_knife_edge", "oscillating_flat_faced"})},
                 {"then", not_sized({"offset_mm"})},
                 {"else", not_sized({"pivot_distance_mm", "arm_length_mm"})}});
  all.push_back({{"if", disc_cam::FollowerTypeIs({"translating_knife_edge", "oscillating_knife_edge",
                                                  "translating_flat_faced", "oscillating_flat_faced"})},
                 {"then", not_sized({"roller_radius_mm"})}});
  all.push_back({{"if", disc_cam::FollowerTypeIs({"translating_flat_faced"})}, {"then", not_sized({"offset_mm"})}});
  return {{"allOf", all}};
}

Study Parse(const Node& root) {
  const Input in = Read<Input>(root);
  Study s;
  // The disc_cam part, read by the disc_cam parser (same paths: only the sizing's own fields are
  // taken out, and its analysis block, which is the sizing's).
  s.base_json = root.json();
  for (const char* k : {"variables", "optimizer", "analysis"}) s.base_json.erase(k);
  s.base_json["study"] = "disc_cam";
  {
    nlohmann::json checked = s.base_json;
    checked["analysis"] = {{"monte_carlo", false}};
    s.base = disc_cam::Parse(Node(&checked, root.file(), root.path()));
  }
  s.name = in.design.name;
  const dc::DiscCam& cam = s.base.cam;
  const bool flat = s.base.contact == disc_cam::Study::Contact::kFlatFaced;
  if (flat && s.base.cam.follower == dc::FollowerType::kOscillatingRoller)
    root["follower"]["type"].FailWith(
        "disc_cam_min_size sizes a roller or knife-edge follower (translating: variables base_circle_radius_mm, "
        "offset_mm, roller_radius_mm; oscillating: base_circle_radius_mm, pivot_distance_mm, arm_length_mm, "
        "roller_radius_mm; a knife edge without roller_radius_mm) or a translating flat face (base_circle_radius_mm "
        "only); oscillating flat-faced followers are not sized: use \"translating_flat_faced\", a roller or a knife "
        "edge, or study \"disc_cam\" to analyse the design");
  // A translating flat face: its profile depends on the base circle alone (model/disc_cam/flat_faced.h).
  if (flat)
    for (const auto& [key, given] : {std::pair{"offset_mm", bool(in.variables.offset_mm)},
                                     std::pair{"roller_radius_mm", bool(in.variables.roller_radius_mm)}})
      if (given)
        root["variables"][key].FailWith(
            "not a variable of a translating flat-faced follower (its profile depends on the base circle alone): "
            "size base_circle_radius_mm only");
  // A knife edge is the roller model with r_f = 0 (its profile is the pitch curve): no roller to size.
  const bool knife = s.base.contact == disc_cam::Study::Contact::kKnifeEdge;
  if (knife && in.variables.roller_radius_mm)
    root["variables"]["roller_radius_mm"].FailWith(
        "not a variable of a knife-edge follower (it has no roller): remove it, or use a roller follower");
  const bool oscillating = cam.follower == dc::FollowerType::kOscillatingRoller;
  // The follower's own variables only: an offset for a translating, pivot and arm for an oscillating one.
  for (const auto& [key, given, other] :
       {std::tuple{"offset_mm", bool(in.variables.offset_mm), "pivot_distance_mm and arm_length_mm"},
        std::tuple{"pivot_distance_mm", bool(in.variables.pivot_distance_mm), "offset_mm"},
        std::tuple{"arm_length_mm", bool(in.variables.arm_length_mm), "offset_mm"}}) {
    const bool own = oscillating == (std::string(key) != "offset_mm");
    if (given && !own)
      root["variables"][key].FailWith(std::string("not a variable of ") +
                                      (oscillating ? "an oscillating" : "a translating") +
                                      " follower: its geometry is sized by " + other);
  }

  sizing::DiscCamSizingSpec& spec = s.spec;
  spec.cam = cam;
  const Node vars = root["variables"];
  struct Entry {
    const char* key;
    DiscCamSizingVariable which;
    double start;
    bool given;
  };
  const Entry entries[] = {{"base_circle_radius_mm", DiscCamSizingVariable::kBaseCircle, cam.base_radius, true},
                           {"offset_mm", DiscCamSizingVariable::kOffset, cam.offset, bool(in.variables.offset_mm)},
                           {"pivot_distance_mm", DiscCamSizingVariable::kPivotDistance, cam.pivot_distance,
                            bool(in.variables.pivot_distance_mm)},
                           {"arm_length_mm", DiscCamSizingVariable::kArmLength, cam.arm_length,
                            bool(in.variables.arm_length_mm)},
                           {"roller_radius_mm", DiscCamSizingVariable::kRollerRadius, cam.roller_radius,
                            bool(in.variables.roller_radius_mm)}};
  for (const Entry& e : entries) {
    if (!e.given) continue;
    const auto [lo, hi] = vars[e.key].Range();  // lower <= upper
    // On the cam's own scale, as every length of a study (PlausibleLength): a range end of 1e308 mm
    // ran for seconds before its non-finite result was refused.
    if (!(std::max(std::abs(lo), std::abs(hi)) <= 1e6 * cam.base_radius))
      vars[e.key].Fail("a range within ±" + Format(1e6 * cam.base_radius, 3) +
                       " mm (1e6 times the study's base circle radius, " + Format(cam.base_radius, 4) + " mm)");
    objectives::Variable v;
    v.name = e.key;
    v.lower = lo;
    v.upper = hi;
    v.initial = std::clamp(e.start, lo, hi);
    v.scale = std::max(1.0, std::max(std::abs(lo), std::abs(hi)) / 2);
    spec.which.push_back(e.which);
    spec.variables.push_back(v);
  }

  spec.limits.pressure_angle_deg = s.base.limits.pressure_angle_deg;
  spec.limits.radius_margin_is_roller = s.base.limits.radius_margin_default && !knife && !flat;
  spec.flat_face = flat;
  spec.limits.radius_margin_mm = s.base.limits.radius_margin_mm;
  if (s.base.limits.contact_stress_MPa) spec.limits.contact_stress_MPa = *s.base.limits.contact_stress_MPa;
  if ((s.base.dynamics || s.base.arm_dynamics) && s.base.face_width_mm && s.base.material) {
    // The translating follower's loads, or an oscillating follower's arm loads (disc_cam::Parse
    // takes each for its follower only).
    sizing::DiscCamStressModel m;
    if (s.base.dynamics) {
      m.loads = s.base.dynamics->loads;
      m.omega_rad_per_s = dc::RadPerSecond(s.base.dynamics->speed_rpm);
    } else {
      m.arm = s.base.arm_dynamics->loads;
      m.omega_rad_per_s = dc::RadPerSecond(s.base.arm_dynamics->speed_rpm);
    }
    m.face_width_mm = *s.base.face_width_mm;
    m.composite_modulus_MPa = s.base.material->composite_modulus_MPa();
    spec.stress = m;
  }

  spec.angle_steps = in.analysis.angle_steps;
  spec.accurate_factor = in.analysis.accurate_factor;
  optimizers::SolverOptions& so = s.options.solver;
  s.backend = optimizers::ToString(ToBackend(in.optimizer.backend));
  so.max_evaluations = in.optimizer.max_evaluations;
  s.options.verify_rounds = in.optimizer.verify_rounds;
  so.backend = ToBackend(s.backend);
  // The rows are smooth (closed forms over the angle samples): tight tolerances, and the budget,
  // never the clock, bounds a run (the same study gives the same design).
  so.tolerance = 1e-10;
  so.constraint_tolerance = 1e-7;
  so.max_seconds = 1e9;
  return s;
}

Result Run(const Study& s, const RunContext& ctx) {
  Result r;
  Progress progress("disc_cam_min_size", ctx.quiet);
  progress.Update(0.0, "solving");
  r.outcome = sizing::SolveDiscCamMinSize(s.spec, s.options);
  progress.Update(1.0);
  progress.Done();
  r.blocking_message = BlockingMessage(s, r.outcome);
  FillResult(s, r);
  return r;
}

namespace {

// A design of this sizing as a complete disc_cam study: the study's own fields, the sized ones
// (base circle, offset or pivot and arm, roller radius) the design's, on the accurate grid.
nlohmann::json DiscCamStudyOf(const Study& s, const dc::DiscCam& cam, const std::string& name) {
  nlohmann::json a = s.base_json;
  a["name"] = name;
  a["base_circle_radius_mm"] = cam.base_radius;
  if (s.spec.cam.follower == dc::FollowerType::kOscillatingRoller) {
    a["follower"]["pivot_distance_mm"] = cam.pivot_distance;
    a["follower"]["arm_length_mm"] = cam.arm_length;
  } else if (!s.spec.flat_face) {
    a["follower"]["offset_mm"] = cam.offset;
  }
  if (s.base.contact == disc_cam::Study::Contact::kRoller) a["follower"]["roller_radius_mm"] = cam.roller_radius;
  // Fields the sized design may no longer take (the cutter no larger than the roller, the bore
  // inside the base circle) are left out.
  if (a.contains("cutter_radius_mm") && a["cutter_radius_mm"].is_number() &&
      a["cutter_radius_mm"].get<double>() > cam.roller_radius)
    a.erase("cutter_radius_mm");
  if (a.contains("bore_diameter_mm") && a["bore_diameter_mm"].is_number() &&
      a["bore_diameter_mm"].get<double>() >= 2 * cam.base_radius)
    a.erase("bore_diameter_mm");
  a["analysis"] = {{"angle_steps", std::min(1000000, s.spec.angle_steps * s.spec.accurate_factor)}, {"monte_carlo", false}};
  return a;
}

}  // namespace

nlohmann::json BestDiscCamStudy(const Study& s, const Result& r) {
  const sizing::DiscCamMinSizeOutcome& o = r.outcome;
  if (o.x.empty()) return nullptr;
  return DiscCamStudyOf(s, o.cam, (o.verified && o.converged ? "best of "
                               : o.verified   ? "verified design (not proven the smallest) of "
                                              : "closest design (not verified) of ") + s.name);
}

nlohmann::json StartDiscCamStudy(const Study& s) {
  std::vector<double> x;
  for (const objectives::Variable& v : s.spec.variables) x.push_back(v.initial);
  return DiscCamStudyOf(s, sizing::DiscCamDesign(s.spec, x), "start of " + s.name);
}

// profile.svg: the sized cam drawn over the start design (each variable's start), each with its
// base circle, in the cam's frame at θ = 0 — what the sizing changed, seen as a part.
void AddProfileDrawing(const Study& s, const sizing::DiscCamMinSizeOutcome& o, Outputs& out) {
  std::vector<double> x0;
  for (const objectives::Variable& v : s.spec.variables) x0.push_back(v.initial);
  const dc::DiscCam start = sizing::DiscCamDesign(s.spec, x0);
  const int n = 720;
  auto outline = [&](const dc::DiscCam& cam) {
    Polyline p;
    for (int i = 0; i < n; ++i) {
      const double th = 2 * kPi * i / n;
      const auto a = s.spec.flat_face ? dc::EvaluateFlatFaced(cam.motion, cam.base_radius, th).contact
                                              : dc::EvaluateCam(cam, th).contact;
      p.emplace_back(a.x(), a.y());
    }
    return p;
  };
  Drawing d;
  d.title = s.name + ": the sized cam over the start design";
  d.layers.push_back({"start design (base circle " + Format(start.base_radius, 5) + " mm)", "gray",
                      {outline(start)}, {{0, 0, start.base_radius}}, true, 1.0, "6,4"});
  d.layers.push_back({"sized cam (base circle " + Format(o.cam.base_radius, 5) + " mm)", "black",
                      {outline(o.cam)}, {{0, 0, o.cam.base_radius}}, true, 1.5});
  d.dimensions = {"base circle radius: start " + Format(start.base_radius, 5) + " mm, sized " +
                  Format(o.cam.base_radius, 5) + " mm"};
  out.Add("profile.svg", SvgDrawing(d));
}

void Write(const Study& s, const Result& r, Outputs& out) {
  out.SetResult(r);
  const sizing::DiscCamMinSizeOutcome& o = r.outcome;
  out.SetStatus(SizingStatus(!o.x.empty(), o.verification.ran, o.verified, o.converged), r.blocking_message);
  if (o.x.empty()) return;
  out.AddJson("best_disc_cam.json", BestDiscCamStudy(s, r));
  AddProfileDrawing(s, o, out);
  // The best design over the accurate grid: pressure angle and the profile's radius of curvature.
  const int n = s.spec.angle_steps * s.spec.accurate_factor;
  const size_t m = static_cast<size_t>(n);
  if (s.spec.flat_face) {
    // The translating flat face: its profile's radius of curvature ρ = r_b + S + S'' against the margin.
    std::vector<double> th(m), rho(m), s_mm(m);
    for (int i = 0; i < n; ++i) {
      const dc::FlatFacePoint<double> p = dc::EvaluateFlatFaced(o.cam.motion, o.cam.base_radius, 2 * kPi * i / n);
      th[size_t(i)] = 360.0 * i / n;
      rho[size_t(i)] = p.radius_of_curvature;
      s_mm[size_t(i)] = p.s;
    }
    Table t;
    t.Add("cam_angle_deg", th);
    t.Add("follower_mm", s_mm);
    t.Add("radius_of_curvature_mm", rho);
    out.Add("series.csv", ToCsv(t));
    PlotOptions po;
    po.title = s.name + ": radius of curvature r_b + S + S'' of the smallest cam (base circle " +
               Format(o.cam.base_radius, 5) + " mm)";
    po.x_label = "cam angle [deg]";
    po.y_label = "radius of curvature [mm]";
    po.guides = {{"margin", sizing::RadiusMarginOf(s.spec, o.cam)}};
    out.Add("radius_of_curvature.svg", SvgLinePlot({{"ρ", th, rho}}, po));
    return;
  }
  const bool oscillating = s.spec.cam.follower == dc::FollowerType::kOscillatingRoller;
  std::vector<double> th(m), phi(m), kappa(m), s_mm(m);
  for (int i = 0; i < n; ++i) {
    const dc::CamPoint<double> p = dc::EvaluateCam(o.cam, 2 * kPi * i / n);
    th[size_t(i)] = 360.0 * i / n;
    phi[size_t(i)] = p.pressure_angle / kDeg;
    kappa[size_t(i)] = p.pitch_curvature;
    s_mm[size_t(i)] = oscillating ? p.s / kDeg : p.s;
  }
  Table t;
  t.Add("cam_angle_deg", th);
  t.Add(oscillating ? "follower_deg" : "follower_mm", s_mm);
  t.Add("pressure_angle_deg", phi);
  t.Add("pitch_curvature_per_mm", kappa);
  out.Add("series.csv", ToCsv(t));
  PlotOptions po;
  po.title = s.name + ": pressure angle of the smallest cam (base circle " + Format(o.cam.base_radius, 5) + " mm)";
  po.x_label = "cam angle [deg]";
  po.y_label = "pressure angle [deg]";
  po.guides = {{"limit", s.spec.limits.pressure_angle_deg}, {"−limit", -s.spec.limits.pressure_angle_deg}};
  out.Add("pressure_angle.svg", SvgLinePlot({{"pressure angle φ", th, phi}}, po));
}

namespace {

std::string Summary(const Study& s, const Result& r) {
  const sizing::DiscCamMinSizeOutcome& o = r.outcome;
  std::ostringstream m;
  char buf[300];
  if (!o.x.empty() && s.spec.cam.follower == dc::FollowerType::kOscillatingRoller) {
    std::snprintf(buf, sizeof buf,
                  "disc_cam_min_size: %s base circle %.6g mm (pivot distance %.6g mm, arm %.6g mm, roller %.6g mm)\n",
                  o.verified && o.converged ? "smallest" : o.verified ? "verified (not proven the smallest)" : "closest (not verified)", o.cam.base_radius,
                  o.cam.pivot_distance, o.cam.arm_length, o.cam.roller_radius);
    m << buf;
  } else if (!o.x.empty()) {
    std::snprintf(buf, sizeof buf, "disc_cam_min_size: %s base circle %.6g mm (offset %.6g mm, roller %.6g mm)\n",
                  o.verified && o.converged ? "smallest" : o.verified ? "verified (not proven the smallest)" : "closest (not verified)", o.cam.base_radius, o.cam.offset,
                  o.cam.roller_radius);
    m << buf;
  }
  for (const auto& [key, cost] : o.limit_cost) {
    std::snprintf(buf, sizeof buf, "disc_cam_min_size: %s binds: %+.4g mm of base circle per %s\n", key.c_str(), cost,
                  LimitUnit(key).c_str());
    m << buf;
  }
  return m.str();
}

// Fidelity for `camopt run --convergence` (studies/convergence.h): the fast rows' angles (the
// accurate grid follows them) and the optimizer's budget. The verified answer should not move.

Fidelity Knobs(const nlohmann::json&) {
  const Input defaults;
  Fidelity f;
  f.knobs.push_back({"angle_steps", {"/analysis/angle_steps"}, defaults.analysis.angle_steps, 2, true, 0,
                     "cam angles of the fast rows (the accurate grid is accurate_factor times as fine)"});
  f.knobs.push_back({"max_evaluations", {"/optimizer/max_evaluations"}, defaults.optimizer.max_evaluations, 2, true, 0,
                     "optimizer budget per solve (Ipopt: iterations; SLSQP: evaluations)"});
  f.headlines = {"/best/base_circle_radius_mm", "/best/accurate/pressure_angle_deg/max_rise"};
  return f;
}

// The work limit (studies/work_limits.h): every solve (two starts, the tightening rounds, two
// re-solves per limit for its cost) may use its whole budget of iterations, each a few evaluations
// of every fast row (one cam point each); each accurate check evaluates the dense grid three times
// (fast, dense, refined).
WorkEstimate EstimateWork(const nlohmann::json& study, const std::string& file, double factor) {
  const Input in = Read<Input>(Node(&study, file, ""));
  const double steps = in.analysis.angle_steps, dense = steps * in.analysis.accurate_factor;
  const double budget = std::max(1, in.optimizer.max_evaluations), rounds = in.optimizer.verify_rounds;
  const double solves = 2 + rounds + 6;
  return LargestTerm({{budget * solves * 3 * steps, "/optimizer/max_evaluations",
                       WorkNumber(budget) + " iterations × " + WorkNumber(solves) + " solves × 3 evaluations × " +
                           WorkNumber(steps) + " angle steps"},
                      {(1 + rounds) * 3 * dense, "/analysis/accurate_factor",
                       WorkNumber(1 + rounds) + " accurate checks × 3 × " + WorkNumber(dense) + " cam angles"}},
                     1e8 * factor, "cam angle evaluations", 16);
}

// The studio's start design: the study's start as a disc_cam study.
nlohmann::json StartStudy(const Node& root, const nlohmann::json&) { return StartDiscCamStudy(Parse(root)); }

CAMOPT_REGISTER_KIND(Kind<Input, Result, Study>{
    .name = "disc_cam_min_size",
    .title = "camopt study: the smallest base circle of a disc cam with a translating or "
              "oscillating roller follower",
    .run = Run, .parse = Parse, .write = Write, .summary = Summary, .knobs = Knobs, .estimate = EstimateWork,
    .report = std::vector<Headline>{
        {"smallest base circle radius", "/best/base_circle_radius_mm", "mm"},
        // A sized offset within 1 nm of zero is the solver's zero (its KKT tolerance), not a design.
        {"offset", "/best/offset_mm", "mm", "", NAN, true, "", "", "", 1e-6},
        {"pivot distance", "/best/pivot_distance_mm", "mm"},
        {"arm length", "/best/arm_length_mm", "mm"},
        {"roller radius", "/best/roller_radius_mm", "mm"},
        {"largest pressure angle, rise (accurate)", "/best/accurate/pressure_angle_deg/max_rise", "deg",
         "/limits/pressure_angle_deg", NAN, true, "/best/estimated_error/pressure_angle_rise_deg"},
        {"largest pressure angle, return (accurate)", "/best/accurate/pressure_angle_deg/max_return", "deg",
         "/limits/pressure_angle_deg", NAN, true, "/best/estimated_error/pressure_angle_return_deg"},
        {"smallest convex radius of curvature (roller: ρ_pitch − r_roller; flat face: r_b + S + S'')", "/best/accurate/min_radius_of_curvature_mm", "mm",
         "/limits/radius_margin_mm", NAN, false, "/best/estimated_error/min_radius_of_curvature_mm"},
        {"largest contact stress (accurate)", "/best/accurate/max_contact_stress_MPa", "MPa", "/limits/contact_stress_MPa",
         NAN, true, "/best/estimated_error/max_contact_stress_MPa"},
        {"largest radial dimension", "/best/accurate/max_radial_dimension_mm", "mm"},
        {"verified", "/verified", ""},
    },
    .init_example = "disc_cam_min_size",
    .sizing_of = "disc_cam",
    .start_study = StartStudy});
}  // namespace

}  // namespace camopt::studies::disc_cam_min_size
