#include "studies/lubrication_input.h"

#include <cmath>

#include "studies/format.h"
#include "studies/writers.h"

namespace camopt::studies {

Lubricant ToLubricant(const LubricantInput& in, const Node& node, std::string* source) {
  Lubricant oil;
  const TabulatedOil* table = nullptr;
  if (in.iso_vg) {
    for (const char* field : {"nu40_cSt", "nu100_cSt"})
      if (node.Has(field))
        node[field].FailWith(std::string("give the oil one way: \"iso_vg\" (the built-in oil of that grade) or "
                                         "\"nu40_cSt\" and \"nu100_cSt\" (a data sheet's), not both"));
    const std::string base = in.base_oil.value_or("mineral");
    table = FindTabulatedOil(*in.iso_vg, base);
    if (!table) {
      std::string grades;
      for (const TabulatedOil& o : kTabulatedOils)
        if (base == o.base) grades += (grades.empty() ? "" : ", ") + std::to_string(o.iso_vg);
      node["iso_vg"].Fail("an ISO VG grade of the built-in " + base + " oils: one of " + grades +
                          " (or give nu40_cSt and nu100_cSt of the oil's data sheet)");
    }
    oil.nu40_mm2_s = table->nu40_mm2_s;
    oil.nu100_mm2_s = table->nu100_mm2_s;
  } else {
    if (in.base_oil)
      node["base_oil"].FailWith("\"base_oil\" picks a built-in oil with \"iso_vg\": give iso_vg, or remove base_oil");
    if (!in.nu40_cSt || !in.nu100_cSt)
      node.FailWith(std::string("expected the oil's viscosity: \"nu40_cSt\" and \"nu100_cSt\" (mm²/s, its data "
                                "sheet's) or \"iso_vg\" (a grade of the built-in oils); found no ") +
                    (in.nu40_cSt ? "nu100_cSt" : "nu40_cSt"));
    oil.nu40_mm2_s = *in.nu40_cSt;
    oil.nu100_mm2_s = *in.nu100_cSt;
  }
  // Equal values are a viscosity that does not change with temperature (the Walther law's B = 0).
  if (!(oil.nu100_mm2_s <= oil.nu40_mm2_s))
    node["nu100_cSt"].Fail("a viscosity at 100 °C at most nu40_cSt (" + Format(oil.nu40_mm2_s) +
                           " mm²/s): oils thin as they warm");
  if (in.temperature_C.has_value() == in.thermal.has_value())
    node.FailWith(in.thermal ? "give the oil's temperature one way: \"temperature_C\" or \"thermal\", not both"
                             : "expected the oil's temperature: \"temperature_C\" (°C) or \"thermal\" (the "
                               "housing's heat balance)");
  if (in.thermal && !(in.thermal->max_oil_temperature_C > in.thermal->ambient_C)) {
    const Node thermal = node["thermal"];
    const std::string why = ": the housing gives off no heat above it";
    if (thermal.Has("ambient_C"))
      thermal["ambient_C"].Fail("an ambient temperature below max_oil_temperature_C (" +
                                Format(in.thermal->max_oil_temperature_C) + " °C)" + why);
    thermal["max_oil_temperature_C"].Fail("an oil limit above ambient_C (" + Format(in.thermal->ambient_C) + " °C)" +
                                          ": the housing gives off no heat below it");
  }
  oil.name = in.name.value_or(table ? std::string(table->product) + " (built-in ISO VG " +
                                          std::to_string(table->iso_vg) + " " + table->base + ")"
                                    : std::string("oil"));
  oil.density15_kg_m3 = in.density_kg_m3.value_or(table && table->density15_kg_m3 > 0 ? table->density15_kg_m3 : 880.0);
  if (source)
    *source = !table ? "given"
                     : std::string(table->source) + " (typical values)" +
                           (in.density_kg_m3 ? "; density given"
                            : table->density15_kg_m3 > 0 ? ""
                                                         : "; density not on the data sheet: 880 kg/m³ assumed");
  oil.pressure_viscosity_per_MPa = in.pressure_viscosity_1_per_GPa.value_or(20.0) * 1e-3;
  return oil;
}

HousingCooling ToCooling(const ThermalInput& in) {
  HousingCooling c;
  c.area_m2 = in.housing_area_m2;
  c.heat_transfer_W_per_m2K = in.heat_transfer_W_per_m2K;
  c.forced_W_per_K = in.forced_W_per_K;
  c.ambient_C = in.ambient_C;
  return c;
}

double CompositeRoughnessMm(const SurfacesInput& in) {
  const double roller = in.roughness_rq_um * 1e-3, cam = in.cam_roughness_rq_um.value_or(in.roughness_rq_um) * 1e-3;
  return std::sqrt(roller * roller + cam * cam);
}

void CheckOilTemperatureLimit(const Node& root, const std::optional<double>& limit, const LubricationCommon& c) {
  if (limit && c.temperature_C)
    root["limits"]["max_oil_temperature_C"].FailWith(
        "a limit on the oil temperature needs the housing's balance, lubricant.thermal, not a given "
        "lubricant.temperature_C (" + Format(*c.temperature_C) + " °C)");
}

std::optional<LubricationCommon> ParseLubricationCommon(const Node& root, const std::optional<LubricantInput>& lubricant,
                                                        const std::optional<SurfacesInput>& surfaces,
                                                        const std::optional<EfficiencyMapInput>& map,
                                                        std::optional<double> speed, bool duty_cycle) {
  if (!lubricant) {
    for (const char* block : {"surfaces", "bearing_friction", "efficiency_map"})
      if (root.Has(block))
        root[block].FailWith(std::string("\"") + block + "\" needs \"lubricant\" (the oil whose losses it sets)");
    if (root.Has("limits"))
      for (const char* limit : {"min_efficiency", "max_oil_temperature_C", "min_film_lambda"})
        if (root["limits"].Has(limit))
          root["limits"][limit].FailWith("a limit on the lubricated losses needs \"lubricant\" (the oil)");
    return std::nullopt;
  }
  const Node node = root["lubricant"];
  LubricationCommon l;
  l.oil = ToLubricant(*lubricant, node, &l.oil_source);
  l.alpha_given = lubricant->pressure_viscosity_1_per_GPa.has_value();
  if (!root.Has("material")) (void)root["material"];  // the film needs E*
  if (!root.Has("load")) (void)root["load"];
  if (!speed)
    root["load"].FailWith(!duty_cycle
                              ? "the lubricated losses (\"lubricant\") need the input speed: give \"input_speed_rpm\" (rpm)"
                              : "the lubricated losses (\"lubricant\") are computed at one speed, "
                                "\"load.input_speed_rpm\", not over a duty cycle: run the line of interest with it");
  l.input_speed_rpm = *speed;
  const SurfacesInput sf = surfaces.value_or(SurfacesInput{});
  l.friction = {sf.boundary_friction, sf.full_film_friction};
  l.composite_roughness_mm = CompositeRoughnessMm(sf);
  l.rollers_rotate = sf.rollers == "rotating";
  l.temperature_C = lubricant->temperature_C;
  if (lubricant->thermal) {
    l.cooling = ToCooling(*lubricant->thermal);
    l.max_oil_temperature_C = lubricant->thermal->max_oil_temperature_C;
  }
  l.map = map;
  if (map && map->torque_Nm.size() * map->speed_rpm.size() > 400)
    root["efficiency_map"].Fail("at most 400 operating points (torques × speeds), found " +
                                std::to_string(map->torque_Nm.size() * map->speed_rpm.size()));
  return l;
}

OilTemperature SolveOilTemperature(const LubricationCommon& l, const std::function<double(double)>& loss_W) {
  OilTemperature t;
  if (l.temperature_C) {
    t.celsius = *l.temperature_C;
    return t;
  }
  t.thermal = SolveOperatingTemperature<double>(loss_W, l.cooling, l.max_oil_temperature_C);
  t.celsius = t.thermal->found ? t.thermal->temperature_C : l.max_oil_temperature_C;
  return t;
}

LubricationResult CommonLubricationResult(const LubricationCommon& l, const OilTemperature& t, double output_torque_Nm,
                                          double output_power_W, double total_loss_W) {
  LubricationResult out;
  out.oil = {l.oil.name, l.oil.nu40_mm2_s, l.oil.nu100_mm2_s, l.oil.density15_kg_m3,
             l.oil.pressure_viscosity_per_MPa * 1e3,
             l.alpha_given ? "given" : "assumed: 20 1/GPa, typical of mineral oils", l.oil_source};
  out.temperature_source = t.thermal ? "thermal balance" : "given";
  out.oil_temperature_C = t.celsius;
  if (t.thermal) {
    out.thermal_residual_W = t.thermal->residual_W;
    out.heat_path_W_per_K = l.cooling.conductance_W_per_K();
  }
  out.viscosity_cSt = l.oil.KinematicViscosityAt(t.celsius);
  out.input_speed_rpm = l.input_speed_rpm;
  out.output_torque_Nm = output_torque_Nm;
  out.output_power_W = output_power_W;
  out.power_loss_W.total = total_loss_W;
  out.input_power_W = output_power_W + total_loss_W;
  out.efficiency = output_power_W > 0.0 ? output_power_W / out.input_power_W : 0.0;
  out.rollers = l.rollers_rotate ? "rotating" : "fixed";
  out.not_modelled = {"seals and churning"};
  if (l.map) out.efficiency_map_file = "efficiency_map.csv";
  return out;
}

void AddLubricationSchemaRules(nlohmann::ordered_json& rules) {
  for (const char* block : {"surfaces", "bearing_friction", "efficiency_map"})
    rules["dependentRequired"][block] = nlohmann::ordered_json::array({"lubricant"});
  rules["dependentRequired"]["lubricant"] = nlohmann::ordered_json::array({"material", "load"});
  rules["allOf"].push_back(nlohmann::ordered_json::parse(R"(
    {"if": {"required": ["limits"],
            "properties": {"limits": {"anyOf": [{"required": ["min_efficiency"]}, {"required": ["max_oil_temperature_C"]},
                                                {"required": ["min_film_lambda"]}]}}},
     "then": {"required": ["lubricant"]}})"));
  rules["allOf"].push_back(nlohmann::ordered_json::parse(R"(
    {"if": {"required": ["lubricant"]},
     "then": {"required": ["load"], "properties": {"load": {"required": ["input_speed_rpm"]}}}})"));
}

void WriteEfficiencyMap(const std::vector<std::array<double, 7>>& rows, const std::vector<double>& torques,
                        Outputs& out) {
  Table t;
  const char* names[] = {"output_torque_Nm", "input_speed_rpm", "efficiency", "power_loss_W", "oil_temperature_C",
                         "min_film_lambda", "thermal_equilibrium"};
  for (size_t c = 0; c < 7; ++c) {
    std::vector<double> column;
    for (const auto& row : rows) column.push_back(row[c]);
    t.Add(names[c], column);
  }
  out.Add("efficiency_map.csv", ToCsv(t));
  std::vector<Series> curves;
  for (double torque : torques) {
    Series line{"T_o = " + Format(torque) + " N·m", {}, {}};
    for (const auto& row : rows)
      if (row[0] == torque) line.x.push_back(row[1]), line.y.push_back(row[2]);
    curves.push_back(line);
  }
  out.Add("efficiency_map.svg", SvgLinePlot(curves, {"Lubricated efficiency over input speed, per output torque",
                                                     "input speed [rpm]", "efficiency [-]"}));
}

std::vector<Headline> WithLubricationHeadlines(std::vector<Headline> rows) {
  const std::string shown = "/lubrication/efficiency";
  rows.push_back({"lubricated efficiency", shown, "", "study:/limits/min_efficiency", NAN, false, "", shown});
  rows.push_back({"power lost", "/lubrication/power_loss_W/total", "W", "", NAN, true,
                  "/lubrication/power_loss_sampling_error_W", shown});
  rows.push_back({"oil temperature", "/lubrication/oil_temperature_C", "°C", "study:/limits/max_oil_temperature_C", NAN,
                  true, "", shown});
  rows.push_back({"least film parameter λ", "/lubrication/min_film_lambda/value", "", "study:/limits/min_film_lambda",
                  NAN, false, "", shown});
  return rows;
}

std::string RegimeName(double lambda) {
  if (lambda <= contact::kBoundaryLambda) return "boundary";
  if (lambda >= contact::kFullFilmLambda) return "full_film";
  return "mixed";
}

}  // namespace camopt::studies
