// Half-maximum matching (seed 001 Eq. 3–10, DESIGN.md §11).
#include <gtest/gtest.h>

#include <cmath>

#include "brdfkit/analysis/ndf_conversion.h"
#include "brdfkit/core/error.h"

namespace brdfkit::analysis {
namespace {

// DESIGN.md §11: Eq. 3–10 invert exactly; every unit form equals ½ at β_half = 0.3.
TEST(HalfMax, AllUnitFormsAreHalfAtBetaHalf) {
  for (const auto& s : ndf_shapes()) {
    SCOPED_TRACE(s.name);
    const auto p = param_from_beta_half(s, 0.3);
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(s.unit(*p, std::cos(0.3)), 0.5, 1e-12);
    EXPECT_NEAR(s.unit(*p, 1.0), 1.0, 1e-14);
    const auto b = beta_half(s, *p);
    ASSERT_TRUE(b.has_value());
    EXPECT_NEAR(*b, 0.3, 1e-12);
  }
}

// Through the conversion entry point: Beckmann with β_half = 0.3 converted to each shape by
// half-max; each result is ½ at 0.3.
TEST(HalfMax, ConvertedShapesAreHalfAtTheSameAngle) {
  const double m_B = beckmann_from_beta_half(0.3);
  EXPECT_NEAR(ndf_shape("beckmann").unit(m_B, std::cos(0.3)), 0.5, 1e-14);
  for (const auto& s : ndf_shapes()) {
    SCOPED_TRACE(s.name);
    const auto c = convert_ndf("beckmann", s.name, m_B, Method::HalfMax);
    EXPECT_NEAR(s.unit(c.result, std::cos(0.3)), 0.5, 1e-12);
    ASSERT_TRUE(c.beta_half_to.has_value());
    EXPECT_NEAR(*c.beta_half_to, 0.3, 1e-12);
  }
}

// Closed forms against values worked by hand from the printed equations at β_half = 0.3:
// Eq. 3 N = −ln2/ln cos 0.3, Eq. 4 m_G = 0.3/√ln2, Eq. 5 C_TR = sqrt((cos² − 1)/(cos² − √2)),
// Eq. 9 m_B = tan 0.3/sqrt(ln2 − 4 ln cos 0.3), Eq. 10 N_DS = (c + 3 − 4 (2c)^¼)/(c − 1).
TEST(HalfMax, PrintedEquationsAtPointThree) {
  const double c = std::cos(0.3), l2 = std::log(2.0);
  EXPECT_NEAR(*param_from_beta_half(ndf_shape("blinn-phong"), 0.3), -l2 / std::log(c), 1e-9);
  EXPECT_NEAR(*param_from_beta_half(ndf_shape("gaussian"), 0.3), 0.3 / std::sqrt(l2), 1e-12);
  EXPECT_NEAR(*param_from_beta_half(ndf_shape("ggx"), 0.3), std::sqrt((c * c - 1) / (c * c - std::sqrt(2.0))), 1e-12);
  EXPECT_NEAR(*param_from_beta_half(ndf_shape("beckmann"), 0.3), std::tan(0.3) / std::sqrt(l2 - 4 * std::log(c)),
              1e-12);
  EXPECT_NEAR(*param_from_beta_half(ndf_shape("sawicki-rational"), 0.3),
              (c + 3 - 4 * std::pow(2 * c, 0.25)) / (c - 1), 1e-9);
}

// Round trip Beckmann → GGX → Beckmann by half-max within 1e-6, over the Beckmann range.
TEST(HalfMax, BeckmannGgxRoundTrip) {
  for (double m : {1e-4, 0.0044, 0.01, 0.05, 0.2, 0.44, 0.6, 0.7}) {
    const auto to = convert_ndf("beckmann", "ggx", m, Method::HalfMax);
    const auto back = convert_ndf("ggx", "beckmann", to.result, Method::HalfMax);
    EXPECT_NEAR(back.result, m, 1e-6 * m) << "m_B = " << m << ", C_TR = " << to.result;
  }
}

// Every pair of shapes round-trips through β_half (closed forms and toms748 alike).
TEST(HalfMax, AllPairsRoundTrip) {
  for (const auto& a : ndf_shapes())
    for (const auto& b : ndf_shapes()) {
      const double v = *param_from_beta_half(a, 0.2);
      const auto there = convert_ndf(a.name, b.name, v, Method::HalfMax);
      const auto back = convert_ndf(b.name, a.name, there.result, Method::HalfMax);
      EXPECT_NEAR(back.result / v, 1.0, 1e-9) << a.name << " -> " << b.name;
    }
}

// Very narrow and very wide lobes keep their precision (cos β → 1 cancellation avoided).
TEST(HalfMax, ExtremeLobes) {
  const auto& phong = ndf_shape("blinn-phong");
  for (double n : {0.2, 1.0, 1e4, 1e8, 1e11}) {
    const double b = *beta_half(phong, n);
    EXPECT_NEAR(phong.unit(n, std::cos(b)), 0.5, 1e-6) << n;
    EXPECT_NEAR(*param_from_beta_half(phong, b) / n, 1.0, 1e-9) << n;
  }
  const auto& ds = ndf_shape("sawicki-rational");
  for (double n : {1e-2, 1.0, 1e4, 1e8}) EXPECT_NEAR(*param_from_beta_half(ds, *beta_half(ds, n)) / n, 1.0, 1e-7) << n;
}

// GGX stays above ½ for C_TR ≥ 2^(−1/4) (D(π/2)/D(0) = C⁴): half-max is undefined, an input error.
TEST(HalfMax, UnreachableHalfIsAnInputError) {
  EXPECT_FALSE(beta_half(ndf_shape("ggx"), 0.85).has_value());
  EXPECT_TRUE(beta_half(ndf_shape("ggx"), 0.84).has_value());
  EXPECT_THROW(convert_ndf("ggx", "beckmann", 0.9, Method::HalfMax), InputError);
  // Beckmann's β_half is largest at m_B = 1/√2; Blinn-Phong N = 0.5 (β_half = acos ¼ = 1.32 rad) has no match.
  EXPECT_LT(*beta_half(ndf_shape("beckmann"), 1 / std::sqrt(2.0)), std::acos(0.25));
  EXPECT_THROW(convert_ndf("blinn-phong", "beckmann", 0.5, Method::HalfMax), InputError);
  // rmse still answers.
  EXPECT_NO_THROW(convert_ndf("ggx", "beckmann", 0.9, Method::Rmse));
}

}  // namespace
}  // namespace brdfkit::analysis
