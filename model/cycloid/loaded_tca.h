// Loaded tooth contact analysis (LTCA) of a cycloid stage with the elastic half-space compliance
// of each contacting pair. Cycloid load-distribution paper, eqs. (15)–(26).
//
// Per crank angle φ: the unloaded TCA gives each pair's arm l_i and backlash φ_bl,i. Under the
// torque T the disc turns further by Δφc; pair i is pressed by the approach δ_i = l_i (Δφc − φ_bl,i)
// when positive (compatibility, eq. 24) and carries the force F_i(δ_i) of its half-space contact
// problem (eqs. 15–23, the gap being the two circles' separations, eqs. 17–18, plus the crowning
// drop, eqs. 19); the moments balance: Σ F_i l_i = T (equilibrium, eq. 25). The paper iterates
// the pair compliances C_i = δ_i / F_i until loads and angle change by < 1 %; here the same fixed
// point is reached by a Newton-like iteration: each pair's law is modelled by a power law
// δ = δ1 (F/F1)^γ through its last solved point (γ measured from its last two solves, or carried
// from the previous crank angle), the model equations are solved exactly for Δφc (a monotone
// equation in one unknown), and each loaded pair whose force moved is solved again
// (load-controlled, warm-started from its last pressure). Converged when every pair's
// compatibility holds within the relative tolerance (typically 3 iterations per crank angle).
//
// Outputs: loads, pressure maps, pairs in contact, loaded transmission error (LTE = the disc lag
// β0 + Δφc; β0 is the unloaded TE) and, over a cycle, the instantaneous gear ratio (GR).
#pragma once

#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "model/common/material.h"
#include "model/contact/half_space.h"
#include "model/cycloid/crowning.h"
#include "model/cycloid/tooth_profile.h"
#include "model/cycloid/unloaded_tca.h"

