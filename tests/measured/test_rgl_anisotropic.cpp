// Anisotropic RGL files (measured/rgl_writer.h with phi_i > 1, read by measured/rgl_tensor.h as
// Mitsuba 3's `measured` plugin reads them): nodes read back exactly at every incidence azimuth,
// look-ups between nodes follow the source at every azimuth (through the fold of a file that
// stores half or a quarter of the azimuths), σ is the projected area of the 2-D D, the samples
// integrate to the source's albedo, and the symmetries are probed and applied as declared.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>

#include "brdfkit/measured/albedo.h"
#include "brdfkit/measured/azimuthal_symmetry.h"
#include "brdfkit/measured/rgl_tensor.h"
#include "brdfkit/measured/rgl_writer.h"
#include "brdfkit/models/model.h"
#include "support/real_data.h"
#include "support/test_util.h"

namespace brdfkit {
namespace {

// Anisotropic GGX (αx 0.2, αy 0.4) on a coloured diffuse base, its tangent turned by `phi_t`.
Brdf turned_ggx(double phi_t) {
  const Model& m = model_by_name("cook-torrance-ggx-aniso");
  ParamValues v = ParamValues::defaults(m.params());
  const double kd[3] = {0.2, 0.15, 0.1};
  for (int c = 0; c < 3; ++c) v.set(m.params(), "kd", kd[c], c);
  v.set(m.params(), "ks", 0.8);
  v.set(m.params(), "alpha_x", 0.2);
  v.set(m.params(), "alpha_y", 0.4);
  v.set(m.params(), "phi_t", phi_t);
  v.set(m.params(), "F0", 0.4);
  return Brdf(m, v);
}

RglSource source_of(const Brdf& b) {
  return [b](const Vec3d& wi, const Vec3d& wo) { return std::optional<Rgb>(b.eval(wi, wo)); };
}

// Smooth, positive, and unchanged by no turn or mirror: ρ depends on wi's and wo's x and y.
const RglSource kLopsided = [](const Vec3d& wi, const Vec3d& wo) {
  return std::optional<Rgb>(Rgb::Constant((0.5 + 0.2 * wi.x() + 0.1 * wi.y() + 0.05 * wo.x()) / kPi));
};

RglWriteOptions anisotropic(int phi_i, int symmetry) {
  return {.theta_i = 9, .phi_i = phi_i, .symmetry = symmetry, .grid = 32, .ndf_nodes = 48, .ndf_azimuths = 48, .vndf_nodes = 64};
}

class RglAnisotropic : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = test::scratch_dir("rgl_anisotropic");
    write_rgl(dir_ / "turned.bsdf", source_of(turned_ggx(0.5)), anisotropic(13, 2));
    write_rgl(dir_ / "aligned.bsdf", source_of(turned_ggx(0.0)), anisotropic(5, 4));
    write_rgl(dir_ / "lopsided_full.bsdf", kLopsided, anisotropic(9, 1));
    write_rgl(dir_ / "lopsided_half.bsdf", kLopsided, anisotropic(5, 2));
    write_rgl(dir_ / "lopsided_quarter.bsdf", kLopsided, anisotropic(3, 4));
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(dir_); }
  static std::filesystem::path dir_;
};
std::filesystem::path RglAnisotropic::dir_;

double relative(const Rgb& got, const Rgb& want) { return ((got - want).cwiseAbs().array() / want.array()).maxCoeff(); }

TEST_F(RglAnisotropic, LayoutFollowsMitsubasMeasuredPlugin) {
  const RglBrdf turned(dir_ / "turned.bsdf"), aligned(dir_ / "aligned.bsdf");
  EXPECT_FALSE(turned.isotropic());
  EXPECT_EQ(turned.reduction(), 2);
  EXPECT_EQ(aligned.reduction(), 4);
  ASSERT_EQ(turned.phi_i().size(), 13u);
  EXPECT_FLOAT_EQ(turned.phi_i().front(), float(-kPi));
  EXPECT_NEAR(turned.phi_i().back(), 0.0, 1e-6);
  EXPECT_NEAR(aligned.phi_i().back(), -kPi / 2, 1e-6);
  EXPECT_EQ(turned.slices(), 13u * 9u);
  EXPECT_NE(turned.dimensions().find("13 phi_i (anisotropic, 1/2 of the azimuths)"), std::string::npos) << turned.dimensions();
}

