// Exported files read back to the fit's values (glTF by tinygltf, the same library; Mitsuba 3 XML
// and pbrt-v4 text by their attribute syntax), the glTF passes the Khronos glTF validator (npm
// gltf-validator, when scripts/setup.sh could install it), every GLSL transcription compiles with
// glslangValidator, and a refit recovers a model its target contains exactly.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "brdfkit/core/error.h"
#include "brdfkit/export/brdf_explorer.h"
#include "brdfkit/export/export_fit.h"
#include "brdfkit/export/glsl_function.h"
#include "brdfkit/export/gltf_material.h"
#include "brdfkit/export/mitsuba_scene.h"
#include "brdfkit/export/pbrt_scene.h"
#include "brdfkit/export/refit.h"
#include "brdfkit/models/model.h"
#include "support/test_util.h"

namespace brdfkit {
namespace {

namespace fs = std::filesystem;
using exporter::Provenance;

// One scratch folder for the whole test process (its files refer to each other).
const fs::path& temp_dir() {
  static const fs::path d = test::scratch_dir("export");
  return d;
}
std::string read(const fs::path& f) {
  std::ifstream in(f);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
Brdf brdf_of(const char* model, const std::vector<std::pair<std::string, std::vector<double>>>& values) {
  const Model& m = model_by_name(model);
  ParamValues v = ParamValues::defaults(m.params());
  for (const auto& [name, x] : values)
    for (int c = 0; c < 3; ++c) v.set(m.params(), name, x.size() == 3 ? x[size_t(c)] : x[0], x.size() == 3 ? c : -1);
  return Brdf(m, v);
}
Provenance provenance(const char* target, const Brdf& b) {
  Provenance p;
  p.target = target;
  p.model = p.source_model = std::string(b.model().name());
  p.metric = "ngan";
  return p;
}
void expect_same_values(const ParamValues& got, const ParamValues& want, const char* what) {
  for (int c = 0; c < 3; ++c)
    for (size_t i = 0; i < want.values[0].size(); ++i)
      EXPECT_NEAR(got.values[size_t(c)][i], want.values[size_t(c)][i], 1e-6 * std::max(1.0, std::abs(want.values[size_t(c)][i])))
          << what << " parameter " << i << " channel " << c;
}

const Brdf kGltf = brdf_of("gltf-metallic-roughness", {{"base_color", {0.712345678901, 0.4, 0.123456789}},
                                                       {"metallic", {0.3}}, {"roughness", {0.4567}}, {"ior", {1.61}},
                                                       {"specular", {0.77}}, {"specular_color", {0.9}}});

TEST(ExportFiles, GltfReadsBackAndValidates) {
  const fs::path f = temp_dir() / "fit.gltf";
  exporter::write_gltf(f, kGltf, provenance("gltf", kGltf));
  expect_same_values(exporter::read_gltf_material(f), kGltf.values(), "glTF");
  // A changed value is seen by the same comparison.
  ParamValues off = kGltf.values();
  off.values[1][0] += 1e-5;
  EXPECT_GT(std::abs(exporter::read_gltf_material(f).values[1][0] - off.values[1][0]), 1e-6);
  const std::string node = BRDFKIT_NODE, validator = BRDFKIT_GLTF_VALIDATOR;
  if (node.empty() || !fs::exists(validator)) {
    std::printf("skipped the Khronos glTF validator: node or %s absent (scripts/setup.sh installs it with npm)\n",
                validator.c_str());
    return;
  }
  const fs::path script = temp_dir() / "validate.mjs", report = temp_dir() / "report.json";
  std::ofstream(script) << "import v from '" << validator << "';\nimport fs from 'fs';\n"
                        << "const r = await v.validateBytes(new Uint8Array(fs.readFileSync(process.argv[2])));\n"
                        << "fs.writeFileSync(process.argv[3], JSON.stringify(r.issues));\n";
  ASSERT_EQ(std::system((node + " " + script.string() + " " + f.string() + " " + report.string()).c_str()), 0);
  const std::string issues = read(report);
  std::printf("Khronos glTF validator: %s\n", issues.substr(0, 120).c_str());
  const auto report_json = nlohmann::json::parse(issues);
  EXPECT_EQ(report_json["numErrors"], 0) << issues;
  EXPECT_EQ(report_json["numWarnings"], 0) << issues;
}

// A material without KHR_materials_ior or KHR_materials_specular reads with those extensions'
// defaults (KHR_materials_ior README: "ior ... default 1.5"; KHR_materials_specular README:
// specularFactor 1, specularColorFactor [1, 1, 1]), so its dielectric F0 is 0.04.
TEST(ExportFiles, GltfWithoutExtensionsReadsWithTheirDefaults) {
  const fs::path f = temp_dir() / "plain.gltf";
  std::ofstream(f) << R"({"asset": {"version": "2.0"}, "materials": [{"pbrMetallicRoughness":
      {"baseColorFactor": [0.5, 0.25, 0.125, 1], "metallicFactor": 0.25, "roughnessFactor": 0.75}}]})";
  const ParamValues v = exporter::read_gltf_material(f);
  const ParamTable t = model_by_name("gltf-metallic-roughness").params();
  auto get = [&](const char* name, int c) { return v.values[size_t(c)][size_t(find_param(t, name))]; };
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(get("ior", c), 1.5) << "channel " << c;
    EXPECT_EQ(get("specular", c), 1.0) << "channel " << c;
    EXPECT_EQ(get("specular_color", c), 1.0) << "channel " << c;
    EXPECT_EQ(get("base_color", c), 0.5 / (1 << c)) << "channel " << c;
    EXPECT_EQ(get("metallic", c), 0.25) << "channel " << c;
    EXPECT_EQ(get("roughness", c), 0.75) << "channel " << c;
  }
}

