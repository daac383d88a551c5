#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "support/test_util.h"

using brdfkit::test::run_cli;

TEST(CmdCheck, JsonHasEveryCheck) {
  const auto r = run_cli("check cook-torrance-ggx --json --samples 20000 --param alpha=0.3 --param kd=0.1,0.2,0.3 "
                         "--param F0[g]=0.5");
  ASSERT_EQ(r.exit_code, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"model", "params", "normalization", "reciprocity", "albedo", "chi2", "passed"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["model"], "cook-torrance-ggx");
  EXPECT_NEAR(j["normalization"].get<double>(), 1.0, 1e-6);
  EXPECT_EQ(j["params"]["alpha"][2], 0.3);
  EXPECT_EQ(j["params"]["kd"][1], 0.2);
  EXPECT_EQ(j["params"]["F0"][1], 0.5);
  EXPECT_EQ(j["params"]["F0"][0], 0.04);
  EXPECT_LT(j["reciprocity"]["max_relative_error"].get<double>(), 1e-10);
  ASSERT_EQ(j["albedo"].size(), 9u);
  EXPECT_EQ(j["albedo"][0]["rgb"].size(), 3u);
  ASSERT_EQ(j["chi2"].size(), 3u);  // θo = 0, 45, 85 by default
  for (const auto& c : j["chi2"])
    for (const char* key : {"theta_o_deg", "statistic", "dof", "p_value", "pdf_integral", "rejected_fraction", "passed"})
      EXPECT_TRUE(c.contains(key)) << key;
  EXPECT_TRUE(j["passed"].get<bool>());
}

TEST(CmdCheck, HumanOutput) {
  const auto r = run_cli("check lambert --samples 5000 --theta-o 30");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("albedo"), std::string::npos);
  EXPECT_NE(r.out.find("all checks passed"), std::string::npos);
}

TEST(CmdCheck, BadInputExitsTwoWithAMessage) {
  struct Case {
    const char* args;
    const char* says;
  };
  for (const Case& c : {Case{"check no-such-model", "unknown"},
                        Case{"check cook-torrance --param bogus=1", "bogus"},
                        Case{"check cook-torrance --param alpha=abc", "not a finite number"},
                        Case{"check cook-torrance --param alpha=nan", "not a finite number"},
                        Case{"check cook-torrance --param alpha", "expected name=value"},
                        Case{"check cook-torrance --param kd[x]=0.1", "channel"},
                        Case{"check cook-torrance --param kd=0.1,0.2", "three"},
                        Case{"check cook-torrance --param alpha[r]=0.1", "shared"},
                        Case{"check cook-torrance --param alpha=0.1,0.1,0.1", "shared"},
                        Case{"check cook-torrance --param kd=-1", "outside the formula's domain"},
                        Case{"check cook-torrance --theta-o 95", "theta-o"}}) {
    const auto r = run_cli(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.says), std::string::npos) << c.args << "\n" << r.err;
    EXPECT_EQ(r.err.find("internal error"), std::string::npos) << c.args;
  }
}

// --samples is bounded on both sides: the upper bound keeps a check within minutes (cmd_check.cpp
// says why 10^8); one line names the option and its range, before any check runs.
TEST(CmdCheck, SamplesOutsideTheirRangeAreRefusedInOneLine) {
  for (const char* n : {"999", "100000001", "10000000000000"}) {
    const auto r = run_cli(std::string("check lambert --samples ") + n);
    EXPECT_EQ(r.exit_code, 2) << n << "\n" << r.err;
    EXPECT_EQ(r.err, "brdfkit: --samples: must be in [1000, 100000000] (got " + std::string(n) + ")\n") << n;
    EXPECT_TRUE(r.out.empty()) << n;
  }
  EXPECT_EQ(run_cli("check lambert --samples 1000 --theta-o 30").exit_code, 0);
}
