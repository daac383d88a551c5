// `brdfkit convert-ndf`: exit codes, messages, JSON and the Table 2 layout.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

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
  EXPECT_NE(r.out.find("ggx C_TR ="), std::string::npos) << r.out;
  r = run_cli("convert-ndf --from beckmann --to ggx 0.2 --method sawicki");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("0.23552"), std::string::npos) << r.out;
  EXPECT_TRUE(r.err.empty()) << r.err;
}

TEST(ConvertNdfCli, SawickiOutsideRangeWarnsAndFallsBack) {
  const auto r = run_cli("convert-ndf --from beckmann --to blinn-phong 0.6 --method sawicki --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("brdfkit: warning:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("0.0044"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["method"]["requested"], "sawicki");
  EXPECT_EQ(j["method"]["used"], "rmse");
  EXPECT_EQ(j["warnings"].size(), 1u);
}

TEST(ConvertNdfCli, BadInputExitsTwoWithMessage) {
  auto r = run_cli("convert-ndf --from beckmann --to phong 0.2");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("brdfkit: --to: unknown distribution 'phong'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("blinn-phong"), std::string::npos) << r.err;  // lists the known names
  r = run_cli("convert-ndf --from nope --to ggx 0.2");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("brdfkit: --from: unknown distribution 'nope'"), std::string::npos) << r.err;
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
  EXPECT_NE(r.err.find("VALUE"), std::string::npos) << r.err;
  r = run_cli("convert-ndf --to ggx 0.2");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--from"), std::string::npos) << r.err;
  r = run_cli("convert-ndf --from ggx --to beckmann 0.9 --method half-max");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("never falls to half its peak"), std::string::npos) << r.err;
  r = run_cli("convert-ndf --table 0.2 --from beckmann");
  EXPECT_EQ(r.exit_code, 2);
  r = run_cli("convert-ndf --table 3");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--table"), std::string::npos) << r.err;
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
  for (const char* s : {"m_B", "N (RMSE)", "m_G (RMSE)", "N_DS (RMSE)", "C_TR (RMSE)", "0.4473", "0.004473"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s;
}

TEST(ConvertNdfCli, HelpStatesTheDomain) {
  const auto r = run_cli("convert-ndf --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("min(4 m_B, pi/2)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2001 samples"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sawicki-rational"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace brdfkit::test