// name → values of the renderer's attributes in a Mitsuba XML or pbrt file.
std::vector<double> numbers_of(const std::string& text, const std::string& pattern) {
  std::smatch m;
  if (!std::regex_search(text, m, std::regex(pattern))) return {};
  std::vector<double> out;
  std::stringstream ss(std::regex_replace(m[1].str(), std::regex(","), " "));
  for (double x; ss >> x;) out.push_back(x);
  return out;
}

TEST(ExportFiles, MitsubaXmlReadsBack) {
  const Brdf b = brdf_of("mitsuba-roughconductor-ggx",
                         {{"eta", {0.2, 0.9, 1.1}}, {"k", {3.9, 2.4, 2.1}}, {"specular_reflectance", {0.9}}, {"alpha", {0.123}}});
  const fs::path f = temp_dir() / "fit.xml";
  const auto files = exporter::write_mitsuba(f, b, provenance("mitsuba3", b));
  ASSERT_EQ(files.size(), 2u);
  const std::string xml = read(f), scene = read(files[1]);
  EXPECT_NE(xml.find("<string name=\"distribution\" value=\"ggx\"/>"), std::string::npos);
  EXPECT_EQ(xml.find("--", xml.find("<!--") + 4), xml.find("-->"));  // no "--" inside the comment
  const auto eta = numbers_of(xml, "name=\"eta\" value=\"([^\"]*)\"");
  ASSERT_EQ(eta.size(), 3u);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(eta[size_t(c)], b.values().values[size_t(c)][0], 1e-12);
  EXPECT_NEAR(numbers_of(xml, "name=\"alpha\" value=\"([^\"]*)\"").at(0), 0.123, 1e-12);
  EXPECT_NE(scene.find("<include filename=\"fit.xml\"/>"), std::string::npos);
  EXPECT_NE(scene.find("<ref id=\"brdfkit_fit\"/>"), std::string::npos);
}

TEST(ExportFiles, PbrtReadsBack) {
  const Brdf b = brdf_of("pbrt-mix-diffuse-conductor", {{"reflectance", {0.6, 0.5, 0.4}}, {"amount", {0.35}},
                                                        {"conductor_reflectance", {0.9, 0.8, 0.7}}, {"roughness", {0.01}}});
  const fs::path f = temp_dir() / "fit.pbrt";
  const auto files = exporter::write_pbrt(f, b, provenance("pbrt-v4", b));
  const std::string text = read(f);
  EXPECT_NEAR(numbers_of(text, "\"float amount\" \\[ ([^\\]]*) \\]").at(0), 0.35, 1e-12);
  EXPECT_NEAR(numbers_of(text, "\"float roughness\" \\[ ([^\\]]*) \\]").at(0), 0.01, 1e-12);
  EXPECT_EQ(numbers_of(text, "\"rgb reflectance\" \\[ ([^\\]]*) \\]").at(2), 0.4);
  EXPECT_NE(text.find("\"bool remaproughness\" [ true ]"), std::string::npos);
  EXPECT_NE(read(files[1]).find("Include \"fit.pbrt\""), std::string::npos);
}

// Every GLSL transcription, as a fragment shader and in a BRDF Explorer file, at its defaults.
TEST(ExportFiles, EveryGlslModelCompiles) {
  const std::string glslang = BRDFKIT_GLSLANG_VALIDATOR;
  if (glslang.empty()) GTEST_SKIP() << "glslangValidator absent (Debian glslang-tools)";
  for (const std::string& name : exporter::glsl_models()) {
    const Model& m = model_by_name(name);
    const Brdf b(m, ParamValues::defaults(m.params()));
    const fs::path f = temp_dir() / (name + ".frag");
    std::ofstream(f) << "#version 330 core\n" << exporter::glsl_file(b, provenance("glsl", b))
                     << "out vec4 o;\nvoid main() { o = vec4(brdfkit_brdf(vec3(0.3, 0.1, 0.9), vec3(-0.2, 0.1, 0.95)), 1.0); }\n";
    EXPECT_EQ(std::system((glslang + " " + f.string() + " > /dev/null").c_str()), 0) << name;
    const std::string be = exporter::brdf_explorer_text(b, provenance("brdf-explorer", b));
    EXPECT_EQ(be.rfind("analytic\n", 0), 0u);
    EXPECT_NE(be.find("vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)"), std::string::npos);
  }
  EXPECT_THROW(exporter::glsl_functions(model_by_name("he")), InputError);
}

// A model the target holds exactly comes back from the refit with (nearly) no added error.
TEST(ExportFiles, RefitRecoversAModelTheTargetContains) {
  const Brdf lambert = brdf_of("lambert", {{"kd", {0.6, 0.4, 0.2}}});
  const exporter::RefitResult r = exporter::refit(lambert, model_by_name("pbrt-diffuse"), "ngan");
  std::printf("lambert -> pbrt-diffuse refit: added ngan error %.2e in %.1f s\n", r.added_error, r.seconds);
  EXPECT_LT(r.added_error, 1e-6);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(r.brdf.values().values[size_t(c)][0], lambert.values().values[size_t(c)][0], 1e-6);
  // The export of that fit says so in its file: not refitted when the model is the target's.
  const fs::path f = temp_dir() / "diffuse.pbrt";
  const auto ex = exporter::export_fit(r.brdf, std::nullopt, exporter::Target::PbrtV4, f);
  EXPECT_FALSE(ex.provenance.refitted);
  EXPECT_NE(read(f).find("exported exactly"), std::string::npos);
}

}  // namespace
}  // namespace brdfkit
