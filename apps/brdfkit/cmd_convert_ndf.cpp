// `brdfkit convert-ndf`: parameter conversion between microfacet distributions (seed 001,
// DESIGN.md §11), one value or the layout of seed 001 Table 2.
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "brdfkit/analysis/ndf_conversion.h"
#include "brdfkit/core/error.h"
#include "brdfkit/core/json_text.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

using namespace brdfkit::analysis;

constexpr const char* kDomainRule =
    "beta uniform on [0, min(4 m_B, pi/2)], both ends included; m_B is the source's Beckmann parameter, or for "
    "another source the Beckmann m_B with the same beta_half (seed 001 Eq. 9), pi/2 when the source never falls "
    "to half its peak";

struct Options {
  std::string from, to, method = "rmse";
  std::vector<double> values;  // VALUE, or with --table the m_B values
  bool table = false;
  bool json = false;
};

nlohmann::json optional_json(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

nlohmann::json domain_json(const RmseDomain& d) {
  return {{"beta_min", 0.0},
          {"beta_max", d.beta_max},
          {"samples", d.samples},
          {"spacing", "uniform"},
          {"m_B", std::isfinite(d.m_B) ? nlohmann::json(d.m_B) : nlohmann::json()},
          {"rule", kDomainRule}};
}

int run_table(const Options& o) {
  const auto& beckmann = ndf_shape("beckmann");
  const std::vector<double> m_Bs = o.values.empty() ? table2_m_B() : o.values;
  for (double m : m_Bs) check_param(beckmann, m, "table");
  std::vector<Table2Row> rows;
  for (double m : m_Bs) rows.push_back(table2_row(m));
  if (o.json) {
    nlohmann::json out = {{"command", "convert-ndf"}, {"version", BRDFKIT_VERSION},
                          {"table", "seed 001 Table 2: Beckmann m_B approximated by least RMSE of D/D(0)"},
                          {"rmse_domain", {{"rule", kDomainRule}, {"samples", kRmseSamples}, {"spacing", "uniform"}}}};
    auto& js = out["rows"] = nlohmann::json::array();
    for (const auto& r : rows)
      js.push_back({{"m_B", r.m_B},
                    {"N_eq11", {{"value", r.N_ward}, {"rmse", r.rmse_ward}}},
                    {"N", {{"value", r.N}, {"rmse", r.rmse_N}}},
                    {"m_G", {{"value", r.m_G}, {"rmse", r.rmse_G}}},
                    {"N_DS", {{"value", r.N_DS}, {"rmse", r.rmse_DS}}},
                    {"C_TR", {{"value", r.C_TR}, {"rmse", r.rmse_TR}}}});
    std::cout << json_text(out) << "\n";
    return 0;
  }
  std::cout << "Seed 001 Table 2: Beckmann m_B approximated with least RMSE of D/D(0)\n"
            << "(" << kDomainRule << ", " << kRmseSamples << " samples)\n\n";
  auto cell = [](double v, double e) { return fmt::format("{:.4g} ({:.4g})", v, e); };
  std::cout << fmt::format("{:<10}{:<24}{:<24}{:<24}{:<24}{}\n", "m_B", "N by Eq. 11 (RMSE)", "N (RMSE)", "m_G (RMSE)",
                           "N_DS (RMSE)", "C_TR (RMSE)");
  for (const auto& r : rows)
    std::cout << fmt::format("{:<10.4g}{:<24}{:<24}{:<24}{:<24}{}\n", r.m_B, cell(r.N_ward, r.rmse_ward),
                             cell(r.N, r.rmse_N), cell(r.m_G, r.rmse_G), cell(r.N_DS, r.rmse_DS),
                             cell(r.C_TR, r.rmse_TR));
  return 0;
}

int run_convert(const Options& o) {
  if (o.from.empty()) throw InputError("--from", "missing: name the source distribution (or use --table)");
  if (o.to.empty()) throw InputError("--to", "missing: name the target distribution (or use --table)");
  if (o.values.empty()) throw InputError("VALUE", "missing: give the source distribution's parameter value");
  if (o.values.size() > 1) throw InputError("VALUE", "give one value (several m_B values go with --table)");
  const Method method = parse_method(o.method);
  const Conversion c = [&] {
    try {
      return convert_ndf(o.from, o.to, o.values[0], method);
    } catch (const SettingError& e) {
      if (e.setting() == "value") throw InputError("VALUE", e.detail());  // the positional argument
      throw;
    }
  }();
  for (const auto& w : c.warnings) std::cerr << "brdfkit: warning: " << w << "\n";
  if (o.json) {
    nlohmann::json out = {
        {"command", "convert-ndf"},
        {"version", BRDFKIT_VERSION},
        {"from", {{"distribution", c.from->name}, {"parameter", c.from->symbol}, {"value", c.value},
                  {"beta_half", optional_json(c.beta_half_from)}}},
        {"to", {{"distribution", c.to->name}, {"parameter", c.to->symbol}, {"value", c.result},
                {"beta_half", optional_json(c.beta_half_to)}}},
        {"method", {{"requested", method_name(c.requested)}, {"used", method_name(c.used)}, {"rule", c.equation}}},
        {"rmse", c.rmse},
        {"rmse_domain", domain_json(c.domain)},
        {"warnings", c.warnings}};
    std::cout << json_text(out) << "\n";
    return 0;
  }
  auto bh = [](const std::optional<double>& b) { return b ? fmt::format("{:.6g} rad", *b) : std::string("none"); };
  std::cout << fmt::format("{} {} = {:.10g}  ->  {} {} = {:.10g}\n", c.from->name, c.from->symbol, c.value, c.to->name,
                           c.to->symbol, c.result);
  std::cout << fmt::format("  method   {}: {}\n", method_name(c.used), c.equation);
  std::cout << fmt::format("  RMSE of D/D(0): {:.4g} over beta uniform on [0, {:.6g}] rad ({} samples)\n", c.rmse,
                           c.domain.beta_max, c.domain.samples);
  std::cout << fmt::format("  beta_half: {} (source), {} (result)\n", bh(c.beta_half_from), bh(c.beta_half_to));
  return 0;
}

const CommandRegistration reg("convert-ndf", [](CLI::App& app) {
  auto* sub = app.add_subcommand("convert-ndf", "Convert a parameter between microfacet distributions (seed 001)");
  auto o = std::make_shared<Options>();
  std::string names;
  for (const auto& s : ndf_shapes()) names += fmt::format("\n  {:<18}{:<7}{}", s.name, s.symbol, s.description);
  sub->add_option("--from", o->from, "Source distribution");
  sub->add_option("--to", o->to, "Target distribution");
  sub->add_option("VALUE", o->values, "The source distribution's parameter value (with --table: the m_B values)");
  sub->add_option("--method", o->method,
                  "half-max: equal beta_half, where D/D(0) = 1/2 (seed 001 Eq. 3-10); sawicki: the paper's fitted "
                  "formulas (Eq. 12-15, Tables 3-4; falls back to rmse with a warning outside m_B in [0.0044, "
                  "0.4473] or for pairs it does not cover); rmse: least RMSE between the D/D(0) shapes (default)")
      ->capture_default_str();
  sub->add_flag("--table", o->table,
                "Print seed 001 Table 2's layout for the m_B values given as VALUE (default: the 17 of the paper)");
  sub->add_flag("--json", o->json, "Print JSON instead of text");
  sub->footer(fmt::format("Distributions (parameter names of seed 001):{}\n\nRMSE domain: {}, {} samples. "
                          "Shapes are compared peak-normalized, D/D(0), never as normalized D.",
                          names, kDomainRule, kRmseSamples));
  return [o]() {
    if (o->table) {
      if (!o->from.empty() || !o->to.empty())
        throw InputError("--table", "takes m_B values only; leave out --from and --to");
      return run_table(*o);
    }
    return run_convert(*o);
  };
});

}  // namespace
}  // namespace brdfkit::cli
