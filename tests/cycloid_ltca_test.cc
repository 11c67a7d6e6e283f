// Tests of the cycloid loaded TCA and the two study kinds (coarse grids: the suite stays fast).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/contact/hertz.h"
#include "model/cycloid/loaded_tca.h"
#include "studies/cycloid_crowning_tuning_study.h"
#include "studies/cycloid_ltca_study.h"
#include "studies/input.h"
#include "studies/report.h"
#include "studies/study.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt::cycloid {
namespace cycloid_ltca_test {

Drive NnmDrive() { return camopt::testing::CycloidNnm(); }  // Tables 2 and 3 of the paper

LoadedOptions Coarse(int p = 16, int q = 16) {
  LoadedOptions o;
  o.profile_cells = p;
  o.axial_cells = q;
  return o;
}

Crowning Log(double f) { return testing::LogCrowning(f); }

void ExpectFinite(const MeshLoad& m) {
  EXPECT_TRUE(std::isfinite(m.rotation_rad));
  EXPECT_TRUE(std::isfinite(m.deflection_rad));
  EXPECT_TRUE(std::isfinite(m.max_pressure_MPa));
  for (const auto& p : m.pairs) {
    EXPECT_TRUE(std::isfinite(p.load_N));
    EXPECT_TRUE(std::isfinite(p.approach_mm));
    for (double v : p.pressure_MPa) ASSERT_TRUE(std::isfinite(v) && v >= 0.0);
  }
}

TEST(CycloidLtca, EquilibriumAndCompatibilityHold) {
  LoadedTca tca(NnmDrive(), Crowning{}, Material{}, Coarse());
  const double crank = 120.0 * kPi / 180.0;
  const MeshLoad m = tca.Solve(350.0e3, crank);
  ASSERT_TRUE(m.converged) << m.message;
  ExpectFinite(m);
  ASSERT_GE(m.pairs_in_contact, 2);
  double moment = 0, max_approach = 0;
  for (const auto& p : m.pairs) {
    moment += p.load_N * p.arm_mm;
    max_approach = std::max(max_approach, p.approach_mm);
    // Pressure integrates to the pair load.
    double w = 0;
    for (double v : p.pressure_MPa) w += v * p.grid.dx * p.grid.dy;
    EXPECT_NEAR(w, p.load_N, 1e-6 * p.load_N);
  }
  EXPECT_NEAR(moment, 350e3, 350e3 * 5e-3);  // eq. 25
  // Eq. 24: every loaded pair is pressed by l_i (Δφc − φ_bl,i); no other loaded-flank pair closes.
  for (const auto& p : m.pairs)
    EXPECT_NEAR(p.approach_mm, p.arm_mm * (m.deflection_rad - p.backlash_rad), 5e-3 * max_approach);
  const auto unloaded = UnloadedTca<double>(NnmDrive(), crank);
  for (const auto& g : unloaded.pairs) {
    if (!g.loaded_flank) continue;
    bool loaded = false;
    for (const auto& p : m.pairs) loaded = loaded || p.roller == g.roller;
    if (!loaded) {
      EXPECT_LE(g.arm_mm * (m.deflection_rad - g.backlash), 5e-3 * max_approach) << g.roller;
    }
  }
  EXPECT_NEAR(m.rotation_rad, unloaded.rotation + m.deflection_rad, 1e-15);
}

TEST(CycloidLtca, LoadsMatchAnIndependentApproachControlledBisection) {
  // Independent construction of eqs. 24–25: bisect the disc deflection Δφc, each pair solved
  // approach-controlled (δ_i = l_i (Δφc − φ_bl,i)) on the grid the LTCA chose, until Σ F_i l_i = T.
  // No pair model, no load control: only the equations.
  const double crank = 0.9, torque = 350.0;
  for (const Crowning& crown : {Crowning{}, Log(0.005)}) {
    LoadedTca tca(NnmDrive(), crown, Material{}, Coarse(16, 16));
    const MeshLoad m = tca.Solve(torque * 1e3, crank);
    ASSERT_TRUE(m.converged) << m.message;
    const auto unloaded = UnloadedTca<double>(NnmDrive(), crank);
    contact::HalfSpaceSolver solver;
    // Gaps as in the LTCA (circle separations + crowning, shifted so the closest cell touches),
    // rebuilt here from the unloaded TCA on each loaded pair's grid.
    struct Pair {
      double arm, backlash;
      contact::Grid grid;
      std::vector<double> gap;
      int roller;
    };
    std::vector<Pair> pairs;
    const double grid_x = 0.3;  // wide enough for every pair at this load
    for (const auto& g : unloaded.pairs) {
      if (!g.loaded_flank || g.backlash > 5e-3) continue;
      Pair p{g.arm_mm, g.backlash, contact::CenteredGrid(24, 16, grid_x, 8.5), {}, g.roller};
      p.gap.resize(24 * 16);
      double lowest = 1e9;
      for (int iy = 0; iy < 16; ++iy)
        for (int ix = 0; ix < 24; ++ix) {
          const double x = p.grid.x_centre_mm(ix), y = p.grid.y_centre_mm(iy);
          const double k1 = g.roller_curvature, k2 = g.profile_curvature;
          const double h = (1.0 / k1 - std::sqrt(1.0 / (k1 * k1) - x * x)) +
                           k2 * x * x / (1.0 + std::sqrt(1.0 - k2 * k2 * x * x)) +
                           CrowningDrop(crown, 17.0, y);
          p.gap[iy * 24 + ix] = h;
          lowest = std::min(lowest, h);
        }
      for (double& h : p.gap) h -= lowest;
      pairs.push_back(std::move(p));
    }
    auto moment = [&](double dphi, std::vector<double>* loads) {
      double mm = 0;
      for (const auto& p : pairs) {
        const double delta = p.arm * (dphi - p.backlash);
        const double f = delta > 0 ? solver.SolveForApproach(p.grid, p.gap, delta, tca.e_star_MPa()).load_N : 0.0;
        if (loads) loads->push_back(f);
        mm += f * p.arm;
      }
      return mm;
    };
    double lo = 0, hi = 1e-3;
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (lo + hi);
      (moment(mid, nullptr) < torque * 1e3 ? lo : hi) = mid;
    }
    std::vector<double> loads;
    moment(0.5 * (lo + hi), &loads);
    EXPECT_NEAR(m.deflection_rad, 0.5 * (lo + hi), 5e-3 * m.deflection_rad);
    for (size_t i = 0; i < pairs.size(); ++i) {
      double ours = 0;
      for (const auto& p : m.pairs)
        if (p.roller == pairs[i].roller) ours = p.load_N;
      EXPECT_NEAR(ours, loads[i], 10.0 + 0.01 * loads[i]) << "roller " << pairs[i].roller;
    }
  }
}

