// Seed 001 Table 2 reproduced by least-RMSE matching of peak-normalized shapes (DESIGN.md §11).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "brdfkit/analysis/ndf_conversion.h"

namespace brdfkit::analysis {
namespace {

struct Printed {
  double value, rmse;
};
struct PrintedRow {
  double m_B;
  Printed ward, N, m_G, N_DS, C_TR;
};

// Seed 001 Table 2, typed from the paper (Sawicki 2021, p. 213) with two corrections, each
// checked in PaperMisprints below: m_B = 0.1415's m_G RMSE is printed 0.01910 (0.001910 fits the
// ratio m_G RMSE / N RMSE = 1.33 of every other row), m_B = 0.005164's Eq. 11 RMSE is printed
// 8.546e-6 (6.546e-6 fits the ratio 3.62 to the N RMSE of every other small-m_B row).
const std::vector<PrintedRow> kTable2 = {
    {0.4473, {10, 0.05929}, {7.654, 0.02463}, {0.4970, 0.03396}, {9.218, 0.04690}, {0.4865, 0.08765}},
    {0.3163, {20, 0.02722}, {17.45, 0.009425}, {0.3344, 0.01228}, {20.80, 0.02967}, {0.3624, 0.05726}},
    {0.2, {50, 0.009946}, {47.33, 0.003024}, {0.2046, 0.003992}, {55.92, 0.02094}, {0.2357, 0.04146}},
    {0.1634, {75, 0.006638}, {72.29, 0.00195}, {0.1658, 0.002583}, {85.24, 0.01967}, {0.1937, 0.03912}},
    {0.1415, {100, 0.004963}, {97.29, 0.00144}, {0.1431, 0.001910}, {114.6, 0.01908}, {0.1682, 0.03805}},
    {0.1, {200, 0.00246}, {197.3, 0.0006967}, {0.1006, 0.0009266}, {232.0, 0.01806}, {0.1194, 0.03617}},
    {0.06325, {500, 0.0009687}, {497.3, 0.0002703}, {0.06339, 0.0003601}, {584.2, 0.01728}, {0.07573, 0.03472}},
    {0.05164, {750, 0.0006542}, {747.2, 0.0001764}, {0.05172, 0.0002350}, {877.7, 0.01686}, {0.06186, 0.03392}},
    {0.04473, {1000, 0.0005033}, {997.3, 0.0001398}, {0.04477, 0.0001863}, {1171, 0.01778}, {0.05360, 0.03572}},
    {0.03163, {2000, 0.0002518}, {1997, 6.975e-5}, {0.03164, 9.298e-5}, {2345, 0.01771}, {0.03791, 0.03558}},
    {0.02, {5000, 9.515e-5}, {4997, 2.632e-5}, {0.02, 3.509e-5}, {5868, 0.01669}, {0.02398, 0.03361}},
    {0.01634, {7500, 6.826e-5}, {7497, 1.747e-5}, {0.01633, 2.329e-5}, {8804, 0.01661}, {0.01958, 0.03345}},
    {0.01415, {10000, 4.761e-5}, {9997, 1.321e-5}, {0.01414, 1.755e-5}, {11749, 0.01669}, {0.01696, 0.03360}},
    {0.01, {20000, 2.452e-5}, {19997, 6.778e-6}, {0.01, 9.035e-6}, {23480, 0.01718}, {0.01199, 0.03456}},
    {0.006325, {50000, 9.493e-6}, {49997, 2.623e-6}, {0.006325, 3.498e-6}, {58710, 0.01662}, {0.007584, 0.03348}},
    {0.005164, {75000, 6.546e-6}, {74996, 1.793e-6}, {0.005164, 2.389e-6}, {88060, 0.01703}, {0.006193, 0.03427}},
    {0.004473, {100000, 5.03e-6}, {99997, 1.390e-6}, {0.004472, 1.853e-6}, {117400, 0.01761}, {0.005364, 0.03540}},
};

class Table2 : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    rows_ = new std::vector<Table2Row>;
    for (const auto& p : kTable2) rows_->push_back(table2_row(p.m_B));
  }
  static void TearDownTestSuite() { delete rows_; }
  static std::vector<Table2Row>* rows_;
};
std::vector<Table2Row>* Table2::rows_ = nullptr;

