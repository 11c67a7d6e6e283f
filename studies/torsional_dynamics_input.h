// The "torsional_dynamics" block of cycloid_ltca and lcr_analysis (docs/torsional_dynamics.md):
// the reducer's lumped torsional model (model/common/torsional_dynamics.h) with the mesh stiffness
// each kind tabulates from its own loaded contact over one mesh period; natural frequencies, mode
// shapes, the dynamic transmission error and overload over an input-speed sweep, resonance speeds,
// and the overload limit of the kind's verdict. Shared parsing, run, result.json and CSV files.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "model/common/torsional_dynamics.h"
#include "studies/archive.h"
#include "studies/input.h"
#include "studies/report.h"
#include "studies/study.h"

namespace camopt::studies {

inline constexpr int kDefaultTorsionalAnglesPerMeshPeriod = 32;

struct TorsionalDynamicsInput {
  double input_inertia_kgm2 = 0, output_inertia_kgm2 = 0;
  std::array<double, 3> speed_sweep_rpm{};
  std::optional<double> input_shaft_stiffness_Nm_per_rad, load_torque_Nm, max_dynamic_factor;
  double damping_ratio = 0.02;
  int angles_per_mesh_period = kDefaultTorsionalAnglesPerMeshPeriod;
  int harmonics = 3;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("input_inertia_kgm2", &input_inertia_kgm2,
             Field().Required().Positive().Unit("kg·m²").Desc(
                 "J_in on the input (crank, eccentric) shaft: motor rotor, input shaft and crank"));
    a->Visit("output_inertia_kgm2", &output_inertia_kgm2,
             Field().Required().Positive().Unit("kg·m²").Desc("J_out on the output: output flange, arm and payload"));
    a->Visit("speed_sweep_rpm", &speed_sweep_rpm,
             Field().Required().Positive().Expect("[lo, hi, n]: speeds > 0, lo < hi, n a whole number in [2, 2000]")
                 .Desc("[lo, hi, n]: n uniform INPUT (crank, eccentric shaft) speeds from lo to hi [rpm]"));
    a->Visit("input_shaft_stiffness_Nm_per_rad", &input_shaft_stiffness_Nm_per_rad,
             Field().Positive().Unit("N·m/rad").Desc(
                 "k_s between the motor (turning at the swept speed) and J_in, at the input (absent: J_in driven "
                 "by a constant motor torque that balances the load, a free pair)"));
    a->Visit("damping_ratio", &damping_ratio,
             Field().Above(0.0, "a number > 0 (an undamped pair has no steady state)").AtMost(1.0)
                 .Desc("ζ of the mesh (and input shaft) mode, viscous"));
    a->Visit("load_torque_Nm", &load_torque_Nm,
             Field().Positive().Unit("N·m").Desc("T_L on the output, where the mesh is linearised (absent: the "
                                                "study's torque)"));
    a->Visit("max_dynamic_factor", &max_dynamic_factor,
             Field().Above(1.0, "a number > 1").Desc(
                 "limit of the verdict: the sweep's largest dynamic overload factor (max mesh torque / static)"));
    a->Visit("angles_per_mesh_period", &angles_per_mesh_period,
             Field().AtLeast(4).AtMost(1024, "at most 1024")
                 .Desc("uniform crank angles of the mesh stiffness table per mesh period (even; with two meshes, "
                       "as the LCR's turrets, per period of the faster one)"));
    a->Visit("harmonics", &harmonics,
             Field().AtLeast(1).AtMost(10, "at most 10").Desc("orders of the mesh frequency whose resonances are marked"));
  }
  static std::vector<CrossFieldRule> CrossFieldRules() {
    return {{{"speed_sweep_rpm"}, "the sweep [lo, hi, n]: lo < hi, n a whole number in [2, 2000]",
             "expected [lo, hi, n] with"}};
  }
};

/// The parsed block: the model's options and the sweep.
struct TorsionalDynamicsSpec {
  TorsionalDynamicsInput in;
  double lo_rpm = 0, hi_rpm = 0;
  int speeds = 0;
};

/// Checks what spans the block's fields ([lo, hi, n]; an even angle count): StudyError (exit 2)
/// naming /…/torsional_dynamics/speed_sweep_rpm.
TorsionalDynamicsSpec ParseTorsionalDynamics(const Node& block, const TorsionalDynamicsInput& in);

/// A kind's mesh over one mesh period, at the output: angles θ_k = k·period/N of the crank.
struct MeshTable {
  double period_rad = 0;  ///< crank angle of one mesh period
  double ratio = 0;       ///< input turns per output turn
  double torque_Nm = 0;   ///< T_ref, the torque the table is linearised at
  std::vector<double> angles_rad, stiffness_Nm_per_rad, static_te_rad;
  std::string source;  ///< how k(θ) was obtained (result.json "mesh_stiffness_source")
  /// The meshes whose engagement makes the table periodic: name and mesh periods per table period
  /// (a cycloid stage: its ring pins, 1; the LCR: each turret, a whole number each).
  std::vector<std::pair<std::string, double>> meshes;
  /// The tangent stiffness by the table's own check, if any (e.g. a finite difference); empty: none.
  std::vector<double> check_stiffness_Nm_per_rad;
};

struct TorsionalDynamicsResult {
  MeshTable table;
  torsion::Modes modes;
  std::vector<torsion::SteadyState> sweep;
  std::vector<torsion::ResonanceSpeed> resonances;
  /// Sampling error of the table's mean/min/max: against every other angle (the half table).
  double mean_error = 0, min_error = 0, max_error = 0;
  int peak_index = -1;  ///< the sweep's largest overload factor (stable rows)
  std::vector<std::string> warnings;
};

/// The model on the table and the sweep (progress on stderr). @throws StudyError (exit 2) when the
/// sweep starts so slow that one table period holds more than 2000 periods of the highest mode.
TorsionalDynamicsResult RunTorsionalDynamics(const TorsionalDynamicsSpec& spec, MeshTable table,
                                             const RunContext& ctx, const std::string& kind);

/// result.json's "torsional_dynamics" object.
nlohmann::json TorsionalDynamicsJson(const TorsionalDynamicsSpec& spec, const TorsionalDynamicsResult& r);

/// mesh_stiffness.csv and dynamic_te.csv.
void WriteTorsionalDynamics(const TorsionalDynamicsResult& r, Outputs& out);

/// The JSON Schema of the block TorsionalDynamicsJson writes (result.json's torsional_dynamics of
/// cycloid_ltca, lcr_analysis and cycloid_min_size): the keys camopt reads, with their types.
nlohmann::ordered_json TorsionalDynamicsResultSchema();

/// report.html's headlines of the torsional_dynamics block: the first natural frequency, the mesh
/// stiffness ripple, the sweep's peak overload factor (against torsional_dynamics.max_dynamic_factor,
/// with its sampling error) and the input speed it is at.
std::vector<Headline> TorsionalDynamicsHeadlines();

}  // namespace camopt::studies