TEST(CycloidLtca, MidFacePressureOfAStraightToothIsNearHertzLineContact) {
  // Away from the face edges an uncrowned pair is a line contact: its mid-face peak is close to
  // Hertz p = sqrt(F E* / (π B R')) with the pair's own load (a little lower, since the edge
  // concentration takes a share of the load).
  LoadedTca tca(NnmDrive(), Crowning{}, Material{}, Coarse(24, 24));
  const MeshLoad m = tca.Solve(350.0e3, 0.5);
  ASSERT_TRUE(m.converged) << m.message;
  for (const auto& p : m.pairs) {
    double mid = 0;
    for (int ix = 0; ix < p.grid.nx; ++ix)
      mid = std::max(mid, 0.5 * (p.pressure_MPa[size_t(11) * p.grid.nx + ix] +
                                 p.pressure_MPa[size_t(12) * p.grid.nx + ix]));
    const double hertz = contact::LineContactPeakPressure(p.load_N, 17.0, p.effective_radius_mm,
                                                          tca.e_star_MPa());
    EXPECT_NEAR(mid, hertz, 0.08 * hertz) << "roller " << p.roller;
    EXPECT_LT(mid, p.max_pressure_MPa) << "edge concentration of a straight tooth";
  }
}

TEST(CycloidLtca, ZeroTorqueIsTheUnloadedState) {
  LoadedTca tca(NnmDrive(), Log(0.005), Material{}, Coarse());
  const MeshLoad m = tca.Solve(0.0, 1.0);
  ExpectFinite(m);
  EXPECT_EQ(m.pairs_in_contact, 0);
  EXPECT_EQ(m.max_pressure_MPa, 0.0);
  EXPECT_EQ(m.rotation_rad, UnloadedTca<double>(NnmDrive(), 1.0).rotation);
  const CycleResult c = RunCycle(tca, 0.0, UniformCrankAngles(4, 2 * kPi / 16));
  EXPECT_TRUE(std::isfinite(c.gear_ratio_peak_to_peak));
  EXPECT_TRUE(std::isfinite(c.lte_peak_to_peak_arcsec));
}

TEST(CycloidLtca, BarelyTouchingPairIsFinite) {
  // A tiny torque: one pair barely touching (its approach is nanometres).
  LoadedTca tca(NnmDrive(), Crowning{}, Material{}, Coarse());
  const MeshLoad m = tca.Solve(1e-6 * 1e3, 0.3);
  ExpectFinite(m);
  ASSERT_EQ(m.pairs_in_contact, 1);
  EXPECT_GT(m.max_pressure_MPa, 0.0);
  EXPECT_LT(m.pairs[0].approach_mm, 1e-6);
  // A pair whose backlash is just closed by the torque: raise the torque until a second pair
  // enters and check the state on both sides of that point stays finite and continuous.
  double lo = 1.0, hi = 350.0;
  for (int k = 0; k < 12; ++k) {
    const double mid = std::sqrt(lo * hi);
    (tca.Solve(mid * 1e3, 0.3).pairs_in_contact >= 2 ? hi : lo) = mid;
  }
  const MeshLoad a = tca.Solve(lo * 1e3, 0.3), b = tca.Solve(hi * 1e3, 0.3);
  ExpectFinite(a);
  ExpectFinite(b);
  EXPECT_NEAR(a.max_pressure_MPa, b.max_pressure_MPa, 0.05 * b.max_pressure_MPa);
}

TEST(CycloidLtca, LteTendsToTheUnloadedTeAsTheTorqueVanishes) {
  // Crowned (point-like) contact on a coarse grid, where the cell centres miss the contact point
  // by half a cell: the deflection must still vanish with the torque.
  Crowning fcm;
  fcm.type = CrowningType::kFull;
  fcm.radius_mm = 3000;
  LoadedTca tca(NnmDrive(), fcm, Material{}, Coarse());
  const double beta0 = UnloadedTca<double>(NnmDrive(), 0.4).rotation;
  const MeshLoad m = tca.Solve(1e-6 * 1e3, 0.4);
  ExpectFinite(m);
  EXPECT_NEAR(m.rotation_rad, beta0, 1e-9);  // 2e-4 arcsec
  EXPECT_GT(m.rotation_rad, beta0);
}

// A contact cut by a grid too narrow for it grows its grid and is solved again; when that happens
// on the last iteration allowed, the solve ends unconverged with every loaded pair's pressure
// whole (it crashed in the crank slope on an emptied pressure map). Every iteration limit from 1
// to the one that converges: converged, or a message and whole pressure maps.
TEST(CycloidLtca, AGridGrownOnTheLastIterationLeavesAWholeUnconvergedState) {
  LoadedOptions o = Coarse();
  o.grid_half_width_factor = 0.4;  // the first grids cut the contacts across the profile
  int grown_on_last = 0;
  bool converged_once = false;
  for (int limit = 1; limit <= 40 && !converged_once; ++limit) {
    o.max_iterations = limit;
    LoadedTca tca(NnmDrive(), Log(0.005), Material{}, o);
    const MeshLoad m = tca.Solve(350.0e3, 0.3);
    converged_once = m.converged;
    if (!m.converged) {
      EXPECT_FALSE(m.message.empty()) << limit;
    }
    if (m.message.find("edge of its grid") != std::string::npos) ++grown_on_last;
    ASSERT_GE(m.pairs_in_contact, 1) << limit;
    for (const PairLoad& p : m.pairs) {
      ASSERT_EQ(p.pressure_MPa.size(), size_t(p.grid.cells())) << "limit " << limit << ", roller " << p.roller;
      double w = 0;
      for (double v : p.pressure_MPa) w += v * p.grid.dx * p.grid.dy;
      EXPECT_NEAR(w, p.load_N, 1e-6 * p.load_N) << limit;
    }
    EXPECT_TRUE(std::isfinite(m.rotation_slope)) << limit;
  }
  EXPECT_TRUE(converged_once);
  EXPECT_GE(grown_on_last, 1);  // the path this test is for was taken
}

TEST(CycloidLtca, PairLosingContactBetweenIterationsConvergesToTheSameState) {
  // Memory from a light load makes the first iteration at a heavy load mispredict the pair laws
  // (too compliant: too large a deflection, pairs that then lose contact again). The end state
  // must equal a fresh solve.
  LoadedTca warm(NnmDrive(), Log(0.005), Material{}, Coarse());
  LtcaWarmStart memory;
  warm.Solve(2.0e3, 0.8, &memory);
  const MeshLoad a = warm.Solve(500.0e3, 0.8, &memory);
  LoadedTca fresh(NnmDrive(), Log(0.005), Material{}, Coarse());
  const MeshLoad b = fresh.Solve(500.0e3, 0.8);
  ASSERT_TRUE(a.converged && b.converged);
  ExpectFinite(a);
  EXPECT_EQ(a.pairs_in_contact, b.pairs_in_contact);
  EXPECT_NEAR(a.max_pressure_MPa, b.max_pressure_MPa, 0.01 * b.max_pressure_MPa);
  EXPECT_NEAR(a.deflection_rad, b.deflection_rad, 0.005 * b.deflection_rad);
  // And back down: heavy-load memory at a light load.
  const MeshLoad c = warm.Solve(2.0e3, 0.8, &memory);
  LoadedTca fresh2(NnmDrive(), Log(0.005), Material{}, Coarse());
  const MeshLoad d = fresh2.Solve(2.0e3, 0.8);
  EXPECT_EQ(c.pairs_in_contact, d.pairs_in_contact);
  EXPECT_NEAR(c.max_pressure_MPa, d.max_pressure_MPa, 0.01 * d.max_pressure_MPa);
}