namespace camopt::cycloid {

/// Disc and roller material (both the same; E* from model/common/material.h).
using Material = camopt::Material;

struct LoadedOptions {
  int profile_cells = 40;  ///< p, cells across the contact (profile direction)
  int axial_cells = 40;    ///< q, cells along the face width
  double tolerance = 1e-3; ///< relative compatibility residual of the pairs (paper: 1e-2)
  /// Relative tolerance of the half-space solver's final solves (its default is 1e-8; the cycle's
  /// peak pressure moves by 0.2 MPa in 1248 between 1e-4 and 1e-8, docs/performance.md; the
  /// compatibility tolerance above is coarser).
  double solver_tolerance = 1e-4;
  /// Solver tolerance of the first (steering) iterations; <= solver_tolerance disables them.
  double rough_solver_tolerance = 1e-2;
  int max_iterations = 40;
  /// Grid half-length in the profile direction, in Hertz line-contact half-widths at the pair's
  /// load (rounded up to a ladder of sizes so that grids, hence kernels, repeat). Enlarged when a
  /// pressure reaches the outer cells across the profile.
  double grid_half_width_factor = 1.6;
  /// Pairs whose backlash exceeds this [rad] are not considered (they cannot close under load).
  double max_backlash_rad = 5e-3;
  /// Keep every pair's pressure map in the results (for maps); off saves memory in sweeps.
  bool keep_pressure = true;
  /// Compute the edge margin of every pair (one extra convolution per loaded pair).
  bool edge_margin = false;
  /// Compute the LTE's derivative over the crank angle at every solve (MeshLoad::rotation_slope,
  /// the instantaneous gear ratio of a cycle): one implicit differentiation per solve. Off where
  /// no gear ratio is needed (the tuning loops).
  bool crank_slope = true;
  /// Relative residual of the crank slope's load-sensitivity solves (their CG). Measured on the
  /// NNM examples: the GR peak-to-peak at 1e-4 equals that at 1e-6 to 7 digits, at 15% less cost.
  double crank_slope_tolerance = 1e-4;
  /// Relative residual of the conjugate gradients of the implicit derivatives (Differentiate).
  double sensitivity_tolerance = 1e-10;
  /// Precondition the final-tolerance contact solves (contact::SolverOptions::precondition): 7
  /// instead of 19 CG iterations per final solve on the NNM cycle, each two FFT pairs
  /// (docs/performance.md). The steering solves run the plain iteration either way. Off in the
  /// cycloid sizing (CycloidSizingSpec::options).
  bool precondition_solves = true;
  /// RunCycle: solve each distinct phase of the crank angles modulo one roller pitch 2π/n1 once
  /// and copy its state, rollers relabelled, to the other angles of that phase (the drive's
  /// z_p-fold symmetry, see RunCycle). Off: every angle is solved.
  bool reuse_symmetric_angles = true;
};

/// One loaded roller-tooth pair at one crank angle.
struct PairLoad {
  int roller = 0;
  double load_N = 0;
  double approach_mm = 0;       ///< δ_i
  double max_pressure_MPa = 0;
  double arm_mm = 0;            ///< l_i
  double backlash_rad = 0;      ///< φ_bl,i
  double effective_radius_mm = 0;  ///< R' of the two profiles at the contact
  contact::Grid grid;
  std::vector<double> pressure_MPa;  ///< row-major iy * nx + ix, x across, y along the face
  /// Clearance left at the two axial edge rows [mm] (> 0: the pattern stays off the edges),
  /// minus (max edge-row pressure / E*) · dy when the contact reaches an edge, so that it is
  /// continuous and negative for edge contact. Filled when LoadedOptions::edge_margin.
  double edge_margin_mm = 0;
  /// Axial distance from the contact's end to the face end [mm], the end located within a cell
  /// from the row maxima (P² linear near an elliptical end); negative when the pressure indicates
  /// contact beyond the face end (bounded, continuous). Filled when LoadedOptions::edge_margin.
  double end_distance_mm = 0;
  int solver_iterations = 0;
};

/// The loaded state at one crank angle.
struct MeshLoad {
  double crank_angle_rad = 0;
  double unloaded_rotation_rad = 0;  ///< β0, unloaded TE
  double deflection_rad = 0;         ///< Δφc
  double rotation_rad = 0;           ///< β0 + Δφc, the loaded TE (disc lag)
  /// dLTE/dφ [rad/rad] by implicit differentiation at this solve (contact sets and loaded pairs
  /// frozen); NaN unless LoadedOptions::crank_slope.
  double rotation_slope = std::numeric_limits<double>::quiet_NaN();
  double max_pressure_MPa = 0;
  int pairs_in_contact = 0;          ///< pairs carrying load
  std::vector<PairLoad> pairs;       ///< the loaded pairs
  double edge_margin_mm = 0;         ///< min over loaded pairs (0 when none)
  double end_distance_mm = 0;        ///< min over loaded pairs (0 when none)
  int iterations = 0;                ///< outer (compatibility) iterations
  int contact_solves = 0;            ///< half-space solves
  long solver_iterations = 0;        ///< their conjugate-gradient iterations, summed
  long slope_iterations = 0;         ///< CG iterations of the crank slope's load sensitivities
  bool converged = true;
  std::string message;
  /// RunCycle's reuse by symmetry (LoadedOptions::reuse_symmetric_angles): -1 when this angle was
  /// solved; else the index, in that call's angles, of the solved angle whose state this is, with
  /// its roller r here roller (r + roller_shift) mod n1. A copy's counts (iterations,
  /// contact_solves, solver_iterations, slope_iterations) are 0: a cycle's sums count work done.
  int symmetric_source = -1;
  int roller_shift = 0;
};

/// What one LTCA solve leaves for the next one as a starting point: per roller, the last solved
/// point of its force law (F, δ, exponent) and its pressure field with the grid it was solved on.
/// Explicit and owned by the caller; passing one changes the cost of a solve, never its answer
/// beyond the compatibility and solver tolerances. The grid of every pair is a function of the
/// solve's inputs only (never of a warm start), so a pressure is reused only on the same grid.
struct LtcaWarmStart {
  struct Pair {
    contact::Grid grid;
    std::vector<double> pressure;
    double f1 = 0, d1 = 0;  // the last solved (F, δ) of the pair
    double gamma = 0.9;     // its measured exponent of δ ∝ F^γ
    // The pair's load sensitivity dp/dW of its last crank slope, on the grid it was solved on:
    // the start of the next slope's CG (LoadedOptions::crank_slope).
    contact::Grid sensitivity_grid;
    std::vector<double> load_sensitivity;
  };
  std::map<int, Pair> pairs;  // by roller
};

/// Per-angle LTCA. Immutable: a solve depends only on the drive, crowning, material, options,
/// torque and crank angle (bit for bit, whatever ran before), and on the warm start when one is
/// passed (within the tolerances). The half-space solvers' caches of kernels and FFT plans are
/// shared by the copies made by WithCrowning; they change the cost, not the numbers. Not
/// thread-safe (the solvers own work arrays); one instance (and its copies) per thread.
class LoadedTca {
 public:
  /// @throws std::invalid_argument for an infeasible drive or crowning (CheckDrive/CheckCrowning).
  LoadedTca(const Drive& drive, const Crowning& crowning, const Material& material,
            LoadedOptions options = {});