// Every node of every (φi, θi) slice reads back the source's value (float32 storage).
TEST_F(RglAnisotropic, NodesReadBackTheSourceValues) {
  const RglBrdf back(dir_ / "turned.bsdf");
  const Brdf b = turned_ggx(0.5);
  double worst = 0;
  int nodes = 0;
  for (size_t s = 0; s < back.slices(); ++s) {
    if (s % back.theta_i().size() + 1 == back.theta_i().size()) continue;  // the horizon node
    for (int y = 0; y < back.grid_size(); ++y)
      for (int x = 0; x < back.grid_size(); ++x) {
        const auto d = back.node_directions(s, y, x);
        if (!d) continue;
        const auto got = back.eval(d->first, d->second);
        ASSERT_TRUE(got.has_value());
        worst = std::max(worst, relative(*got, b.eval(d->first, d->second)));
        ++nodes;
      }
  }
  std::printf("anisotropic RGL: %d nodes over %zu slices read back, worst relative difference %.2e\n", nodes, back.slices(), worst);
  EXPECT_GT(nodes, 9 * 8 * 32 * 32 / 2);
  EXPECT_LT(worst, 1e-5);
}

// Between nodes, at pairs over the whole circle of incidence azimuths (wi with y > 0 is folded
// into the stored half by a half turn, x > 0 or y > 0 into the stored quarter by mirrors), the
// file follows the source, as well at folded azimuths as at stored ones. Printed apart: pairs
// whose wi is an incidence node (the colour grid's interpolation alone) and pairs at any wi (also
// the interpolation between slices, which blends lobes at different absolute azimuths: Mitsuba 3
// `measured`'s scheme, the larger part).
TEST_F(RglAnisotropic, LookupsFollowTheSourceAtEveryAzimuth) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  const double max_theta = 80 * kPi / 180;
  auto direction = [&](double phi) { return spherical_direction(std::acos(1 - (1 - std::cos(max_theta)) * u(rng)), phi); };
  for (const auto& [file, phi_t] : {std::pair{"turned.bsdf", 0.5}, std::pair{"aligned.bsdf", 0.0}}) {
    const RglBrdf back(dir_ / file);
    const Brdf b = turned_ggx(phi_t);
    std::vector<double> err[3];  // at an incidence node; any wi stored; any wi folded
    for (int k = 0; k < 6000; ++k) {
      const Vec3d wo = direction(2 * kPi * u(rng));
      if (k % 3 == 0) {
        const size_t s = size_t(u(rng) * double(back.slices()));
        const Vec3d wi = back.incidence(s);
        if (s % back.theta_i().size() == 0 || wi.z() < std::cos(max_theta)) continue;
        err[0].push_back(relative(*back.eval(wi, wo), b.eval(wi, wo)));
        continue;
      }
      const Vec3d wi = direction(2 * kPi * u(rng));
      const bool stored = wi.y() < 0 && (back.reduction() < 4 || wi.x() < 0);
      err[stored ? 1 : 2].push_back(relative(*back.eval(wi, wo), b.eval(wi, wo)));
    }
    for (auto& e : err) std::sort(e.begin(), e.end());
    auto pct = [](const std::vector<double>& e, double q) { return e[size_t(q * double(e.size() - 1))]; };
    std::printf("anisotropic RGL %s, relative error median / 95th percentile: wi at a node %.2e / %.2e; any wi: stored azimuths "
                "%.2e / %.2e, folded %.2e / %.2e\n",
                file, pct(err[0], 0.5), pct(err[0], 0.95), pct(err[1], 0.5), pct(err[1], 0.95), pct(err[2], 0.5), pct(err[2], 0.95));
    EXPECT_LT(pct(err[0], 0.5), 0.01) << file;
    EXPECT_LT(pct(err[0], 0.95), 0.05) << file;
    for (int i : {1, 2}) {
      EXPECT_LT(pct(err[i], 0.5), 0.03) << file;
      EXPECT_LT(pct(err[i], 0.95), 0.15) << file;
    }
  }
}