TEST(CycloidLtca, VanishingLogCrowningTendsToTheStraightTooth) {
  LoadedTca straight(NnmDrive(), Crowning{}, Material{}, Coarse());
  LoadedTca tiny(NnmDrive(), Log(1e-9), Material{}, Coarse());
  LoadedTca zero(NnmDrive(), Log(0.0), Material{}, Coarse());
  const MeshLoad a = straight.Solve(350.0e3, 0.2), b = tiny.Solve(350.0e3, 0.2), c = zero.Solve(350.0e3, 0.2);
  ExpectFinite(b);
  ExpectFinite(c);
  EXPECT_NEAR(b.max_pressure_MPa, a.max_pressure_MPa, 0.005 * a.max_pressure_MPa);
  EXPECT_NEAR(c.max_pressure_MPa, a.max_pressure_MPa, 1e-9 * a.max_pressure_MPa);
}

TEST(CycloidLtca, CrowningMovesThePeakOffTheEdges) {
  // A straight tooth peaks at its axial edge rows; with LCM the edge rows carry less than the middle.
  LoadedTca straight(NnmDrive(), Crowning{}, Material{}, Coarse());
  LoadedTca crowned(NnmDrive(), Log(0.005), Material{}, Coarse());
  auto edge_and_mid = [](const PairLoad& p) {
    double edge = 0, mid = 0;
    for (int ix = 0; ix < p.grid.nx; ++ix) {
      edge = std::max({edge, p.pressure_MPa[ix], p.pressure_MPa[size_t(p.grid.ny - 1) * p.grid.nx + ix]});
      mid = std::max(mid, p.pressure_MPa[size_t(p.grid.ny / 2) * p.grid.nx + ix]);
    }
    return std::pair<double, double>(edge, mid);
  };
  for (const auto& p : straight.Solve(350.0e3, 1.1).pairs) {
    const auto [edge, mid] = edge_and_mid(p);
    EXPECT_GT(edge, mid);
  }
  for (const auto& p : crowned.Solve(350.0e3, 1.1).pairs) {
    const auto [edge, mid] = edge_and_mid(p);
    EXPECT_LT(edge, mid);
  }
}

TEST(CycloidLtca, ContactEndDistanceIsLocatedWithinACell) {
  // A crowned tooth whose pattern ends inside the face: the end distance on coarse grids against
  // the last loaded row's outer boundary on a fine grid (error <= its cell), within a fifth of the
  // coarse cell (the row-centre rule alone would be off by up to half a cell).
  Crowning c = Log(0.006);
  c.effective_length_mm = 18.7;
  auto solve = [&](int q) {
    LoadedOptions o = Coarse(16, q);
    o.edge_margin = true;
    return LoadedTca(NnmDrive(), c, Material{}, o).Solve(350.0e3, 0.8);
  };
  const MeshLoad fine = solve(192);
  ASSERT_TRUE(fine.converged);
  const double dy_fine = 17.0 / 192;
  for (const PairLoad& p : fine.pairs) {
    double reference = kInf;  // per pair: the smaller of the two sides
    for (int side : {0, 1}) {
      int last = -1;
      for (int j = 0; j < 96; ++j) {
        const int iy = side ? 96 + j : 95 - j;
        for (int ix = 0; ix < p.grid.nx; ++ix)
          if (p.pressure_MPa[size_t(iy) * p.grid.nx + ix] > 0) last = j;
      }
      reference = std::min(reference, 8.5 - (last + 1) * dy_fine);
    }
    ASSERT_GT(reference, 0.5);  // the pattern ends inside the face
    for (int q : {24, 48}) {
      const MeshLoad m = solve(q);
      for (const PairLoad& pq : m.pairs)
        if (pq.roller == p.roller) {
          EXPECT_NEAR(pq.end_distance_mm, reference, 0.2 * 17.0 / q + dy_fine) << "q " << q << " roller " << p.roller;
        }
    }
  }
}

TEST(CycloidLtca, ImplicitDerivativesMatchCentralDifferences) {
  // Frozen contact sets (implicit-function theorem) against central differences of converged solves, for the
  // torque, each field of a finite-drop logarithmic crowning and the modifications Δa, Δρ.
  LoadedOptions o = Coarse(16, 16);
  o.tolerance = 1e-11;
  o.solver_tolerance = 1e-12;
  o.rough_solver_tolerance = 0;  // final-tolerance passes only
  o.max_iterations = 400;
  Crowning c = Log(0.004);
  c.effective_length_mm = 18.7;
  c.end_drop_mm = 0.006;
  const double torque = 350.0e3, crank = 0.8;
  const LoadedTca tca(NnmDrive(), c, Material{}, o);
  const MeshLoad m = tca.Solve(torque, crank);
  ASSERT_TRUE(m.converged) << m.message;
  for (const char* name : {"torque_Nmm", "coefficient_mm", "effective_length_mm", "end_drop_mm",
                           "delta_position_mm", "delta_radius_mm", "eccentricity_mm",
                           "roller_position_radius_mm", "roller_radius_mm", "face_width_mm"}) {
    const LoadedTca::Derivative d = tca.Differentiate(m, name);
    ASSERT_TRUE(d.converged) << name;
    auto at = [&](double sign) {
      Crowning cc = c;
      double t = torque;
      const std::string n = name;
      double h = 0;
      if (n == "torque_Nmm") t += sign * (h = 1e-5 * torque);
      if (n == "coefficient_mm") cc.coefficient_mm += sign * (h = 1e-5 * c.coefficient_mm);
      if (n == "effective_length_mm") cc.effective_length_mm += sign * (h = 1e-5 * c.effective_length_mm);
      if (n == "end_drop_mm") cc.end_drop_mm += sign * (h = 1e-5 * c.end_drop_mm);
      Drive dd = NnmDrive();
      if (n == "delta_position_mm") dd.delta_position_mm += sign * (h = 1e-6);
      if (n == "delta_radius_mm") dd.delta_radius_mm += sign * (h = 1e-6);
      if (n == "eccentricity_mm") dd.eccentricity_mm += sign * (h = 1e-6 * dd.eccentricity_mm);
      if (n == "roller_position_radius_mm") dd.roller_position_radius_mm += sign * (h = 1e-6 * dd.roller_position_radius_mm);
      if (n == "roller_radius_mm") dd.roller_radius_mm += sign * (h = 1e-6 * dd.roller_radius_mm);
      if (n == "face_width_mm") {
        dd.face_width_mm += sign * (h = 1e-6 * dd.face_width_mm);
        cc.effective_length_mm = c.effective_length_mm;  // L is its own field here
      }
      if (n.find("delta_") == 0 || n == "eccentricity_mm" || n.find("roller_") == 0 || n == "face_width_mm")
        return std::pair<MeshLoad, double>(LoadedTca(dd, cc, Material{}, o).Solve(t, crank), h);
      return std::pair<MeshLoad, double>(tca.WithCrowning(cc).Solve(t, crank), h);
    };
    const auto [plus, h] = at(1.0);
    const auto [minus, h2] = at(-1.0);
    ASSERT_EQ(plus.pairs.size(), m.pairs.size());
    ASSERT_EQ(minus.pairs.size(), m.pairs.size());
    const double fd = (plus.deflection_rad - minus.deflection_rad) / (2 * h);
    EXPECT_NEAR(d.deflection_rad, fd, 2e-3 * std::abs(fd) + 1e-14) << name;
    const double fdr = (plus.rotation_rad - minus.rotation_rad) / (2 * h);
    EXPECT_NEAR(d.rotation_rad, fdr, 2e-3 * std::abs(fdr) + 1e-14) << name;
    double scale = 0;
    for (size_t i = 0; i < m.pairs.size(); ++i)
      scale = std::max(scale, std::abs((plus.pairs[i].load_N - minus.pairs[i].load_N) / (2 * h)));
    for (size_t i = 0; i < m.pairs.size(); ++i) {
      const double fdl = (plus.pairs[i].load_N - minus.pairs[i].load_N) / (2 * h);
      EXPECT_NEAR(d.pair_load_N[i], fdl, 5e-3 * scale) << name << " pair " << i;
    }
  }
  EXPECT_THROW(tca.Differentiate(m, "flat_length_um"), std::invalid_argument);
}

