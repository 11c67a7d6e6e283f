#include "studies/lcr_crowning_tuning_study.h"
#include "studies/kind.h"
#include "studies/verification_json.h"

#include <algorithm>
#include <cmath>

#include "model/lcr/sliced_life.h"
#include "studies/format.h"
#include "studies/lcr_input.h"
#include "studies/material_input.h"
#include "studies/report.h"
#include "studies/work_limits.h"
#include "studies/writers.h"

namespace camopt::studies::lcr_crowning_tuning {

namespace {
// A contact's end pressure up to this share of its peak counts as off the ends (as in
// sizing/lcr_sizing3d.cc's verification).
constexpr double kEdgeShareLimit = 0.01;
}  // namespace

Study Parse(const Node& root) {
  // Every field's type and bounds; what spans fields follows.
  Study st;
  st.in = Read<Input>(root);
  const Input& in = st.in;
  auto& sp = st.spec;
  const Node reducer = root["reducer"];
  sp.reducer = ToReducer(in.reducer.Design(), reducer);
  sp.material = in.material.ToMaterial();
  const Node load = root["load"];
  sp.design_load.output_torque_Nmm = in.load.output_torque_Nm * 1000.0;
  sp.design_load.friction_coefficient = in.load.friction_coefficient;
  sp.overload_torque_Nmm = in.load.overload_torque_Nm * 1000.0;
  if (sp.overload_torque_Nmm < sp.design_load.output_torque_Nmm)
    load["overload_torque_Nm"].Fail("an overload torque >= output_torque_Nm");
  CheckCarriedTorque(sp.reducer, sp.material.youngs_modulus_MPa, sp.overload_torque_Nmm, load["overload_torque_Nm"]);
  const Input::Tuning& tuning = in.tuning;
  const Node t = root["tuning"];
  for (lcr::Side s : {lcr::Side::kInput, lcr::Side::kOutput}) {
    const int k = s == lcr::Side::kInput ? 0 : 1;
    sp.effective_length_mm[k] = tuning.effective_length_mm;
    if (!(sp.effective_length_mm[k] > sp.reducer.side(s).roller_length))
      t["effective_length_mm"].Fail("an effective length above the roller length (" +
                                    std::to_string(sp.reducer.side(s).roller_length) +
                                    " mm; Le <= l_r gives an unbounded drop at the roller's ends)");
  }
  const auto [lo, hi] = tuning.coefficient_range_mm;
  if (!(lo <= hi)) t["coefficient_range_mm"].Fail("[lower, upper] with lower <= upper");
  if (!(hi > lo)) t["coefficient_range_mm"].Fail("[lo, hi] with 0 < lo < hi");
  // Lundberg's f is micrometres to a few tenths of a millimetre: from 1e-9 to 1e6 times the
  // shortest roller (as the cycloid's crowning, cycloid::CheckCrowning); a denormal or 1e308 made
  // the slices' gaps infinite.
  const double shortest = std::min(sp.reducer.side(lcr::Side::kInput).roller_length,
                                   sp.reducer.side(lcr::Side::kOutput).roller_length);
  if (!(lo >= 1e-9 * shortest && hi <= 1e6 * shortest))
    t["coefficient_range_mm"].Fail("a range within [" + Format(1e-9 * shortest, 3) + ", " + Format(1e6 * shortest, 3) +
                                   "] mm (1e-9 to 1e6 times the shortest roller, " + Format(shortest, 4) + " mm)");
  sp.coefficient_range_mm = {lo, hi};
  sp.misalignments_rad.clear();
  for (double m : tuning.misalignment_mrad) sp.misalignments_rad.push_back(m * 1e-3);
  sp.curve_points = tuning.curve_points;
  sp.refine_iterations = tuning.refine_iterations;
  sp.angle_steps = tuning.angle_steps;
  sp.slices = tuning.slices;
  // The tuned design's lives (the tuning's objective stays the contact pressure).
  std::string why;
  if (auto lines = ParseDutyCycle(root, in.duty_cycle, sp.design_load.output_torque_Nmm, &why)) {
    LifeSpec life;
    life.lines = std::move(*lines);
    for (int k = 0; k < 2; ++k) {
      const LcrSideWithRatingsInput& side = k == 0 ? in.reducer.input : in.reducer.output;
      if (!side.dynamic_rating_N) {
        const Node n = reducer[k == 0 ? "input" : "output"];
        const std::string path = n.path() + "/dynamic_rating_N";
        const std::string expected = "the bearing's dynamic load rating C [N] > 0 (" + why + ")";
        throw StudyError(n.file() + ": " + path + ": expected " + expected + ", found nothing", n.file(), path,
                         expected, "nothing");
      }
      life.dynamic_rating_N[size_t(k)] = *side.dynamic_rating_N;
      life.static_rating_N[size_t(k)] = side.static_rating_N.value_or(0.0);
    }
    if (in.reducer.eccentric_bearing) {
      const EccentricBearingInput& eb = *in.reducer.eccentric_bearing;
      life.eccentric = EccentricBearingRating{eb.dynamic_rating_N, eb.static_rating_N.value_or(0.0), eb.kind == "ball"};
    }
    st.life = std::move(life);
  }
  return st;
}

namespace {
// The lives of the tuned design (docs/life.md, "Sliced roller life under tilt"): ISO 281 of each
// bearing over the duty cycle (rigid law, the tuning's angle steps), and each roller sliced with
// its tuned crowning at every misalignment of the tuning (the slices model's load per slice).
LifeResult TunedLives(const Study& st, const std::array<sizing::LcrCrowningSideResult, 2>& tuned) {
  const sizing::LcrCrowningTuningSpec& sp = st.spec;
  const LifeSpec& spec = *st.life;
  LifeResult out;
  for (int k = 0; k < 2; ++k)
    out.rollers[size_t(k)] = lcr::BearingLifeOverDutyCycle(
        sp.reducer, sp.material, sp.design_load, lcr::LoadModel::kRigid,
        k == 0 ? lcr::LcrBearing::kInputRoller : lcr::LcrBearing::kOutputRoller, spec.dynamic_rating_N[size_t(k)],
        BearingKind::kRoller, spec.lines, sp.angle_steps);
  if (spec.eccentric)
    out.eccentric = lcr::BearingLifeOverDutyCycle(sp.reducer, sp.material, sp.design_load, lcr::LoadModel::kRigid,
                                                  lcr::LcrBearing::kEccentric, spec.eccentric->dynamic_N,
                                                  spec.eccentric->ball ? BearingKind::kBall : BearingKind::kRoller,
                                                  spec.lines, sp.angle_steps);
  for (double gamma : sp.misalignments_rad) {
    std::array<SlicedLife, 2> at;
    for (int k = 0; k < 2; ++k) {
      const lcr::Side s = k == 0 ? lcr::Side::kInput : lcr::Side::kOutput;
      lcr::RollerCrowning<double> crown;
      crown.type = contact::CrowningType::kLogarithmic;
      crown.coefficient = tuned[size_t(k)].coefficient_mm;
      crown.effective_length = sp.effective_length_mm[size_t(k)];
      std::vector<SlicedDutyLine> lines;
      for (const lcr::LcrDutyLine& line : spec.lines) {
        lcr::LoadCase load = sp.design_load;
        load.output_torque_Nmm = line.output_torque_Nmm;
        lcr::RollerSliceSamples x = lcr::SampleRollerSliceLoads(sp.reducer, sp.material, load, lcr::LoadModel::kRigid, s,
                                                                sp.angle_steps, crown, gamma, sp.slices);
        lines.push_back({line.time_share, line.input_speed_rpm * x.revolutions_per_input_revolution,
                         std::move(x.loads), std::move(x.weights)});
      }
      at[size_t(k)] = SlicedRatingLifeHours(spec.dynamic_rating_N[size_t(k)], lines, BearingKind::kRoller);
    }
    out.sliced.push_back(at);
  }
  return out;
}
}  // namespace

namespace {

// The peaks of one check per misalignment (result.json's tuned/uncrowned slices and half_space).
std::vector<Result::CheckRow> CheckRows(const Study& st, const sizing::LcrCrowningCheck& c,
                                        const std::vector<double>& dy) {
  std::vector<Result::CheckRow> out;
  for (size_t g = 0; g < st.spec.misalignments_rad.size(); ++g) {
    Result::CheckRow j;
    j.misalignment_mrad = st.spec.misalignments_rad[g] * 1e3;
    j.design_max_contact_stress_MPa = c.design_MPa[g];
    j.design_edge_loaded = bool(c.design_edge[g]);
    j.overload_max_contact_stress_MPa = c.overload_MPa[g];
    j.overload_edge_loaded = bool(c.overload_edge[g]);
    if (g < dy.size()) j.cell_dy_mm = dy[g];
    out.push_back(j);
  }
  return out;
}

// result.json's members (Result's Serialize) from the model's numbers, in the file's units.
void FillResult(const Study& st, Result& res) {
  res.name = st.in.name;
  res.design_torque_Nm = st.spec.design_load.output_torque_Nmm / 1000;
  res.overload_torque_Nm = st.spec.overload_torque_Nmm / 1000;
  res.slices = st.spec.slices;
  res.angle_steps = st.spec.angle_steps;
  for (int k : {0, 1}) {
    const auto& r = res.tuned[k];
    Result::Side& c = k == 0 ? res.input : res.output;
    c.crowning.coefficient_mm = r.coefficient_mm;
    c.crowning.effective_length_mm = st.spec.effective_length_mm[k];
    c.feasible = r.feasible;
    c.evaluations = r.evaluations;
    c.tuned.slices = CheckRows(st, res.tuned_check[k].slices, {});
    c.uncrowned.slices = CheckRows(st, res.uncrowned_check[k].slices, {});
    if (st.in.tuning.half_space_check) {
      c.tuned.half_space = CheckRows(st, res.tuned_check[k].half_space, res.tuned_check[k].half_space_dy_mm);
      c.uncrowned.half_space =
          CheckRows(st, res.uncrowned_check[k].half_space, res.uncrowned_check[k].half_space_dy_mm);
      c.half_space_grid = st.in.tuning.grid;
    }
  }
  if (st.in.tuning.half_space_check) {
    res.verified = res.verification.verified();
    res.verification_block = VerificationBlock::Of(res.verification);
    // The verdict's one number: the largest edge-pressure share the accurate model finds on either
    // cam, misalignment and torque, against its limit (with that check's error estimate).
    const objectives::VerifiedLimit* worst = nullptr;
    for (const objectives::VerifiedLimit& c : res.verification.checks)
      if (!worst || c.accurate_value - c.limit_value > worst->accurate_value - worst->limit_value) worst = &c;
    if (worst) {
      res.max_edge_pressure_share = worst->accurate_value;
      res.max_edge_pressure_share_error = worst->estimated_error;
      res.max_edge_pressure_share_where = worst->limit + ", " + worst->where;
      res.edge_pressure_share_limit = worst->limit_value;
    }
  } else {
    res.verified = false;
    res.verification_block = VerificationBlock::NotRun("tuning.half_space_check is false: not verified");
  }
  if (res.life) {
    const LifeResult& l = *res.life;
    Result::Life& lj = res.life_block.emplace();
    const char* names[2] = {"input_roller", "output_roller"};
    double shortest = kInf;
    std::string shortest_name;
    auto row = [&](const std::string& element, const std::string& kind, const lcr::LcrBearingLife& b, double c,
                   double c0, double hours) {
      LifeTableRow e;
      e.element = element;
      e.kind = kind;
      e.equivalent_load_N = b.equivalent_load_N;
      e.max_load_N = b.max_load_N;
      e.revolutions_per_input_revolution = b.revolutions_per_input_revolution;
      e.dynamic_rating_N = c;
      e.L10h = hours;
      if (c0 > 0) e.static_rating_N = c0, e.s0 = b.max_load_N > 0 ? c0 / b.max_load_N : NAN;
      lj.table.push_back(e);
    };
    for (int k = 0; k < 2; ++k) {
      (k == 0 ? lj.input_roller_L10h : lj.output_roller_L10h) = l.rollers[size_t(k)].L10h;
      if (l.rollers[size_t(k)].L10h < shortest || shortest_name.empty())
        shortest = l.rollers[size_t(k)].L10h, shortest_name = names[k];
      row(names[k], "roller", l.rollers[size_t(k)], st.life->dynamic_rating_N[size_t(k)],
          st.life->static_rating_N[size_t(k)], l.rollers[size_t(k)].L10h);
    }
    if (l.eccentric) {
      lj.eccentric_bearing_L10h = l.eccentric->L10h;
      if (l.eccentric->L10h < shortest) shortest = l.eccentric->L10h, shortest_name = "eccentric_bearing";
      row("eccentric_bearing", st.life->eccentric->ball ? "ball" : "roller", *l.eccentric, st.life->eccentric->dynamic_N,
          st.life->eccentric->static_N, l.eccentric->L10h);
    }
    lj.shortest_L10h = shortest;
    lj.shortest_bearing = shortest_name;
    for (size_t g = 0; g < l.sliced.size(); ++g) {
      const double mrad = st.spec.misalignments_rad[g] * 1e3;
      Result::SlicedRow sj;
      sj.misalignment_mrad = mrad;
      for (int k = 0; k < 2; ++k) {
        const SlicedLife& sl = l.sliced[g][size_t(k)];
        (k == 0 ? sj.input_roller_sliced_L10h : sj.output_roller_sliced_L10h) = sl.L10h;
        row(std::string(names[k]) + "_sliced at " + Format(mrad) + " mrad", "roller, sliced (ISO/TS 16281)",
            l.rollers[size_t(k)], st.life->dynamic_rating_N[size_t(k)], st.life->static_rating_N[size_t(k)], sl.L10h);
      }
      lj.sliced.push_back(sj);
    }
    lj.duty_cycle = DutyCycleEchoOf(st.life->lines);
    lj.model = "lives of the tuned design (the tuning's objective is the contact pressure, not the life): ISO 281:2007 "
               "basic rating life of each bearing over the duty cycle (rigid load law, the tuning's angle steps), and "
               "each roller sliced with its tuned crowning at every misalignment of the tuning (ISO/TS 16281's idea, "
               "docs/life.md \"Sliced roller life under tilt\"); sliced lives are not in shortest_L10h";
  }
  res.notes = {"uncrowned rollers are edge-loaded: their peak is the end row's pressure and grows as the resolution "
               "refines (slice width / cell_dy_mm); the crowned values are converged (docs/lcr.md)"};
}

}  // namespace

Result Run(const Study& st, const RunContext& ctx) {
  Result res;
  sizing::LcrCrowningTuningSpec spec = st.spec;
  Progress progress("lcr_crowning_tuning", ctx.quiet);
  spec.progress = [&](double f) { progress.Update(f, "crowning coefficient scan and refinement"); };
  try {
    res.tuned = sizing::TuneLcrCrowning(spec);
  } catch (const std::domain_error& e) {
    throw StudyError(ctx.study_file + ": /reducer: infeasible geometry: " + e.what());
  }
  progress.Done();
  for (lcr::Side s : {lcr::Side::kInput, lcr::Side::kOutput}) {
    const int k = s == lcr::Side::kInput ? 0 : 1;
    lcr::RollerCrowning<double> crown;
    crown.type = contact::CrowningType::kLogarithmic;
    crown.coefficient = res.tuned[k].coefficient_mm;
    crown.effective_length = spec.effective_length_mm[k];
    res.tuned_check[k].slices = res.tuned[k].tuned;
    res.uncrowned_check[k].slices = res.tuned[k].uncrowned;
    if (!st.in.tuning.half_space_check) continue;
    const sizing::StageClock::Scope stage("verification");  // the half_space checks, `--timings`
    std::vector<lcr::Contact3DCycleSide> coarse;
    for (auto [check, c] : {std::pair{&res.tuned_check[k], crown}, std::pair{&res.uncrowned_check[k], lcr::RollerCrowning<double>{}}}) {
      std::vector<lcr::Contact3DCycleSide> details;
      check->half_space = sizing::CheckLcrCrowning(spec, s, c, lcr::ContactModel::kHalfSpace, &details,
                                                       st.in.tuning.grid[0], st.in.tuning.grid[1]);
      for (size_t g = 0; g < spec.misalignments_rad.size(); ++g) check->half_space_dy_mm.push_back(details[2 * g].cell_dy_mm);
      if (check == &res.tuned_check[k]) coarse = details;
    }
    // The verified-optimum contract: the tuned crowning on twice the input angles and twice the
    // half_space cells each way; per misalignment, the largest pressure at a contact end as a
    // share of the peak at the overload torque (the tuning's constraint: off the ends) and at the
    // design torque, the error the change from the study's own settings.
    sizing::LcrCrowningTuningSpec fine_spec = spec;
    fine_spec.angle_steps = 2 * spec.angle_steps;
    fine_spec.progress = nullptr;
    std::vector<lcr::Contact3DCycleSide> fine;
    sizing::CheckLcrCrowning(fine_spec, s, crown, lcr::ContactModel::kHalfSpace, &fine, 2 * st.in.tuning.grid[0],
                                 2 * st.in.tuning.grid[1]);
    const auto end_share = [](const lcr::Contact3DCycleSide& c) {
      const auto& p = c.worst_pressure_MPa;
      return p.empty() || !(c.max_contact_stress_MPa > 0) ? 0.0
                                                           : std::max(p.front(), p.back()) / c.max_contact_stress_MPa;
    };
    for (size_t g = 0; g < spec.misalignments_rad.size(); ++g)
      for (int torque = 0; torque < 2; ++torque) {
        objectives::VerifiedLimit c;
        c.limit = torque == 1 ? "overload_edge_pressure_share" : "design_edge_pressure_share";
        c.where = std::string(k == 0 ? "input cam" : "output cam") + " at " + Format(spec.misalignments_rad[g] * 1e3) +
                  " mrad, " + (torque == 1 ? "overload" : "design") + " torque";
        c.limit_value = kEdgeShareLimit;
        c.accurate_value = end_share(fine[2 * g + torque]);
        c.fast_value = end_share(coarse[2 * g + torque]);
        c.estimated_error = std::abs(c.accurate_value - c.fast_value);
        res.verification.checks.push_back(c);
      }
  }
  if (st.life) {
    try {
      res.life = TunedLives(st, res.tuned);
    } catch (const std::domain_error& e) {
      throw StudyError(ctx.study_file + ": /reducer: infeasible geometry: " + e.what());
    }
  }
  if (st.in.tuning.half_space_check) {
    res.verification.ran = true;
    res.verification.accurate_model = "half_space on " + std::to_string(2 * st.in.tuning.grid[0]) + "x" +
                                      std::to_string(2 * st.in.tuning.grid[1]) + " cells at the worst contacts of " +
                                      std::to_string(2 * spec.angle_steps) + " input angles (error: the change from " +
                                      std::to_string(st.in.tuning.grid[0]) + "x" + std::to_string(st.in.tuning.grid[1]) + " cells, " +
                                      std::to_string(spec.angle_steps) + " angles)";
  }
  FillResult(st, res);
  return res;
}

void Write(const Study& st, const Result& res, Outputs& out) {
  Table t;
  t.Add("coefficient_mm", res.tuned[0].curve_coefficient_mm);
  std::vector<Series> curves;
  for (int k : {0, 1}) {
    const std::string name = k == 0 ? "input" : "output";
    const auto& r = res.tuned[k];
    t.Add(name + "_worst_design_stress_MPa", r.curve_worst_design_MPa);
    t.Add(name + "_edge_free_at_overload",
          std::vector<double>(r.curve_edge_free_at_overload.begin(), r.curve_edge_free_at_overload.end()));
    curves.push_back({name + " cam", r.curve_coefficient_mm, r.curve_worst_design_MPa});
  }
  out.Add("stress_vs_coefficient.csv", ToCsv(t));
  out.Add("stress_vs_coefficient.svg",
          SvgLinePlot(curves, {"Largest contact pressure at the design torque (worst misalignment), slices model",
                               "logarithmic crowning coefficient f [mm]", "contact pressure [MPa]"}));
  out.SetResult(res);
  std::string infeasible;
  for (int k = 0; k < 2; ++k)
    if (!res.tuned[k].feasible) infeasible += std::string(infeasible.empty() ? "" : "; ") + (k == 0 ? "input" : "output") +
                                              " cam: no coefficient in the range meets the limits at the overload torque";
  if (!infeasible.empty())
    out.SetStatus(Status::kInfeasible, infeasible + " (widen tuning.coefficient_mm or raise the limits)");
  else if (!st.in.tuning.half_space_check)
    out.SetStatus(Status::kNotVerifiable, "tuning.half_space_check is false: the tuned crowning is not checked by the "
                                          "accurate model (set it to true)");
  else
    out.SetStatus(SizingStatus(true, res.verification.ran, res.verification.verified(), true),
                  VerificationFailure(res.verification, "the pressure reaches a roller end: raise "
                                                        "tuning.effective_length_mm or the coefficient range"));
}

namespace {

// The declared input of a study, for the knobs and the estimate below, which run before Parse.
Input ReadInput(const nlohmann::json& study, const std::string& file) { return Read<Input>(Node(&study, file, "")); }

// Fidelity for `camopt run --convergence` (studies/convergence.h): slices, angle grid, the
// golden-section steps and the half_space check's grid, from the declaration's defaults.
Fidelity Knobs(const nlohmann::json&) {
  const Input::Tuning defaults;
  Fidelity f;
  f.knobs.push_back({"slices", {"/tuning/slices"}, defaults.slices, 2, true, 0, "slices along the roller"});
  f.knobs.push_back({"angle_steps", {"/tuning/angle_steps"}, defaults.angle_steps, 2, true, 0,
                     "samples of the input revolution"});
  f.knobs.push_back({"refine_iterations", {"/tuning/refine_iterations"}, defaults.refine_iterations, 2, true, 0,
                     "golden-section steps in ln f after the scan"});
  f.knobs.push_back({"grid", {"/tuning/grid"}, {defaults.grid[0], defaults.grid[1]}, 2, true, 0,
                     "half_space check cells"});
  f.headlines = {"/input/crowning/coefficient_mm", "/output/crowning/coefficient_mm",
                 "/input/tuned/slices/0/design_max_contact_stress_MPa",
                 "/output/tuned/slices/0/design_max_contact_stress_MPa"};
  return f;
}

// The work limit (studies/work_limits.h): slices solves of 40 slices as the unit (≈0.6 ms; N slices
// cost (N/40)³), 69 per cam and cycle (13 × 5 table + 4 exact), 2 cycles (design, overload) per
// misalignment and evaluation; the half_space checks as 100 units per 48×256 grid; ≤ 1e5 units.
WorkEstimate EstimateWork(const nlohmann::json& study, const std::string& file, double factor) {
  const Input in = ReadInput(study, file);
  const Input::Tuning& t = in.tuning;
  const double evaluations = double(t.curve_points) + t.refine_iterations + 2;
  const double misalignments = std::max<double>(1, double(t.misalignment_mrad.size()));
  const double slices = t.slices;
  const double per_solve = std::pow(std::max(slices, 4.0) / 40.0, 3);
  const double cells = double(t.grid[0]) * t.grid[1];
  // The check: tuned and uncrowned on the grid, and the tuned crowning verified on twice the cells
  // each way (four times the cells, about five times the time).
  const double check = !t.half_space_check ? 0.0 : (2 + 5) * 2 * misalignments * 4 * 100 * cells / (48.0 * 256.0);
  // The load stage over the angle grid: about 1/4000 of a slices solve per angle and cam.
  const double angle_steps = t.angle_steps;
  const double angles = evaluations * 2 * 2 * misalignments * angle_steps / 4000.0;
  return LargestTerm({{evaluations * 2 * 2 * misalignments * 69 * per_solve, "/tuning/curve_points",
                       WorkNumber(evaluations) + " evaluations × 2 cams × 2 torques × " + WorkNumber(misalignments) +
                           " misalignments × 69 contact solves × " + WorkNumber(per_solve) + " (slices)"},
                      {check, "/tuning/grid", "half_space checks on " + WorkNumber(cells) + " cells"},
                      {angles, "/tuning/angle_steps", WorkNumber(angle_steps) + " input angles per cycle"}},
                     1e5 * factor, "slice-solve units", 1000);
}

CAMOPT_REGISTER_KIND(Kind<Input, Result, Study>{
    .name = "lcr_crowning_tuning",
    .title = "camopt study: logarithmic roller crowning of a lobe cam reducer, tuned per cam",
    .run = Run, .parse = Parse, .write = Write, .knobs = Knobs, .estimate = EstimateWork,
    // report.html and the summary: the tuned coefficients, the tuned and uncrowned peak pressures of
    // the aligned rollers at the design torque (the accurate model's), and the verdict on the edge
    // loading the tuning is for.
    .report = std::vector<Headline>{
        {"tuned LCM coefficient, input rollers", "/input/crowning/coefficient_mm", "mm"},
        {"tuned LCM coefficient, output rollers", "/output/crowning/coefficient_mm", "mm"},
        {"largest edge-pressure share, tuned (accurate model)", "/max_edge_pressure_share", "",
         "/edge_pressure_share_limit", NAN, true, "/max_edge_pressure_share_error"},
        {"where", "/max_edge_pressure_share_where", ""},
        {"peak pressure, input cam, tuned (0 mrad, design torque)",
         "/input/tuned/half_space/0/design_max_contact_stress_MPa", "MPa"},
        {"peak pressure, input cam, uncrowned", "/input/uncrowned/half_space/0/design_max_contact_stress_MPa", "MPa"},
        {"peak pressure, output cam, tuned (0 mrad, design torque)",
         "/output/tuned/half_space/0/design_max_contact_stress_MPa", "MPa"},
        {"peak pressure, output cam, uncrowned", "/output/uncrowned/half_space/0/design_max_contact_stress_MPa", "MPa"},
        {"verified", "/verified", ""},
    },
    .init_example = "lcr_crowning_tuning"});
}  // namespace

}  // namespace camopt::studies::lcr_crowning_tuning
