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

/// result.json's "torsional_dynamics" (docs/torsional_dynamics.md): the modes, the mesh table's
/// stiffness and its sampling error, the resonance speeds, the sweep's peak and its limit.
struct TorsionalDynamicsBlock {
  struct ModeShape {
    double input_referred = 0, output = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("input_referred", &input_referred, Field().Desc("θ_in / i"));
      a->Visit("output", &output, Field().Desc("θ_out"));
    }
  };
  struct Mesh {
    std::string name;
    double mesh_periods_per_input_revolution = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("name", &name, Field());
      a->Visit("mesh_periods_per_input_revolution", &mesh_periods_per_input_revolution, Field());
    }
  };
  struct EstimatedError {
    double mean_mesh_stiffness_Nm_per_rad = 0, min_mesh_stiffness_Nm_per_rad = 0, max_mesh_stiffness_Nm_per_rad = 0;
    std::string note;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("mean_mesh_stiffness_Nm_per_rad", &mean_mesh_stiffness_Nm_per_rad, Field().NullWhenNotFinite().Unit("N·m/rad"));
      a->Visit("min_mesh_stiffness_Nm_per_rad", &min_mesh_stiffness_Nm_per_rad, Field().NullWhenNotFinite().Unit("N·m/rad"));
      a->Visit("max_mesh_stiffness_Nm_per_rad", &max_mesh_stiffness_Nm_per_rad, Field().NullWhenNotFinite().Unit("N·m/rad"));
      a->Visit("note", &note, Field());
    }
  };
  struct Resonance {
    double input_speed_rpm = 0, frequency_Hz = 0;
    std::string mesh;
    int order = 0, mode = 0;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("input_speed_rpm", &input_speed_rpm, Field().Unit("rpm"));
      a->Visit("mesh", &mesh, Field().Desc("the mesh whose order excites it"));
      a->Visit("order", &order, Field().Desc("the harmonic of that mesh's frequency"));
      a->Visit("mode", &mode, Field().Desc("the mode, from 1"));
      a->Visit("frequency_Hz", &frequency_Hz, Field().Unit("Hz"));
    }
  };
  struct SweepPeak {
    double input_speed_rpm = 0, overload_factor = 0, dynamic_te_peak_to_peak_arcsec = 0, nearest_resonance_rpm = 0;
    double overload_sampling_error = 0;
    std::vector<double> mesh_frequencies_Hz;
    bool within_one_step_of_resonance = false;
    std::string note;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("input_speed_rpm", &input_speed_rpm, Field().Unit("rpm"));
      a->Visit("mesh_frequencies_Hz", &mesh_frequencies_Hz, Field().Unit("Hz").Desc("each mesh's, as meshes"));
      a->Visit("overload_factor", &overload_factor, Field().Desc("the dynamic overload factor at the sweep's peak"));
      a->Visit("dynamic_te_peak_to_peak_arcsec", &dynamic_te_peak_to_peak_arcsec, Field().Unit("arcsec"));
      a->Visit("nearest_resonance_rpm", &nearest_resonance_rpm,
               Field().NullWhenNotFinite().Unit("rpm").Desc("null: no resonance in the sweep"));
      a->Visit("within_one_step_of_resonance", &within_one_step_of_resonance, Field());
      a->Visit("overload_sampling_error", &overload_sampling_error,
               Field().NullWhenNotFinite().Desc("its sampling error, the largest over the sweep"));
      a->Visit("note", &note, Field());
    }
  };
  struct OverloadLimit {
    double max_dynamic_factor = 0;
    bool met = false;
    template <typename Archive>
    void Serialize(Archive* a) {
      a->Visit("max_dynamic_factor", &max_dynamic_factor, Field().Desc("the study's limit"));
      a->Visit("met", &met, Field().Desc("the peak within the limit plus its sampling error"));
    }
  };
  std::vector<double> natural_frequencies_Hz;
  std::vector<ModeShape> mode_shapes;
  std::string mode_shapes_note, mesh_stiffness_source, model;
  double ratio = 0, reference_torque_Nm = 0, table_periods_per_input_revolution = 0;
  std::vector<Mesh> meshes;
  double mean_mesh_stiffness_Nm_per_rad = 0, min_mesh_stiffness_Nm_per_rad = 0, max_mesh_stiffness_Nm_per_rad = 0;
  double mesh_stiffness_ripple_percent = 0;
  EstimatedError estimated_error;
  double mesh_damping_Nms_per_rad = 0, damping_ratio = 0, sweep_step_rpm = 0;
  std::vector<Resonance> resonances;
  std::vector<double> resonance_speeds_rpm;
  std::optional<SweepPeak> sweep_peak;
  std::optional<double> max_periodicity_residual;
  std::optional<OverloadLimit> overload_limit;
  template <typename Archive>
  void Serialize(Archive* a) {
    a->Visit("natural_frequencies_Hz", &natural_frequencies_Hz, Field().Unit("Hz"));
    a->Visit("mode_shapes", &mode_shapes, Field());
    a->Visit("mode_shapes_note", &mode_shapes_note, Field());
    a->Visit("ratio", &ratio, Field().Desc("input turns per output turn"));
    a->Visit("reference_torque_Nm", &reference_torque_Nm, Field().Unit("N·m").Desc("T_ref, where the mesh is linearised"));
    a->Visit("meshes", &meshes, Field());
    a->Visit("table_periods_per_input_revolution", &table_periods_per_input_revolution, Field());
    a->Visit("mesh_stiffness_source", &mesh_stiffness_source, Field());
    a->Visit("mean_mesh_stiffness_Nm_per_rad", &mean_mesh_stiffness_Nm_per_rad, Field().Unit("N·m/rad"));
    a->Visit("min_mesh_stiffness_Nm_per_rad", &min_mesh_stiffness_Nm_per_rad, Field().Unit("N·m/rad"));
    a->Visit("max_mesh_stiffness_Nm_per_rad", &max_mesh_stiffness_Nm_per_rad, Field().Unit("N·m/rad"));
    a->Visit("mesh_stiffness_ripple_percent", &mesh_stiffness_ripple_percent, Field().NullWhenNotFinite().Unit("%"));
    a->Visit("estimated_error", &estimated_error, Field().Desc("of the table's stiffness by angle sampling"));
    a->Visit("mesh_damping_Nms_per_rad", &mesh_damping_Nms_per_rad, Field().Unit("N·m·s/rad"));
    a->Visit("damping_ratio", &damping_ratio, Field());
    a->Visit("resonances", &resonances, Field());
    a->Visit("resonance_speeds_rpm", &resonance_speeds_rpm, Field().Unit("rpm"));
    a->Visit("sweep_step_rpm", &sweep_step_rpm, Field().Unit("rpm"));
    a->Visit("sweep_peak", &sweep_peak,
             Field().NullWhenAbsent().Desc("null when no swept speed has a stable periodic solution"));
    a->Visit("max_periodicity_residual", &max_periodicity_residual, Field().NullWhenNotFinite().Desc("with a peak"));
    a->Visit("overload_limit", &overload_limit, Field().Desc("with max_dynamic_factor"));
    a->Visit("model", &model, Field());
  }
  static TorsionalDynamicsBlock Of(const TorsionalDynamicsSpec& spec, const TorsionalDynamicsResult& r);
};

/// mesh_stiffness.csv and dynamic_te.csv.
void WriteTorsionalDynamics(const TorsionalDynamicsResult& r, Outputs& out);


/// report.html's headlines of the torsional_dynamics block: the first natural frequency, the mesh
/// stiffness ripple, the sweep's peak overload factor (against torsional_dynamics.max_dynamic_factor,
/// with its sampling error) and the input speed it is at.
std::vector<Headline> TorsionalDynamicsHeadlines();

}  // namespace camopt::studies