TEST(CycloidLtca, LteRepeatsEveryMeshPeriod) {
  LoadedTca tca(NnmDrive(), Crowning{}, Material{}, Coarse(12, 12));
  const double period = 2 * kPi / 16;
  const MeshLoad a = tca.Solve(350.0e3, 0.1), b = tca.Solve(350.0e3, 0.1 + 3 * period);
  EXPECT_NEAR(a.rotation_rad, b.rotation_rad, 1e-3 * a.rotation_rad);
  EXPECT_NEAR(a.max_pressure_MPa, b.max_pressure_MPa, 1e-3 * a.max_pressure_MPa);
}

void ExpectSameBits(const MeshLoad& a, const MeshLoad& b) {
  EXPECT_EQ(a.rotation_rad, b.rotation_rad);
  EXPECT_EQ(a.max_pressure_MPa, b.max_pressure_MPa);
  ASSERT_EQ(a.pairs.size(), b.pairs.size());
  for (size_t i = 0; i < a.pairs.size(); ++i) {
    EXPECT_EQ(a.pairs[i].load_N, b.pairs[i].load_N);
    EXPECT_EQ(a.pairs[i].grid.dx, b.pairs[i].grid.dx);
    EXPECT_EQ(a.pairs[i].pressure_MPa, b.pairs[i].pressure_MPa);
  }
}

TEST(CycloidLtca, ASolveDependsOnItsInputsOnly) {
  // The same solve before and after other solves (other torques, angles and a crowned copy that
  // shares the solver caches) gives the same bits; with a warm start from elsewhere it gives the
  // same grids and the same answer within the tolerances.
  const LoadedTca tca(NnmDrive(), Log(0.005), Material{}, Coarse());
  const MeshLoad a = tca.Solve(350.0e3, 0.8);
  LtcaWarmStart memory;
  tca.Solve(20.0e3, 0.5, &memory);
  tca.WithCrowning(Log(0.02)).Solve(550.0e3, 0.75, &memory);
  tca.Solve(500.0e3, 0.79);
  const MeshLoad b = tca.Solve(350.0e3, 0.8);
  ExpectSameBits(a, b);
  const LoadedTca other(NnmDrive(), Log(0.005), Material{}, Coarse());
  ExpectSameBits(a, other.Solve(350.0e3, 0.8));
  const MeshLoad w = tca.Solve(350.0e3, 0.8, &memory);
  ASSERT_TRUE(w.converged);
  ASSERT_EQ(w.pairs.size(), a.pairs.size());
  for (size_t i = 0; i < a.pairs.size(); ++i) {
    EXPECT_EQ(w.pairs[i].grid.dx, a.pairs[i].grid.dx);
    EXPECT_NEAR(w.pairs[i].load_N, a.pairs[i].load_N, 3e-3 * a.pairs[i].load_N);
  }
  EXPECT_NEAR(w.deflection_rad, a.deflection_rad, 2e-3 * a.deflection_rad);
}

TEST(CycloidLtca, ACycleDependsOnItsInputsOnly) {
  const LoadedTca tca(NnmDrive(), Log(0.005), Material{}, Coarse(12, 12));
  const std::vector<double> angles = UniformCrankAngles(5, 2 * kPi / 16);
  const CycleResult a = RunCycle(tca, 350.0e3, angles);
  RunCycle(tca.WithCrowning(Log(0.0)), 550.0e3, UniformCrankAngles(3, 1.0));
  std::vector<double> reversed(angles.rbegin(), angles.rend());
  RunCycle(tca, 350.0e3, reversed);
  const CycleResult b = RunCycle(tca, 350.0e3, angles);
  EXPECT_EQ(a.lte_arcsec, b.lte_arcsec);
  EXPECT_EQ(a.gear_ratio, b.gear_ratio);
  EXPECT_EQ(a.max_pressure_MPa, b.max_pressure_MPa);
  for (size_t k = 0; k < angles.size(); ++k) ExpectSameBits(a.meshes[k], b.meshes[k]);
}

TEST(CycloidLtca, BadInputIsRejected) {
  Drive d = NnmDrive();
  d.eccentricity_mm = 7.0;
  EXPECT_THROW(LoadedTca(d, Crowning{}, Material{}, Coarse()), std::invalid_argument);
  Crowning c;
  c.type = CrowningType::kFull;
  c.radius_mm = 5.0;  // smaller than half the face
  EXPECT_THROW(LoadedTca(NnmDrive(), c, Material{}, Coarse()), std::invalid_argument);
  LoadedTca tca(NnmDrive(), Crowning{}, Material{}, Coarse());
  EXPECT_THROW(tca.Solve(-1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(tca.Solve(std::nan(""), 0.0), std::invalid_argument);
}

// --- The study kinds: numbers through the C++ entry points, files and exit codes through the CLI ---

// testing::CycloidNnm() as a study file's "drive" and "modification".
const std::string kNnmDriveJson = R"(
    "drive": {"teeth": 15, "rollers": 16, "roller_position_radius_mm": 90, "roller_radius_mm": 7.2,
              "eccentricity_mm": 4.5, "face_width_mm": 17},
    "modification": {"delta_position_um": -16, "delta_radius_um": -8},)";

std::string StudyJson(const std::string& crowning, const std::string& analysis) {
  return R"({"study": "cycloid_ltca", "name": "test",)" + kNnmDriveJson + R"(
    "crowning": )" + crowning + R"(,
    "material": {"youngs_modulus_GPa": 206, "poisson_ratio": 0.3},
    "load": {"torque_Nm": 350},
    "analysis": )" + analysis + "}";
}

