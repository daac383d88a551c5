// The RGL writer (measured/rgl_writer.h): its files read back through brdfkit's reader with the
// values written at every node, consistent microfacet tables (σ = ∫ D projected), the source's
// albedo, and a MERL → RGL → MERL round trip that keeps the albedo at every θi within 1 %.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "brdfkit/measured/albedo.h"
#include "brdfkit/measured/merl_brdf.h"
#include "brdfkit/measured/merl_tabulate.h"
#include "brdfkit/measured/rgl_tensor.h"
#include "brdfkit/measured/rgl_writer.h"
#include "brdfkit/models/model.h"
#include "support/test_util.h"

namespace brdfkit {
namespace {

// Cook-Torrance GGX α = 0.25 with a coloured diffuse term: a lobe the tables must follow.
Brdf glossy() {
  const Model& m = model_by_name("cook-torrance-ggx");
  ParamValues v = ParamValues::defaults(m.params());
  const double kd[3] = {0.3, 0.2, 0.1};
  for (int c = 0; c < 3; ++c) v.set(m.params(), "kd", kd[c], c);
  v.set(m.params(), "ks", 0.8);
  v.set(m.params(), "alpha", 0.25);
  v.set(m.params(), "F0", 0.5);
  return Brdf(m, v);
}

RglSource source_of(const Brdf& b) {
  return [b](const Vec3d& wi, const Vec3d& wo) { return std::optional<Rgb>(b.eval(wi, wo)); };
}

class RglWriter : public testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = test::scratch_dir("rgl_writer");
    write_rgl(dir_ / "glossy.bsdf", source_of(glossy()), {.description = "glossy test lobe"});
  }
  static void TearDownTestSuite() { std::filesystem::remove_all(dir_); }
  static std::filesystem::path dir_;
};
std::filesystem::path RglWriter::dir_;

// Every node of the colour grid reads back the source's value (float32 storage: 1e-5).
TEST_F(RglWriter, NodesReadBackTheSourceValues) {
  const RglBrdf back(dir_ / "glossy.bsdf");
  const Brdf b = glossy();
  EXPECT_EQ(back.description(), "glossy test lobe");
  double worst = 0;
  int nodes = 0;
  for (size_t t = 0; t + 1 < back.theta_i().size(); ++t)
    for (int y = 0; y < back.grid_size(); ++y)
      for (int x = 0; x < back.grid_size(); ++x) {
        const auto d = back.node_directions(t, y, x);
        if (!d) continue;
        const auto got = back.eval(d->first, d->second);
        ASSERT_TRUE(got.has_value());
        const Rgb want = b.eval(d->first, d->second);
        worst = std::max(worst, ((*got - want).cwiseAbs().array() / want.array()).maxCoeff());
        ++nodes;
      }
  std::printf("RGL writer: %d grid nodes read back, worst relative difference %.2e\n", nodes, worst);
  EXPECT_GT(nodes, 15 * 32 * 32 / 2);
  EXPECT_LT(worst, 1e-5);
}

// The file's σ is the projected area of its own D: ∫ D(m) max(0, ω·m) dωm by an independent
// quadrature (midpoints in θm and φm) of the read-back D, at directions between table nodes.
TEST_F(RglWriter, SigmaIsTheProjectedAreaOfTheNdf) {
  const RglBrdf back(dir_ / "glossy.bsdf");
  const int nt = 1200, np = 240;
  double worst = 0, mass = 0;
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < np; ++j) {
      const double th = (i + 0.5) * (kPi / 2) / nt;
      const Vec3d m = spherical_direction(th, (j + 0.5) * 2 * kPi / np);
      mass += back.ndf(m) * m.z() * std::sin(th) * (kPi / 2 / nt) * (2 * kPi / np);
    }
  for (double deg : {0.0, 17.0, 33.0, 51.0, 68.0, 85.0}) {
    const Vec3d w = spherical_direction(deg * kPi / 180, 0.4);
    double s = 0;
    for (int i = 0; i < nt; ++i)
      for (int j = 0; j < np; ++j) {
        const double th = (i + 0.5) * (kPi / 2) / nt;
        const Vec3d m = spherical_direction(th, (j + 0.5) * 2 * kPi / np);
        s += back.ndf(m) * std::max(0.0, w.dot(m)) * std::sin(th) * (kPi / 2 / nt) * (2 * kPi / np);
      }
    worst = std::max(worst, std::abs(s / back.sigma(w) - 1));
  }
  std::printf("RGL writer: integral of D cos = %.5f; sigma vs integral of D projected: worst relative %.2e\n", mass,
              worst);
  EXPECT_NEAR(mass, 1.0, 2e-3);
  EXPECT_LT(worst, 2e-3);
}

// The directional albedo of the file equals the source's within 1 % at θi = 0 … 80°.
TEST_F(RglWriter, AlbedoOfTheSourceIsKept) {
  const RglBrdf back(dir_ / "glossy.bsdf");
  const Brdf b = glossy();
  double worst = 0;
  for (int deg = 0; deg <= 80; deg += 5) {
    const double th = deg * kPi / 180;
    const Rgb want = directional_albedo([&](const Vec3d& wi, const Vec3d& wo) { return std::optional(b.eval(wi, wo)); }, th).value;
    const Rgb got = directional_albedo([&](const Vec3d& wi, const Vec3d& wo) { return back.eval(wi, wo); }, th).value;
    worst = std::max(worst, ((got - want).cwiseAbs().array() / want.array()).maxCoeff());
  }
  std::printf("RGL writer: albedo of the file vs the source, theta_i 0..80 deg: worst relative %.2e\n", worst);
  EXPECT_LT(worst, 0.01);
}