// The file's σ is the projected area of its own 2-D D: ∫ D(m) max(0, ω·m) dωm by an independent
// midpoint quadrature of the read-back D, at directions between table nodes in θ and φ (σ is
// interpolated between the 48 θ nodes of this layout: 2.7e-3 at 85°, 3e-4 below 75°).
TEST_F(RglAnisotropic, SigmaIsTheProjectedAreaOfTheNdf) {
  const RglBrdf back(dir_ / "turned.bsdf");
  const int nt = 600, np = 480;
  double worst = 0, mass = 0;
  std::vector<std::pair<Vec3d, double>> m;  // D dωm at the midpoints
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < np; ++j) {
      const double th = (i + 0.5) * (kPi / 2) / nt;
      const Vec3d h = spherical_direction(th, (j + 0.5) * 2 * kPi / np);
      m.emplace_back(h, back.ndf(h) * std::sin(th) * (kPi / 2 / nt) * (2 * kPi / np));
      mass += m.back().second * h.z();
    }
  for (double deg : {0.0, 23.0, 47.0, 71.0, 85.0})
    for (double phi : {-2.9, -1.3, 0.4, 2.2}) {
      const Vec3d w = spherical_direction(deg * kPi / 180, phi);
      double s = 0;
      for (const auto& [h, dw] : m) s += std::max(0.0, w.dot(h)) * dw;
      worst = std::max(worst, std::abs(s / back.sigma(w) - 1));
    }
  std::printf("anisotropic RGL: integral of D cos = %.5f; sigma vs integral of D projected: worst relative %.2e\n", mass, worst);
  EXPECT_NEAR(mass, 1.0, 3e-3);
  EXPECT_LT(worst, 4e-3);
}

// The samples of one θi (every slice and every image under the symmetry) weigh 2π of outgoing
// solid angle shared among the azimuths, so Σ weight · ρ · cosθo is the source's albedo averaged
// over the incidence azimuths.
TEST_F(RglAnisotropic, SamplesIntegrateToTheAzimuthalMeanOfTheAlbedo) {
  const RglBrdf back(dir_ / "turned.bsdf");
  const Brdf b = turned_ggx(0.5);
  const SampleSet s = back.samples();
  double worst = 0;
  for (size_t t = 1; t + 2 < back.theta_i().size(); ++t) {
    const double theta = back.theta_i()[t];
    Rgb sum = Rgb::Zero();
    for (size_t k = 0; k < s.size(); ++k)
      if (std::abs(std::acos(s.wi_z[k]) - theta) < 1e-5) sum += s.weight[k] * s.value(k) * s.wo_z[k];
    Rgb mean = Rgb::Zero();
    constexpr int kAzimuths = 36;
    for (int p = 0; p < kAzimuths; ++p) {
      const double c = std::cos(2 * kPi * p / kAzimuths), sn = std::sin(2 * kPi * p / kAzimuths);
      auto turn = [&](const Vec3d& v) { return Vec3d(c * v.x() - sn * v.y(), sn * v.x() + c * v.y(), v.z()); };
      mean += directional_albedo([&](const Vec3d& wi, const Vec3d& wo) { return std::optional(b.eval(turn(wi), turn(wo))); }, theta).value /
              kAzimuths;
    }
    worst = std::max(worst, relative(sum, mean));
    std::printf("anisotropic RGL: theta_i %.1f deg: samples %.5f, azimuthal mean of the albedo %.5f (G)\n", theta * 180 / kPi, sum[1],
                mean[1]);
  }
  EXPECT_LT(worst, 0.01);
}