TEST(CycloidStudies, LtcaStudyReportsEveryAngle) {
  // Through the C++ entry points: Parse, Run and the result.json content.
  const nlohmann::json study = nlohmann::json::parse(
      StudyJson(R"({"type": "partial", "radius_mm": 4500, "flat_length_mm": 13.6})",
                R"({"crank_angles_deg": [0, 120, 300], "grid": [12, 10]})"));
  namespace ltca = studies::cycloid_ltca;
  const ltca::Study s = ltca::Parse(studies::Node(&study, "s.json", ""));
  studies::RunContext ctx;
  ctx.quiet = true;
  const ltca::Result r = ltca::Run(s, ctx);
  const nlohmann::json j = studies::WriteResult(r);
  for (const char* k : {"max_contact_stress_MPa", "lte_peak_to_peak_arcsec", "lte_mean_abs_arcsec",
                        "gear_ratio_peak_to_peak", "max_pairs_in_contact", "axial_cell_mm"})
    EXPECT_TRUE(j.contains(k)) << k;
  EXPECT_NEAR(j["axial_cell_mm"].get<double>(), 1.7, 1e-12);
  ASSERT_EQ(r.cycle.meshes.size(), 3u);
  ASSERT_EQ(j["per_angle"].size(), 3u);
  EXPECT_NEAR(j["per_angle"][1]["crank_angle_deg"].get<double>(), 120.0, 1e-9);
  EXPECT_GE(r.cycle.meshes[1].pairs_in_contact, 1);
  // 120° and 300° are 8 mesh periods apart: the same state.
  EXPECT_NEAR(r.cycle.meshes[1].max_pressure_MPa, r.cycle.meshes[2].max_pressure_MPa,
              1e-3 * r.cycle.max_pressure_MPa);
}

TEST(CycloidStudies, LtcaChecksTheToothAndPinGeometryByDefault) {
  // The NNM drive (N = 16 pins on a = 90 mm, rho = 7.2 mm, e = 4.5 mm, a' = 89.984 mm,
  // rho' = 7.192 mm) by hand: the pin gap 2 a sin(pi/N) - 2 rho, and the smallest convex radius of
  // the tooth from the curvature of the generating curve, on the flank since
  // lambda = e N / a' = 0.8001 > (N - 2)/(2N - 1): a' sqrt(27 (N - 1)(1 - lambda^2) / (N + 1)^3) - rho'.
  const double pi = std::acos(-1.0), n = 16, a = 90, rho = 7.2, e = 4.5, ap = 89.984, rhop = 7.192;
  const double gap = 2 * a * std::sin(pi / n) - 2 * rho;  // 20.716 mm
  const double lambda = e * n / ap;
  ASSERT_GT(lambda, (n - 2) / (2 * n - 1));
  const double radius = ap * std::sqrt(27 * (n - 1) * (1 - lambda * lambda) / std::pow(n + 1, 3)) - rhop;  // 8.304 mm
  namespace ltca = studies::cycloid_ltca;
  for (const char* limits : {"", R"(, "limits": {"min_pin_gap_mm": 21})", R"(, "limits": {"min_profile_radius_mm": 8.31})"}) {
    SCOPED_TRACE(limits);
    const nlohmann::json study = nlohmann::json::parse(R"({"study": "cycloid_ltca", "name": "geometry",)" +
                                                       kNnmDriveJson + R"( "analysis": {"evaluate": ["unloaded"],
                                                       "crank_angles_deg": [0]})" + limits + "}");
    const ltca::Study s = ltca::Parse(studies::Node(&study, "s.json", ""));
    studies::RunContext ctx;
    ctx.quiet = true;
    const nlohmann::json j = studies::WriteResult(ltca::Run(s, ctx));
    EXPECT_NEAR(j["pin_gap_mm"].get<double>(), gap, 1e-9);
    EXPECT_NEAR(j["min_profile_radius_mm"].get<double>(), radius, 1e-9);
    const studies::HeadlineTable t = studies::EvaluateHeadlines("cycloid_ltca", study, j);
    EXPECT_EQ(t.limits, 2);
    if (std::string(limits).empty()) {
      EXPECT_TRUE(t.exceeded.empty());
      EXPECT_EQ(studies::VerdictOf(t, j), "All 2 limits met");
    } else {
      ASSERT_EQ(t.exceeded.size(), 1u);
      EXPECT_EQ(t.exceeded[0], std::string(limits).find("gap") != std::string::npos ? "gap between pins"
                                                                                      : "smallest tooth radius");
    }
  }
}

TEST(CycloidStudies, LtcaSamplesOneMeshPeriodAndEstimatesItsErrors) {
  namespace ltca = studies::cycloid_ltca;
  const nlohmann::json study = nlohmann::json::parse(
      StudyJson(R"({"type": "none"})", R"({"crank_angles_per_mesh_period": 8, "grid": [12, 12]})"));
  const ltca::Study s = ltca::Parse(studies::Node(&study, "s.json", ""));
  ASSERT_EQ(s.crank_angles_rad.size(), 8u);
  EXPECT_NEAR(s.crank_angles_rad[1], 2 * kPi / 16 / 8, 1e-15);
  const ltca::Result r = ltca::Run(s, studies::RunContext{"", true});
  // The refinement recomputed here: the 8 angles, the same shifted by half a step, their union
  // (16 uniform angles) reported; the grid part on a 6 x 6 grid over the 8 angles.
  const double step = 2 * kPi / 16 / 8;
  std::vector<double> shifted, both;
  for (double a : s.crank_angles_rad) shifted.push_back(a + 0.5 * step);
  const LoadedTca tca(s.drive, s.crowning, s.material, s.options);
  const CycleResult base = RunCycle(tca, 350.0e3, s.crank_angles_rad);
  const CycleResult moved = RunCycle(tca, 350.0e3, shifted);
  std::vector<MeshLoad> meshes;
  for (size_t k = 0; k < 8; ++k) {
    meshes.push_back(base.meshes[k]);
    meshes.push_back(moved.meshes[k]);
    both.push_back(s.crank_angles_rad[k]);
    both.push_back(shifted[k]);
  }
  const CycleResult doubled = SummariseCycle(s.drive, meshes, both);
  ASSERT_EQ(r.cycle.meshes.size(), 16u);
  ASSERT_EQ(r.crank_angles_rad.size(), 16u);
  for (size_t k = 0; k < 16; ++k) EXPECT_NEAR(r.crank_angles_rad[k], step * 0.5 * double(k), 1e-15);
  EXPECT_EQ(r.cycle.max_pressure_MPa, doubled.max_pressure_MPa);
  EXPECT_EQ(r.cycle.lte_peak_to_peak_arcsec, doubled.lte_peak_to_peak_arcsec);
  EXPECT_EQ(r.cycle.gear_ratio_peak_to_peak, doubled.gear_ratio_peak_to_peak);
  const CycleResult coarse = RunCycle(LoadedTca(s.drive, s.crowning, s.material, Coarse(6, 6)), 350.0e3,
                                      s.crank_angles_rad);
  const nlohmann::json j = studies::WriteResult(r);
  EXPECT_EQ(j["crank_angles_used"], 16);
  EXPECT_EQ(j["crank_angles_refined"], true);
  EXPECT_EQ(j["per_angle"].size(), 16u);
  EXPECT_EQ(j["lte_peak_to_peak_arcsec"].get<double>(), doubled.lte_peak_to_peak_arcsec);
  const auto& e = j["estimated_error"];
  const auto& grid = j["estimated_error_sources"]["grid"]["error"];
  const auto& crank = j["estimated_error_sources"]["crank_angles"]["error"];
  // The grid part: the 8 angles on 12 x 12 against 6 x 6. The crank-angle part: at least the
  // change from 8 to 16 angles (CrankError's smallest factor is 1). The total is their sum.
  EXPECT_NEAR(grid["lte_peak_to_peak_arcsec"].get<double>(),
              std::abs(base.lte_peak_to_peak_arcsec - coarse.lte_peak_to_peak_arcsec), 1e-12);
  EXPECT_NEAR(grid["max_contact_stress_MPa"].get<double>(), std::abs(base.max_pressure_MPa - coarse.max_pressure_MPa),
              1e-9);
  EXPECT_GE(crank["lte_peak_to_peak_arcsec"].get<double>(),
            std::abs(doubled.lte_peak_to_peak_arcsec - base.lte_peak_to_peak_arcsec));
  EXPECT_GE(crank["max_contact_stress_MPa"].get<double>(), std::abs(doubled.max_pressure_MPa - base.max_pressure_MPa));
  for (const char* k : {"max_contact_stress_MPa", "lte_peak_to_peak_arcsec", "lte_mean_abs_arcsec",
                        "gear_ratio_peak_to_peak", "max_pair_load_N"})
    EXPECT_NEAR(e[k].get<double>(), grid[k].get<double>() + crank[k].get<double>(), 1e-12 * (1 + e[k].get<double>())) << k;
  EXPECT_EQ(j["estimated_error_sources"]["crank_angles"]["coarse_angles"], 8);
  EXPECT_EQ(j["estimated_error_sources"]["crank_angles"]["refined_angles"], 16);
  for (const char* k : {"gear_ratio_peak_to_peak", "lte_mean_abs_arcsec", "max_pair_load_N"})
    EXPECT_TRUE(e.contains(k)) << k;
  EXPECT_EQ(j["estimated_error_sources"]["grid"]["coarse_grid"], nlohmann::json::array({6, 6}));
  // A straight tooth's edge peak on a 12 x 12 grid against 6 x 6: the peak stress moves by more
  // than 5 %, and the study says so.
  ASSERT_GT(e["max_contact_stress_MPa"].get<double>(), 0.05 * r.cycle.max_pressure_MPa);
  bool warned = false;
  for (const auto& w : j["warnings"]) warned = warned || w.get<std::string>().rfind("max_contact_stress_MPa", 0) == 0;
  EXPECT_TRUE(warned);
}

