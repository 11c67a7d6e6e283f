// A lubricant's viscosity against temperature and pressure, over the scalar T.
// Units: kinematic viscosity ν in mm²/s (cSt), dynamic viscosity η in MPa·s (= N·s/mm², the
// project's mm–N–MPa system: 1 Pa·s = 1e-6 MPa·s), density in kg/m³, temperature in °C,
// pressure–viscosity coefficient α in 1/MPa (1 GPa⁻¹ = 1e-3 MPa⁻¹).
//
// Temperature: the Walther equation as standardised in ASTM D341,
//   log10 log10(ν + 0.7) = A − B log10(T_K),
// fixed by two measured points (ν40, ν100 of a data sheet). Pressure: Barus, η(p) = η0 exp(α p).
// Density: ρ(t) = ρ15 (1 − β (t − 15)), a linear thermal expansion (β ≈ 6.5e-4 K⁻¹ for mineral
// oils, stated per lubricant).
#pragma once

#include <cmath>
#include <stdexcept>
#include <string>

#include "model/common/scalar.h"

namespace camopt {

/// Absolute zero in °C, for the Walther equation's absolute temperature.
inline constexpr double kZeroCelsiusK = 273.15;

/// ASTM D341 (Walther): log10 log10(ν + 0.7) = a − b log10(T_K), ν in mm²/s.
template <typename T>
struct WaltherLaw {
  T a;
  T b;
};

/// The Walther law through two measured points (ν1 at t1, ν2 at t2; °C, mm²/s), t1 ≠ t2.
template <typename T>
WaltherLaw<T> WaltherThroughTwoPoints(const T& nu1, const T& t1_C, const T& nu2, const T& t2_C) {
  using std::log10;
  const T z1 = log10(log10(nu1 + T(0.7))), z2 = log10(log10(nu2 + T(0.7)));
  const T x1 = log10(t1_C + T(kZeroCelsiusK)), x2 = log10(t2_C + T(kZeroCelsiusK));
  WaltherLaw<T> law;
  law.b = (z1 - z2) / (x2 - x1);
  law.a = z1 + law.b * x1;
  return law;
}

/// ν(t) [mm²/s] of a Walther law at t [°C]: 10^(10^(a − b log10 T_K)) − 0.7.
template <typename T>
T KinematicViscosity(const WaltherLaw<T>& law, const T& t_C) {
  using std::log10;
  using std::pow;
  return pow(T(10.0), pow(T(10.0), law.a - law.b * log10(t_C + T(kZeroCelsiusK)))) - T(0.7);
}

/// A lubricant as a data sheet gives it.
struct Lubricant {
  std::string name = "ISO VG 68 mineral oil";
  double nu40_mm2_s = 68.0;        ///< kinematic viscosity at 40 °C
  double nu100_mm2_s = 8.6;        ///< kinematic viscosity at 100 °C
  double density15_kg_m3 = 880.0;  ///< density at 15 °C
  double thermal_expansion_per_K = 6.5e-4;  ///< β of ρ(t) = ρ15 (1 − β (t − 15))
  double pressure_viscosity_per_MPa = 0.02;  ///< Barus α (20 GPa⁻¹, typical of mineral oils)
  bool operator==(const Lubricant&) const = default;

  /// Throws std::invalid_argument naming the first value outside what the laws above take.
  void Validate() const {
    if (!(nu40_mm2_s > 0.0 && nu100_mm2_s > 0.0 && nu100_mm2_s < nu40_mm2_s))
      throw std::invalid_argument("lubricant: expected 0 < nu100 < nu40 (mm²/s), found nu40 " +
                                  std::to_string(nu40_mm2_s) + ", nu100 " + std::to_string(nu100_mm2_s));
    if (!(density15_kg_m3 > 0.0)) throw std::invalid_argument("lubricant: expected a density > 0 kg/m³");
    if (!(thermal_expansion_per_K >= 0.0 && thermal_expansion_per_K < 1e-2))
      throw std::invalid_argument("lubricant: expected a thermal expansion in [0, 0.01) per K");
    if (!(pressure_viscosity_per_MPa >= 0.0 && pressure_viscosity_per_MPa < 0.1))
      throw std::invalid_argument("lubricant: expected a pressure-viscosity coefficient in [0, 100) per GPa");
  }

