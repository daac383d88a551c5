// `brdfkit eval MODEL [--param name=value ...] --wi θ,φ --wo θ,φ [--radians] [--json]` (or with
// --params FILE [--material NAME], or a measured file in place of MODEL): ρ(wi, wo) per channel in
// sr⁻¹, wi towards the light and wo towards the viewer in the local frame with the normal at θ = 0
// (DESIGN.md §2; an RGL table is conditioned on wi, §7). Angles are in degrees unless --radians is
// given.
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "brdfkit/core/error.h"
#include "brdfkit/core/json_text.h"
#include "brdfkit/measured/load.h"
#include "brdf_options.h"
#include "command.h"

namespace brdfkit::cli {
namespace {

struct EvalArgs {
  BrdfOptions brdf;
  std::vector<double> wi, wo;
  bool radians = false;
  bool json = false;
};

// (θ, φ) in the chosen unit → unit direction; θ ∈ [0, 90°] (above or on the horizon).
Vec3d direction(const std::vector<double>& angles, bool radians, const std::string& option) {
  if (angles.size() != 2) throw InputError(option, "expected two angles theta,phi");
  for (double x : angles)
    if (!std::isfinite(x)) throw InputError(option, "angles must be finite numbers");
  const double to_rad = radians ? 1.0 : kPi / 180.0;
  const double theta = angles[0] * to_rad, phi = angles[1] * to_rad;
  if (!(theta >= 0 && theta <= kPi / 2 + 1e-12))
    throw InputError(option, fmt::format("theta = {:g} {} is not in [0, {}] (the upper hemisphere)", angles[0],
                                         radians ? "rad" : "deg", radians ? "pi/2" : "90"));
  return spherical_direction(std::min(theta, kPi / 2), phi);
}

// A measured file named in place of a model: given when its name has a measured extension and
// no parameters are set.
bool names_measured_file(const EvalArgs& a) {
  return a.brdf.params.empty() && a.brdf.params_file.empty() && has_measured_extension(a.brdf.model);
}

// ρ of the measured file at (wi, wo), and its JSON description. InputError where the data have no value.
Rgb eval_measured(const std::string& file, const Vec3d& wi, const Vec3d& wo, nlohmann::json& out) {
  const auto data = load_measured(file);
  const std::optional<Rgb> rho = data->eval(wi, wo);
  if (!rho) throw InputError(file, "the measurement has no value at these directions");
  out = {{"file", file}, {"format", data->format()}};
  return *rho;
}

// ρ of the model at (wi, wo), and its JSON description (model, material, parameters).
Rgb eval_model(const BrdfOptions& o, const Vec3d& wi, const Vec3d& wo, nlohmann::json& out) {
  const Brdf brdf = o.brdf();
  out = {{"model", brdf.model().name()}};
  if (!o.material.empty()) out["material"] = o.material;
  const ParamTable& t = brdf.model().params();
  nlohmann::json pj = nlohmann::json::object();
  for (size_t i = 0; i < t.size(); ++i)
    pj[t[i].name] = {brdf.values().values[0][i], brdf.values().values[1][i], brdf.values().values[2][i]};
  out["params"] = pj;
  return brdf.eval(wi, wo);
}

int run_eval(const EvalArgs& a) {
  const Vec3d wi = direction(a.wi, a.radians, "--wi"), wo = direction(a.wo, a.radians, "--wo");
  nlohmann::json out;
  const Rgb rho = names_measured_file(a) ? eval_measured(a.brdf.model, wi, wo, out) : eval_model(a.brdf, wi, wo, out);
  if (a.json) {
    const char* unit = a.radians ? "rad" : "deg";
    out["wi"] = {{"theta", a.wi[0]}, {"phi", a.wi[1]}, {"unit", unit}};
    out["wo"] = {{"theta", a.wo[0]}, {"phi", a.wo[1]}, {"unit", unit}};
    // JSON has no NaN: a non-finite value is written as null (and the exit code says so).
    out["rho"] = nlohmann::json::array();
    for (int c = 0; c < 3; ++c) out["rho"].push_back(std::isfinite(rho[c]) ? nlohmann::json(rho[c]) : nlohmann::json());
    std::cout << json_text(out) << "\n";
  } else {
    std::cout << fmt::format("{:.10g} {:.10g} {:.10g}\n", rho[0], rho[1], rho[2]);
  }
  if (!rho.allFinite())
    throw InputError(fmt::format("model '{}'", a.brdf.model), "the BRDF is not finite at these directions");
  return 0;
}

const CommandRegistration reg("eval", [](CLI::App& app) {
  auto* sub = app.add_subcommand(
      "eval", "Print rho(wi, wo) in 1/sr for R, G, B of a model with given parameters (MODEL --param ..., or "
              "--params FILE [--material NAME]) or of a measured file (FILE in place of MODEL)");
  auto a = std::make_shared<EvalArgs>();
  add_brdf_options(sub, a->brdf);
  sub->add_option("--wi", a->wi, "Direction towards the light: theta,phi")->required()->delimiter(',')->expected(2);
  sub->add_option("--wo", a->wo, "Direction towards the viewer: theta,phi")->required()->delimiter(',')->expected(2);
  sub->add_flag("--radians,!--degrees", a->radians, "Angles in radians (--degrees, the default: in degrees)");
  sub->add_flag("--json", a->json, "Print JSON (model, directions, parameters, rho)");
  return [a]() { return run_eval(*a); };
});

}  // namespace
}  // namespace brdfkit::cli