TEST(CycloidStudies, PaperDriveRippleWithTheExampleSettingsIsNearTheConvergedValues) {
  // The paper's drive (NNM, 350 N·m, no crowning) with the example's settings against an
  // independent model converged in crank angle and grid (docs/validation.md): LTE
  // peak-to-peak 1.37 arcsec and GR peak-to-peak 0.027, within 5 % or within the estimated error.
  namespace ltca = studies::cycloid_ltca;
  const nlohmann::json study = nlohmann::json::parse(
      camopt::testing::ReadFile(camopt::testing::SourcePath("studies/examples/cycloid_ltca_nnm_none.json")));
  const ltca::Study s = ltca::Parse(studies::Node(&study, "s.json", ""));
  const ltca::Result r = ltca::Run(s, studies::RunContext{"", true});
  const nlohmann::json j = studies::WriteResult(r);
  const double lte = j["lte_peak_to_peak_arcsec"], gr = j["gear_ratio_peak_to_peak"];
  EXPECT_LE(std::abs(lte - 1.37), std::max(0.05 * 1.37, j["estimated_error"]["lte_peak_to_peak_arcsec"].get<double>()));
  EXPECT_LE(std::abs(gr - 0.027), std::max(0.05 * 0.027, j["estimated_error"]["gear_ratio_peak_to_peak"].get<double>()));
}