  /// LTCA at crank angle φ [rad] under the torque on the disc torque_Nmm [N·mm] (>= 0). When
  /// `warm` is given it is read as a starting point and updated with this solve's pairs.
  MeshLoad Solve(double torque_Nmm, double crank_angle_rad, LtcaWarmStart* warm = nullptr) const;

  /// A measured disc: its tooth moved by the normal deviation d(t) (model/common/profile_deviation.h)
  /// in the unloaded TCA of every solve (arms, backlash and β0 with d in each pair's contact, the
  /// tooth's curvature that of the moved profile; UnloadedTca). The drive then has no symmetry:
  /// solve with LoadedOptions::reuse_symmetric_angles and crank_slope off. Empty: the nominal disc.
  void SetProfileDeviation(profile::NormalDeviation<double> shape) { shape_ = std::move(shape); }

  /// Derivatives of a converged solve's outputs with respect to one parameter, by implicit
  /// differentiation with every pair's contact set and the set of loaded pairs frozen
  /// (implicit-function theorem): per pair one forward sensitivity for its load (its compliance
  /// dδ/dF), the approach's rate at fixed load dδ/ds from it by reciprocity, then the outer
  /// equations δ_i = l_i (Δφc − φ_bl,i), Σ l_i F_i = T differentiated. Parameters: the torque [N·mm] ("torque_Nmm"); the geometry
  /// "eccentricity_mm", "roller_position_radius_mm", "roller_radius_mm" and the profile
  /// modifications "delta_position_mm", "delta_radius_mm" (arms, backlash, the tooth's and the
  /// roller's curvature through the unloaded TCA with a Jet, the first-contact pair frozen); the
  /// crank angle "crank_angle_rad" (the same path: the LTE's slope dLTE/dφ of the instantaneous
  /// gear ratio); "face_width_mm" (the q rows stretch: the crowning drop at the moved rows, the
  /// half-space kernel's change contact::DisplacementRateByCellHeight, the larger cell area at
  /// fixed force; the pairs' x-grids, laddered, stay); and the crowning's coefficient_mm,
  /// effective_length_mm, end_drop_mm, flat_length_mm, radius_mm (per its type).
  /// @pre `solved` from Solve(torque_Nmm, ·) on this model with LoadedOptions::keep_pressure.
  /// @throws std::invalid_argument for an unknown parameter or a solve without pressures.
  struct Derivative {
    std::string parameter;
    double deflection_rad = 0;            ///< dΔφc/ds
    double rotation_rad = 0;              ///< d(β0 + Δφc)/ds, the LTE's derivative
    double unloaded_rotation_rad = 0;     ///< dβ0/ds, the unloaded TE's (geometry parameters)
    std::vector<double> pair_load_N;      ///< dF_i/ds, in the order of solved.pairs
    std::vector<double> pair_max_pressure_MPa;  ///< d p_i(peak cell)/ds, peak cell frozen
    double max_pressure_MPa = 0;          ///< of the pair carrying the maximum
    /// d(end distance)/ds of the solve's minimum (the pair nearest its face end), row maxima's
    /// cells frozen; filled when LoadedOptions::edge_margin.
    double end_distance_mm = 0;
    /// CG iterations of the sensitivities and adjoints behind this solve's derivatives (shared by
    /// every parameter of one call)
    long cg_iterations = 0;
    bool converged = true;
  };
  Derivative Differentiate(const MeshLoad& solved, const std::string& parameter) const;
  /// The same for several parameters at once, at the cost of one: per pair one forward
  /// sensitivity (its load) and one adjoint (its peak cell), plus one adjoint for the end distance
  /// (edge_margin) per solve, whatever the number of parameters; the approaches' rates by
  /// reciprocity.
  std::vector<Derivative> Differentiate(const MeshLoad& solved,
                                        const std::vector<std::string>& parameters) const;

  /// The same model with other profile modifications Δa, Δρ [mm] (tuning), sharing the solver
  /// caches. @throws std::invalid_argument for an infeasible drive.
  LoadedTca WithModification(double delta_position_mm, double delta_radius_mm) const;

  /// The same material and options with another drive and crowning (sizing), sharing the solver
  /// caches. @throws std::invalid_argument for an infeasible drive or crowning.
  LoadedTca WithDesign(const Drive& drive, const Crowning& crowning) const;

  /// The same model with another crowning (sweeps and tuning), sharing the solver caches.
  /// @throws std::invalid_argument for invalid crowning.
  LoadedTca WithCrowning(const Crowning& crowning) const;

