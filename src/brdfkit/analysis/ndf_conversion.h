#pragma once
// Parameter conversion between one-parameter microfacet distributions (seed 001, DESIGN.md §11).
//
// Every distribution is compared through its peak-normalized shape D(β)/D(0) (seed 001 Table 1,
// "unit form"), never through the normalized D: the conversions keep the look of the highlight,
// not its energy. Three methods:
//   half-max  equal β_half, the angle where D(β)/D(0) = ½ (Blinn 1977; seed 001 Eq. 3–10),
//   sawicki   the paper's fitted formulas (Eq. 12–15, Tables 3–4), fitted for m_B ∈ [0.0044, 0.44],
//   rmse      the parameter minimizing the RMSE between the two unit forms over β uniform on
//             [0, β_max], β_max = min(4 m_B, π/2) (reproduces Table 2, DESIGN.md §11).
// For a source that is not Beckmann, m_B above is its half-max equivalent (Eq. 9 at the source's
// β_half), so the domain is the same whichever of two half-max-equivalent sources one starts from.
#include <optional>
#include "brdfkit/core/registry.h"
#include <string>
#include <vector>

namespace brdfkit::analysis {

// A one-parameter distribution seen through its unit form: every distribution of
// ndf/distributions.h that declares a kUnitForm (ndf/distribution.h).
struct NdfShape {
  std::string name;         // the distribution's kName, e.g. "blinn-phong"
  std::string symbol;       // seed 001's name of the parameter, e.g. "N"
  std::string description;  // one line with the source of the unit form
  double lower;             // parameter range in which D(0) is the maximum of D (so D/D(0) is the
  double upper;             // paper's D/max D) and the shape is a single decreasing lobe
  double (*unit_form)(double param, double cos_beta);
  // Seed 001 Eq. 3–10 where the distribution has them in closed form, nullptr otherwise.
  std::optional<double> (*closed_beta_half)(double param);
  std::optional<double> (*closed_from_beta_half)(double beta);
  std::string half_max_rule;  // which equations give β_half both ways

  double unit(double param, double cos_beta) const;
};

// The shapes, in ndf/distributions.h order, by name.
const Registry<NdfShape>& ndf_shapes();
// Throws SettingError(setting, …) naming the known distributions when `name` is unknown.
const NdfShape& ndf_shape(const std::string& name, const std::string& setting = "distribution");
// Throws SettingError(setting, …) unless `value` is finite and in [lower, upper].
void check_param(const NdfShape& s, double value, const std::string& setting);

// β_half of the unit form (radians), or nullopt when D/D(0) stays above ½ on [0, π/2].
std::optional<double> beta_half(const NdfShape& s, double param);
// The parameter whose unit form falls to ½ at `beta` (radians), or nullopt when none in
// [lower, upper] does.
std::optional<double> param_from_beta_half(const NdfShape& s, double beta);
// Seed 001 Eq. 9: the Beckmann m_B that falls to ½ at β_half.
double beckmann_from_beta_half(double beta);

// The β sampling the RMSE is measured on.
struct RmseDomain {
  double beta_max = 0;  // β uniform on [0, beta_max], both ends included
  int samples = 0;
  double m_B = 0;       // the (half-max equivalent) Beckmann parameter that set beta_max
};
inline constexpr int kRmseSamples = 2001;
// [0, min(4 m_B, π/2)], m_B = the source's half-max-equivalent Beckmann parameter; π/2 when the
// source never falls to ½.
RmseDomain rmse_domain(const NdfShape& from, double value);
// sqrt(mean over the domain of (a(β)/a(0) − b(β)/b(0))²).
double unit_rmse(const NdfShape& a, double pa, const NdfShape& b, double pb, const RmseDomain& domain);
// The parameter of `to` minimizing unit_rmse against (from, value) (Boost brent_find_minima in
// log-parameter after a coarse scan).
double rmse_fit(const NdfShape& from, double value, const NdfShape& to, const RmseDomain& domain);

// Seed 001's fitted conversions (Eq. 12–15, Tables 3–4), exactly as printed, for the pairs among
// beckmann, schlick-rational (same m_B as Beckmann, §3 of the paper), blinn-phong, gaussian,
// sawicki-rational and ggx. `equation` names the formula used.
struct FittedFormula {
  double value;
  std::string equation;
  double m_B;  // the source's Beckmann equivalent by the same formulas, for the range check
};
std::optional<FittedFormula> sawicki_formula(const NdfShape& from, double value, const NdfShape& to);
// The range of m_B the formulas were fitted on: the paper's text says 0.0044–0.44, its Table 2
// spans m_B = √(2/N) for N ∈ [10, 10⁵], i.e. 0.004472–0.4472 (printed 0.4473): the upper end
// includes the table's first row.
inline constexpr double kSawickiMinMB = 0.0044;
inline constexpr double kSawickiMaxMB = 0.4473;

enum class Method { HalfMax, Sawicki, Rmse };
Method parse_method(const std::string& name);  // throws SettingError("method", …)
std::string method_name(Method m);

struct Conversion {
  const NdfShape* from = nullptr;
  const NdfShape* to = nullptr;
  double value = 0;
  Method requested = Method::Rmse;
  Method used = Method::Rmse;
  double result = 0;
  std::string equation;               // the formula or rule that produced `result`
  std::optional<double> beta_half_from, beta_half_to;
  RmseDomain domain;
  double rmse = 0;                    // unit_rmse(from, value, to, result) on `domain`
  std::vector<std::string> warnings;  // e.g. outside the fitted range, fell back to rmse
};
// Throws InputError for unknown names, out-of-range values, or a half-max target that cannot
// reach the source's β_half.
Conversion convert_ndf(const std::string& from, const std::string& to, double value, Method method);

// One row of seed 001 Table 2: Beckmann m_B approximated by the other shapes with least RMSE,
// plus the first column, Phong N from Ward's m_B² N = 2 (Eq. 11), with its RMSE.
struct Table2Row {
  double m_B;
  double N_ward, rmse_ward;
  double N, rmse_N;
  double m_G, rmse_G;
  double N_DS, rmse_DS;
  double C_TR, rmse_TR;
};
Table2Row table2_row(double m_B);
// The 17 m_B values printed in Table 2.
const std::vector<double>& table2_m_B();

}  // namespace brdfkit::analysis