TEST(CycloidStudies, LtcaStudyWritesResultsAndMaps) {
  // Through the CLI: exit code and the files written.
  const auto dir = camopt::testing::TempDir("cycloid-ltca");
  camopt::testing::WriteFile(dir / "s.json", StudyJson(R"({"type": "partial", "radius_mm": 4500, "flat_length_mm": 13.6})",
                                                       R"({"crank_angles_deg": [0, 120, 300], "grid": [12, 10]})"));
  const auto r = camopt::testing::RunCamopt("run " + (dir / "s.json").string() + " --out " +
                                            (dir / "out").string() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  for (const char* f : {"result.json", "per_angle.csv", "backlash.csv", "pressure_map.svg", "lte.svg", "tooth.dxf"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
  // The drawing's main dimensions: the NNM drive (a 90, ρ 7.2, e 4.5 mm, Δa −16, Δρ −8 µm), whose
  // disc spans (a + Δa) − (ρ + Δρ) ∓ e = 78.292 to 87.292 mm from its centre.
  const std::string tooth = camopt::testing::ReadFile(dir / "out" / "tooth.svg");
  for (const char* text : {"15 teeth, 16 rollers; pin circle diameter 180 mm; roller diameter 14.4 mm; eccentricity 4.5 mm",
                           "Δa -0.016 mm, Δρ -0.008 mm; face width 17 mm; disc radius 78.292 to 87.292 mm"})
    EXPECT_NE(tooth.find(text), std::string::npos) << text;
  // The registered runner writes what the C++ entry points return.
  namespace ltca = studies::cycloid_ltca;
  const nlohmann::json study = nlohmann::json::parse(camopt::testing::ReadFile(dir / "s.json"));
  const ltca::Study s = ltca::Parse(studies::Node(&study, "s.json", ""));
  const nlohmann::json j = nlohmann::json::parse(camopt::testing::ReadFile(dir / "out" / "result.json"));
  EXPECT_EQ(camopt::testing::WithoutRunStamp(j), studies::WriteResult(ltca::Run(s, studies::RunContext{"", true})));

  // The tables: a row per crank angle of the study (0, 120, 300°), a load column per roller of the
  // drive (16), and numbers (written to 10 digits) that agree with result.json.
  const std::vector<double> angles = {0.0, 120.0, 300.0};
  auto near = [](double a, double b) { return std::abs(a - b) <= 1e-9 * std::max(1.0, std::abs(b)); };
  const auto per_angle = camopt::testing::ReadCsv(camopt::testing::ReadFile(dir / "out" / "per_angle.csv"));
  ASSERT_EQ(per_angle.at("crank_angle_deg").size(), angles.size());
  ASSERT_EQ(j["per_angle"].size(), angles.size());
  EXPECT_TRUE(per_angle.count("load_roller_16_N"));
  EXPECT_FALSE(per_angle.count("load_roller_17_N"));
  EXPECT_TRUE(per_angle.count("max_pressure_roller_16_MPa"));
  EXPECT_FALSE(per_angle.count("max_pressure_roller_17_MPa"));
  double max_stress = 0, lte_min = kInf, lte_max = -kInf;
  for (size_t k = 0; k < angles.size(); ++k) {
    const nlohmann::json& row = j["per_angle"][k];
    EXPECT_NEAR(per_angle.at("crank_angle_deg")[k], angles[k], 1e-9);
    EXPECT_TRUE(near(per_angle.at("max_contact_stress_MPa")[k], row["max_contact_stress_MPa"])) << k;
    EXPECT_TRUE(near(per_angle.at("lte_arcsec")[k], row["lte_arcsec"])) << k;
    EXPECT_EQ(per_angle.at("pairs_in_contact")[k], row["pairs_in_contact"].get<double>()) << k;
    int loaded = 0;
    for (const nlohmann::json& pair : row["loads"]) {
      const std::string column = "load_roller_" + std::to_string(pair["roller"].get<int>()) + "_N";
      EXPECT_TRUE(near(per_angle.at(column)[k], pair["load_N"])) << column << " at row " << k;
      // Each pair's own peak pressure: the pair's max_contact_stress_MPa of result.json.
      const std::string pressure = "max_pressure_roller_" + std::to_string(pair["roller"].get<int>()) + "_MPa";
      EXPECT_TRUE(near(per_angle.at(pressure)[k], pair["max_contact_stress_MPa"])) << pressure << " at row " << k;
      loaded += pair["load_N"].get<double>() > 0;
    }
    EXPECT_GE(loaded, 1) << k;
    max_stress = std::max(max_stress, per_angle.at("max_contact_stress_MPa")[k]);
    lte_min = std::min(lte_min, per_angle.at("lte_arcsec")[k]);
    lte_max = std::max(lte_max, per_angle.at("lte_arcsec")[k]);
  }
  // The summary is the table's extreme and range (a difference of two 10-digit numbers).
  EXPECT_TRUE(near(max_stress, j["max_contact_stress_MPa"])) << max_stress;
  EXPECT_NEAR(lte_max - lte_min, j["lte_peak_to_peak_arcsec"].get<double>(),
              2e-9 * std::max(std::abs(lte_max), std::abs(lte_min)));
  const auto backlash = camopt::testing::ReadCsv(camopt::testing::ReadFile(dir / "out" / "backlash.csv"));
  EXPECT_EQ(backlash.size(), 1u + 16u);
  EXPECT_EQ(backlash.at("crank_angle_deg"), per_angle.at("crank_angle_deg"));
  EXPECT_EQ(backlash.at("backlash_roller_16_arcsec").size(), angles.size());
  // The drawings are whole files of their kind, with their titles.
  const std::string lte_svg = camopt::testing::ReadFile(dir / "out" / "lte.svg");
  EXPECT_EQ(lte_svg.rfind("<svg", 0), 0u);
  EXPECT_NE(lte_svg.find("</svg>"), std::string::npos);
  EXPECT_NE(lte_svg.find("Loaded transmission error"), std::string::npos);
  const std::string map_svg = camopt::testing::ReadFile(dir / "out" / "pressure_map.svg");
  EXPECT_NE(map_svg.find("Contact pressure at crank angle"), std::string::npos);
  EXPECT_NE(map_svg.find("</svg>"), std::string::npos);
  const std::string dxf = camopt::testing::ReadFile(dir / "out" / "tooth.dxf");
  EXPECT_NE(dxf.find("ENTITIES"), std::string::npos);
  EXPECT_NE(dxf.rfind("EOF"), std::string::npos);
}

TEST(CycloidStudies, ExamplesRunOnACoarseGrid) {
  // Every shipped example parses and runs (with its analysis made coarse to keep the suite fast).
  for (const char* name : {"cycloid_ltca_nnm_none", "cycloid_ltca_nnm_fcm", "cycloid_ltca_nnm_pcm",
                           "cycloid_ltca_nnm_lcm", "cycloid_crowning_tuning_nnm",
                           "cycloid_crowning_tuning_joint_nnm"}) {
    const std::string file = camopt::testing::SourcePath("studies/examples/") + name + ".json";
    nlohmann::json j = studies::LoadStudyFile(file);
    ASSERT_TRUE(j.contains("analysis")) << name;
    j["analysis"]["grid"] = {8, 8};
    if (j["analysis"].contains("crank_angle_steps")) j["analysis"]["crank_angle_steps"] = 3;
    if (j.contains("tuning")) {
      j["analysis"]["crank_angles_per_mesh_period"] = 2;
      j["tuning"]["curve_points"] = 3;
      j["tuning"]["max_evaluations"] = 3;
      if (j.contains("optimizer")) j["optimizer"]["max_evaluations"] = 3;
    }
    studies::RunContext ctx;
    ctx.study_file = file;
    ctx.quiet = true;
    const studies::Outputs out = studies::RunStudy(j, ctx);
    ASSERT_TRUE(out.files().count("result.json")) << name;
  }
}

TEST(CycloidStudies, LtcaBadInputExitsWithCode2) {
  const auto dir = camopt::testing::TempDir("cycloid-bad");
  camopt::testing::WriteFile(dir / "a.json", StudyJson(R"({"type": "elliptic"})", "{}"));
  auto r = camopt::testing::RunCamopt("run " + (dir / "a.json").string() + " --out " + (dir / "o").string() + " --quiet");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_text.find("/crowning/type"), std::string::npos) << r.stderr_text;
  std::string s = StudyJson(R"({"type": "none"})", "{}");
  s.replace(s.find("\"eccentricity_mm\": 4.5"), 22, "\"eccentricity_mm\": 7.5");
  camopt::testing::WriteFile(dir / "b.json", s);
  r = camopt::testing::RunCamopt("run " + (dir / "b.json").string() + " --out " + (dir / "o").string() + " --quiet");
  EXPECT_EQ(r.exit_code, 2);
  // e·N = 7.5 × 16 = 120 mm > a' = 90 − 0.016 mm: e must be below a'/N = 5.624 mm.
  EXPECT_NE(r.stderr_text.find("/drive/eccentricity_mm: eccentricity too large"), std::string::npos) << r.stderr_text;
  EXPECT_NE(r.stderr_text.find("e must be below 5.624 mm"), std::string::npos) << r.stderr_text;
}

const std::string kTuningStudy = R"({"study": "cycloid_crowning_tuning", "name": "t",)" + kNnmDriveJson + R"(
    "material": {"youngs_modulus_GPa": 206, "poisson_ratio": 0.3},
    "load": {"design_torque_Nm": 350, "max_torque_Nm": 550},
    "tuning": {"coefficient_mm": [0.0, 0.02], "curve_points": 4, "max_evaluations": 4},
    "analysis": {"crank_angles_per_mesh_period": 2, "grid": [10, 10]}})";

TEST(CycloidStudies, CrowningTuningFindsAFeasibleCoefficient) {
  const nlohmann::json study = nlohmann::json::parse(kTuningStudy);
  namespace tuning = studies::cycloid_crowning_tuning;
  const tuning::Study s = tuning::Parse(studies::Node(&study, "t.json", ""));
  studies::RunContext ctx;
  ctx.quiet = true;
  const tuning::Result r = tuning::Run(s, ctx);
  EXPECT_TRUE(r.feasible);
  EXPECT_GE(r.best.edge_margin_um, 0.0);
  // f = 0 (a straight tooth) touches the edges: infeasible, so the tuned f is above it.
  ASSERT_EQ(r.curve.size(), 4u);
  EXPECT_LT(r.curve[0].edge_margin_um, 0.0);
  EXPECT_GT(r.best.coefficient_mm, 0.0);
  // The tuned stress is no worse than any feasible point of the scan.
  for (const auto& c : r.curve)
    if (c.edge_margin_um >= 0) {
      EXPECT_LE(r.best.stress_MPa, c.stress_MPa + 1e-9);
    }
  // Every evaluation is counted: the scan, the reference and the optimizer's.
  EXPECT_EQ(r.evaluations, int(r.curve.size() + 1 + r.history.size()));
}

