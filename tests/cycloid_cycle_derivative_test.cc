// Cycle-level implicit derivatives of the cycloid LTCA against central differences of
// converged cycles: the smooth peak stress, the exact peak, LTE peak-to-peak, the largest pair
// load, every pair load and the end distance at the maximum torque, for every parameter.
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "model/cycloid/loaded_tca.h"
#include "tests/reference_designs.h"

namespace camopt::cycloid {
namespace cycloid_cycle_derivative_test {

// Tolerances of the comparison (relative to the central difference). The solves run at a
// compatibility tolerance of 1e-11 and CG residuals of 1e-12, the derivatives' CG at 1e-10, and the
// central differences take a relative step of 1e-5 (truncation ~1e-10 relative): measured
// agreement is 2e-7 or better for every output and parameter.
constexpr double kRelTol = 1e-5;          // smooth and exact peak, LTE p-p, LTE, loads
constexpr double kEndDistanceTol = 1e-5;  // end distance, through its row maxima (cells frozen)

LoadedOptions Tight() {
  LoadedOptions o;
  o.profile_cells = 14;
  o.axial_cells = 14;
  o.tolerance = 1e-11;
  o.solver_tolerance = 1e-12;
  o.rough_solver_tolerance = 0;
  o.max_iterations = 400;
  o.edge_margin = true;
  return o;
}

Crowning FiniteDropLog() {
  Crowning c;
  c.type = CrowningType::kLogarithmic;
  c.coefficient_mm = 0.003;
  c.effective_length_mm = 18.7;
  c.end_drop_mm = 0.006;
  c.flat_length_mm = 3.0;
  return c;
}

struct Point {
  Drive drive = camopt::testing::CycloidNnm();
  Crowning crowning = FiniteDropLog();
  double torque_Nmm = 450.0e3;
};

// Moves one parameter of p by h (its own unit) and returns the new point.
Point Moved(Point p, const std::string& name, double h) {
  if (name == "torque_Nmm") p.torque_Nmm += h;
  if (name == "coefficient_mm") p.crowning.coefficient_mm += h;
  if (name == "effective_length_mm") p.crowning.effective_length_mm += h;
  if (name == "end_drop_mm") p.crowning.end_drop_mm += h;
  if (name == "flat_length_mm") p.crowning.flat_length_mm += h;
  if (name == "radius_mm") p.crowning.radius_mm += h;
  if (name == "delta_position_mm") p.drive.delta_position_mm += h;
  if (name == "delta_radius_mm") p.drive.delta_radius_mm += h;
  if (name == "eccentricity_mm") p.drive.eccentricity_mm += h;
  if (name == "roller_position_radius_mm") p.drive.roller_position_radius_mm += h;
  if (name == "roller_radius_mm") p.drive.roller_radius_mm += h;
  if (name == "face_width_mm") p.drive.face_width_mm += h;
  return p;
}

double Step(const Point& p, const std::string& name) {
  if (name == "torque_Nmm") return 1e-5 * p.torque_Nmm;
  if (name == "coefficient_mm") return 1e-5 * p.crowning.coefficient_mm;
  if (name == "effective_length_mm") return 1e-5 * p.crowning.effective_length_mm;
  if (name == "end_drop_mm") return 1e-5 * p.crowning.end_drop_mm;
  if (name == "flat_length_mm") return 1e-5 * p.crowning.flat_length_mm;
  if (name == "radius_mm") return 1e-5 * p.crowning.radius_mm;
  if (name == "eccentricity_mm") return 1e-5 * p.drive.eccentricity_mm;
  if (name == "roller_position_radius_mm") return 1e-5 * p.drive.roller_position_radius_mm;
  if (name == "roller_radius_mm") return 1e-5 * p.drive.roller_radius_mm;
  if (name == "face_width_mm") return 1e-5 * p.drive.face_width_mm;
  return 1e-6;  // Δa, Δρ [mm]
}

constexpr double kTemperatureMPa = 5.0;

void ExpectCycleDerivativesMatch(const Point& base, const std::vector<std::string>& names) {
  const std::vector<double> angles = UniformCrankAngles(4, 2 * kPi / 16);
  const LoadedTca tca(base.drive, base.crowning, Material{}, Tight());
  const CycleResult cycle = RunCycle(tca, base.torque_Nmm, angles);
  ASSERT_TRUE(cycle.converged);
  const std::vector<CycleDerivative> d = DifferentiateCycle(tca, cycle, names, kTemperatureMPa);
  ASSERT_EQ(d.size(), names.size());
  auto run = [&](const Point& p) {
    return RunCycle(LoadedTca(p.drive, p.crowning, Material{}, Tight()), p.torque_Nmm, angles);
  };
  for (size_t j = 0; j < names.size(); ++j) {
    const std::string& name = names[j];
    ASSERT_EQ(d[j].parameter, name);
    ASSERT_TRUE(d[j].converged) << name;
    const double h = Step(base, name);
    const CycleResult plus = run(Moved(base, name, h)), minus = run(Moved(base, name, -h));
    auto fd = [&](double a, double b) { return (a - b) / (2 * h); };
    auto expect = [&](double ad, double cd, double tol, const std::string& what) {
      EXPECT_NEAR(ad, cd, tol * std::abs(cd) + 1e-12) << name << ": " << what;
    };
    expect(d[j].smooth_peak_MPa,
           fd(SmoothPeakPressure(plus, kTemperatureMPa), SmoothPeakPressure(minus, kTemperatureMPa)), kRelTol,
           "smooth peak");
    expect(d[j].max_pressure_MPa, fd(plus.max_pressure_MPa, minus.max_pressure_MPa), kRelTol, "exact peak");
    expect(d[j].lte_peak_to_peak_arcsec, fd(plus.lte_peak_to_peak_arcsec, minus.lte_peak_to_peak_arcsec),
           kRelTol, "LTE peak-to-peak");
    expect(d[j].max_pair_load_N, fd(plus.max_pair_load_N, minus.max_pair_load_N), kRelTol, "max pair load");
    double load_scale = 0;
    for (size_t k = 0; k < angles.size(); ++k)
      for (size_t i = 0; i < cycle.meshes[k].pairs.size(); ++i)
        load_scale = std::max(load_scale, std::abs(fd(plus.meshes[k].pairs[i].load_N,
                                                      minus.meshes[k].pairs[i].load_N)));
    for (size_t k = 0; k < angles.size(); ++k) {
      ASSERT_EQ(plus.meshes[k].pairs.size(), cycle.meshes[k].pairs.size());
      ASSERT_EQ(minus.meshes[k].pairs.size(), cycle.meshes[k].pairs.size());
      for (size_t i = 0; i < cycle.meshes[k].pairs.size(); ++i)
        EXPECT_NEAR(d[j].pair_load_N[k][i],
                    fd(plus.meshes[k].pairs[i].load_N, minus.meshes[k].pairs[i].load_N), kRelTol * load_scale)
            << name << " angle " << k << " pair " << i;
      expect(d[j].rotation_rad[k], fd(plus.meshes[k].rotation_rad, minus.meshes[k].rotation_rad), kRelTol,
             "LTE at angle " + std::to_string(k));
    }
    expect(d[j].end_distance_mm, fd(plus.end_distance_mm, minus.end_distance_mm), kEndDistanceTol,
           "end distance");
  }
}

TEST(CycloidCycleDerivative, EveryOutputMatchesCentralDifferencesForEveryParameter) {
  ExpectCycleDerivativesMatch(Point{}, {"torque_Nmm", "coefficient_mm", "effective_length_mm", "end_drop_mm",
                                        "flat_length_mm", "delta_position_mm", "delta_radius_mm"});
}

TEST(CycloidCycleDerivative, GeometryParametersMatchCentralDifferences) {
  // The sizing variables: eccentricity, pin circle, pin radius, face width (the rows stretch; the
  // crowning's effective length is its own field here and the face width's own in the second).
  ExpectCycleDerivativesMatch(Point{}, {"eccentricity_mm", "roller_position_radius_mm", "roller_radius_mm",
                                        "face_width_mm"});
  Point whole_face;
  whole_face.crowning.effective_length_mm = 0;  // L = the face width
  whole_face.crowning.end_drop_mm = 0;
  whole_face.crowning.flat_length_mm = 0;
  ExpectCycleDerivativesMatch(whole_face, {"face_width_mm"});
}

TEST(CycloidCycleDerivative, FullAndPartialCrowningParametersMatchCentralDifferences) {
  Point full;
  full.crowning = Crowning{};
  full.crowning.type = CrowningType::kFull;
  full.crowning.radius_mm = 3000;
  ExpectCycleDerivativesMatch(full, {"radius_mm"});
  Point partial;
  partial.crowning = Crowning{};
  partial.crowning.type = CrowningType::kPartial;
  partial.crowning.radius_mm = 1500;
  partial.crowning.flat_length_mm = 8.0;
  ExpectCycleDerivativesMatch(partial, {"radius_mm", "flat_length_mm"});
}

// The LTE's slope over the crank angle (MeshLoad::rotation_slope, the instantaneous gear ratio's
// dLTE/dφ) against central differences of converged solves over ±1e-6 rad (no contact cell
// changes state within the step on these grids), for the three crowning forms, at the zero torque
// (the unloaded TE's slope alone) and at a torque; and the cycle's gear ratio built from it.
TEST(CycloidCycleDerivative, CrankSlopeMatchesCentralDifferencesOfTheLte) {
  constexpr double kStepRad = 1e-6;
  // The slopes are ~1e-5 rad/rad, so the central difference carries the solves' residual noise
  // divided by the small step: measured agreement 1.1e-5 relative at worst.
  constexpr double kSlopeRelTol = 3e-5;
  // The default (looser) CG residual of the slope's sensitivity solves against the tight one.
  constexpr double kDefaultSlopeRelTol = 1e-4;  // measured: 1e-5
  Crowning full;
  full.type = CrowningType::kFull;
  full.radius_mm = 3000;
  for (const Crowning& crowning : {FiniteDropLog(), full, Crowning{}}) {
    LoadedOptions tight = Tight();
    tight.crank_slope_tolerance = 1e-10;
    const LoadedTca tca(camopt::testing::CycloidNnm(), crowning, Material{}, tight);
    const LoadedTca by_default(camopt::testing::CycloidNnm(), crowning, Material{}, Tight());
    for (double torque : {0.0, 350.0e3})
      for (double angle : {0.05, 0.21, 0.33}) {
        const MeshLoad m = tca.Solve(torque, angle);
        ASSERT_TRUE(m.converged);
        EXPECT_NEAR(by_default.Solve(torque, angle).rotation_slope, m.rotation_slope,
                    kDefaultSlopeRelTol * std::abs(m.rotation_slope));
        const double cd =
            (tca.Solve(torque, angle + kStepRad).rotation_rad - tca.Solve(torque, angle - kStepRad).rotation_rad) /
            (2 * kStepRad);
        EXPECT_NEAR(m.rotation_slope, cd, kSlopeRelTol * std::abs(cd) + 1e-12)
            << "torque " << torque << " angle " << angle << " crowning " << int(crowning.type);
      }
    const std::vector<double> angles = UniformCrankAngles(4, 2 * kPi / 16);
    const CycleResult c = RunCycle(tca, 350.0e3, angles);
    ASSERT_EQ(c.gear_ratio.size(), angles.size());
    double lo = 1e300, hi = -1e300;
    for (size_t k = 0; k < angles.size(); ++k) {
      const double ratio = 1.0 / (1.0 / 15.0 + c.meshes[k].rotation_slope);  // n2 = 15 teeth
      EXPECT_NEAR(c.gear_ratio[k], ratio, 1e-12 * ratio);
      lo = std::min(lo, ratio);
      hi = std::max(hi, ratio);
    }
    EXPECT_NEAR(c.gear_ratio_peak_to_peak, hi - lo, 1e-12);
  }
  // A solve without a loaded state (no roller on the loaded flank: a vanishing eccentricity) is
  // not converged and carries the placeholder slope 0, so the cycle's series stay whole.
  {
    Drive flat = camopt::testing::CycloidNnm();
    flat.eccentricity_mm = 1e-4;
    const CycleResult c = RunCycle(LoadedTca(flat, Crowning{}, Material{}, Tight()), 350.0e3,
                                   UniformCrankAngles(4, 2 * kPi / 16));
    EXPECT_FALSE(c.converged);
    ASSERT_EQ(c.gear_ratio.size(), 4u);
    for (const MeshLoad& m : c.meshes) EXPECT_EQ(m.rotation_slope, 0.0) << m.message;
  }
  // Without the slope the cycle says so: no gear ratio, a NaN peak-to-peak.
  LoadedOptions off = Tight();
  off.crank_slope = false;
  const CycleResult c = RunCycle(LoadedTca(camopt::testing::CycloidNnm(), FiniteDropLog(), Material{}, off), 350.0e3,
                                 UniformCrankAngles(4, 2 * kPi / 16));
  EXPECT_TRUE(c.gear_ratio.empty());
  EXPECT_TRUE(std::isnan(c.gear_ratio_peak_to_peak));
  for (const MeshLoad& m : c.meshes) EXPECT_TRUE(std::isnan(m.rotation_slope));
}

TEST(CycloidCycleDerivative, SmoothPeakBiasIsWithinItsStatedBound) {
  const LoadedTca tca(camopt::testing::CycloidNnm(), FiniteDropLog(), Material{}, Tight());
  const CycleResult cycle = RunCycle(tca, 350.0e3, UniformCrankAngles(4, 2 * kPi / 16));
  int terms = 0;
  for (const MeshLoad& m : cycle.meshes) terms += int(m.pairs.size());
  for (double t : {0.5, 2.0, 10.0}) {
    const double s = SmoothPeakPressure(cycle, t);
    EXPECT_GE(s, cycle.max_pressure_MPa);
    EXPECT_LE(s, cycle.max_pressure_MPa + t * std::log(double(terms)) + 1e-9);
  }
  EXPECT_EQ(SmoothPeakPressure(cycle, 0.0), cycle.max_pressure_MPa);
}

}  // namespace cycloid_cycle_derivative_test
}  // namespace camopt::cycloid