  const Drive& drive() const { return drive_; }
  const Crowning& crowning() const { return crowning_; }
  const LoadedOptions& options() const { return options_; }
  double e_star_MPa() const { return e_star_; }

 private:
  /// Per pair of a solve (in the order of its pairs), the load sensitivity dp/dW on the pair's
  /// grid: in, a starting guess of its CG (empty: none); out, the solved one; with the CG
  /// iterations of the load sensitivities.
  struct LoadSensitivities {
    std::vector<std::vector<double>> by_pair;
    long iterations = 0;
  };
  /// rotation_only: the deflection and rotation alone (no pressure derivatives), the approach's
  /// rate at fixed load by reciprocity from the load sensitivity: one solve per pair, not 1 + k.
  /// load_sensitivities (optional): the starts and results of the load sensitivities.
  std::vector<Derivative> Differentiate(const MeshLoad& solved, const std::vector<std::string>& parameters,
                                        double sensitivity_tolerance, bool rotation_only,
                                        LoadSensitivities* load_sensitivities = nullptr) const;
  /// dLTE/dφ at crank_slope_tolerance; the load sensitivities start from the warm start's (when
  /// given) and are left in it; sets solved.slope_iterations.
  double CrankSlope(MeshLoad& solved, LtcaWarmStart* warm) const;
  contact::Grid MakeGrid(double half_x_mm) const;
  std::vector<double> Gap(const contact::Grid& grid, double effective_curvature_roller,
                          double profile_curvature) const;
  void SetCrowning(const Crowning& crowning);