TEST(Table2Inputs, DefaultMBAreThePrintedOnes) {
  ASSERT_EQ(table2_m_B().size(), kTable2.size());
  for (size_t i = 0; i < kTable2.size(); ++i) EXPECT_EQ(table2_m_B()[i], kTable2[i].m_B);
}

// Every converted parameter within 1 % of the printed value, all 17 rows.
TEST_F(Table2, ParametersWithinOnePercent) {
  double worst = 0;
  for (size_t i = 0; i < kTable2.size(); ++i) {
    const auto& p = kTable2[i];
    const auto& r = (*rows_)[i];
    SCOPED_TRACE(::testing::Message() << "m_B = " << p.m_B);
    for (auto [mine, printed] : {std::pair{r.N_ward, p.ward.value}, {r.N, p.N.value}, {r.m_G, p.m_G.value},
                                 {r.N_DS, p.N_DS.value}, {r.C_TR, p.C_TR.value}}) {
      EXPECT_NEAR(mine / printed, 1.0, 0.01) << mine << " vs printed " << printed;
      worst = std::max(worst, std::abs(mine / printed - 1));
    }
  }
  std::cout << "worst parameter deviation from Table 2: " << worst * 100 << " %\n";
}

// RMSE within 10 % of the printed value (15 % for the first row, m_B = 0.4473).
TEST_F(Table2, RmseWithinTenPercent) {
  double worst = 0, worst_first = 0;
  for (size_t i = 0; i < kTable2.size(); ++i) {
    const auto& p = kTable2[i];
    const auto& r = (*rows_)[i];
    SCOPED_TRACE(::testing::Message() << "m_B = " << p.m_B);
    const double tol = i == 0 ? 0.15 : 0.10;
    for (auto [mine, printed] : {std::pair{r.rmse_ward, p.ward.rmse}, {r.rmse_N, p.N.rmse}, {r.rmse_G, p.m_G.rmse},
                                 {r.rmse_DS, p.N_DS.rmse}, {r.rmse_TR, p.C_TR.rmse}}) {
      EXPECT_NEAR(mine / printed, 1.0, tol) << mine << " vs printed " << printed;
      (i == 0 ? worst_first : worst) = std::max(i == 0 ? worst_first : worst, std::abs(mine / printed - 1));
    }
  }
  std::cout << "worst RMSE deviation from Table 2: first row " << worst_first * 100 << " %, other rows "
            << worst * 100 << " %\n";
}

// The table's own claims: Blinn-Phong always beats Gauss, least-RMSE beats Ward's Eq. 11, and
// Trowbridge-Reitz and Sawicki stay far worse than both (seed 001 §3, §4.1).
TEST_F(Table2, OrderingOfTheFits) {
  for (const auto& r : *rows_) {
    SCOPED_TRACE(::testing::Message() << "m_B = " << r.m_B);
    EXPECT_LT(r.rmse_N, r.rmse_G);
    EXPECT_LT(r.rmse_N, r.rmse_ward);
    EXPECT_LT(r.rmse_G, r.rmse_DS);
    EXPECT_LT(r.rmse_DS, r.rmse_TR);
  }
}

// The two printed values corrected above: what the paper prints is 10× (resp. 1.31×) what the
// computation gives, while the corrected value agrees to 1 %.
TEST(Table2Misprints, PaperMisprints) {
  const auto r1 = table2_row(0.1415);
  EXPECT_NEAR(r1.rmse_G / 0.01910, 0.1, 0.002);
  EXPECT_NEAR(r1.rmse_G / 0.001910, 1.0, 0.01);
  const auto r2 = table2_row(0.005164);
  EXPECT_LT(r2.rmse_ward / 8.546e-6, 0.8);
  EXPECT_NEAR(r2.rmse_ward / 6.546e-6, 1.0, 0.01);
}

}  // namespace
}  // namespace brdfkit::analysis
