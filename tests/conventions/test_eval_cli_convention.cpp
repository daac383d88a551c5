// `brdfkit eval MODEL --wi θ,φ --wo θ,φ` (apps/brdfkit/cmd_eval.cpp, README): --wi is the direction
// towards the light and --wo towards the viewer, each θ from the normal and φ the azimuth, in
// degrees unless --radians. Every model of the catalogue is reciprocal, so a model's value cannot
// tell --wi from --wo; a measured RGL file can (its table is conditioned on wi, DESIGN.md §7, and
// cc_ibiza_sunset is far from reciprocal). For models what is pinned is that each option becomes
// the direction it names (θ and φ in that order, in that unit, on the tangent frame's axes): an
// anisotropic model at pairs where θ ≠ φ, φ is off the axes and θi ≠ θo, compared with the
// library's ρ at the directions built here, and against the same pair with θ and φ exchanged or φ
// measured from the other tangent axis.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "brdfkit/measured/load.h"
#include "brdfkit/models/model.h"
#include "support/test_util.h"

namespace brdfkit::test {
namespace {

Rgb library_eval(const Model& m, const ParamValues& v, const Vec3d& wi, const Vec3d& wo) {
  Rgb out;
  for (int c = 0; c < 3; ++c) out[c] = m.eval(v.channel(c), c, wi, wo);
  return out;
}
Vec3d deg(double theta, double phi) { return spherical_direction(theta * kPi / 180, phi * kPi / 180); }

TEST(EvalCliConvention, WiAndWoAreTheDirectionsTheyName) {
  const Model& m = model_by_name("ward-aniso");
  ParamValues v = ParamValues::defaults(m.params());
  for (auto [name, value] : {std::pair{"kd", 0.0}, std::pair{"ks", 0.5}, std::pair{"alpha_x", 0.08}, std::pair{"alpha_y", 0.4}})
    v.set(m.params(), name, value);
  struct Pair { double ti, pi, to, po; };
  for (Pair p : {Pair{30, 20, 45, 215}, Pair{62, 75, 20, 240}, Pair{15, 110, 50, 300}}) {
    const std::string args = "eval ward-aniso --param kd=0 --param ks=0.5 --param alpha_x=0.08 --param alpha_y=0.4 --wi " +
                             std::to_string(p.ti) + "," + std::to_string(p.pi) + " --wo " + std::to_string(p.to) + "," +
                             std::to_string(p.po) + " --json";
    const CliResult r = run_cli(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_DOUBLE_EQ(j["wi"]["theta"].get<double>(), p.ti);
    EXPECT_DOUBLE_EQ(j["wo"]["phi"].get<double>(), p.po);
    const Rgb want = library_eval(m, v, deg(p.ti, p.pi), deg(p.to, p.po));
    const Rgb theta_phi_exchanged = library_eval(m, v, deg(p.pi, p.ti), deg(p.po, p.to));
    const Rgb rotated = library_eval(m, v, deg(p.ti, p.pi + 90), deg(p.to, p.po + 90));
    for (int c = 0; c < 3; ++c) {
      const double got = j["rho"][size_t(c)].get<double>();
      EXPECT_NEAR(got, want[c], 1e-12 * want[c]) << args;
      EXPECT_GT(std::abs(got - theta_phi_exchanged[c]), 0.01 * want[c]) << args;
      EXPECT_GT(std::abs(got - rotated[c]), 0.01 * want[c]) << args;
    }
    // The same pair in radians gives the same value.
    std::ostringstream rad;
    rad.precision(17);
    rad << "eval ward-aniso --param kd=0 --param ks=0.5 --param alpha_x=0.08 --param alpha_y=0.4 --radians --wi "
        << p.ti * kPi / 180 << "," << p.pi * kPi / 180 << " --wo " << p.to * kPi / 180 << "," << p.po * kPi / 180
        << " --json";
    const CliResult rr = run_cli(rad.str());
    ASSERT_EQ(rr.exit_code, 0) << rr.err;
    EXPECT_NEAR(nlohmann::json::parse(rr.out)["rho"][0].get<double>(), want[0], 1e-12 * want[0]);
  }
}

// A non-reciprocal measurement: the CLI's value is the data's ρ(wi = --wi, wo = --wo) and differs
// from the swapped pair by more than 5 % at each of these pairs.
TEST(EvalCliConvention, MeasuredFileIsAskedWithWiTowardsTheLight) {
  BRDFKIT_REQUIRE_DATA("rgl");
  const auto file = data_dir() / "rgl" / "cc_ibiza_sunset_rgb.bsdf";
  const auto data = load_measured(file);
  struct Pair { double ti, pi, to, po; };
  for (Pair p : {Pair{20, 0, 60, 180}, Pair{55, 30, 10, 200}, Pair{70, 90, 35, 250}}) {
    const std::string args = "eval " + file.string() + " --wi " + std::to_string(p.ti) + "," + std::to_string(p.pi) +
                             " --wo " + std::to_string(p.to) + "," + std::to_string(p.po) + " --json";
    const CliResult r = run_cli(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["format"], "rgl");
    const auto want = data->eval(deg(p.ti, p.pi), deg(p.to, p.po));
    const auto swapped = data->eval(deg(p.to, p.po), deg(p.ti, p.pi));
    ASSERT_TRUE(want && swapped);
    double largest_gap = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double got = j["rho"][size_t(c)].get<double>();
      EXPECT_NEAR(got, (*want)[c], 1e-12 * std::abs((*want)[c])) << args;
      largest_gap = std::max(largest_gap, std::abs(got - (*swapped)[c]) / std::abs((*want)[c]));
    }
    EXPECT_GT(largest_gap, 0.05) << args << ": the pair does not tell wi from wo";
  }
}

}  // namespace
}  // namespace brdfkit::test
