#include "brdfkit/analysis/ndf_conversion.h"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

#include "brdfkit/core/error.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/ndf/beckmann.h"
#include "brdfkit/ndf/blinn_phong.h"
#include "brdfkit/ndf/exponential.h"
#include "brdfkit/ndf/ggx.h"
#include "brdfkit/ndf/sawicki_rational.h"
#include "brdfkit/ndf/schlick_rational.h"

namespace brdfkit::analysis {
namespace {

constexpr double kHalfPi = kPi / 2;
const double kLn2 = std::log(2.0);
const double kSqrt2 = std::sqrt(2.0);

enum Id : int { kBeckmann, kBlinnPhong, kGaussian, kGgx, kSawicki, kSchlick, kExponential };

// 1 − cos β without cancellation for small β.
double one_minus_cos(double beta) {
  const double s = std::sin(beta / 2);
  return 2 * s * s;
}

}  // namespace

const std::vector<NdfShape>& ndf_shapes() {
  // Ranges: where D(0) is the maximum of D, so that D/D(0) is seed 001's D/max D. Beckmann's
  // (1+x)² exp(−x/m²) (x = tan²β) rises at β = 0 for m > 1/√2; the exponential distribution's
  // exp(−tanβ/α)/cos⁴β rises again beyond tanβ = 1 for α > ½.
  static const std::vector<NdfShape> shapes = {
      {"beckmann", "m_B", "Beckmann, exp(-tan^2 b/m_B^2)/cos^4 b (seed 001 Table 1)", 1e-6, 1 / std::sqrt(2.0), kBeckmann},
      {"blinn-phong", "N", "Blinn-Phong, cos^N b (seed 001 Table 1)", 0.1, 1e12, kBlinnPhong},
      {"gaussian", "m_G", "Gaussian (Torrance-Sparrow), exp(-b^2/m_G^2) (seed 001 Table 1)", 1e-6, 4.0, kGaussian},
      {"ggx", "C_TR", "Trowbridge-Reitz / GGX, [C^2/(cos^2 b (C^2-1)+1)]^2 (seed 001 Table 1)", 1e-6, 1.0, kGgx},
      {"sawicki-rational", "N_DS", "Sawicki 2006, 256 cos b/((1-N)cos b+N+3)^4 (seed 001 Table 1)", 1e-3, 1e12, kSawicki},
      {"schlick-rational", "m_B",
       "Schlick 1994, m^5 x/(cos b (m x^2-x^2+m^2)^2), x = cos b+m-1, zero for cos b < 1-m (seed 001 Table 1)", 1e-6,
       1.0, kSchlick},
      {"exponential", "alpha", "exponential, exp(-tan b/alpha)/cos^4 b (seed 000 Table 1)", 1e-6, 0.5, kExponential},
  };
  return shapes;
}

double NdfShape::unit(double p, double c) const {
  if (!(c > 0)) return 0;
  c = std::min(c, 1.0);
  switch (id) {
    case kBeckmann:
      return Beckmann<double>(&p).unit(c);
    case kBlinnPhong:
      return BlinnPhong<double>(&p).unit(c);
    case kGaussian: {
      // Not Gaussian<double>(&p).unit(c): its constructor integrates the normalization (a quadrature
      // per new m, 200× the cost of a whole fit here), which the unit form does not need.
      const double beta = std::acos(c);
      return std::exp(-beta * beta / (p * p));
    }
    case kGgx:
      return Ggx<double>(&p).unit(c);
    case kSawicki:
      return SawickiRational<double>(&p).unit(c);
    case kSchlick:
      return SchlickRational<double>(&p).unit(c);  // zero for cos β < 1 − m (seed 001 §2.2)
    case kExponential:
      return Exponential<double>(&p).unit(c);
  }
  return 0;
}

const NdfShape& ndf_shape(const std::string& name, const std::string& where) {
  std::string known;
  for (const auto& s : ndf_shapes()) {
    if (s.name == name) return s;
    known += (known.empty() ? "" : ", ") + s.name;
  }
  throw InputError(where, fmt::format("unknown distribution '{}' (known: {})", name, known));
}

void check_param(const NdfShape& s, double value, const std::string& where) {
  if (!std::isfinite(value) || value < s.lower || value > s.upper)
    throw InputError(where, fmt::format("{} {} = {} is outside [{:g}, {:g}], where D/D(0) is a single decreasing lobe",
                                        s.name, s.symbol, value, s.lower, s.upper));
}

double beckmann_from_beta_half(double beta) {
  // Seed 001 Eq. 9; ln cos β through log1p for small β.
  return std::tan(beta) / std::sqrt(kLn2 - 4 * std::log1p(-one_minus_cos(beta)));
}

std::optional<double> beta_half(const NdfShape& s, double p) {
  switch (s.id) {
    case kBlinnPhong:
      // Eq. 6, cos β = 2^(−1/N), in the form 2 asin(sqrt((1 − cos β)/2)) that keeps N up to 1e12 exact.
      return 2 * std::asin(std::sqrt(-std::expm1(-kLn2 / p) / 2));
    case kGaussian: {
      const double b = p * std::sqrt(kLn2);  // Eq. 7
      if (b >= kHalfPi) return std::nullopt;
      return b;
    }
    case kGgx: {
      // Eq. 8 as sin²β = 1 − cos²β = C²(√2 − 1)/(1 − C²): no cancellation for small C. The shape
      // stays above ½ (D(π/2)/D(0) = C⁴) for C ≥ 2^(−1/4).
      const double c2 = p * p;
      const double s2 = c2 * (kSqrt2 - 1) / (1 - c2);
      if (!(s2 < 1)) return std::nullopt;
      return std::asin(std::sqrt(s2));
    }
    default:
      break;
  }
  // No closed form (Beckmann, Sawicki, Schlick, exponential): D/D(0) − ½ changes sign once on [0, π/2].
  auto f = [&](double b) { return s.unit(p, std::cos(b)) - 0.5; };
  const double f_hi = f(kHalfPi);
  if (f_hi >= 0) return std::nullopt;
  std::uintmax_t iters = 200;
  const auto [lo, hi] = boost::math::tools::toms748_solve(f, 0.0, kHalfPi, 0.5, f_hi,
                                                          boost::math::tools::eps_tolerance<double>(52), iters);
  return (lo + hi) / 2;
}

std::optional<double> param_from_beta_half(const NdfShape& s, double beta) {
  if (!(beta > 0) || !(beta < kHalfPi)) return std::nullopt;
  std::optional<double> p;
  switch (s.id) {
    case kBeckmann:
      p = beckmann_from_beta_half(beta);
      break;
    case kBlinnPhong:  // Eq. 3, ln cos β through log1p
      p = -kLn2 / std::log1p(-one_minus_cos(beta));
      break;
    case kGaussian:  // Eq. 4
      p = beta / std::sqrt(kLn2);
      break;
    case kGgx: {  // Eq. 5 as C² = sin²β/(√2 − 1 + sin²β)
      const double s2 = std::sin(beta) * std::sin(beta);
      p = std::sqrt(s2 / (kSqrt2 - 1 + s2));
      break;
    }
    case kSawicki: {
      // Eq. 10 with d = 1 − cos β: (4 (2(1 − d))^¼ + d − 4)/d; the numerator tends to
      // 4·2^¼ − 4, so only the denominator is small and it is exact.
      const double d = one_minus_cos(beta);
      p = (4 * std::pow(2 * (1 - d), 0.25) + d - 4) / d;
      break;
    }
    default: {
      // Schlick, exponential: root of D/D(0) − ½ in the log-parameter (monotone in it).
      auto g = [&](double lp) { return s.unit(std::exp(lp), std::cos(beta)) - 0.5; };
      const double a = std::log(s.lower), b = std::log(s.upper);
      const double ga = g(a), gb = g(b);
      if (ga == 0) return s.lower;
      if (gb == 0) return s.upper;
      if ((ga > 0) == (gb > 0)) return std::nullopt;
      std::uintmax_t iters = 200;
      const auto [lo, hi] =
          boost::math::tools::toms748_solve(g, a, b, ga, gb, boost::math::tools::eps_tolerance<double>(52), iters);
      p = std::exp((lo + hi) / 2);
    }
  }
  if (!p || !std::isfinite(*p) || *p < s.lower || *p > s.upper) return std::nullopt;
  return p;
}

RmseDomain rmse_domain(const NdfShape& from, double value) {
  RmseDomain d;
  d.samples = kRmseSamples;
  if (from.id == kBeckmann) {
    d.m_B = value;
  } else if (auto b = beta_half(from, value)) {
    d.m_B = beckmann_from_beta_half(*b);
  } else {
    d.m_B = std::numeric_limits<double>::infinity();
  }
  // DESIGN.md §11: β uniform on [0, min(4 m_B, π/2)] reproduces Table 2's RMSE column.
  d.beta_max = std::min(4 * d.m_B, kHalfPi);
  return d;
}

double unit_rmse(const NdfShape& a, double pa, const NdfShape& b, double pb, const RmseDomain& domain) {
  double sum = 0;
  const int n = domain.samples;
  for (int i = 0; i < n; ++i) {
    const double c = std::cos(domain.beta_max * i / (n - 1));
    const double r = a.unit(pa, c) - b.unit(pb, c);
    sum += r * r;
  }
  return std::sqrt(sum / n);
}

double rmse_fit(const NdfShape& from, double value, const NdfShape& to, const RmseDomain& domain) {
  if (from.id == to.id) return value;
  auto cost = [&](double lp) { return unit_rmse(from, value, to, std::exp(lp), domain); };
  const double range_lo = std::log(to.lower), range_hi = std::log(to.upper);
  // Coarse scan in log-parameter around the half-max guess (or over the whole range), moving the
  // window while the best point sits on an edge that is not the range's; then Brent in the
  // bracket around the best scan point.
  double centre = (range_lo + range_hi) / 2, half_width = (range_hi - range_lo) / 2;
  if (auto bh = beta_half(from, value))
    if (auto guess = param_from_beta_half(to, *bh)) centre = std::log(*guess), half_width = 3;
  constexpr int kScan = 49;
  double lo = 0, hi = 0;
  for (int attempt = 0; attempt < 20; ++attempt) {
    const double a = std::max(range_lo, centre - half_width), b = std::min(range_hi, centre + half_width);
    int best = 0;
    double best_cost = std::numeric_limits<double>::infinity();
    for (int i = 0; i < kScan; ++i) {
      const double c = cost(a + (b - a) * i / (kScan - 1));
      if (c < best_cost) best_cost = c, best = i;
    }
    const double step = (b - a) / (kScan - 1);
    lo = std::max(a, a + (best - 1) * step);
    hi = std::min(b, a + (best + 1) * step);
    if (best == 0 && a > range_lo) {
      centre = a;
    } else if (best == kScan - 1 && b < range_hi) {
      centre = b;
    } else {
      break;
    }
  }
  const auto [lp, c] = boost::math::tools::brent_find_minima(cost, lo, hi, std::numeric_limits<double>::digits / 2);
  (void)c;
  return std::exp(lp);
}

std::optional<FittedFormula> sawicki_formula(const NdfShape& from, double v, const NdfShape& to) {
  // The paper's groups: Beckmann (and Schlick, "approximates Beckmann for the same value of m_B",
  // seed 001 §3), Blinn-Phong, Gauss, Sawicki, Trowbridge-Reitz. Constants exactly as printed,
  // including 1.696 (C_TR → N) against 1.697 (N → C_TR) (DESIGN.md §11).
  enum G { B, N, MG, DS, TR, None };
  auto group = [](const NdfShape& s) {
    switch (s.id) {
      case kBeckmann:
      case kSchlick: return B;
      case kBlinnPhong: return N;
      case kGaussian: return MG;
      case kSawicki: return DS;
      case kGgx: return TR;
      default: return None;
    }
  };
  const G f = group(from), t = group(to);
  if (f == None || t == None) return std::nullopt;
  auto eq12_to_N = [](double mb) { return 2 / (mb * mb) - 2.5; };
  auto eq12_to_B = [](double n) { return kSqrt2 / std::sqrt(n + 2.5); };
  auto eq14_to_N = [](double mg) { return 2 / (mg * mg) - 0.5; };
  auto eq14_to_G = [](double n) { return kSqrt2 / std::sqrt(n + 0.5); };
  auto eq15_to_DS = [](double n) { return 1.174 * n + 0.3; };
  auto eq15_to_N = [](double nds) { return (nds - 0.3) / 1.174; };
  auto t3_TR_to_N = [](double c) { return 1.696 * 1.696 / (c * c) - 4.5; };
  auto t4_N_to_TR = [](double n) { return 1.697 / std::sqrt(n + 4.5); };

  auto apply = [&](G a, G b, double x) -> FittedFormula {
    if (a == b) return {x, a == B && from.id != to.id ? "identity (seed 001 §3: Schlick approximates Beckmann for the same m_B)" : "identity", 0};
    switch (a) {
      case B:
        switch (b) {
          case N: return {eq12_to_N(x), "Eq. 12: N = 2/m_B^2 - 2.5", 0};
          case MG: return {0.5591 * x * x * x + x, "Eq. 13: m_G = 0.5591 m_B^3 + m_B", 0};
          case DS: return {eq15_to_DS(eq12_to_N(x)), "Table 4: N = 2/m_B^2 - 2.5 (Eq. 12), then N_DS = 1.174 N + 0.3 (Eq. 15)", 0};
          case TR: return {1.2 * x - 0.56 * x * x * x, "Table 4: C_TR = 1.2 m_B - 0.56 m_B^3", 0};
          default: break;
        }
        break;
      case N:
        switch (b) {
          case B: return {eq12_to_B(x), "Eq. 12: m_B = sqrt(2)/sqrt(N + 2.5)", 0};
          case MG: return {eq14_to_G(x), "Eq. 14: m_G = sqrt(2)/sqrt(N + 0.5)", 0};
          case DS: return {eq15_to_DS(x), "Eq. 15: N_DS = 1.174 N + 0.3", 0};
          case TR: return {t4_N_to_TR(x), "Table 4: C_TR = 1.697/sqrt(N + 4.5)", 0};
          default: break;
        }
        break;
      case MG:
        switch (b) {
          case B: return {x - 0.4134 * x * x * x, "Eq. 13: m_B = m_G - 0.4134 m_G^3", 0};
          case N: return {eq14_to_N(x), "Eq. 14: N = 2/m_G^2 - 0.5", 0};
          case DS: return {eq15_to_DS(eq14_to_N(x)), "Table 4: N = 2/m_G^2 - 0.5 (Eq. 14), then N_DS = 1.174 N + 0.3 (Eq. 15)", 0};
          case TR: return {1.186 * x - 0.835 * x * x * x, "Table 4: C_TR = 1.186 m_G - 0.835 m_G^3", 0};
          default: break;
        }
        break;
      case DS:
        switch (b) {
          case B: return {eq12_to_B(eq15_to_N(x)), "Table 3: N = (N_DS - 0.3)/1.174 (Eq. 15), then m_B = sqrt(2)/sqrt(N + 2.5) (Eq. 12)", 0};
          case N: return {eq15_to_N(x), "Eq. 15: N = (N_DS - 0.3)/1.174", 0};
          case MG: return {eq14_to_G(eq15_to_N(x)), "Table 3: N = (N_DS - 0.3)/1.174 (Eq. 15), then m_G = sqrt(2)/sqrt(N + 0.5) (Eq. 14)", 0};
          case TR: return {t4_N_to_TR(eq15_to_N(x)), "Table 3: N = (N_DS - 0.3)/1.174 (Eq. 15), then C_TR = 1.697/sqrt(N + 4.5)", 0};
          default: break;
        }
        break;
      case TR:
        switch (b) {
          case B: return {0.8388 * x + 0.7 * std::pow(x, 4), "Table 3: m_B = 0.8388 C_TR + 0.7 C_TR^4", 0};
          case N: return {t3_TR_to_N(x), "Table 3: N = 1.696^2/C_TR^2 - 4.5", 0};
          case MG: return {0.8222 * x + 0.82 * x * x * x, "Table 3: m_G = 0.8222 C_TR + 0.82 C_TR^3", 0};
          case DS: return {eq15_to_DS(t3_TR_to_N(x)), "Table 3: N = 1.696^2/C_TR^2 - 4.5, then N_DS = 1.174 N + 0.3 (Eq. 15)", 0};
          default: break;
        }
        break;
      default:
        break;
    }
    return {std::numeric_limits<double>::quiet_NaN(), "", 0};
  };
  FittedFormula out = apply(f, t, v);
  out.m_B = apply(f, B, v).value;
  return out;
}

Method parse_method(const std::string& name) {
  if (name == "half-max") return Method::HalfMax;
  if (name == "sawicki") return Method::Sawicki;
  if (name == "rmse") return Method::Rmse;
  throw InputError("--method", fmt::format("unknown method '{}' (known: half-max, sawicki, rmse)", name));
}

std::string method_name(Method m) {
  switch (m) {
    case Method::HalfMax: return "half-max";
    case Method::Sawicki: return "sawicki";
    case Method::Rmse: return "rmse";
  }
  return "?";
}

namespace {

std::string beta_half_rule(const NdfShape& s) {
  switch (s.id) {
    case kBlinnPhong: return "Eq. 6/3";
    case kGaussian: return "Eq. 7/4";
    case kGgx: return "Eq. 8/5";
    case kBeckmann: return "Boost toms748 on D/D(0) = 1/2 / Eq. 9";
    case kSawicki: return "Boost toms748 on D/D(0) = 1/2 / Eq. 10";
    default: return "Boost toms748 on D/D(0) = 1/2 both ways";
  }
}

}  // namespace

Conversion convert_ndf(const std::string& from_name, const std::string& to_name, double value, Method method) {
  Conversion c;
  c.from = &ndf_shape(from_name, "--from");
  c.to = &ndf_shape(to_name, "--to");
  check_param(*c.from, value, "VALUE");
  c.value = value;
  c.requested = c.used = method;
  c.domain = rmse_domain(*c.from, value);
  c.beta_half_from = beta_half(*c.from, value);

  const auto& from = *c.from;
  const auto& to = *c.to;
  if (from.id == to.id) {
    c.result = value;
    c.equation = "identity (same distribution)";
  } else if (method == Method::HalfMax) {
    if (!c.beta_half_from)
      throw InputError("VALUE", fmt::format("{} {} = {} never falls to half its peak on [0, pi/2]: half-max conversion "
                                            "is undefined (use --method rmse)",
                                            from.name, from.symbol, value));
    const auto p = param_from_beta_half(to, *c.beta_half_from);
    if (!p)
      throw InputError("--to", fmt::format("no {} {} in [{:g}, {:g}] falls to half its peak at beta_half = {} rad "
                                           "(use --method rmse)",
                                           to.name, to.symbol, to.lower, to.upper, *c.beta_half_from));
    c.result = *p;
    c.equation = fmt::format("equal beta_half: {} ({}), {} ({})", from.name, beta_half_rule(from), to.name,
                             beta_half_rule(to));
  } else {
    if (method == Method::Sawicki) {
      const auto f = sawicki_formula(from, value, to);
      if (!f) {
        c.warnings.push_back(fmt::format("seed 001 gives no fitted formula from {} to {}; using rmse", from.name, to.name));
      } else if (!(f->m_B >= kSawickiMinMB && f->m_B <= kSawickiMaxMB)) {
        const std::string source = from.symbol == "m_B" ? fmt::format("m_B = {}", value)
                                                         : fmt::format("{} {} = {} (m_B = {:.6g} by the same formulas)",
                                                                       from.name, from.symbol, value, f->m_B);
        c.warnings.push_back(fmt::format("{} is outside the range m_B in [{}, {}] seed 001's formulas were fitted on; "
                                         "using rmse",
                                         source, kSawickiMinMB, kSawickiMaxMB));
      } else if (!std::isfinite(f->value) || f->value < to.lower || f->value > to.upper) {
        c.warnings.push_back(fmt::format("seed 001's formula gives {} {} = {}, outside [{:g}, {:g}]; using rmse",
                                         to.name, to.symbol, f->value, to.lower, to.upper));
      } else {
        c.result = f->value;
        c.equation = "seed 001 " + f->equation;
      }
      if (!c.warnings.empty()) c.used = Method::Rmse;
    }
    if (c.used == Method::Rmse) {
      c.result = rmse_fit(from, value, to, c.domain);
      c.equation = fmt::format("least RMSE of D/D(0) over beta uniform on [0, {:.6g}] rad ({} samples), Boost "
                               "brent_find_minima",
                               c.domain.beta_max, c.domain.samples);
    }
  }
  c.rmse = unit_rmse(from, value, to, c.result, c.domain);
  c.beta_half_to = beta_half(to, c.result);
  return c;
}

Table2Row table2_row(double m_B) {
  const auto& b = ndf_shape("beckmann");
  const auto dom = rmse_domain(b, m_B);
  Table2Row r{};
  r.m_B = m_B;
  auto fit = [&](const char* name, double& p, double& e) {
    const auto& s = ndf_shape(name);
    p = rmse_fit(b, m_B, s, dom);
    e = unit_rmse(b, m_B, s, p, dom);
  };
  r.N_ward = 2 / (m_B * m_B);  // Eq. 11 (Ward): m_B² N = 2
  r.rmse_ward = unit_rmse(b, m_B, ndf_shape("blinn-phong"), r.N_ward, dom);
  fit("blinn-phong", r.N, r.rmse_N);
  fit("gaussian", r.m_G, r.rmse_G);
  fit("sawicki-rational", r.N_DS, r.rmse_DS);
  fit("ggx", r.C_TR, r.rmse_TR);
  return r;
}

const std::vector<double>& table2_m_B() {
  static const std::vector<double> v = {0.4473,  0.3163,  0.2,     0.1634,   0.1415,   0.1,
                                        0.06325, 0.05164, 0.04473, 0.03163,  0.02,     0.01634,
                                        0.01415, 0.01,    0.006325, 0.005164, 0.004473};
  return v;
}

}  // namespace brdfkit::analysis
