// Uses camopt as a library: runs an LCR analysis study given as JSON through the C++ API and
// calls one model function (the composite modulus E* of model/common/material.h).
// Prints the study's headline numbers; exits non-zero when something is off.
#include <cmath>
#include <cstdio>
#include <exception>

#include <nlohmann/json.hpp>

#include "model/common/material.h"
#include "studies/input.h"
#include "studies/study.h"

int main() {
  // One model function: E* of two steel bodies, E / (2 (1 − ν²)).
  const double e_star = camopt::CompositeModulus(206000.0, 0.3, 206000.0, 0.3);
  const double expected = 206000.0 / (2.0 * (1.0 - 0.09));
  std::printf("composite modulus of steel on steel: %.1f MPa\n", e_star);
  if (std::abs(e_star - expected) > 1e-9 * expected) return 1;

  // A study through the C++ API: the outputs stay in memory (nothing is written).
  const nlohmann::json study = {
      {"study", "lcr_analysis"},
      {"name", "LCR II from the consumer project"},
      {"reducer",
       {{"eccentricity_mm", 2},
        {"input", {{"lobes", 12}, {"rollers", 13}, {"turret_radius_mm", 37}, {"roller_diameter_mm", 12},
                   {"roller_length_mm", 10}, {"cam_thickness_mm", 8}}},
        {"output", {{"lobes", 14}, {"rollers", 15}, {"turret_radius_mm", 42}, {"roller_diameter_mm", 12},
                    {"roller_length_mm", 10}, {"cam_thickness_mm", 8}}}}},
      {"material", {{"youngs_modulus_GPa", 206}, {"poisson_ratio", 0.3}}},
      {"load", {{"output_torque_Nm", 80}, {"friction_coefficient", 0.05}}},
      {"analysis", {{"angle_steps", 360}}}};
  try {
    camopt::studies::RunContext ctx;
    ctx.study_file = "<consumer>";
    ctx.quiet = true;
    const camopt::studies::Outputs outputs = camopt::studies::RunStudy(study, ctx);
    const auto result = nlohmann::json::parse(outputs.files().at("result.json"));
    std::printf("study %s, %zu output files\n", result.at("study").get<std::string>().c_str(),
                outputs.files().size());
    for (const char* side : {"input_cam", "output_cam"}) {
      const double stress = result.at(side).at("max_contact_stress_MPa").get<double>();
      std::printf("%s: largest contact stress %.1f MPa\n", side, stress);
      if (!(stress > 0.0)) return 1;
    }
  } catch (const camopt::studies::StudyError& e) {
    std::fprintf(stderr, "bad study: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
