// `brdfkit convert-ndf`: exit codes, messages, JSON and the Table 2 layout.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/output_lines.h"
#include "support/test_util.h"

namespace brdfkit::test {
namespace {

TEST(ConvertNdfCli, RmseJson) {
  const auto r = run_cli("convert-ndf --from beckmann --to blinn-phong 0.2 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["from"]["distribution"], "beckmann");
  EXPECT_EQ(j["from"]["parameter"], "m_B");
  EXPECT_EQ(j["to"]["parameter"], "N");
  EXPECT_NEAR(j["to"]["value"].get<double>(), 47.33, 0.005);
  EXPECT_EQ(j["method"]["requested"], "rmse");
  EXPECT_EQ(j["method"]["used"], "rmse");
  EXPECT_NEAR(j["rmse"].get<double>(), 0.003024, 0.0001);
  EXPECT_DOUBLE_EQ(j["rmse_domain"]["beta_max"].get<double>(), 0.8);
  EXPECT_EQ(j["rmse_domain"]["samples"], 2001);
  EXPECT_EQ(j["rmse_domain"]["spacing"], "uniform");
  EXPECT_TRUE(j["warnings"].empty());
}

TEST(ConvertNdfCli, HalfMaxAndSawickiText) {
  auto r = run_cli("convert-ndf --from beckmann --to ggx 0.2 --method half-max");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Half-max: the result's beta_half is the source's (the line states both).
  EXPECT_EQ(test::lines_of(r.out).at(0).rfind("beckmann m_B = 0.2  ->  ggx C_TR = ", 0), 0u) << r.out;
  const auto half = test::line_led_by(r.out, "beta_half:");
  ASSERT_TRUE(half) << r.out;
  const auto ht = test::tokens_of(*half);
  ASSERT_EQ(ht.size(), 7u) << *half;
  EXPECT_EQ(ht[1], ht[4]) << *half;
  r = run_cli("convert-ndf --from beckmann --to ggx 0.2 --method sawicki");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Seed 001 Table 4: C_TR = 1.2 m_B − 0.56 m_B³ = 0.23552 at m_B = 0.2.
  EXPECT_EQ(test::lines_of(r.out).at(0), "beckmann m_B = 0.2  ->  ggx C_TR = 0.23552") << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST(ConvertNdfCli, SawickiOutsideRangeWarnsAndFallsBack) {
  const auto r = run_cli("convert-ndf --from beckmann --to blinn-phong 0.6 --method sawicki --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "brdfkit: warning: m_B = 0.6 is outside the range m_B in [0.0044, 0.4473] seed 001's formulas "
                   "were fitted on; using rmse\n");
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["method"]["requested"], "sawicki");
  EXPECT_EQ(j["method"]["used"], "rmse");
  EXPECT_EQ(j["warnings"].size(), 1u);
}

TEST(ConvertNdfCli, BadInputExitsTwoWithMessage) {
  auto r = run_cli("convert-ndf --from beckmann --to phong 0.2");
  EXPECT_EQ(r.exit_code, 2);
  const std::string known = "beckmann, blinn-phong, gaussian, ggx, exponential, schlick-rational, sawicki-rational";
  EXPECT_EQ(r.err, "brdfkit: --to: unknown distribution 'phong'; known distributions: " + known + "\n");
  r = run_cli("convert-ndf --from nope --to ggx 0.2");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "brdfkit: --from: unknown distribution 'nope'; known distributions: " + known + "\n");
  r = run_cli("convert-ndf --from beckmann --to ggx 0.9");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("brdfkit: VALUE: beckmann m_B = 0.9 is outside"), std::string::npos) << r.err;
  r = run_cli("convert-ndf --from beckmann --to ggx nan");
  EXPECT_EQ(r.exit_code, 2);
  r = run_cli("convert-ndf --from beckmann --to ggx 0.2 --method fancy");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("brdfkit: --method: unknown method 'fancy'"), std::string::npos) << r.err;
  r = run_cli("convert-ndf --from beckmann --to ggx");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "brdfkit: VALUE: missing: give the source distribution's parameter value\n");
  r = run_cli("convert-ndf --to ggx 0.2");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "brdfkit: --from: missing: name the source distribution (or use --table)\n");
  r = run_cli("convert-ndf --from ggx --to beckmann 0.9 --method half-max");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("never falls to half its peak"), std::string::npos) << r.err;
  r = run_cli("convert-ndf --table 0.2 --from beckmann");
  EXPECT_EQ(r.exit_code, 2);
  r = run_cli("convert-ndf --table 3");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.err, "brdfkit: --table: beckmann m_B = 3 is outside [1e-06, 0.707107], where D/D(0) is a single "
                   "decreasing lobe\n");
}

TEST(ConvertNdfCli, TableJsonAndText) {
  auto r = run_cli("convert-ndf --table 0.2 0.01 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["rows"].size(), 2u);
  EXPECT_NEAR(j["rows"][0]["N"]["value"].get<double>(), 47.33, 0.005);
  EXPECT_NEAR(j["rows"][0]["C_TR"]["value"].get<double>(), 0.2357, 0.00005);
  EXPECT_NEAR(j["rows"][1]["N"]["value"].get<double>(), 19997, 0.5);
  r = run_cli("convert-ndf --table");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The header row, then one row per m_B of the paper, led by its value; the 0.2 row holds the
  // JSON's numbers (N 47.33, C_TR 0.2357).
  const auto header = test::line_led_by(r.out, "m_B");
  ASSERT_TRUE(header) << r.out;
  EXPECT_EQ(test::tokens_of(*header), (std::vector<std::string>{"m_B", "N", "by", "Eq.", "11", "(RMSE)", "N", "(RMSE)", "m_G",
                                                                  "(RMSE)", "N_DS", "(RMSE)", "C_TR", "(RMSE)"}));
  for (const char* m : {"0.4473", "0.004473"}) EXPECT_TRUE(test::line_led_by(r.out, m)) << m;
  const auto row = test::line_led_by(r.out, "0.2");
  ASSERT_TRUE(row) << r.out;
  const auto t = test::tokens_of(*row);
  ASSERT_EQ(t.size(), 11u) << *row;
  EXPECT_EQ(t[3], "47.33") << *row;
  EXPECT_EQ(t[9], "0.2357") << *row;
}

TEST(ConvertNdfCli, HelpStatesTheDomain) {
  const auto r = run_cli("convert-ndf --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("min(4 m_B, pi/2)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2001 samples"), std::string::npos) << r.out;
  const auto sawicki = test::line_led_by(r.out, "sawicki-rational");
  ASSERT_TRUE(sawicki) << r.out;
  EXPECT_EQ(test::tokens_of(*sawicki).at(1), "N_DS") << *sawicki;
}

}  // namespace
}  // namespace brdfkit::test