  /// The Walther law through (ν40, ν100).
  template <typename T>
  WaltherLaw<T> Walther() const {
    return WaltherThroughTwoPoints(T(nu40_mm2_s), T(40.0), T(nu100_mm2_s), T(100.0));
  }
  /// ν(t) [mm²/s].
  template <typename T>
  T KinematicViscosityAt(const T& t_C) const {
    return KinematicViscosity(Walther<T>(), t_C);
  }
  /// ρ(t) [kg/m³].
  template <typename T>
  T DensityAt(const T& t_C) const {
    return T(density15_kg_m3) * (T(1.0) - T(thermal_expansion_per_K) * (t_C - T(15.0)));
  }
  /// Dynamic viscosity at ambient pressure, η0(t) = ρ(t) ν(t) [MPa·s]:
  /// ρ [kg/m³] × ν [mm²/s] × 1e-6 is Pa·s, × 1e-6 more is MPa·s.
  template <typename T>
  T DynamicViscosityAt(const T& t_C) const {
    return DensityAt(t_C) * KinematicViscosityAt(t_C) * T(1e-12);
  }
};

/// A tabulated oil: an ISO VG grade (ISO 3448: ν40 within ±10 % of the grade) of one base, with the
/// typical properties its maker's data sheet prints (the row's `source`).
struct TabulatedOil {
  int iso_vg;
  const char* base;     ///< "mineral" or "synthetic" (synthesized hydrocarbon, PAO-type)
  const char* product;  ///< the data sheet's product
  double nu40_mm2_s, nu100_mm2_s;
  double density15_kg_m3;  ///< 0: not on the data sheet
  const char* source;
};

/// The built-in oils: one product line per base where it covers the grades (Shell Omala S2 GX /
/// S2 G mineral gear oils, Tellus S2 MX for VG 32 and 46; Shell Omala S4 GXV synthesized-hydrocarbon
/// gear oils, Mobil SHC 624–627 for VG 32–100). Typical values as printed on the makers' data
/// sheets (docs/lubrication.md "Built-in oils" lists the documents); a batch differs by a few %.
inline constexpr TabulatedOil kTabulatedOils[] = {
    {32, "mineral", "Shell Tellus S2 MX 32", 32.0, 5.4, 854.0, "Shell Tellus S2 MX data sheet v4.1 (2016)"},
    {46, "mineral", "Shell Tellus S2 MX 46", 46.0, 6.9, 856.0, "Shell Tellus S2 MX data sheet v4.1 (2016)"},
    {68, "mineral", "Shell Omala S2 GX 68", 68.0, 8.7, 885.0, "Shell Omala S2 GX 68 data sheet v1.8 (2018)"},
    {100, "mineral", "Shell Omala S2 G 100", 100.0, 11.4, 891.0, "Shell Omala S2 G data sheet v4.2 (2017)"},
    {150, "mineral", "Shell Omala S2 GX 150", 150.0, 15.0, 897.0, "Shell Omala S2 GX 150 data sheet v2.8"},
    {220, "mineral", "Shell Omala S2 GX 220", 220.0, 19.4, 899.0, "Shell Omala S2 GX 220 data sheet v2.8"},
    {320, "mineral", "Shell Omala S2 GX 320", 320.0, 24.4, 897.0, "Shell Omala S2 GX 320 data sheet v1.4 (2016)"},
    {460, "mineral", "Shell Omala S2 G 460", 460.0, 30.8, 904.0, "Shell Omala S2 G data sheet v4.2 (2017)"},
    {680, "mineral", "Shell Omala S2 GX 680", 680.0, 42.1, 912.0, "Shell Omala S2 GX 680 data sheet v1.7 (2018)"},
    {32, "synthetic", "Mobil SHC 624", 32.0, 6.3, 0.0, "Mobil SHC 600 Series typical properties (2014)"},
    {46, "synthetic", "Mobil SHC 625", 46.0, 8.5, 0.0, "Mobil SHC 600 Series typical properties (2014)"},
    {68, "synthetic", "Mobil SHC 626", 68.0, 11.6, 0.0, "Mobil SHC 600 Series typical properties (2014)"},
    {100, "synthetic", "Mobil SHC 627", 100.0, 15.3, 0.0, "Mobil SHC 600 Series typical properties (2014)"},
    {150, "synthetic", "Shell Omala S4 GXV 150", 150.0, 22.0, 862.0, "Shell Omala S4 GXV data sheet v1.4 (2017)"},
    {220, "synthetic", "Shell Omala S4 GXV 220", 220.0, 30.0, 864.0, "Shell Omala S4 GXV 220 data sheet v1.4 (2017)"},
    {320, "synthetic", "Shell Omala S4 GXV 320", 320.0, 37.0, 866.0, "Shell Omala S4 GXV data sheet v1.4 (2017)"},
    {460, "synthetic", "Shell Omala S4 GXV 460", 460.0, 53.0, 868.0, "Shell Omala S4 GXV data sheet v1.4 (2017)"},
    {680, "synthetic", "Shell Omala S4 GXV 680", 680.0, 74.0, 868.0, "Shell Omala S4 GXV 680 data sheet v1.9 (2022)"},
};

/// The built-in oil of ISO VG grade `iso_vg` and `base`, or nullptr when the table has none.
inline const TabulatedOil* FindTabulatedOil(int iso_vg, const std::string& base) {
  for (const TabulatedOil& o : kTabulatedOils)
    if (o.iso_vg == iso_vg && base == o.base) return &o;
  return nullptr;
}

/// Barus: η(p) = η0 exp(α p) (p in MPa, α in 1/MPa).
template <typename T>
T BarusViscosity(const T& eta0, const T& alpha_per_MPa, const T& pressure_MPa) {
  using std::exp;
  return eta0 * exp(alpha_per_MPa * pressure_MPa);
}

}  // namespace camopt
