// AnalyzeCycle's double fast path (declared in cycle.h): structure-of-arrays buffers reused over
// the angles, so that the per-roller square roots and divisions run two at a time; the same
// operations in the same order as AnalyzeAngle (contact.h, forces.h), hence the same bits.
#include "model/lcr/cycle.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>
#include <utility>

namespace camopt::lcr {

namespace internal {
namespace {

/// Reusable per-turret buffers of the double fast path of AnalyzeCycle, in structure-of-arrays
/// form so that the per-roller square roots and divisions of one turret run several at a time.
struct TurretBuffers {
  std::vector<double> cx, cy;            // roller centres O_k [mm]
  std::vector<double> arm, dx, dy, kappa;  // a_k, d_k, κ_k (contact.h's RollerContact, without the point)
  std::vector<double> loaded;            // PositivePart(sign · a_k)
};

void Resize(TurretBuffers& b, int n) {
  for (auto* v : {&b.cx, &b.cy, &b.arm, &b.dx, &b.dy, &b.kappa, &b.loaded}) v->resize(n);
}

/// The slots u(2πi/n) of one turret (TurretSlots), a copy for the cycle.
std::vector<Vec2<double>> Slots(const CamSide<double>& c) {
  return c.rollers > 0 ? TurretSlots(c.rollers) : std::vector<Vec2<double>>{};
}

/// Roller centres of one turret at θ into b.cx, b.cy: the same expressions as RollerCentres.
void FillCentres(TurretBuffers& b, const Reducer<double>& r, Side s, const std::vector<Vec2<double>>& slots,
                 double theta) {
  const CamSide<double>& c = r.side(s);
  if (s == Side::kInput) {
    for (int i = 0; i < c.rollers; ++i) b.cx[i] = c.turret_radius * slots[i].x(), b.cy[i] = c.turret_radius * slots[i].y();
    return;
  }
  const Vec2<double> turn = U(OutputSpeedRatio(r) * theta);
  for (int i = 0; i < c.rollers; ++i) {
    const Vec2<double> o = RotatedSlot(c.turret_radius, slots[i], turn);
    b.cx[i] = o.x(), b.cy[i] = o.y();
  }
}

/// The per-roller loop of FillContacts over plain arrays (restrict: no aliasing, so it vectorises).
void ContactKernel(const CamSide<double> c, double e, double px, double py, double ex, double ey,
                          double sign, int n, const double* __restrict cx, const double* __restrict cy,
                          double* __restrict arm, double* __restrict dx, double* __restrict dy,
                          double* __restrict kappa, double* __restrict loaded) {
  const double inv_radius = 1.0 / c.turret_radius;
  for (int k = 0; k < n; ++k) {
    const double vx = px - cx[k], vy = py - cy[k];
    const double norm = std::sqrt(vx * vx + vy * vy);
    const double inv = 1.0 / norm;
    const double ux = vx * inv, uy = vy * inv;
    dx[k] = ux, dy[k] = uy;
    const double a = cx[k] * uy - cy[k] * ux;
    arm[k] = a;
    const double sa = sign * a;
    loaded[k] = sa > 0.0 ? sa : 0.0;  // PositivePart
    kappa[k] = PitchCurvatureAtPitchDistance(c, e, (cx[k] * ex + cy[k] * ey) * inv_radius, inv);
  }
}

/// FillStresses' largest Hertz stress of one turret (0 when nothing is loaded, +∞ when a loaded
/// roller sits on an undercut part of the pitch curve), branch-free over plain arrays so that it
/// vectorises. It takes the maximum of p² and one square root of it: the root is monotonic and
/// correctly rounded, so this is bit for bit the maximum of FillStresses' per-roller p.
double MaxStressKernel(int n, const double* __restrict force, const double* __restrict kappa,
                       double roller_radius, double length, double e_star) {
  double max_sq = 0.0;
  for (int k = 0; k < n; ++k) {
    const double r_eff = roller_radius * (1.0 - roller_radius * kappa[k]);
    // NaN or negative where r_eff <= 0: replaced by the choice below.
    const double q = contact::LineContactPeakPressureSquared(force[k], length, r_eff, e_star);
    const bool loaded = force[k] > 0;  // p → 0 continuously as F → 0
    const bool convex = r_eff > 0;
    const double p_sq = loaded ? (convex ? q : kInf) : 0.0;
    max_sq = p_sq > max_sq ? p_sq : max_sq;
  }
  return std::sqrt(max_sq);
}

/// The contact geometry of RollerContacts (same operations in the same order, so the same bits),
/// written as plain loops over arrays that the compiler vectorises.
void FillContacts(TurretBuffers& b, const Reducer<double>& r, Side s, const Vec2<double>& ecc,
                         double sign) {
  const CamSide<double>& c = r.side(s);
  const Vec2<double> pitch = r.eccentricity * double(c.pitch_factor()) * ecc;  // PitchPointOfCam
  ContactKernel(c, r.eccentricity, pitch.x(), pitch.y(), ecc.x(), ecc.y(), sign, c.rollers, b.cx.data(),
                b.cy.data(), b.arm.data(), b.dx.data(), b.dy.data(), b.kappa.data(), b.loaded.data());
}

/// Both turrets' contacts at θ (u = u(θ)) into the buffers, the output turret's centres first, and
/// each turret's Σ a² (internal::SumLoadedArmSquares), as AnalyzeAngle has them; throws as it does.
/// @pre the input turret's centres are in a (they do not move).
std::pair<double, double> FillTurrets(TurretBuffers& a, TurretBuffers& b, const Reducer<double>& r,
                                      const std::vector<Vec2<double>>& slots_b, double theta,
                                      const Vec2<double>& u, double sign_a, double sign_b) {
  FillCentres(b, r, Side::kOutput, slots_b, theta);
  FillContacts(a, r, Side::kInput, u, sign_a);
  FillContacts(b, r, Side::kOutput, u, sign_b);
  double sum_a = 0.0, sum_b = 0.0;  // SumLoadedArmSquares
  for (double x : a.loaded) sum_a += x * x;
  for (double x : b.loaded) sum_b += x * x;
  if (!(sum_a > 0) || !(sum_b > 0)) throw std::domain_error("no roller of a turret can carry load at this input angle");
  return {sum_a, sum_b};
}

/// G per N·mm of output torque (AnalyzeAngle's per_torque, summed in its order) from the contacts
/// in the buffers and Σ a² of each turret.
Vec2<double> EccentricLoadPerTorque(const TurretBuffers& a, const TurretBuffers& b, const Reducer<double>& r,
                                    double sum_a, double sum_b) {
  double px = 0.0, py = 0.0;
  const LoadCase unit_torque_load{1.0};  // C per N·mm of output torque (AnalyzeAngle's)
  const double unit_a = ForceScale(r, Side::kInput, unit_torque_load, sum_a, sum_b);
  const double unit_b = ForceScale(r, Side::kOutput, unit_torque_load, sum_a, sum_b);
  for (auto [buf, c] : {std::pair{&a, unit_a}, std::pair{&b, unit_b}})
    for (size_t k = 0; k < buf->loaded.size(); ++k) {
      const double w = c * buf->loaded[k];
      px += w * buf->dx[k], py += w * buf->dy[k];
    }
  return {px, py};
}

}  // namespace
}  // namespace internal

// AnalyzeCycle: see cycle.h.
CycleSeries AnalyzeCycle(const Reducer<double>& r, const Material& material, const LoadCase& load,
                         int steps, const Stages& stages, const std::function<void(double)>& progress) {
  CycleSeries s;
  s.theta_rad.reserve(steps);
  const bool any_stage = stages.forces || stages.stress || stages.efficiency;
  for (auto [series, cam] : {std::pair{&s.input, &r.input}, std::pair{&s.output, &r.output}}) {
    series->actuating.reserve(steps);
    series->max_force_N.reserve(steps);
    series->max_stress_MPa.reserve(steps);
    series->turret_torque_Nmm.reserve(steps);
    series->roller_force_N.Reset(any_stage ? cam->rollers : 0, steps);  // no forces: empty rows
    if (stages.stress && stages.roller_stress) series->roller_stress_MPa.Reset(cam->rollers, steps);
  }
  for (auto* v : {&s.tangential_force_N, &s.radial_force_N, &s.input_torque_Nmm, &s.efficiency})
    v->reserve(steps);

  internal::TurretBuffers buf_a, buf_b;
  internal::Resize(buf_a, r.input.rollers);
  internal::Resize(buf_b, r.output.rollers);
  const std::vector<Vec2<double>> slots_a = internal::Slots(r.input), slots_b = internal::Slots(r.output);
  if (any_stage) internal::FillCentres(buf_a, r, Side::kInput, slots_a, 0.0);  // the fixed turret stands
  const double sign_a = LoadedArmSign(r, Side::kInput), sign_b = LoadedArmSign(r, Side::kOutput);
  const double tol_a = 1e-9 * r.input.turret_radius, tol_b = 1e-9 * r.output.turret_radius;
  const double e_star = material.composite_modulus_MPa();
  const double ratio = std::abs(SpeedReductionRatio(r));
  const double mu = load.friction_coefficient;

  for (int i = 0; i < steps; ++i) {
    const double theta = 2 * kPi * i / steps;
    s.theta_rad.push_back(theta);
    if (!any_stage) {  // contacts only: nothing of the series depends on them
      AngleLoads<double> a = AnalyzeAngle(r, material, load, theta, stages);
      for (auto [series, side] : {std::pair{&s.input, &a.input}, std::pair{&s.output, &a.output}}) {
        series->actuating.push_back(side->actuating);
        series->max_force_N.push_back(side->max_force);
        series->max_stress_MPa.push_back(side->max_stress);
        series->turret_torque_Nmm.push_back(side->turret_torque);
        series->roller_force_N.AddRow(side->force);
      }
      s.tangential_force_N.push_back(a.tangential_force);
      s.radial_force_N.push_back(a.radial_force);
      s.input_torque_Nmm.push_back(a.input_torque);
      s.efficiency.push_back(a.efficiency);
    } else {
      const Vec2<double> u = U(theta);
      const auto [sum_a, sum_b] = internal::FillTurrets(buf_a, buf_b, r, slots_b, theta, u, sign_a, sign_b);
      const double c_a = internal::ForceScale(r, Side::kInput, load, sum_a, sum_b);
      const double c_b = internal::ForceScale(r, Side::kOutput, load, sum_a, sum_b);
      for (auto [series, buf, cam, c, tol] :
           {std::tuple{&s.input, &buf_a, &r.input, c_a, tol_a},
            std::tuple{&s.output, &buf_b, &r.output, c_b, tol_b}}) {
        // FillForces
        const size_t n = buf->loaded.size();
        double* __restrict force = series->roller_force_N.AddRow();
        int actuating = 0;
        double max_force = 0.0, torque = 0.0;
        for (size_t k = 0; k < n; ++k) {
          const double a = buf->loaded[k];
          force[k] = c * a;
          torque += force[k] * a;
          actuating += a > tol;
          max_force = force[k] > max_force ? force[k] : max_force;  // branch-free, same value
        }
        // FillStresses
        double max_stress = 0.0;
        if (stages.stress && stages.roller_stress) {
          // internal::FillStresses' p of each roller, the same operations, branch-free; their largest
          // is MaxStressKernel's (the root is monotonic and correctly rounded: contact/hertz.h).
          double* __restrict stress = series->roller_stress_MPa.AddRow();
          const double length = cam->contact_length(), radius = cam->roller_radius;
          for (size_t k = 0; k < n; ++k) {
            const double r_eff = radius * (1.0 - radius * buf->kappa[k]);
            const double root = std::sqrt(contact::LineContactPeakPressureSquared(force[k], length, r_eff, e_star));
            const double p = force[k] > 0 ? (r_eff > 0 ? root : kInf) : 0.0;
            stress[k] = p;
            max_stress = p > max_stress ? p : max_stress;
          }
        } else if (stages.stress) {
          max_stress = internal::MaxStressKernel(int(n), force, buf->kappa.data(), cam->roller_radius,
                                                 cam->contact_length(), e_star);
        }
        series->actuating.push_back(actuating);
        series->max_force_N.push_back(max_force);
        series->max_stress_MPa.push_back(max_stress);
        series->turret_torque_Nmm.push_back(torque);
      }
      double tangential = 0.0, radial = 0.0, input_torque = 0.0, efficiency = 0.0;
      if (stages.efficiency) {
        const bool unloaded = load.output_torque_Nmm == 0.0;
        const Vec2<double> per_torque = internal::EccentricLoadPerTorque(buf_a, buf_b, r, sum_a, sum_b);
        const Vec2<double> g = load.output_torque_Nmm * per_torque + Vec2<double>(0.0, -load.cam_weight_N);
        tangential = -g.dot(Perp(u));
        radial = g.dot(u);
        input_torque = InputTorque(tangential, radial, mu, r.eccentricity);
        if (!unloaded) {
          efficiency = Efficiency(load.output_torque_Nmm, input_torque, ratio);
        } else if (load.cam_weight_N > 0) {
          efficiency = 0.0;
        } else {
          const double unit_torque = InputTorque(-per_torque.dot(Perp(u)), per_torque.dot(u), mu, r.eccentricity);
          efficiency = Efficiency(1.0, unit_torque, ratio);
        }
      }
      s.tangential_force_N.push_back(tangential);
      s.radial_force_N.push_back(radial);
      s.input_torque_Nmm.push_back(input_torque);
      s.efficiency.push_back(efficiency);
    }
    if (progress && (i % 256 == 0 || i + 1 == steps)) progress(double(i + 1) / steps);
  }
  return s;
}

RollerZeroLoads RigidRollerZeroLoads(const Reducer<double>& r, const LoadCase& load,
                                     const std::vector<double>& theta_rad) {
  RollerZeroLoads out;
  const size_t n = theta_rad.size();
  for (auto* v : {&out.input_force_N, &out.output_force_N, &out.input_torque_Nmm, &out.input_spin_rate,
                  &out.output_spin_rate})
    v->resize(n);
  out.eccentric_load_N.resize(n);
  internal::TurretBuffers buf_a, buf_b;
  internal::Resize(buf_a, r.input.rollers);
  internal::Resize(buf_b, r.output.rollers);
  const std::vector<Vec2<double>> slots_a = internal::Slots(r.input), slots_b = internal::Slots(r.output);
  internal::FillCentres(buf_a, r, Side::kInput, slots_a, 0.0);  // the fixed turret stands
  const double sign_a = LoadedArmSign(r, Side::kInput), sign_b = LoadedArmSign(r, Side::kOutput);
  // RollerSpinRate's ψ' of each turret
  const double psi_a = std::abs(0.0 - CamSpeedRatio(r)), psi_b = std::abs(OutputSpeedRatio(r) - CamSpeedRatio(r));
  for (size_t i = 0; i < n; ++i) {
    const double theta = theta_rad[i];
    const Vec2<double> u = U(theta);
    const auto [sum_a, sum_b] = internal::FillTurrets(buf_a, buf_b, r, slots_b, theta, u, sign_a, sign_b);
    // FillForces' force of roller 0
    out.input_force_N[i] = internal::ForceScale(r, Side::kInput, load, sum_a, sum_b) * buf_a.loaded[0];
    out.output_force_N[i] = internal::ForceScale(r, Side::kOutput, load, sum_a, sum_b) * buf_b.loaded[0];
    const Vec2<double> per_torque = internal::EccentricLoadPerTorque(buf_a, buf_b, r, sum_a, sum_b);
    const Vec2<double> g = load.output_torque_Nmm * per_torque + Vec2<double>(0.0, -load.cam_weight_N);
    out.eccentric_load_N[i] = g;
    out.input_torque_Nmm[i] = InputTorque(-g.dot(Perp(u)), g.dot(u), load.friction_coefficient, r.eccentricity);
    // RollerSpinRate: ψ' |ρ − r_r| / r_r, ρ = |I − O_0|
    for (auto [buf, cam, psi, spin] : {std::tuple{&buf_a, &r.input, psi_a, &out.input_spin_rate[i]},
                                       std::tuple{&buf_b, &r.output, psi_b, &out.output_spin_rate[i]}}) {
      const Vec2<double> pitch = r.eccentricity * double(cam->pitch_factor()) * u;  // PitchPointOfCam
      const double vx = pitch.x() - buf->cx[0], vy = pitch.y() - buf->cy[0];
      *spin = psi * std::abs(std::sqrt(vx * vx + vy * vy) - cam->roller_radius) / cam->roller_radius;
    }
  }
  return out;
}

struct RigidLoadsSweep::State {
  const Reducer<double>* r;
  LoadCase load;
  internal::TurretBuffers a, b;
  std::vector<Vec2<double>> slots_b;
  double sign_a, sign_b;
};

RigidLoadsSweep::RigidLoadsSweep(const Reducer<double>& r, const LoadCase& load)
    : state_(std::make_unique<State>(State{&r, load, {}, {}, internal::Slots(r.output),
                                           LoadedArmSign(r, Side::kInput), LoadedArmSign(r, Side::kOutput)})) {
  internal::Resize(state_->a, r.input.rollers);
  internal::Resize(state_->b, r.output.rollers);
  internal::FillCentres(state_->a, r, Side::kInput, internal::Slots(r.input), 0.0);  // the fixed turret stands
}

RigidLoadsSweep::~RigidLoadsSweep() = default;

void RigidLoadsSweep::At(double theta) {
  State& s = *state_;
  const Reducer<double>& r = *s.r;
  const Vec2<double> u = U(theta);
  const auto [sum_a, sum_b] = internal::FillTurrets(s.a, s.b, r, s.slots_b, theta, u, s.sign_a, s.sign_b);
  const double c_a = internal::ForceScale(r, Side::kInput, s.load, sum_a, sum_b);
  const double c_b = internal::ForceScale(r, Side::kOutput, s.load, sum_a, sum_b);
  for (auto [buf, cam, contacts, forces, c] :
       {std::tuple{&s.a, &r.input, &input_contacts, &input_force_N, c_a},
        std::tuple{&s.b, &r.output, &output_contacts, &output_force_N, c_b}}) {
    const size_t n = buf->loaded.size();
    contacts->resize(n);
    forces->resize(n);
    for (size_t k = 0; k < n; ++k) {
      // RollerContacts' {O, d, O + r_r d, Cross(O, d), κ} and FillForces' C a_k
      const Vec2<double> o(buf->cx[k], buf->cy[k]), d(buf->dx[k], buf->dy[k]);
      (*contacts)[k] = {o, d, o + cam->roller_radius * d, buf->arm[k], buf->kappa[k]};
      (*forces)[k] = c * buf->loaded[k];
    }
  }
  const Vec2<double> per_torque = internal::EccentricLoadPerTorque(s.a, s.b, r, sum_a, sum_b);
  eccentric_load_N = s.load.output_torque_Nmm * per_torque + Vec2<double>(0.0, -s.load.cam_weight_N);
}

std::vector<double> CycleCurvatures(const Reducer<double>& r, Side s, const std::vector<double>& theta_rad) {
  const CamSide<double>& c = r.side(s);
  const size_t n = size_t(c.rollers);
  std::vector<double> kappa(theta_rad.size() * n);
  internal::TurretBuffers b;
  internal::Resize(b, c.rollers);
  const std::vector<Vec2<double>> slots = internal::Slots(c);
  if (s == Side::kInput) internal::FillCentres(b, r, s, slots, 0.0);  // the fixed turret stands
  const double sign = LoadedArmSign(r, s);
  for (size_t i = 0; i < theta_rad.size(); ++i) {
    if (s == Side::kOutput) internal::FillCentres(b, r, s, slots, theta_rad[i]);
    internal::FillContacts(b, r, s, U(theta_rad[i]), sign);
    std::copy(b.kappa.begin(), b.kappa.end(), kappa.begin() + i * n);
  }
  return kappa;
}

}  // namespace camopt::lcr
