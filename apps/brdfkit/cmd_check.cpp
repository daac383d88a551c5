// `brdfkit check MODEL [--param name=value ...] [--json]`: the numerical checks of a model at
// given parameter values: normalization of its microfacet distribution (DESIGN.md §3),
// reciprocity, albedo at θi = 0…80° (DESIGN.md §2), and a χ² test of its importance sampling
// with the integral of its pdf (analysis/chi2_test.h).
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "brdfkit/analysis/chi2_test.h"
#include "brdfkit/analysis/model_checks.h"
#include "brdfkit/core/error.h"
#include "brdfkit/core/json_text.h"
#include "brdfkit/fit/param_source.h"
#include "brdfkit/models/microfacet_model.h"
#include "brdfkit/models/model.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

constexpr int kChecksFailed = 3;  // exit code when a check fails (2 stays "bad input")

// Draws per chi-square test. The closed-form samplers draw and bin 10^6 directions in 0.1-1.3 s
// on one core (lambert 0.1 s, cook-torrance-ggx 0.15 s, holzschuch-pacanowski 1.3 s), so 10^8
// keeps a check at the default three viewing angles within a few minutes (measured on a shared
// 2-core machine). cook-torrance-gaussian and -sawicki-rational took ~130 s per 10^6 draws there:
// keep them near the default. 10^3: fewer would leave most of the 800 cells pooled.
constexpr long kMinSamples = 1000, kMaxSamples = 100'000'000;

struct CheckOptions {
  std::string model;
  std::vector<std::string> params;
  std::vector<double> theta_o_deg{0, 45, 85};
  int channel = 0;
  long samples = 200000;
  std::uint64_t seed = 5489;
  bool json = false;
};

// ∫ D cos dω of the model's distribution, or null for a model without one; shape parameters are
// shared, so channel 0 stands for all.
nlohmann::json normalization_json(const Model& model, const ParamValues& values) {
  const auto* view = dynamic_cast<const MicrofacetDistributionView*>(&model);
  if (!view) return nullptr;
  return ndf_normalization([&](double c) { return view->ndf(values.channel(0), c); });
}

nlohmann::json reciprocity_json(const Model& model, const ParamValues& values) {
  double worst = 0;
  int pairs = 0;
  for (int c = 0; c < 3; ++c) {
    const ReciprocityCheck r = reciprocity_check(model, values.channel(c), c);
    worst = std::max(worst, r.max_relative_error);
    pairs += r.pairs;
  }
  return {{"max_relative_error", worst}, {"pairs", pairs}, {"reciprocal", model.reciprocal()}};
}

nlohmann::json albedo_json(const Model& model, const ParamValues& values) {
  nlohmann::json alb = nlohmann::json::array();
  for (double t : albedo_angles_deg()) {
    nlohmann::json rgb = nlohmann::json::array();
    for (int c = 0; c < 3; ++c) rgb.push_back(albedo(model, values.channel(c), c, t * kPi / 180));
    alb.push_back({{"theta_i_deg", t}, {"rgb", rgb}});
  }
  return alb;
}

nlohmann::json chi2_json(const Model& model, const ParamValues& values, const CheckOptions& o) {
  nlohmann::json chi = nlohmann::json::array();
  Chi2Options co;
  co.samples = o.samples;
  co.seed = o.seed;
  co.test_count = int(o.theta_o_deg.size());
  for (double t : o.theta_o_deg) {
    const Vec3d wo = spherical_direction(t * kPi / 180, 0.0);
    const Chi2Result r = chi2_test(model, values.channel(o.channel), o.channel, wo, co);
    chi.push_back({{"theta_o_deg", t},
                   {"channel", o.channel},
                   {"statistic", r.statistic},
                   {"dof", r.dof},
                   {"p_value", r.p_value},
                   {"pdf_integral", r.pdf_integral},
                   {"rejected_fraction", r.rejected_fraction},
                   {"integral_z", r.integral_z},
                   {"passed", r.passed},
                   {"message", r.message}});
  }
  return chi;
}

// Every check as the JSON that --json prints; "passed" is false when one fails.
nlohmann::json checks_json(const Model& model, const ParamValues& values, const CheckOptions& o) {
  const ParamTable& table = model.params();
  nlohmann::json out;
  out["model"] = model.name();
  nlohmann::json pj = nlohmann::json::object();
  for (size_t i = 0; i < table.size(); ++i)
    pj[table[i].name] = {values.values[0][i], values.values[1][i], values.values[2][i]};
  out["params"] = pj;
  out["normalization"] = normalization_json(model, values);
  out["reciprocity"] = reciprocity_json(model, values);
  out["albedo"] = albedo_json(model, values);
  out["chi2"] = chi2_json(model, values, o);
  bool passed = out["normalization"].is_null() || std::abs(out["normalization"].get<double>() - 1) < 1e-3;
  if (model.reciprocal() && !(out["reciprocity"]["max_relative_error"].get<double>() < 1e-8)) passed = false;
  for (const auto& r : out["chi2"])
    if (!r["passed"].get<bool>()) passed = false;
  out["passed"] = passed;
  return out;
}

