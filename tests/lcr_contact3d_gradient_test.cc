// AD of the per-contact quantities behind lcr_analysis's 3D contact outputs ("AD gradients
// of every new output"): the R' that `stress_radius_mm` reports, the slices peak
// (`max_contact_stress_MPa`), and the pressure along the roller (`worst_pressure_MPa`, one entry per
// slice), through the LCR geometry, for a logarithmic and a partial crown with misalignment, against
// central differences. The cycle-level maxima are maxima of these (double; a kink where the worst
// contact changes).
#include <array>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include "model/common/material.h"
#include "model/lcr/contact.h"
#include "model/lcr/contact3d.h"
#include "tests/reference_designs.h"
#include "tests/test_util.h"

namespace camopt {
namespace lcr_contact3d_gradient_test {

TEST(LcrContact3D, RadiusPeakAndPressureAlongTheRollerGradientsMatchCentralDifferences) {
  // x = (e, r_r, crown parameter (f [µm] or R [100 mm]), γ [mrad], F), scaled so that the central-
  // difference step 6e-6 max(1, |x|) is small against each: output roller 3 of LCR II at 0.3 rad.
  for (const contact::CrowningType type : {contact::CrowningType::kLogarithmic, contact::CrowningType::kPartial}) {
    auto fn = [type](const auto& x) {
      using T = std::decay_t<decltype(x[0])>;
      const auto [r, r_eff] = testing::LcrIIOutputRoller3(x[0], x[1]);
      lcr::RollerCrowning<T> c;
      c.type = type;
      if (type == contact::CrowningType::kLogarithmic) {
        c.coefficient = x[2] * T(1e-3);  // µm -> mm
        c.effective_length = T(10.5);
      } else {
        c.radius = x[2] * T(100.0);  // x[2] = 2 -> R = 200 mm
        c.flat_length = T(3.0);
      }
      const auto s = lcr::RollerContactSlices<T>(x[4], r_eff, r.output.contact_length(),
                                                 Material{}.composite_modulus_MPa(), c, x[3] * T(1e-3), 24);
      std::vector<T> out{r_eff, s.peak_pressure};
      for (int j : {2, 8, 12, 18, 21}) out.push_back(s.pressure_MPa[j]);
      return out;
    };
    testing::ExpectJacobianMatchesCentralDifferences<5>(fn, {2.0, 6.0, 2.0, 0.5, 800.0}, 1e-5, 1e-6);
  }
}

}  // namespace lcr_contact3d_gradient_test
}  // namespace camopt