  Drive drive_;
  Crowning crowning_;
  Material material_;
  LoadedOptions options_;
  double e_star_;
  std::vector<double> crown_;  // crowning drop per axial cell
  std::shared_ptr<contact::HalfSpaceSolver> solver_;        // final tolerance
  std::shared_ptr<contact::HalfSpaceSolver> rough_solver_;  // steering iterations
  profile::NormalDeviation<double> shape_;                  // a measured disc's d(t); empty: none
};

/// A mesh cycle: the LTCA at each crank angle, with the derived series.
struct CycleResult {
  std::vector<MeshLoad> meshes;
  std::vector<double> lte_arcsec;    ///< loaded TE per angle [arcsec]
  /// instantaneous ratio dφ_in/dφ_out = 1/(1/n2 + dLTE/dφ) per angle, from each mesh's
  /// rotation_slope (empty when the meshes carry none; the peak-to-peak is then NaN)
  std::vector<double> gear_ratio;
  double max_pressure_MPa = 0;
  int max_pressure_index = 0;        ///< angle index of the maximum
  double lte_peak_to_peak_arcsec = 0;
  double lte_mean_abs_arcsec = 0;
  double gear_ratio_peak_to_peak = 0;
  int max_pairs_in_contact = 0;
  double max_pair_load_N = 0;        ///< max over pairs and angles
  double edge_margin_mm = 0;         ///< min over angles
  double end_distance_mm = 0;        ///< min over angles
  int contact_solves = 0;
  long solver_iterations = 0;
  long slope_iterations = 0;         ///< of the crank slopes' load sensitivities, summed
  bool converged = true;
};

/// Runs the LTCA under the disc torque torque_Nmm [N·mm] over the crank angles [rad] (in order),
/// each solved angle warm-started from the previous solved one with a warm start local to the
/// call: the result is a function of the arguments only.
///
/// Symmetry (LoadedOptions::reuse_symmetric_angles, on by default). The model's drive is ideal:
/// n1 = n2 + 1 alike rollers on one circle (a, ρ), n2 alike teeth (one profile with the shared
/// modifications Δa, Δρ), one crowning, material and grid for every pair, and no output
/// mechanism or per-roller/per-tooth deviation in the LTCA (the deviations of
/// model/cycloid/transmission_error.h are not part of it). Turning the crank by one roller pitch
/// 2π/n1 then turns the eccentric by 2π/n1 and the disc by −2π/(n1 n2): in the disc frame every
/// roller centre moves to where its predecessor was, rotated by 2π/n1 + 2π/(n1 n2) = 2π/n2, one
/// tooth pitch, under which the tooth profile is invariant (eqs. 3–4, 12). So the state at
/// φ + m·2π/n1 is the state at φ with roller i renamed i + m (mod n1): the same LTE, loads,
/// arms, backlash, pressure maps (in each pair's own coordinates) and crank slope. An angle whose
/// phase φ mod 2π/n1 equals an earlier solved angle's within 1e-9 rad gets that state, relabelled
/// (MeshLoad::symmetric_source); the error of the match moves the state by the state's change over
/// 1e-9 rad of crank (the LTE by |dLTE/dφ|·1e-9 < 1e-11 rad, the loads by ~1e-8 of themselves), far
/// below the solver and compatibility tolerances, while the angles' own rounding is ~1e-15 rad.
/// Sixty uniform angles over 2π with n1 = 16 fall on 15 phases: 15 solves. Angle sets on distinct
/// phases (one mesh period, a half-step-shifted set of a period) solve every angle, as does the
/// option off. Every LoadedTca drive qualifies (CheckDrive asks n1 = n2 + 1); a model with
/// per-roller errors or an output mechanism in the LTCA would have to turn the reuse off.
/// Copies differ from solving their angle only within the tolerances (a different warm start).
/// The gear ratio uses each solve's exact derivative of the
/// LTE over the crank angle (LoadedOptions::crank_slope): a difference quotient of the LTE over a
/// small step divides the jumps of the discretised contact (a cell entering or leaving it) by the
/// step and has no crank-converged value.
CycleResult RunCycle(const LoadedTca& tca, double torque_Nmm, const std::vector<double>& crank_angles_rad,
                     const std::function<void(double)>& progress = nullptr);

/// The series and cycle values of RunCycle from the solved meshes (one per angle, in order): a
/// subset of a cycle's meshes (e.g. every second angle) gives the values of the coarser sampling.
/// @throws std::invalid_argument when the sizes differ.
CycleResult SummariseCycle(const Drive& drive, std::vector<MeshLoad> meshes,
                           const std::vector<double>& crank_angles_rad);

/// A smooth peak of the contact stress over a cycle: the soft-max
///   S = m + τ ln Σ_k exp((p_k − m)/τ),  m = max_k p_k,
/// over every (crank angle, loaded pair) peak pressure p_k with the temperature τ [MPa]. Its bias
/// is stated: 0 <= S − m <= τ ln N (N terms); it tends to the exact maximum as τ → 0 and is
/// differentiable where the exact maximum switches between angles or pairs.
double SmoothPeakPressure(const CycleResult& cycle, double temperature_MPa);

/// Derivatives of the cycle's outputs with respect to one parameter (LoadedTca::Differentiate at
/// every crank angle, at the converged states).
struct CycleDerivative {
  std::string parameter;
  double smooth_peak_MPa = 0;           ///< d SmoothPeakPressure(τ)
  double max_pressure_MPa = 0;          ///< d(exact maximum), at its active angle and pair
  double lte_peak_to_peak_arcsec = 0;   ///< at the active angles of the LTE's max and min
  double max_pair_load_N = 0;           ///< at the active angle and pair
  double end_distance_mm = 0;           ///< d(min over angles), active angle (edge_margin only)
  std::vector<double> rotation_rad;     ///< per angle, d LTE
  std::vector<double> unloaded_rotation_rad;  ///< per angle, dβ0 (the unloaded TE)
  std::vector<double> max_pressure_per_angle_MPa;  ///< per angle (its peak pair)
  std::vector<double> end_distance_per_angle_mm;   ///< per angle (edge_margin only)
  std::vector<std::vector<double>> pair_load_N;    ///< per angle, per loaded pair (in its order)
  /// per angle, per loaded pair (in its order): d(the pair's peak pressure)/ds, peak cell frozen
  std::vector<std::vector<double>> pair_max_pressure_MPa;
  long cg_iterations = 0;  ///< the CG iterations of every sensitivity and adjoint (all parameters)
  bool converged = true;
};

/// The cycle's derivatives for each parameter (names as LoadedTca::Differentiate). The cycle must
/// come from RunCycle(tca, …) with LoadedOptions::keep_pressure; τ as SmoothPeakPressure. Every
/// parameter is shared by all rollers and teeth (and the crank angle), so at a mesh copied by
/// symmetry (MeshLoad::symmetric_source) the derivatives are its source's, pairs relabelled; they
/// are reused when the source is found in the cycle (an earlier solved mesh on the same phase
/// whose pairs, relabelled, are the copy's bit for bit), else differentiated.
std::vector<CycleDerivative> DifferentiateCycle(const LoadedTca& tca, const CycleResult& cycle,
                                                const std::vector<std::string>& parameters,
                                                double temperature_MPa);

/// Uniform crank angles over [0, span) [rad].
std::vector<double> UniformCrankAngles(int steps, double span_rad);

constexpr double kArcsecPerRad = 180.0 * 3600.0 / kPi;

}  // namespace camopt::cycloid