// MERL → RGL → MERL: the albedo at every θi from 0° to 85° (1° steps, measured/albedo.h) within
// 1 %; beyond, towards the horizon, the RGL's grid and the MERL cells both coarsen (printed). The
// ngan distance (ρ cosθi differences weighted by the cells' solid angles) between the two MERL
// tables is stated beside the ngan norm of the first: grazing pairs dominate it (a GGX lobe at
// θi = 87°, θo = 89.97° reads 10 times too large through the RGL's last incidence cell).
TEST_F(RglWriter, MerlToRglToMerlKeepsTheAlbedo) {
  const Brdf b = glossy();
  const MerlBrdf first(merl::tabulate([&](const Vec3d& wi, const Vec3d& wo) { return b.eval(wi, wo); }), "first");
  write_rgl(dir_ / "from_merl.bsdf", [&](const Vec3d& wi, const Vec3d& wo) { return first.eval(wi, wo); });
  const RglBrdf rgl(dir_ / "from_merl.bsdf");
  const MerlBrdf second(
      merl::tabulate([&](const Vec3d& wi, const Vec3d& wo) { return rgl.eval(wi, wo).value_or(Rgb::Constant(-1)); }),
      "second");
  double worst = 0, grazing = 0;
  int worst_deg = 0;
  for (int deg = 0; deg < 90; ++deg) {
    const double th = deg * kPi / 180;
    const Rgb a = directional_albedo(first, th)->value, c = directional_albedo(second, th)->value;
    const double rel = ((c - a).cwiseAbs().array() / a.array()).maxCoeff();
    if (deg > 85) grazing = std::max(grazing, rel);
    else if (rel > worst) worst = rel, worst_deg = deg;
  }
  const SampleSet s = first.samples();
  double num = 0, den = 0, norm = 0, num80 = 0, den80 = 0;
  for (size_t k = 0; k < s.size(); ++k) {
    if (!s.valid[k]) continue;
    const auto other = second.eval(s.wi(k), s.wo(k));
    if (!other) continue;
    const double ci = s.wi_z[k];
    num += s.weight[k] * ((s.value(k) - *other) * ci).square().sum() / 3;
    norm += s.weight[k] * (s.value(k) * ci).square().sum() / 3;
    if (ci >= std::cos(80 * kPi / 180) && s.wo_z[k] >= std::cos(80 * kPi / 180)) {
      num80 += s.weight[k] * ((s.value(k) - *other) * ci).square().sum() / 3;
      den80 += s.weight[k];
    }
    den += s.weight[k];
  }
  std::printf("MERL -> RGL -> MERL: albedo worst relative %.2e at %d deg (0..85), %.2e at 86..89 deg; ngan distance %.4g "
              "(ngan norm of the first table %.4g; rms of rho cos_i, 1/sr), %.4g over the cells with both angles <= 80 deg\n",
              worst, worst_deg, grazing, std::sqrt(num / den), std::sqrt(norm / den), std::sqrt(num80 / den80));
  EXPECT_LT(worst, 0.01);
}

// The `spectra` table (what Mitsuba 3 reads) holds the same colours: a file without `rgb` reads
// back, through the reader's spectrum → RGB conversion, the values of the file with it.
TEST_F(RglWriter, SpectraHoldTheSameColours) {
  write_rgl(dir_ / "spectral.bsdf", source_of(glossy()), {.rgb_table = false});
  const RglBrdf spectral(dir_ / "spectral.bsdf"), rgb(dir_ / "glossy.bsdf");
  EXPECT_TRUE(spectral.spectral());
  EXPECT_FALSE(rgb.spectral());
  double worst = 0;
  for (size_t t = 0; t < rgb.theta_i().size(); t += 3)
    for (int y = 0; y < rgb.grid_size(); ++y)
      for (int x = 0; x < rgb.grid_size(); ++x) {
        const Rgb a = rgb.rgb_node(t, y, x), b = spectral.rgb_node(t, y, x);
        worst = std::max(worst, (a - b).cwiseAbs().maxCoeff() / std::max(1e-6, a.abs().maxCoeff()));
      }
  std::printf("RGL writer: colours from the spectra vs the rgb table: worst relative %.2e\n", worst);
  EXPECT_LT(worst, 1e-5);
}

TEST(RglWriterOptions, OutOfRangeIsAnInputError) {
  const auto dir = test::scratch_dir("rgl_writer_options");
  const RglSource flat = [](const Vec3d&, const Vec3d&) { return std::optional<Rgb>(Rgb::Constant(0.2)); };
  EXPECT_THROW(write_rgl(dir / "x.bsdf", flat, {.theta_i = 1}), InputError);
  EXPECT_THROW(write_rgl(dir / "x.bsdf", flat, {.grid = 1}), InputError);
  const RglSource dark = [](const Vec3d&, const Vec3d&) { return std::optional<Rgb>(Rgb::Zero()); };
  EXPECT_THROW(write_rgl(dir / "x.bsdf", dark), InputError);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.bsdf"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace brdfkit
