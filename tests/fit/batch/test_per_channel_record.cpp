// Fits with one lobe shape per channel (`fit --per-channel-shape`) are saved so that `error`
// reads them back and prints the same metrics: the JSON says "shape": "per-channel",
// and a record that says "shared" still refuses differing values of a shared parameter.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "brdfkit/core/error.h"
#include "brdfkit/fit/fit_record.h"
#include "brdfkit/measured/merl.h"
#include "support/merl_cases.h"
#include "support/test_util.h"

namespace brdfkit::test {
namespace {

// The "parameters" and "metrics" blocks of the human output.
std::string block(const std::string& out, const std::string& title) {
  const auto at = out.find(title + "\n");
  if (at == std::string::npos) return "";
  std::string lines;
  std::istringstream in(out.substr(at + title.size() + 1));
  std::string line;
  while (std::getline(in, line) && line.rfind("  ", 0) == 0) lines += line + "\n";
  return lines;
}

TEST(PerChannelRecord, FitThenErrorPrintsTheSameNumbers) {
  const auto dir = scratch_dir("per_channel_record");
  const std::string data = (dir / "ct.binary").string(), saved = (dir / "fit.json").string();
  // A Cook-Torrance-Beckmann material whose lobe width differs per channel, on 1/27 of the cells.
  const Model& m = model_by_name("cook-torrance-beckmann");
  ParamValues v = with(m, {{"kd", Rgb(0.1, 0.2, 0.3)}, {"ks", Rgb(0.5, 0.5, 0.5)}, {"F0", Rgb::Constant(0.05)}});
  const int alpha = find_param(m.params(), "alpha");
  for (int c = 0; c < 3; ++c) v.values[size_t(c)][size_t(alpha)] = 0.15 + 0.05 * c;
  merl::write(dir / "ct.binary", tabulate_cells(m, v, 3));

  const std::string metrics = "ngan,bagher,low-e1,low-e2";
  const auto fit = run_cli("fit " + data + " --model cook-torrance-beckmann --per-channel-shape --coarsen 3 --report " +
                           metrics + " -o " + saved);
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  const auto err = run_cli("error " + data + " --params " + saved + " --metric " + metrics);
  ASSERT_EQ(err.exit_code, 0) << err.err;
  std::printf("fit:\n%s%s", block(fit.out, "parameters").c_str(), block(fit.out, "metrics").c_str());
  const std::string printed = block(fit.out, "metrics"), recomputed_lines = block(err.out, "metrics");
  EXPECT_EQ(printed, recomputed_lines);
  EXPECT_EQ(std::count(printed.begin(), printed.end(), '\n'), 4) << fit.out;
  EXPECT_EQ(block(fit.out, "parameters"), block(err.out, "parameters"));
  EXPECT_EQ(err.err, "");

  std::ifstream in(saved);
  const nlohmann::json doc = nlohmann::json::parse(in);
  EXPECT_EQ(doc["shape"], "per-channel");
  EXPECT_EQ(doc["params"][size_t(alpha)]["scope"], "per-channel");
  // The three fitted widths are the truth's (the cells are exact), so they do differ.
  for (int c = 0; c < 3; ++c)
    EXPECT_NEAR(doc["params"][size_t(alpha)]["values"][c].get<double>(), 0.15 + 0.05 * c, 1e-6) << c;

  // Bit for bit under --json too.
  const auto ej = run_cli("error " + data + " --params " + saved + " --metric " + metrics + " --json");
  ASSERT_EQ(ej.exit_code, 0) << ej.err;
  const nlohmann::json recomputed = nlohmann::json::parse(ej.out);
  for (const char* id : {"ngan", "bagher", "low-e1", "low-e2"})
    EXPECT_EQ(doc["metrics"][id].get<double>(), recomputed["metrics"][id].get<double>()) << id;

  // Saying "shared" with differing values is still an error naming the parameter (exit 2).
  nlohmann::json shared = doc;
  shared["shape"] = "shared";
  std::ofstream(dir / "shared.json") << shared.dump(2);
  const auto bad = run_cli("error " + data + " --params " + (dir / "shared.json").string());
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("'alpha' is shared by the three channels but its values differ"), std::string::npos)
      << bad.err;
  nlohmann::json odd = doc;
  odd["shape"] = "sideways";
  std::ofstream(dir / "odd.json") << odd.dump(2);
  const auto bad2 = run_cli("error " + data + " --params " + (dir / "odd.json").string());
  EXPECT_EQ(bad2.exit_code, 2);
  EXPECT_NE(bad2.err.find("field 'shape'"), std::string::npos) << bad2.err;
  std::filesystem::remove_all(dir);
}

// In the library: a record with differing shared values round-trips through JSON, and one
// written by an older brdfkit (no "shape" field, fit.per_channel_shape = true) is read too.
TEST(PerChannelRecord, JsonRoundTrip) {
  const Model& m = model_by_name("cook-torrance-ggx");
  fit::FitRecord r;
  r.model = "cook-torrance-ggx";
  r.values = ParamValues::defaults(m.params());
  const int alpha = find_param(m.params(), "alpha");
  r.values.values[1][size_t(alpha)] = 0.31;
  EXPECT_TRUE(fit::shape_differs_by_channel(m, r.values));
  nlohmann::json j = fit::to_json(r);
  EXPECT_EQ(j["shape"], "per-channel");
  const fit::FitRecord back = fit::fit_record_from_json(j, "test");
  EXPECT_TRUE(back.per_channel_shape);
  EXPECT_EQ(back.values.values, r.values.values);
  j.erase("shape");
  EXPECT_THROW(fit::fit_record_from_json(j, "test"), InputError);
  j["fit"]["per_channel_shape"] = true;
  EXPECT_EQ(fit::fit_record_from_json(j, "test").values.values, r.values.values);
  // One shared shape is still written as such.
  r.values = ParamValues::defaults(m.params());
  EXPECT_EQ(fit::to_json(r)["shape"], "shared");
}

}  // namespace
}  // namespace brdfkit::test
