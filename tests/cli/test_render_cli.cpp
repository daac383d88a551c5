// `brdfkit render`: a MERL file tabulated from a model beside that model gives the panel, the
// linear EXR and the JSON, with small image errors against the measurement; a point light renders
// ρ cos θ I exactly (the EXR read back); the same seed gives the same image with 1 or 2 threads;
// bad input is a one-line message, exit code 2 and no file written.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "brdfkit/render/image_io.h"
#include "support/output_lines.h"
#include "support/test_util.h"

namespace brdfkit {
namespace {

namespace fs = std::filesystem;

nlohmann::json read_json(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

TEST(RenderCli, MeasuredBesideItsModel) {
  const fs::path dir = test::scratch_dir("render_cli");
  const std::string params = "--param kd=0.3,0.2,0.1 --param alpha=0.2";
  ASSERT_EQ(test::run_cli("tabulate cook-torrance-ggx " + params + " -o " + (dir / "t.binary").string()).exit_code, 0);
  const auto r = test::run_cli("render " + (dir / "t.binary").string() + " --model cook-torrance-ggx " + params +
                               " --env-constant 0.5 --light 30,45,2 --size 24 --spp 16 -q -o " + (dir / "out" / "p.png").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* f : {"p.png", "p.exr", "p.json"}) EXPECT_TRUE(fs::exists(dir / "out" / f)) << f;
  const nlohmann::json j = read_json(dir / "out" / "p.json");
  ASSERT_EQ(j["columns"].size(), 2u);
  EXPECT_TRUE(j["columns"][0]["measured"].get<bool>());
  const double rmse = j["columns"][1]["image_rmse"], smape = j["columns"][1]["mean_smape"];
  EXPECT_LT(smape, 0.05);
  EXPECT_GT(smape, 0.0);
  EXPECT_LT(j["columns"][1]["mean_delta_e2000"].get<double>(), 3.0);
  EXPECT_TRUE(j.contains("exposure_ev"));
  const render::Rgb8Image panel = render::read_png(dir / "out" / "p.png");
  EXPECT_EQ(panel.width, 48);   // two columns
  EXPECT_EQ(panel.height, 72);  // renders, sMAPE, ΔE
  // The fit's row of the printed table, led by its label, with the JSON's numbers.
  const auto row = test::line_led_by(r.out, "cook-torrance-ggx");
  ASSERT_TRUE(row) << r.out;
  const auto t = test::tokens_of(*row);
  ASSERT_EQ(t.size(), 10u) << *row;
  EXPECT_EQ(t[1] + " " + t[2], "image RMSE") << *row;
  EXPECT_NEAR(std::stod(t[3]), rmse, 5e-7 + 1e-4 * rmse) << *row;
  EXPECT_EQ(t[4] + " " + t[5], "mean sMAPE") << *row;
  EXPECT_NEAR(std::stod(t[6]), smape, 5e-5) << *row;
  std::printf("render: tabulated GGX vs GGX at 24 px, 16 spp: image RMSE %.4g, mean sMAPE %.4f\n", rmse, smape);
  fs::remove_all(dir);
}

TEST(RenderCli, PointLightExactAndThreadCountIndependent) {
  const fs::path dir = test::scratch_dir("render_cli_light");
  const auto one = test::run_cli("render --model lambert --param kd=0.6 --light 0,0,2 --size 9 --spp 2 -q --threads 1 -o " + (dir / "a.png").string());
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const render::Image a = render::read_hdr_image(dir / "a.exr");
  // The centre pixel faces the camera and the light: 2 · 0.6/π · cos θ, θ ≤ 10° over the pixel's
  // jittered footprint on a sphere 8.5 pixels wide (exact without jitter:
  // tests/render/test_lights_and_convergence.cpp).
  EXPECT_NEAR(a.at(4, 4)[0], 2 * 0.6 / kPi, 2 * 0.6 / kPi * (1 - std::cos(10 * kPi / 180)));
  EXPECT_LE(a.at(4, 4)[0], 2 * 0.6 / kPi * (1 + 1e-6));
  ASSERT_EQ(test::run_cli("render --model cook-torrance-ggx --env-constant 1 --size 12 --spp 8 -q --threads 1 -o " + (dir / "b.png").string()).exit_code, 0);
  ASSERT_EQ(test::run_cli("render --model cook-torrance-ggx --env-constant 1 --size 12 --spp 8 -q --threads 2 -o " + (dir / "c.png").string()).exit_code, 0);
  const render::Image b = render::read_hdr_image(dir / "b.exr"), c = render::read_hdr_image(dir / "c.exr");
  for (size_t k = 0; k < b.size(); ++k) EXPECT_TRUE((b.pixels[k] == c.pixels[k]).all()) << "pixel " << k;
  fs::remove_all(dir);
}

TEST(RenderCli, BadInputIsOneLineAndExitTwo) {
  const fs::path dir = test::scratch_dir("render_cli_bad");
  const std::string out = " -o " + (dir / "x.png").string();
  for (const std::string& args : {std::string("render --model lambert --env ") + (dir / "none.exr").string() + out,
                                  std::string("render --model lambert --light 30") + out, std::string("render") + out,
                                  std::string("render --model lambert -o ") + (dir / "x.jpg").string(),
                                  std::string("render ") + (dir / "missing.binary").string() + out}) {
    const auto r = test::run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << args << "\n" << r.err;
    EXPECT_FALSE(fs::exists(dir / "x.png")) << args;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace brdfkit
