// Tests of the transmission rigidity chain (the transmission-rigidity paper, docs/papers.md §4).
#include <array>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "model/rigidity/chain.h"
#include "model/rigidity/chain_elements.h"
#include "model/rigidity/elements.h"
#include "model/rigidity/lost_motion.h"
#include "studies/transmission_rigidity_study.h"
#include "tests/test_util.h"

namespace camopt::rigidity {
namespace rigidity_test {

constexpr double kG = 82500.0;   // MPa, the paper's steel
constexpr double kE = 205000.0;  // MPa

ElementSpec Torsion(double d_out, double d_in, double length, double g = kG) {
  return {ElementKind::kShaftTorsion, "shaft_torsion", "", {}, {g, d_out, d_in, length}};
}
ElementSpec Gear(double ratio, double backlash_rad = 0.0) {
  ElementSpec s{ElementKind::kGearStage, "gear_stage", "", {}, {ratio}};
  s.backlash_rad = backlash_rad;
  return s;
}
ElementSpec Coupling(double rigidity_nmm, double backlash_rad = 0.0) {
  ElementSpec s{ElementKind::kCoupling, "coupling", "", {}, {rigidity_nmm}};
  s.backlash_rad = backlash_rad;
  return s;
}

// ---- The paper's stepped shaft (eq. 1, eq. 2) ------------------------------------------------

TEST(Rigidity, SteppedShaftMatchesThePaper) {
  const std::vector<ElementSpec> shaft = {Torsion(30, 15, 40), Torsion(25, 15, 35),
                                          Torsion(22, 0, 160)};
  // The paper's compliances in rad/(N·m): 0.000006503, 0.00001271, 0.00008433 (4 digits).
  const double paper[3] = {0.000006503, 0.00001271, 0.00008433};
  for (int i = 0; i < 3; ++i) {
    const double c_nm = 1000.0 * EvaluateElement<double>(shaft[i], shaft[i].params).compliance;
    EXPECT_NEAR(c_nm, paper[i], 0.0005 * paper[i]) << "section " << i + 1;
  }
  const auto r = EvaluateChain(shaft);
  // 1/R = 0.00010354 -> 9,657 N·m/rad.
  EXPECT_NEAR(1000.0 * r.compliance_b, 0.00010354, 2e-8);
  EXPECT_NEAR(1.0e-3 / r.compliance_b, 9657.0, 1.0);
  // "Had we ignored the most rigid part - R1 - the result would have been 10,305."
  EXPECT_NEAR(1.0e-3 / (r.compliance_b - r.compliance_at_b[0]), 10305.0, 1.0);
  // "the overall rigidity is less ... than the least rigid part" and section 3 dominates.
  EXPECT_EQ(r.dominant, 2);
  EXPECT_LT(1.0e-3 / r.compliance_b, 1.0e-3 / r.compliance_at_b[2]);
  double sum = 0.0;
  for (double s : r.share) sum += s;
  EXPECT_NEAR(sum, 1.0, 1e-12);
}

TEST(Rigidity, HollowShaftIsTheDifferenceOfTwoSolidOnes) {
  // Torsional rigidity is additive in the polar moment: R(D, d) = R(D, 0) − R(d, 0).
  const double full = ShaftTorsionRigidity(kG, 40.0, 0.0, 100.0);
  const double core = ShaftTorsionRigidity(kG, 25.0, 0.0, 100.0);
  EXPECT_NEAR(ShaftTorsionRigidity(kG, 40.0, 25.0, 100.0), full - core, 1e-9 * full);
}

// ---- Beams: eq. 8 and the overhang against a numerical unit-load integral ---------------------

// Deflection at x = a of a beam under a unit load at a, by the unit-load method
// δ = ∫ M(x)² / (E J) dx, integrated numerically (midpoint rule) from the bending moment diagram.
double UnitLoadDeflection(const std::function<double(double)>& moment, double x0, double x1,
                          double ej) {
  const int n = 200000;
  const double h = (x1 - x0) / n;
  double s = 0.0;
  for (int i = 0; i < n; ++i) {
    const double m = moment(x0 + (i + 0.5) * h);
    s += m * m;
  }
  return s * h / ej;
}

TEST(Rigidity, SimplySupportedStiffnessMatchesUnitLoadIntegral) {
  const double d = 38.0, l1 = 130.0, l2 = 320.0, length = l1 + l2;
  const double j = BendingMoment(d, 0.0);
  // Unit load at x = l1 between supports at 0 and L: reactions l2/L and l1/L.
  auto moment = [&](double x) { return x < l1 ? x * l2 / length : (length - x) * l1 / length; };
  const double delta = UnitLoadDeflection(moment, 0.0, length, kE * j);
  EXPECT_NEAR(SimplySupportedStiffness(kE, j, l1, l2), 1.0 / delta, 1e-6 / delta);
}

TEST(Rigidity, OverhungStiffnessMatchesUnitLoadIntegral) {
  const double d = 30.0, span = 200.0, a = 60.0;
  const double j = BendingMoment(d, 12.0);
  // Supports at 0 and span, unit load at span + a: M = x a/span inside, (span + a − x) outside.
  auto moment = [&](double x) { return x < span ? x * a / span : span + a - x; };
  const double delta = UnitLoadDeflection(moment, 0.0, span + a, kE * j);
  EXPECT_NEAR(OverhungStiffness(kE, j, span, a), 1.0 / delta, 1e-6 / delta);
}

TEST(Rigidity, CantileverAndRodClosedForms) {
  // Cantilever: M = (L − x) under a unit tip load.
  const double length = 120.0, i = 20.0 * 40.0 * 40.0 * 40.0 / 12.0;
  auto moment = [&](double x) { return length - x; };
  const double delta = UnitLoadDeflection(moment, 0.0, length, kE * i);
  EXPECT_NEAR(CantileverStiffness(kE, i, length), 1.0 / delta, 1e-6 / delta);
  // Rod: 8 mm steel rod 120 mm long, E A / L = 205000 · 16π / 120 N/mm.
  EXPECT_NEAR(RodStiffness(kE, 8.0, 0.0, 120.0), kE * 16.0 * kPi / 120.0, 1e-9);
}

// ---- Gear stages (eq. 6) ---------------------------------------------------------------------

// An independent construction: apply a torque T at end B and follow it back through the chain.
// The shaft of element k carries T_k = T / Π N (stages after k); its twist c_k T_k appears at B
// divided by the same product (a reduction turns the far side's angle down). Backlash likewise.
double DeflectionAtB(const std::vector<Link<double>>& links, double torque_b) {
  double angle = 0.0;
  double product = 1.0;
  for (size_t i = links.size(); i-- > 0;) {
    const double torque_k = torque_b / product;
    angle += links[i].compliance * torque_k / product;
    product *= links[i].ratio;
  }
  return angle;
}

TEST(Rigidity, ReductionRaisesAndStepUpLowersTheTransmittedRigidity) {
  const double r_in = 2.0e6, r_out = 5.0e6;  // N·mm/rad
  for (double n : {4.0, 0.25}) {
    const std::vector<ElementSpec> chain = {Coupling(r_in), Gear(n), Coupling(r_out)};
    const auto r = EvaluateChain(chain);
    // Eq. 6: 1/R = 1/(R_i (Z_o/Z_i)²) + 1/R_o, with Z_o/Z_i = N.
    EXPECT_NEAR(1.0 / r.compliance_b, 1.0 / (1.0 / (r_in * n * n) + 1.0 / r_out), 1e-6);
    EXPECT_NEAR(1.0 / r.compliance_at_b[0], r_in * n * n, 1e-6);
    if (n > 1.0) {
      EXPECT_GT(1.0 / r.compliance_at_b[0], r_in);  // reduction raises
    } else {
      EXPECT_LT(1.0 / r.compliance_at_b[0], r_in);  // step-up lowers
    }
    // From the other end everything is undone: R_A = R_B / N².
    EXPECT_NEAR(r.compliance_a, r.compliance_b * n * n, 1e-15);
    // Against the torque-following construction.
    std::vector<Link<double>> links;
    for (const auto& s : chain) links.push_back(EvaluateElement<double>(s, s.params));
    EXPECT_NEAR(r.compliance_b * 1000.0, DeflectionAtB(links, 1000.0), 1e-15);
  }
}

TEST(Rigidity, BacklashIsCarriedThroughTheRatio) {
  const double b_coupling = 0.01, b_mesh = 0.002;  // rad
  for (double n : {5.0, 0.5}) {
    const std::vector<ElementSpec> chain = {Coupling(1e6, b_coupling), Gear(n, b_mesh),
                                            Coupling(3e6)};
    const auto r = EvaluateChain(chain);
    // The coupling's play on the fast shaft is b/N at B; the mesh's own play sits on B's shaft.
    EXPECT_NEAR(r.backlash_at_b[0], b_coupling / n, 1e-15);
    EXPECT_NEAR(r.backlash_at_b[1], b_mesh, 1e-15);
    EXPECT_NEAR(r.backlash_b, b_coupling / n + b_mesh, 1e-15);
    EXPECT_NEAR(r.backlash_a, b_coupling + b_mesh * n, 1e-15);
  }
}

TEST(Rigidity, TwoStagesCompose) {
  // Two stages 3 and 4 in a row equal one stage of 12.
  const auto two = EvaluateChain({Coupling(1e6, 0.01), Gear(3.0), Gear(4.0), Coupling(2e6)});
  const auto one = EvaluateChain({Coupling(1e6, 0.01), Gear(12.0), Coupling(2e6)});
  EXPECT_NEAR(two.compliance_b, one.compliance_b, 1e-18);
  EXPECT_NEAR(two.backlash_b, one.backlash_b, 1e-15);
  EXPECT_NEAR(two.total_ratio, 12.0, 1e-12);
}

TEST(Rigidity, GearMeshRigidityIsStiffnessTimesDrivenRadiusSquared) {
  // Eqs. 3–4: R_b = S r_b², measured on the driven gear; on the driving gear S r_a² = R_b / N².
  const double s = 4.0e5, r_b = 100.0, n = 5.0;
  ElementSpec g{ElementKind::kGearStage, "gear_stage", "", {}, {n, s, r_b}};
  const auto r = EvaluateChain({g});
  EXPECT_NEAR(1.0 / r.compliance_b, s * r_b * r_b, 1e-3);
  EXPECT_NEAR(1.0 / r.compliance_a, s * (r_b / n) * (r_b / n), 1e-3);
}

// ---- The paper's examples set up from their text --------------------------------------------

TEST(Rigidity, InputTransmissionNumbersGivenInTheText) {
  // Primary shaft Ø38 × 454 mm in torsion, referred to the camshaft through the 2:1 chain drive.
  const double r1 = kPi * kG * std::pow(38.0, 4) / (32.0 * 454.0);
  ElementSpec chain_span{ElementKind::kSpan, "chain_span", "", {}, {6000.0, 1000.0, 496.0, 122.0}};
  const auto r = EvaluateChain({Torsion(38, 0, 454), Gear(2.0), chain_span});
  EXPECT_NEAR(1.0 / r.compliance_at_b[0], 4.0 * r1, 1e-6 * r1);
  // Chain: 6e6 N/m for 1 m, 496 mm loaded, on a 122 mm chain-wheel: S r² = 6e6/0.496 · 0.122².
  EXPECT_NEAR(1.0e-3 / r.compliance_at_b[2], 6.0e6 / 0.496 * 0.122 * 0.122, 1e-6);
}

std::vector<ElementSpec> OutputTransmission(double pivot_d) {
  ElementSpec rod{ElementKind::kPullRod, "pull_rod", "", {}, {kE, 8.0, 0.0, 120.0, 90.0}};
  ElementSpec bend_rod{ElementKind::kShaftBending, "shaft_bending", "", {},
                       {kE, pivot_d, 0.0, 20.0, 260.0, 90.0}};
  ElementSpec bend_arm = bend_rod;
  bend_arm.params[5] = 60.0;
  return {rod, bend_rod, Torsion(pivot_d, 0.0, 240.0), bend_arm};
}

TEST(Rigidity, OutputTransmissionFollowsThePapersConclusions) {
  const auto r20 = EvaluateChain(OutputTransmission(20.0));
  // "torsion of the pivot shaft is by far the most elastic element".
  EXPECT_EQ(r20.dominant, 2);
  EXPECT_GT(r20.share[2], 0.8);
  // Pull-rod: E A / L at the 90 mm lever.
  EXPECT_NEAR(1.0 / r20.compliance_at_b[0], kE * 16.0 * kPi / 120.0 * 90.0 * 90.0, 1e-3);
  // "an increase from 20 mm to 24 mm would approximately double the overall rigidity".
  const auto r24 = EvaluateChain(OutputTransmission(24.0));
  const double gain = r20.compliance_b / r24.compliance_b;
  EXPECT_GT(gain, 1.9);
  EXPECT_LT(gain, std::pow(1.2, 4.0));  // at most the D⁴ of the shaft alone
}

// ---- Sensitivities ---------------------------------------------------------------------------

TEST(Rigidity, ElasticitiesObeyDimensionalHomogeneity) {
  // R of every element is (modulus) × (length)³, so scaling all lengths by λ scales R by λ³:
  // the length elasticities sum to 3 and the modulus elasticities to 1 (Euler's theorem).
  const std::vector<ElementSpec> chain = OutputTransmission(20.0);
  const auto el = RigidityElasticities(chain);
  double lengths = 0.0, moduli = 0.0;
  for (size_t k = 0; k < chain.size(); ++k)
    for (size_t q = 0; q < chain[k].params.size(); ++q) (q == 0 ? moduli : lengths) += el[k][q];
  EXPECT_NEAR(moduli, 1.0, 1e-12);
  EXPECT_NEAR(lengths, 3.0, 1e-12);
  // And they agree with a finite difference of the chain.
  auto perturbed = chain;
  const double h = 1e-6;
  perturbed[2].params[1] *= 1.0 + h;
  const double fd = (std::log(EvaluateChain(chain).compliance_b) -
                     std::log(EvaluateChain(perturbed).compliance_b)) / std::log1p(h);
  EXPECT_NEAR(el[2][1], fd, 1e-5);
}

TEST(Rigidity, ElementGradientsMatchCentralDifferences) {
  const std::vector<ElementSpec> specs = {
      Torsion(30, 15, 40),
      {ElementKind::kShaftBending, "", "", {}, {kE, 38, 10, 130, 320, 61}},
      {ElementKind::kShaftOverhung, "", "", {}, {kE, 38, 10, 200, 60, 61}},
      {ElementKind::kLinearStiffness, "", "", {}, {4e5, 50}},
      {ElementKind::kSpan, "", "", {}, {6000, 1000, 496, 122}},
      {ElementKind::kPullRod, "", "", {}, {kE, 8, 2, 120, 90}},
      {ElementKind::kLeverSection, "", "", {}, {kE, 20, 40, 120}},
      {ElementKind::kLeverStiffness, "", "", {}, {3e4, 120}},
      Coupling(3e6),
      {ElementKind::kGearStage, "", "", {}, {5, 4e5, 100}},
  };
  for (const ElementSpec& s : specs) {
    SCOPED_TRACE(static_cast<int>(s.kind));
    // Scale to O(1) variables so that the fixed-size Jacobian check sees every parameter.
    ASSERT_LE(s.params.size(), 6u);
    auto f = [&s](const auto& x) {
      using T = std::decay_t<decltype(x[0])>;
      std::vector<T> p;
      for (size_t q = 0; q < s.params.size(); ++q) p.push_back(x[q] * T(s.params[q]));
      const Link<T> l = EvaluateElement<T>(s, p);
      return std::vector<T>{T(1e6) * l.compliance * T(s.params[0]), l.ratio};
    };
    std::array<double, 6> x{};
    for (size_t q = 0; q < 6; ++q) x[q] = 1.0 + 0.01 * q;
    camopt::testing::ExpectJacobianMatchesCentralDifferences<6>(f, x, 1e-6, 1e-9);
  }
}

TEST(Rigidity, ChainGradientThroughAGearStageMatchesCentralDifferences) {
  // Variables: upstream rigidity, ratio, downstream rigidity, coupling backlash.
  auto f = [](const auto& x) {
    using T = std::decay_t<decltype(x[0])>;
    std::vector<Link<T>> links(3);
    links[0].compliance = T(1.0) / x[0];
    links[0].backlash = x[3];
    links[1].ratio = x[1];
    links[2].compliance = T(1.0) / x[2];
    const ChainResult<T> r = ComposeChain(links);
    return std::vector<T>{T(1.0) / r.compliance_b, T(1.0) / r.compliance_a, r.backlash_b,
                          r.backlash_a, r.share[0]};
  };
  camopt::testing::ExpectJacobianMatchesCentralDifferences<4>(f, {2.0, 3.0, 5.0, 0.01});
}

// ---- The chain rule of elasticities (model/rigidity/lost_motion.h) ----------------------------

TEST(RigidityChainRule, SeriesSpringsShareIsTheElasticityOfEach) {
  // Two springs in series: R = R1 R2/(R1 + R2), so ∂ln R/∂ln R1 = R2/(R1 + R2), the share of 1.
  const double r1 = 3.0e6, r2 = 1.0e6;
  const std::vector<ElementSpec> specs = {Coupling(r1), Coupling(r2)};
  const auto chain = EvaluateChain<double>(specs);
  EXPECT_NEAR(ChainElasticity(chain.share[0], 1.0), r2 / (r1 + r2), 1e-14);
  EXPECT_NEAR(ChainElasticity(chain.share[1], 1.0), r1 / (r1 + r2), 1e-14);
  // The AD elasticities of the whole chain agree.
  const auto el = RigidityElasticities(specs);
  EXPECT_NEAR(el[0][0], r2 / (r1 + r2), 1e-12);
  EXPECT_NEAR(el[1][0], r1 / (r1 + r2), 1e-12);
}

TEST(RigidityChainRule, UniformShaftInSeriesWithACoupling) {
  // A solid uniform shaft, R_s = π G D⁴/(32 L): ∂ln R_s/∂ln D = 4, ∂ln R_s/∂ln L = −1. In series
  // with a coupling R_c the chain's elasticity is that times R_c/(R_s + R_c).
  const double d = 30.0, l = 400.0, rc = 2.0e6;
  const double rs = kPi * kG * std::pow(d, 4) / (32.0 * l);
  const std::vector<ElementSpec> specs = {Torsion(d, 0.0, l), Coupling(rc)};
  const auto chain = EvaluateChain<double>(specs);
  const double share = rc / (rs + rc);
  ASSERT_NEAR(chain.share[0], share, 1e-12);
  const auto named = ChainElasticities<double>(chain.share[0], {{"outer_diameter_mm", 4.0}, {"length_mm", -1.0}});
  ASSERT_EQ(named.size(), 2u);
  EXPECT_EQ(named[0].first, "outer_diameter_mm");
  EXPECT_NEAR(named[0].second, 4.0 * share, 1e-12);
  EXPECT_NEAR(named[1].second, -share, 1e-12);
  const auto el = RigidityElasticities(specs);  // [G, D, d, L] of the shaft
  EXPECT_NEAR(el[0][1], 4.0 * share, 1e-10);
  EXPECT_NEAR(el[0][3], -share, 1e-10);
  // Over ceres::Jet the rule carries derivatives: d(share·e)/d share = e.
  using J = ceres::Jet<double, 1>;
  const J j = ChainElasticity(J(share, 0), J(4.0));
  EXPECT_DOUBLE_EQ(j.a, 4.0 * share);
  EXPECT_DOUBLE_EQ(j.v[0], 4.0);
}

TEST(Rigidity, ReportRadiusAndReferredRigidityClosedForms) {
  // Eq. 5 transposed: a rigidity R = 9657 N·m/rad at r = 60 mm is S = R/r² = 2682.5 N/mm.
  const double c = 1.0 / 9657.0e3;  // rad/(N·mm)
  EXPECT_NEAR(LinearStiffnessAtRadius(c, 60.0), 9657.0e3 / 3600.0, 1e-9);
  // Eq. 6: 8000 N·m/rad behind a 1:90 reduction is 8000/8100 N·m/rad at its input.
  EXPECT_NEAR(RigidityThroughRatio(8000.0, 90.0), 8000.0 / 8100.0, 1e-15);
  // Making a link rigid removes exactly its compliance referred to B.
  const std::vector<ElementSpec> specs = {Coupling(2.0e6), Gear(3.0), Coupling(5.0e6)};
  const auto chain = EvaluateChain<double>(specs);
  const double c0 = 1.0 / 2.0e6 / 9.0, c2 = 1.0 / 5.0e6;
  EXPECT_NEAR(chain.compliance_b_if_rigid[0], c2, 1e-20);
  EXPECT_NEAR(chain.compliance_b_if_rigid[2], c0, 1e-20);
  EXPECT_NEAR(chain.compliance_b_if_rigid[1], c0 + c2, 1e-20);
}

// ---- The study: numbers through the C++ entry points, exit codes and files through the CLI ---------------------------------------------------------------

TEST(RigidityStudy, ExamplesReportRigidityAndShares) {
  // Through the C++ entry points (Parse, Run, WriteResult).
  namespace tr = studies::transmission_rigidity;
  for (const std::string name : {"stepped_shaft", "input_transmission", "output_transmission",
                                 "gearbox"}) {
    SCOPED_TRACE(name);
    const nlohmann::json study = camopt::testing::Example("rigidity_" + name + ".json");
    const tr::Study s = tr::Parse(studies::Node(&study, name + ".json", ""));
    studies::RunContext ctx;
    ctx.quiet = true;
    const tr::Result r = tr::Run(s, ctx);
    const nlohmann::json j = studies::WriteResult(r);
    ASSERT_TRUE(j["rigidity_Nm_per_rad"].is_number());
    double sum = 0.0;
    for (const auto& e : j["elements"]) {
      ASSERT_TRUE(e.contains("rigidity_Nm_per_rad"));
      sum += e["compliance_share"].get<double>();
    }
    EXPECT_NEAR(sum, 1.0, 1e-9);
    if (name == "stepped_shaft") {
      EXPECT_NEAR(1.0e-3 / r.chain.compliance_b, 9657.0, 1.0);
    }
    if (name == "output_transmission") {
      // Eq. 5 transposed at the 60 mm follower arm: S = R / r².
      EXPECT_NEAR(j["linear_stiffness_at_report_radius_N_per_mm"].get<double>(),
                  j["rigidity_Nm_per_rad"].get<double>() * 1000.0 / 3600.0, 1e-6);
      EXPECT_EQ(r.elements[r.chain.dominant].spec.name, "pivot shaft torsion");
      EXPECT_EQ(j["dominant"]["name"], "pivot shaft torsion");
    }
  }
}

TEST(RigidityStudy, ExamplesRunThroughTheCli) {
  for (const std::string name : {"stepped_shaft", "input_transmission", "output_transmission",
                                 "gearbox"}) {
    SCOPED_TRACE(name);
    const auto dir = camopt::testing::TempDir("rigidity-" + name);
    const auto res = camopt::testing::RunCamopt(
        "run -q " + camopt::testing::SourcePath("studies/examples/rigidity_" + name + ".json") +
        " -o " + dir.string());
    ASSERT_EQ(res.exit_code, 0) << res.stderr_text;
    EXPECT_TRUE(std::filesystem::exists(dir / "result.json"));
    // The registered runner writes what the C++ entry points return.
    namespace tr = studies::transmission_rigidity;
    const nlohmann::json study = camopt::testing::Example("rigidity_" + name + ".json");
    const tr::Study s = tr::Parse(studies::Node(&study, name + ".json", ""));
    const nlohmann::json j = nlohmann::json::parse(camopt::testing::ReadFile(dir / "result.json"));
    EXPECT_EQ(camopt::testing::WithoutRunStamp(j), studies::WriteResult(tr::Run(s, studies::RunContext{"", true})));
    // elements.csv: a row per element of the study's chain; springs in series, so the element
    // rigidities referred to end B combine as 1/R = Σ 1/R_i to result.json's rigidity, and the
    // compliance shares sum to 1.
    const auto table = camopt::testing::ReadCsv(camopt::testing::ReadFile(dir / "elements.csv"));
    ASSERT_EQ(table.at("index").size(), study["chain"].size());
    double compliance = 0, shares = 0;
    for (size_t i = 0; i < study["chain"].size(); ++i) {
      compliance += 1.0 / table.at("rigidity_at_end_b_Nm_per_rad")[i];
      shares += table.at("compliance_share")[i];
    }
    const double rigidity = j["rigidity_Nm_per_rad"].get<double>();
    EXPECT_NEAR(1.0 / compliance, rigidity, 1e-8 * rigidity);
    EXPECT_NEAR(shares, 1.0, 1e-8);
  }
}

// The verdict's limits at end b: the gearbox example asks for 30 000 N·m/rad, 3 arcmin and 0.1°
// under 50 N·m; its backlash at end b is the coupling's 6′ and the stage's 3′ seen through the
// 5:1 stage, 6/5 + 3 = 4.2′ (by hand), so that limit alone fails.
TEST(RigidityStudy, LimitsAtEndBGiveTheVerdict) {
  namespace tr = studies::transmission_rigidity;
  nlohmann::json study = camopt::testing::Example("rigidity_gearbox.json");
  tr::Study s = tr::Parse(studies::Node(&study, "gearbox.json", ""));
  nlohmann::json j = studies::WriteResult(tr::Run(s, studies::RunContext{"", true}));
  EXPECT_NEAR(j["backlash_at_end_b_arcmin"].get<double>(), 6.0 / 5.0 + 3.0, 1e-9);
  EXPECT_TRUE(j["rigidity_ok"].get<bool>());
  EXPECT_FALSE(j["backlash_ok"].get<bool>());
  EXPECT_TRUE(j["deflection_ok"].get<bool>());
  EXPECT_FALSE(j["limits_ok"].get<bool>());
  const auto dir = camopt::testing::TempDir("rigidity-limits");
  camopt::testing::WriteFile(dir / "s.json", study.dump());
  const auto res = camopt::testing::RunCamopt("run -q --strict " + (dir / "s.json").string() + " -o " + (dir / "o").string());
  EXPECT_EQ(res.exit_code, 3);
  EXPECT_NE(res.stderr_text.find("1 of 3 limits exceeded: backlash at end b"), std::string::npos) << res.stderr_text;
  // Without limits: no verdict keys; a deflection limit without the torque is refused.
  study.erase("limits");
  s = tr::Parse(studies::Node(&study, "gearbox.json", ""));
  EXPECT_FALSE(studies::WriteResult(tr::Run(s, studies::RunContext{"", true})).contains("limits_ok"));
  study.erase("load_torque_Nm");
  study["limits"] = {{"deflection_deg", 0.1}};
  camopt::testing::WriteFile(dir / "bad.json", study.dump());
  const auto bad = camopt::testing::RunCamopt("run -q " + (dir / "bad.json").string() + " -o " + (dir / "b").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.stderr_text.find("/limits/deflection_deg"), std::string::npos) << bad.stderr_text;
}

TEST(RigidityStudy, BadInputIsAClearErrorWithExitCode2) {
  const auto dir = camopt::testing::TempDir("rigidity-bad");
  const std::string shaft =
      R"({"element": "shaft_torsion", "outer_diameter_mm": 20, "length_mm": 100})";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {R"({"study": "transmission_rigidity", "chain": []})", "/chain"},
      {R"({"study": "transmission_rigidity", "chain": [)" + shaft + "]}", "/material"},
      {R"({"study": "transmission_rigidity", "material": {"shear_modulus_GPa": 80},
          "chain": [{"element": "shaft_torsion", "outer_diameter_mm": 20, "inner_diameter_mm": 25,
          "length_mm": 100}]})", "/chain/0/inner_diameter_mm"},
      {R"({"study": "transmission_rigidity", "material": {"shear_modulus_GPa": 80},
          "chain": [{"element": "shaft_torsion", "outer_diameter_mm": -20, "length_mm": 100}]})",
       "/chain/0/outer_diameter_mm"},
      {R"({"study": "transmission_rigidity", "chain": [{"element": "spring"}]})", "/chain/0/element"},
      {R"({"study": "transmission_rigidity", "chain": [{"element": "coupling", "rigid": true}]})",
       "/chain"},
      {R"({"study": "transmission_rigidity", "chain": [{"element": "gear_stage", "ratio": 0}]})",
       "/chain/0/ratio"},
  };
  for (size_t i = 0; i < cases.size(); ++i) {
    const auto file = dir / ("bad" + std::to_string(i) + ".json");
    camopt::testing::WriteFile(file, cases[i].first);
    const auto res = camopt::testing::RunCamopt("run -q " + file.string() + " -o " +
                                                (dir / "out").string());
    EXPECT_EQ(res.exit_code, 2) << cases[i].first << "\n" << res.stderr_text;
    EXPECT_NE(res.stderr_text.find(cases[i].second), std::string::npos)
        << "expected the path " << cases[i].second << " in: " << res.stderr_text;
  }
}

TEST(RigidityStudy, MisspeltElementFieldIsRejected) {
  // A misspelt mesh rigidity would otherwise make the gear stage rigid.
  auto study = nlohmann::json::parse(R"({"study": "transmission_rigidity",
      "material": {"shear_modulus_GPa": 80, "youngs_modulus_GPa": 206},
      "chain": [{"element": "shaft_torsion", "outer_diameter_mm": 20, "length_mm": 100},
                {"element": "gear_stage", "ratio": 3, "rigidty_Nm_per_rad": 2000}]})");
  camopt::testing::ExpectStudyRejected(study, "rigidity-typo", "/chain/1/rigidty_Nm_per_rad", "unknown field");
  // A field of the other shaft support is not silently ignored either.
  study["chain"][1] = nlohmann::json::parse(R"({"element": "shaft_bending", "support": "overhung",
      "outer_diameter_mm": 20, "pitch_radius_mm": 40, "bearing_span_mm": 100, "overhang_mm": 30,
      "to_bearing_1_mm": 50})");
  camopt::testing::ExpectStudyRejected(study, "rigidity-support", "/chain/1/to_bearing_1_mm", "unknown field");
}

}  // namespace rigidity_test
}  // namespace camopt::rigidity
