// `brdfkit export`: a fit in the target's own model is written exactly and reads back to its
// values; bad input (unknown target, a model without a GLSL form, --for a non-renderer) is a
// one-line message with exit code 2 and no file written.
#include <gtest/gtest.h>

#include <cmath>

#include "brdfkit/analysis/model_checks.h"
#include "brdfkit/core/vec.h"
#include "brdfkit/export/gltf_material.h"
#include "brdfkit/fit/fit_record.h"
#include "brdfkit/fit/param_source.h"
#include "support/output_lines.h"
#include "support/test_util.h"

namespace brdfkit {
namespace {

namespace fs = std::filesystem;

fs::path saved_fit(const fs::path& dir, const char* model, const std::vector<std::pair<std::string, double>>& values) {
  fit::FitRecord r;
  r.model = model;
  const Model& m = model_by_name(model);
  r.values = ParamValues::defaults(m.params());
  for (const auto& [name, v] : values) r.values.set(m.params(), name, v);
  r.fit_metric = "ngan";
  r.data_file = "synthetic";
  const fs::path f = dir / (std::string(model) + ".json");
  fit::save_fit_record(f, r);
  return f;
}

TEST(ExportCli, OwnModelExportsExactlyAndReadsBack) {
  const fs::path dir = test::scratch_dir("export_cli");
  const fs::path fit = saved_fit(dir, "gltf-metallic-roughness", {{"base_color", 0.25}, {"roughness", 0.375}, {"metallic", 0.5}});
  const auto r = test::run_cli("export " + fit.string() + " --to gltf -o " + (dir / "m.gltf").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(test::has_line(r.out, "added      0 (the fit's own model, exported exactly)")) << r.out;
  const ParamValues back = exporter::read_gltf_material(dir / "m.gltf");
  EXPECT_EQ(back.values[0][0], 0.25);
  EXPECT_EQ(back.values[2][2], 0.375);
  const fs::path mitsuba = saved_fit(dir, "mitsuba-principled", {{"roughness", 0.3}});
  const auto m = test::run_cli("export " + mitsuba.string() + " --to mitsuba3 -o " + (dir / "m.xml").string());
  EXPECT_EQ(m.exit_code, 0) << m.err;
  EXPECT_TRUE(fs::exists(dir / "m_scene.xml"));
  fs::remove_all(dir);
}

// --material picks the published fit that is refitted into the target's model: the exported glTF
// material's albedo at θi = 30° is pink-felt's (a diffuse red-dominant felt), not alum-bronze's.
// One refit on the full MERL grid (~13 s).
TEST(ExportCli, MaterialChoosesThePublishedFitThatIsRefitted) {
  BRDFKIT_REQUIRE_DATA("published-fits/bagher2012-sgd.json");
  const fs::path dir = test::scratch_dir("export_cli_material");
  const fs::path published = test::data_dir() / "published-fits/bagher2012-sgd.json";
  const auto r = test::run_cli("export " + published.string() + " --material pink-felt --to gltf -o " +
                               (dir / "pink.gltf").string());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Brdf gltf(model_by_name("gltf-metallic-roughness"), exporter::read_gltf_material(dir / "pink.gltf"));
  const Brdf pink = fit::load_params_file(published, "pink-felt"), bronze = fit::load_params_file(published, "alum-bronze");
  auto albedo30 = [](const Brdf& b, int c) { return albedo(b.model(), b.values().channel(c), c, 30 * kPi / 180, 1e-4); };
  for (int c = 0; c < 3; ++c) {
    const double a = albedo30(gltf, c), want = albedo30(pink, c), other = albedo30(bronze, c);
    std::printf("channel %d: albedo(30°) exported %.4f, pink-felt %.4f, alum-bronze %.4f\n", c, a, want, other);
    EXPECT_NEAR(a / want, 1.0, 0.05) << "channel " << c;
    EXPECT_GT(std::abs(a / other - 1.0), 0.3) << "channel " << c;
  }
  fs::remove_all(dir);
}

TEST(ExportCli, BadInputExitsWithTwoAndWritesNothing) {
  const fs::path dir = test::scratch_dir("export_cli_bad");
  const fs::path he = saved_fit(dir, "he", {});
  for (const std::string& args : {"export " + he.string() + " --to blender -o " + (dir / "x").string(),
                                  "export " + he.string() + " --to glsl -o " + (dir / "x").string(),
                                  "fit " + he.string() + " --for glsl -o " + (dir / "x").string()}) {
    const auto r = test::run_cli(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(fs::exists(dir / "x")) << args;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace brdfkit
