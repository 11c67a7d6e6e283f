// Study kind "cycloid_ltca": loaded tooth contact analysis of a cycloid stage over the crank
// angles (model/cycloid/, docs/cycloid.md). Outputs result.json, per_angle.csv, backlash.csv,
// lte.svg, gear_ratio.svg, contact_stress.svg, pressure_map.svg (every contacting pair at the
// angle of the maximum stress), pressure_max.csv and a tooth drawing (tooth.svg, tooth.dxf).
#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/cycloid/loaded_tca.h"
#include "model/cycloid/unloaded_tca.h"
#include "studies/cycloid_study_common.h"
#include "studies/study.h"
#include "studies/writers.h"

namespace camopt::studies {
namespace {

using namespace camopt::cycloid;
using cycloid_common::Fmt;

void RunCycloidLtca(const Node& root, const RunContext& ctx, Outputs& out) {
  root.CheckKnownFields({"study", "name", "description", "drive", "modification", "crowning", "material", "load", "analysis"});
  const Drive drive = cycloid_common::ParseDrive(root);
  const Crowning crowning = cycloid_common::ParseCrowning(root, drive.face_width_mm);
  const Material material = cycloid_common::ParseMaterial(root);
  root["load"].CheckKnownFields({"torque_Nm"});
  const double torque = root["load"]["torque_Nm"].NonNegative();
  LoadedOptions options;
  std::vector<double> angles;
  if (root.Has("analysis")) {
    const Node a = root["analysis"];
    a.CheckKnownFields({"grid", "tolerance", "crank_angles_deg", "crank_angle_steps", "crank_span_deg"});
    cycloid_common::ParseGrid(a, options);
    options.tolerance = a.PositiveOr("tolerance", options.tolerance);
    if (a.Has("crank_angles_deg")) {
      if (a.Has("crank_angle_steps"))
        a.FailWith("give either crank_angle_steps or crank_angles_deg, not both");
      for (const Node& e : a["crank_angles_deg"].Elements()) angles.push_back(e.Number() * kPi / 180.0);
      if (angles.empty()) a["crank_angles_deg"].Fail("a non-empty array of angles");
    } else {
      const int steps = a.IntegerOr("crank_angle_steps", 1, 60);
      if (steps > 100000) a["crank_angle_steps"].Fail("at most 100000 steps");
      angles = UniformCrankAngles(steps, a.PositiveOr("crank_span_deg", 360.0) * kPi / 180.0);
    }
  } else {
    angles = UniformCrankAngles(60, 2.0 * kPi);
  }

  LoadedTca tca(drive, crowning, material, options);
  Progress progress("cycloid_ltca", ctx.quiet);
  const CycleResult cycle = RunCycle(tca, torque * 1000.0, angles, [&](double f) { progress.Update(f); });
  progress.Done();

  const int n1 = drive.rollers;
  nlohmann::json per_angle = nlohmann::json::array();
  Table table;
  std::vector<double> col_angle, col_lte, col_ute, col_gr, col_p, col_pairs;
  std::vector<std::vector<double>> col_load(n1, std::vector<double>(angles.size(), 0.0));
  Table backlash;
  std::vector<std::vector<double>> col_bl(n1, std::vector<double>(angles.size(), 0.0));
  for (size_t k = 0; k < cycle.meshes.size(); ++k) {
    const MeshLoad& m = cycle.meshes[k];
    nlohmann::json loads = nlohmann::json::array();
    for (const PairLoad& p : m.pairs) {
      loads.push_back({{"roller", p.roller + 1},
                       {"load_N", Finite(p.load_N, "load")},
                       {"max_contact_stress_MPa", Finite(p.max_pressure_MPa, "pressure")},
                       {"approach_um", Finite(p.approach_mm * 1e3, "approach")},
                       {"arm_mm", p.arm_mm}});
      col_load[p.roller][k] = p.load_N;
    }
    per_angle.push_back({{"crank_angle_deg", angles[k] * 180.0 / kPi},
                         {"max_contact_stress_MPa", Finite(m.max_pressure_MPa, "max stress")},
                         {"pairs_in_contact", m.pairs_in_contact},
                         {"lte_arcsec", Finite(cycle.lte_arcsec[k], "lte")},
                         {"unloaded_te_arcsec", Finite(m.unloaded_rotation_rad * kArcsecPerRad, "ute")},
                         {"gear_ratio", Finite(cycle.gear_ratio[k], "gear ratio")},
                         {"converged", m.converged},
                         {"loads", loads}});
    col_angle.push_back(angles[k] * 180.0 / kPi);
    col_lte.push_back(cycle.lte_arcsec[k]);
    col_ute.push_back(m.unloaded_rotation_rad * kArcsecPerRad);
    col_gr.push_back(cycle.gear_ratio[k]);
    col_p.push_back(m.max_pressure_MPa);
    col_pairs.push_back(m.pairs_in_contact);
    const UnloadedMesh<double> u = UnloadedTca<double>(drive, angles[k]);
    for (const auto& g : u.pairs)
      col_bl[g.roller][k] = g.loaded_flank ? g.backlash * kArcsecPerRad : -1.0;
  }
  table.Add("crank_angle_deg", col_angle);
  table.Add("lte_arcsec", col_lte);
  table.Add("unloaded_te_arcsec", col_ute);
  table.Add("gear_ratio", col_gr);
  table.Add("max_contact_stress_MPa", col_p);
  table.Add("pairs_in_contact", col_pairs);
  for (int i = 0; i < n1; ++i) table.Add("load_roller_" + std::to_string(i + 1) + "_N", col_load[i]);
  backlash.Add("crank_angle_deg", col_angle);
  for (int i = 0; i < n1; ++i)
    backlash.Add("backlash_roller_" + std::to_string(i + 1) + "_arcsec", col_bl[i]);

  std::string warning;
  if (!cycle.converged) {
    for (const auto& m : cycle.meshes)
      if (!m.converged) {
        warning = "not converged at crank angle " + Fmt(m.crank_angle_rad * 180 / kPi) + " deg: " + m.message;
        break;
      }
  }
  const MeshLoad& worst = cycle.meshes[cycle.max_pressure_index];
  nlohmann::json result = {
      {"study", "cycloid_ltca"},
      {"name", root.json().value("name", "")},
      {"torque_Nm", torque},
      {"max_contact_stress_MPa", Finite(cycle.max_pressure_MPa, "max stress")},
      {"max_contact_stress_crank_angle_deg", angles[cycle.max_pressure_index] * 180.0 / kPi},
      {"lte_peak_to_peak_arcsec", Finite(cycle.lte_peak_to_peak_arcsec, "lte p2p")},
      {"lte_mean_abs_arcsec", Finite(cycle.lte_mean_abs_arcsec, "lte mean")},
      {"gear_ratio_nominal", double(drive.teeth)},
      {"gear_ratio_peak_to_peak", Finite(cycle.gear_ratio_peak_to_peak, "gr p2p")},
      {"max_pairs_in_contact", cycle.max_pairs_in_contact},
      {"axial_cell_mm", drive.face_width_mm / options.axial_cells},
      {"grid", {options.profile_cells, options.axial_cells}},
      {"composite_modulus_MPa", tca.e_star_MPa()},
      {"contact_solves", cycle.contact_solves},
      {"converged", cycle.converged},
      {"warning", warning},
      {"per_angle", per_angle}};
  out.AddJson("result.json", result);
  out.Add("per_angle.csv", ToCsv(table));
  out.Add("backlash.csv", ToCsv(backlash));

  PlotOptions po;
  po.x_label = "crank angle [deg]";
  po.title = "Loaded transmission error";
  po.y_label = "LTE [arcsec]";
  out.Add("lte.svg", SvgLinePlot({{"loaded", col_angle, col_lte}, {"unloaded", col_angle, col_ute}}, po));
  po.title = "Instantaneous gear ratio";
  po.y_label = "ratio";
  out.Add("gear_ratio.svg", SvgLinePlot({{"GR", col_angle, col_gr}}, po));
  po.title = "Maximum contact stress";
  po.y_label = "stress [MPa]";
  out.Add("contact_stress.svg", SvgLinePlot({{"max", col_angle, col_p}}, po));
  out.Add("pressure_map.svg",
          cycloid_common::PressureMapsSvg(
              worst, "Contact pressure at crank angle " + Fmt(worst.crank_angle_rad * 180 / kPi) + " deg"));
  // The pressure field of the worst pair as a long table (x across, y along the face).
  Table pmap;
  std::vector<double> cr, cx, cy, cp;
  for (const PairLoad& p : worst.pairs)
    for (int iy = 0; iy < p.grid.ny; ++iy)
      for (int ix = 0; ix < p.grid.nx; ++ix) {
        cr.push_back(p.roller + 1);
        cx.push_back(p.grid.x0 + (ix + 0.5) * p.grid.dx);
        cy.push_back(p.grid.y0 + (iy + 0.5) * p.grid.dy);
        cp.push_back(p.pressure_MPa[size_t(iy) * p.grid.nx + ix]);
      }
  pmap.Add("roller", cr);
  pmap.Add("x_mm", cx);
  pmap.Add("y_mm", cy);
  pmap.Add("pressure_MPa", cp);
  out.Add("pressure_max.csv", ToCsv(pmap));

  // Tooth drawing: the modified profile of the whole disc and the rollers at crank angle 0.
  Drawing drawing;
  drawing.title = "Cycloid gear (disc frame) and rollers at crank angle 0";
  Drawing::Layer disc{"disc", "black", {}, {}, true, 1.0};
  Polyline pl;
  const int samples = 40 * drive.teeth;
  for (int k = 0; k < samples; ++k) {
    const auto p = ToothProfile<double>(drive, 2.0 * kPi * k / samples);
    pl.push_back({p.point.x(), p.point.y()});
  }
  disc.polylines.push_back(pl);
  Drawing::Layer rollers{"rollers", "blue", {}, {}, true, 1.0};
  for (int i = 0; i < n1; ++i) {
    const Vec2<double> c = RollerCentreInDisc<double>(drive, i, 0.0, 0.0);
    rollers.circles.push_back({c.x(), c.y(), drive.roller_radius_mm});
  }
  drawing.layers = {disc, rollers};
  out.Add("tooth.svg", SvgDrawing(drawing));
  out.Add("tooth.dxf", ToDxf(drawing));
}

CAMOPT_REGISTER_STUDY("cycloid_ltca", RunCycloidLtca);

}  // namespace
}  // namespace camopt::studies