void print_checks(const nlohmann::json& out, const Model& model, const ParamValues& values, const CheckOptions& o) {
  const ParamTable& table = model.params();
  std::cout << fmt::format("{}  ({} samples per chi2 test, seed {})\n", model.name(), o.samples, o.seed);
  for (size_t i = 0; i < table.size(); ++i)
    std::cout << fmt::format("  {:<8} {:g} {:g} {:g}\n", table[i].name, values.values[0][i], values.values[1][i],
                             values.values[2][i]);
  if (out["normalization"].is_null())
    std::cout << "normalization  (no microfacet distribution)\n";
  else
    std::cout << fmt::format("normalization  int D cos dw = {:.8f}\n", out["normalization"].get<double>());
  const auto& rec = out["reciprocity"];
  std::cout << fmt::format("reciprocity    max relative error {:.3g} over {} pairs{}\n", rec["max_relative_error"].get<double>(),
                           rec["pairs"].get<int>(), model.reciprocal() ? "" : " (model not reciprocal)");
  std::cout << "albedo         theta_i      R          G          B\n";
  for (const auto& a : out["albedo"])
    std::cout << fmt::format("               {:5.0f}   {:9.6f}  {:9.6f}  {:9.6f}\n", a["theta_i_deg"].get<double>(),
                             a["rgb"][0].get<double>(), a["rgb"][1].get<double>(), a["rgb"][2].get<double>());
  std::cout << "sampling       theta_o   chi2      dof   p-value    int pdf    rejected  result\n";
  for (const auto& r : out["chi2"])
    std::cout << fmt::format("               {:5.0f}   {:9.2f} {:5d}   {:8.4f}   {:.6f}   {:.6f}  {}{}\n",
                             r["theta_o_deg"].get<double>(), r["statistic"].get<double>(), r["dof"].get<int>(),
                             r["p_value"].get<double>(), r["pdf_integral"].get<double>(),
                             r["rejected_fraction"].get<double>(), r["passed"].get<bool>() ? "pass" : "FAIL ",
                             r["message"].get<std::string>());
  std::cout << (out["passed"].get<bool>() ? "all checks passed\n" : "some checks FAILED\n");
}

int run_check(const CheckOptions& o) {
  const Model& model = model_by_name(o.model);
  const ParamValues values = fit::params_from_args(model.params(), o.params);
  if (o.samples < kMinSamples || o.samples > kMaxSamples)
    throw InputError("--samples", fmt::format("must be in [{}, {}] (got {})", kMinSamples, kMaxSamples, o.samples));
  for (double t : o.theta_o_deg)
    if (!(t >= 0 && t < 90)) throw InputError("--theta-o", fmt::format("{:g} is not in [0, 90) degrees", t));
  const nlohmann::json out = checks_json(model, values, o);
  if (o.json)
    std::cout << json_text(out) << "\n";
  else
    print_checks(out, model, values, o);
  return out["passed"].get<bool>() ? 0 : kChecksFailed;
}

const CommandRegistration reg("check", [](CLI::App& app) {
  auto* sub = app.add_subcommand(
      "check",
      "Check a model: distribution normalization, reciprocity, albedo at theta_i = 0..80 deg, chi-square test of "
      "its importance sampling and the integral of its pdf. Exit 0 when every check passes, 3 when one fails, 2 on "
      "bad input");
  auto o = std::make_shared<CheckOptions>();
  sub->add_option("model", o->model, "Model name (see `brdfkit models`)")->required();
  sub->add_option("--param", o->params,
                  "name=value (all channels), name[r|g|b]=value (one channel) or name=r,g,b; repeatable");
  sub->add_option("--theta-o", o->theta_o_deg, "Viewing angles in degrees for the chi-square test")
      ->capture_default_str();
  sub->add_option("--channel", o->channel, "Channel (0, 1, 2) whose sampling is tested")
      ->check(CLI::Range(0, 2))
      ->capture_default_str();
  sub->add_option("--samples", o->samples,
                  fmt::format("Samples per chi-square test ({} to {})", kMinSamples, kMaxSamples))
      ->capture_default_str();
  sub->add_option("--seed", o->seed, "Seed of the sample generator")->capture_default_str();
  sub->add_flag("--json", o->json, "Print JSON instead of a table");
  return [o]() { return run_check(*o); };
});

}  // namespace
}  // namespace brdfkit::cli
