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
#include "brdfkit/ndf/distributions.h"

namespace brdfkit::analysis {
namespace {

constexpr double kHalfPi = kPi / 2;
const double kSqrt2 = std::sqrt(2.0);

template <template <class> class D> NdfShape shape_of() {
  using X = D<double>;
  NdfShape s{std::string(X::kName), std::string(X::kUnitForm.symbol), std::string(X::kUnitForm.formula),
             X::kUnitForm.lower, X::kUnitForm.upper, nullptr, nullptr, nullptr, "Boost toms748 on D/D(0) = 1/2 both ways"};
  if constexpr (requires { X::unit_form(1.0, 1.0); })
    s.unit_form = &X::unit_form;
  else
    s.unit_form = [](double p, double c) { return X(&p).unit(c); };
  if constexpr (requires { X::beta_half(1.0); }) s.closed_beta_half = &X::beta_half;
  if constexpr (requires { X::from_beta_half(1.0); }) s.closed_from_beta_half = &X::from_beta_half;
  if constexpr (requires { X::kHalfMaxRule; }) s.half_max_rule = std::string(X::kHalfMaxRule);
  return s;
}

}  // namespace

const Registry<NdfShape>& ndf_shapes() {
  static const Registry<NdfShape> shapes = [] {
    Registry<NdfShape> r("distribution");
    Distributions::for_each([&]<template <class> class D>() {
      if constexpr (requires { D<double>::kUnitForm; }) r.add(std::string(D<double>::kName), shape_of<D>());
    });
    return r;
  }();
  return shapes;
}

double NdfShape::unit(double p, double c) const {
  if (!(c > 0)) return 0;
  return unit_form(p, std::min(c, 1.0));
}

const NdfShape& ndf_shape(const std::string& name, const std::string& setting) {
  if (const NdfShape* s = ndf_shapes().find(name)) return *s;
  throw ndf_shapes().unknown_setting(setting, name);
}

void check_param(const NdfShape& s, double value, const std::string& setting) {
  if (!std::isfinite(value) || value < s.lower || value > s.upper)
    throw SettingError(setting, fmt::format("{} {} = {} is outside [{:g}, {:g}], where D/D(0) is a single decreasing lobe",
                                            s.name, s.symbol, value, s.lower, s.upper));
}

double beckmann_from_beta_half(double beta) { return *Beckmann<double>::from_beta_half(beta); }

std::optional<double> beta_half(const NdfShape& s, double p) {
  if (s.closed_beta_half) return s.closed_beta_half(p);
  // No closed form: D/D(0) − ½ changes sign once on [0, π/2].
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
  if (s.closed_from_beta_half) {
    p = s.closed_from_beta_half(beta);
  } else {
    // Root of D/D(0) − ½ in the log-parameter (monotone in it).
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
  if (!p || !std::isfinite(*p) || *p < s.lower || *p > s.upper) return std::nullopt;
  return p;
}

RmseDomain rmse_domain(const NdfShape& from, double value) {
  RmseDomain d;
  d.samples = kRmseSamples;
  if (from.name == "beckmann") {
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
  if (from.name == to.name) return value;
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

namespace {

// seed 001's groups: Beckmann (and Schlick, "approximates Beckmann for the same value of m_B",
// seed 001 §3), Blinn-Phong, Gauss, Sawicki, Trowbridge-Reitz.
enum class Group { B, N, MG, DS, TR };

std::optional<Group> sawicki_group(const NdfShape& s) {
  if (s.name == "beckmann" || s.name == "schlick-rational") return Group::B;
  if (s.name == "blinn-phong") return Group::N;
  if (s.name == "gaussian") return Group::MG;
  if (s.name == "sawicki-rational") return Group::DS;
  if (s.name == "ggx") return Group::TR;
  return std::nullopt;
}

// Constants exactly as printed, including 1.696 (C_TR → N) against 1.697 (N → C_TR) (DESIGN.md §11).
double eq12_to_N(double mb) { return 2 / (mb * mb) - 2.5; }
double eq12_to_B(double n) { return kSqrt2 / std::sqrt(n + 2.5); }
double eq14_to_N(double mg) { return 2 / (mg * mg) - 0.5; }
double eq14_to_G(double n) { return kSqrt2 / std::sqrt(n + 0.5); }
double eq15_to_DS(double n) { return 1.174 * n + 0.3; }
double eq15_to_N(double nds) { return (nds - 0.3) / 1.174; }
double t3_TR_to_N(double c) { return 1.696 * 1.696 / (c * c) - 4.5; }
double t4_N_to_TR(double n) { return 1.697 / std::sqrt(n + 4.5); }

struct SawickiConversion {
  Group from, to;
  double (*convert)(double);
  const char* equation;
};

using enum Group;
const SawickiConversion kConversions[] = {
    {B, N, eq12_to_N, "Eq. 12: N = 2/m_B^2 - 2.5"},
    {B, MG, [](double x) { return 0.5591 * x * x * x + x; }, "Eq. 13: m_G = 0.5591 m_B^3 + m_B"},
    {B, DS, [](double x) { return eq15_to_DS(eq12_to_N(x)); },
     "Table 4: N = 2/m_B^2 - 2.5 (Eq. 12), then N_DS = 1.174 N + 0.3 (Eq. 15)"},
    {B, TR, [](double x) { return 1.2 * x - 0.56 * x * x * x; }, "Table 4: C_TR = 1.2 m_B - 0.56 m_B^3"},
    {N, B, eq12_to_B, "Eq. 12: m_B = sqrt(2)/sqrt(N + 2.5)"},
    {N, MG, eq14_to_G, "Eq. 14: m_G = sqrt(2)/sqrt(N + 0.5)"},
    {N, DS, eq15_to_DS, "Eq. 15: N_DS = 1.174 N + 0.3"},
    {N, TR, t4_N_to_TR, "Table 4: C_TR = 1.697/sqrt(N + 4.5)"},
    {MG, B, [](double x) { return x - 0.4134 * x * x * x; }, "Eq. 13: m_B = m_G - 0.4134 m_G^3"},
    {MG, N, eq14_to_N, "Eq. 14: N = 2/m_G^2 - 0.5"},
    {MG, DS, [](double x) { return eq15_to_DS(eq14_to_N(x)); },
     "Table 4: N = 2/m_G^2 - 0.5 (Eq. 14), then N_DS = 1.174 N + 0.3 (Eq. 15)"},
    {MG, TR, [](double x) { return 1.186 * x - 0.835 * x * x * x; }, "Table 4: C_TR = 1.186 m_G - 0.835 m_G^3"},
    {DS, B, [](double x) { return eq12_to_B(eq15_to_N(x)); },
     "Table 3: N = (N_DS - 0.3)/1.174 (Eq. 15), then m_B = sqrt(2)/sqrt(N + 2.5) (Eq. 12)"},
    {DS, N, eq15_to_N, "Eq. 15: N = (N_DS - 0.3)/1.174"},
    {DS, MG, [](double x) { return eq14_to_G(eq15_to_N(x)); },
     "Table 3: N = (N_DS - 0.3)/1.174 (Eq. 15), then m_G = sqrt(2)/sqrt(N + 0.5) (Eq. 14)"},
    {DS, TR, [](double x) { return t4_N_to_TR(eq15_to_N(x)); },
     "Table 3: N = (N_DS - 0.3)/1.174 (Eq. 15), then C_TR = 1.697/sqrt(N + 4.5)"},
    {TR, B, [](double x) { return 0.8388 * x + 0.7 * std::pow(x, 4); }, "Table 3: m_B = 0.8388 C_TR + 0.7 C_TR^4"},
    {TR, N, t3_TR_to_N, "Table 3: N = 1.696^2/C_TR^2 - 4.5"},
    {TR, MG, [](double x) { return 0.8222 * x + 0.82 * x * x * x; }, "Table 3: m_G = 0.8222 C_TR + 0.82 C_TR^3"},
    {TR, DS, [](double x) { return eq15_to_DS(t3_TR_to_N(x)); },
     "Table 3: N = 1.696^2/C_TR^2 - 4.5, then N_DS = 1.174 N + 0.3 (Eq. 15)"},
};

FittedFormula apply(Group a, Group b, double x, bool schlick_as_beckmann) {
  if (a == b)
    return {x, schlick_as_beckmann ? "identity (seed 001 §3: Schlick approximates Beckmann for the same m_B)" : "identity",
            0};
  for (const SawickiConversion& c : kConversions)
    if (c.from == a && c.to == b) return {c.convert(x), c.equation, 0};
  return {std::numeric_limits<double>::quiet_NaN(), "", 0};
}

}  // namespace

std::optional<FittedFormula> sawicki_formula(const NdfShape& from, double v, const NdfShape& to) {
  const auto f = sawicki_group(from), t = sawicki_group(to);
  if (!f || !t) return std::nullopt;
  FittedFormula out = apply(*f, *t, v, *f == Group::B && from.name != to.name);
  out.m_B = apply(*f, Group::B, v, false).value;
  return out;
}

Method parse_method(const std::string& name) {
  if (name == "half-max") return Method::HalfMax;
  if (name == "sawicki") return Method::Sawicki;
  if (name == "rmse") return Method::Rmse;
  throw SettingError("method", fmt::format("unknown method '{}'; known methods: half-max, sawicki, rmse", name));
}

std::string method_name(Method m) {
  switch (m) {
    case Method::HalfMax: return "half-max";
    case Method::Sawicki: return "sawicki";
    case Method::Rmse: return "rmse";
  }
  return "?";
}

Conversion convert_ndf(const std::string& from_name, const std::string& to_name, double value, Method method) {
  Conversion c;
  c.from = &ndf_shape(from_name, "from");
  c.to = &ndf_shape(to_name, "to");
  check_param(*c.from, value, "value");
  c.value = value;
  c.requested = c.used = method;
  c.domain = rmse_domain(*c.from, value);
  c.beta_half_from = beta_half(*c.from, value);

  const auto& from = *c.from;
  const auto& to = *c.to;
  if (from.name == to.name) {
    c.result = value;
    c.equation = "identity (same distribution)";
  } else if (method == Method::HalfMax) {
    if (!c.beta_half_from)
      throw SettingError("value", fmt::format("{} {} = {} never falls to half its peak on [0, pi/2]: half-max conversion "
                                            "is undefined (use --method rmse)",
                                            from.name, from.symbol, value));
    const auto p = param_from_beta_half(to, *c.beta_half_from);
    if (!p)
      throw SettingError("to", fmt::format("no {} {} in [{:g}, {:g}] falls to half its peak at beta_half = {} rad "
                                           "(use --method rmse)",
                                           to.name, to.symbol, to.lower, to.upper, *c.beta_half_from));
    c.result = *p;
    c.equation = fmt::format("equal beta_half: {} ({}), {} ({})", from.name, from.half_max_rule, to.name,
                             to.half_max_rule);
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