TEST_F(RglAnisotropic, SymmetriesAreProbed) {
  EXPECT_EQ(azimuthal_symmetry(source_of(turned_ggx(0.5))), AzimuthalSymmetry::HalfTurn);
  EXPECT_EQ(azimuthal_symmetry(source_of(turned_ggx(0.0))), AzimuthalSymmetry::Mirrors);
  EXPECT_EQ(azimuthal_symmetry(kLopsided), AzimuthalSymmetry::None);
  const Model& ggx = model_by_name("cook-torrance-ggx");
  EXPECT_EQ(azimuthal_symmetry(source_of(Brdf(ggx, ParamValues::defaults(ggx.params())))), AzimuthalSymmetry::Isotropic);
  // A file read back keeps what it stores: the half-turn file has the half turn, and no more.
  EXPECT_EQ(azimuthal_symmetry([back = std::make_shared<RglBrdf>(dir_ / "turned.bsdf")](const Vec3d& wi, const Vec3d& wo) {
              return back->eval(wi, wo);
            }),
            AzimuthalSymmetry::HalfTurn);
}

// A file that stores part of the azimuths answers every other wi with the stored pair it folds to
// (Mitsuba 3 `measured`): through a half turn (1/2), through mirrors about the x and y axes (1/4).
// The three files of a source without symmetry share their slices' azimuths, so each folded
// answer is the full-circle file's at the folded pair, to the last digit; a wrong fold would read
// another pair, whose value differs by 1 % or more.
TEST_F(RglAnisotropic, FoldedLookupsAnswerTheStoredPair) {
  const RglBrdf full(dir_ / "lopsided_full.bsdf"), half(dir_ / "lopsided_half.bsdf"), quarter(dir_ / "lopsided_quarter.bsdf");
  auto flip = [](const Vec3d& v, double sx, double sy) { return Vec3d(sx * v.x(), sy * v.y(), v.z()); };
  const double deg = kPi / 180;
  double worst = 0, nearest_other = 1;
  for (double phi_i : {-150.0, -60.0, 30.0, 120.0})
    for (double dphi : {20.0, 170.0, 250.0}) {
      const Vec3d wi = spherical_direction(40 * deg, phi_i * deg), wo = spherical_direction(50 * deg, (phi_i + dphi) * deg);
      const double sy = wi.y() < 0 ? 1 : -1, sx = wi.x() < 0 ? 1 : -1;
      const double h = (*half.eval(wi, wo))[0], q = (*quarter.eval(wi, wo))[0];
      worst = std::max(worst, std::abs(h / (*full.eval(flip(wi, sy, sy), flip(wo, sy, sy)))[0] - 1));
      worst = std::max(worst, std::abs(q / (*full.eval(flip(wi, sx, sy), flip(wo, sx, sy)))[0] - 1));
      if (sx != sy) nearest_other = std::min(nearest_other, std::abs(q / h - 1));
    }
  std::printf("anisotropic RGL: 1/2 and 1/4 of the azimuths vs the full circle at the folded pairs: worst relative %.2e "
              "(half vs quarter where their folds differ: at least %.2e apart)\n",
              worst, nearest_other);
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(nearest_other, 0.01);
}

// phi_i ranges that no symmetry explains are refused, naming the field (the plugin would fold
// look-ups into azimuths the file does not hold).
TEST_F(RglAnisotropic, PhiRangesOutsideTheLayoutAreRefused) {
  auto fields = test::parse_tensor(test::read_bytes(dir_ / "lopsided_half.bsdf"));
  auto variant = [&](const std::vector<float>& phi, const std::string& name) {
    auto f = fields;
    for (size_t k = 0; k < phi.size(); ++k) test::set_float(f, "phi_i", k, phi[k]);
    const auto file = dir_ / name;
    test::write_bytes(file, test::write_tensor(f));
    try {
      RglBrdf{file};
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const std::string span = variant({-1.0f, -0.5f, 0.0f, 0.5f, 1.0f}, "span.bsdf");
  EXPECT_NE(span.find("field 'phi_i' spans 2.0000 rad"), std::string::npos) << span;
  const std::string start = variant({-2.0f, -1.0f, 0.0f, 0.5f, 1.14f}, "start.bsdf");
  EXPECT_NE(start.find("field 'phi_i' runs from -2.0000 to 1.1400"), std::string::npos) << start;
  const std::string order = variant({-3.0f, -2.0f, -2.5f, -1.0f, 0.0f}, "order.bsdf");
  EXPECT_NE(order.find("field 'phi_i' entry 2 [2] is -2.5: must be greater than entry 1"), std::string::npos) << order;
}

}  // namespace
}  // namespace brdfkit