TEST(CycloidStudies, CrowningTuningIsTheSameWhateverRanBefore) {
  // The same study gives byte-identical result.json after another scan (other size) ran in the
  // same process; a point common to both scans has the same bits in both.
  namespace tuning = studies::cycloid_crowning_tuning;
  studies::RunContext ctx;
  ctx.quiet = true;
  auto run = [&](const std::string& text) {
    const nlohmann::json study = nlohmann::json::parse(text);
    const tuning::Study s = tuning::Parse(studies::Node(&study, "t.json", ""));
    const tuning::Result r = tuning::Run(s, ctx);
    return std::pair<tuning::Result, std::string>(r, studies::WriteResult(r).dump());
  };
  const auto [first, first_json] = run(kTuningStudy);
  std::string other = kTuningStudy;
  other.replace(other.find("\"curve_points\": 4"), 17, "\"curve_points\": 3");
  const auto [wide, wide_json] = run(other);
  const auto [again, again_json] = run(kTuningStudy);
  EXPECT_EQ(first_json, again_json);
  ASSERT_EQ(wide.curve.size(), 3u);
  EXPECT_EQ(wide.curve[0].stress_MPa, first.curve[0].stress_MPa);       // f = 0
  EXPECT_EQ(wide.curve[2].stress_MPa, first.curve[3].stress_MPa);       // f = 0.02
  EXPECT_EQ(wide.curve[2].edge_margin_um, first.curve[3].edge_margin_um);
}

TEST(CycloidStudies, CrowningTuningTakesAFiniteDropForm) {
  namespace tuning = studies::cycloid_crowning_tuning;
  std::string text = kTuningStudy;
  text.replace(text.find("\"tuning\""), 0,
               R"("crowning": {"type": "logarithmic", "effective_length_mm": 18.7, "end_drop_mm": 0.01}, )");
  const nlohmann::json study = nlohmann::json::parse(text);
  const tuning::Study s = tuning::Parse(studies::Node(&study, "t.json", ""));
  EXPECT_FALSE(s.tune_length);
  EXPECT_EQ(s.length_lo_mm, 18.7);
  EXPECT_EQ(s.shape.end_drop_mm, 0.01);
  const tuning::Result r = tuning::Run(s, studies::RunContext{"", true});
  for (const auto& e : r.history) EXPECT_EQ(e.length_mm, 18.7);
  // The scan's f = 0.02 point is that finite-drop crowning: the model run directly gives its bits.
  Crowning c;
  c.type = CrowningType::kLogarithmic;
  c.coefficient_mm = 0.02;
  c.effective_length_mm = 18.7;
  c.end_drop_mm = 0.01;
  LoadedOptions o = s.options;
  o.keep_pressure = false;
  const CycleResult d = RunCycle(LoadedTca(s.drive, c, s.material, o), 350.0e3,
                                 UniformCrankAngles(2, 2 * kPi / 16));
  EXPECT_EQ(r.curve.back().stress_MPa, d.max_pressure_MPa);
  // A crowning that is not logarithmic is an input error.
  std::string bad = kTuningStudy;
  bad.replace(bad.find("\"tuning\""), 0, R"("crowning": {"type": "full"}, )");
  const nlohmann::json jb = nlohmann::json::parse(bad);
  EXPECT_THROW(tuning::Parse(studies::Node(&jb, "t.json", "")), studies::StudyError);
}

TEST(CycloidStudies, CrowningTuningWritesItsFiles) {
  const auto dir = camopt::testing::TempDir("cycloid-tuning");
  camopt::testing::WriteFile(dir / "t.json", kTuningStudy);
  const auto r = camopt::testing::RunCamopt("run " + (dir / "t.json").string() + " --out " +
                                            (dir / "out").string() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  for (const char* f : {"result.json", "stress_vs_coefficient.csv", "history.csv", "stress_vs_coefficient.svg",
                        "edge_margin_vs_coefficient.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / f)) << f;
  const auto j = nlohmann::json::parse(camopt::testing::ReadFile(dir / "out" / "result.json"));
  EXPECT_TRUE(j["feasible"].get<bool>());
  // The scan: curve_points = 4 coefficients spread evenly over the study's range [0, 0.02] mm, with
  // result.json's values; the optimizer's history stays in that range.
  const auto curve = camopt::testing::ReadCsv(camopt::testing::ReadFile(dir / "out" / "stress_vs_coefficient.csv"));
  ASSERT_EQ(curve.at("coefficient_mm").size(), 4u);
  ASSERT_EQ(j["curve"].size(), 4u);
  for (size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(curve.at("coefficient_mm")[k], 0.02 * double(k) / 3, 1e-9 * 0.02) << k;  // 10 digits
    for (const char* c : {"max_contact_stress_MPa", "edge_margin_at_max_torque_um"}) {
      const double v = j["curve"][k][c].get<double>();
      EXPECT_NEAR(curve.at(c)[k], v, 1e-9 * std::max(1.0, std::abs(v))) << c << " " << k;
    }
  }
  const auto history = camopt::testing::ReadCsv(camopt::testing::ReadFile(dir / "out" / "history.csv"));
  ASSERT_FALSE(history.at("coefficient_mm").empty());
  for (double f : history.at("coefficient_mm")) {
    EXPECT_GE(f, 0.0);
    EXPECT_LE(f, 0.02);
  }
  // The registered runner writes what the C++ entry points return.
  namespace tuning = studies::cycloid_crowning_tuning;
  const nlohmann::json study = nlohmann::json::parse(kTuningStudy);
  const tuning::Study s = tuning::Parse(studies::Node(&study, "t.json", ""));
  EXPECT_EQ(camopt::testing::WithoutRunStamp(j),
            camopt::testing::WithoutRunStamp(studies::WriteResult(tuning::Run(s, studies::RunContext{"", true}))));
}

TEST(CycloidStudies, MisspeltNestedFieldIsRejected) {
  // Each would otherwise be read as its default: L = B, no required edge margin.
  nlohmann::json ltca = camopt::testing::Example("cycloid_ltca_nnm_lcm.json");
  ltca["crowning"]["efective_length_mm"] = 20;
  camopt::testing::ExpectStudyRejected(ltca, "cycloid-ltca-typo", "/crowning/efective_length_mm", "unknown field");
  nlohmann::json tuning = camopt::testing::Example("cycloid_crowning_tuning_nnm.json");
  tuning["tuning"]["edge_margin_mm"] = 0.002;
  camopt::testing::ExpectStudyRejected(tuning, "cycloid-tuning-typo", "/tuning/edge_margin_mm", "unknown field");
}

}  // namespace cycloid_ltca_test
}  // namespace camopt::cycloid
