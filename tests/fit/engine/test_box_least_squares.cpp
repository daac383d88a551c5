// The colour sub-problem solver: exact NNLS / box-constrained least squares on normal equations.
#include <gtest/gtest.h>

#include <random>

#include "brdfkit/fit/engine/box_least_squares.h"

namespace brdfkit::fit {
namespace {

// Brute force over a fine grid of the feasible box as an independent reference.
TEST(BoxLeastSquares, MatchesUnconstrainedSolutionInsideTheBox) {
  Eigen::MatrixXd B(5, 2);
  B << 1, 0.5, 0.2, 1, 0.3, 0.3, 0.9, 0.1, 0.4, 0.8;
  const Eigen::Vector2d x_true(0.3, 0.7);
  const Eigen::VectorXd m = B * x_true;
  const Eigen::VectorXd x = box_least_squares(B.transpose() * B, B.transpose() * m, Eigen::Vector2d::Zero(),
                                              Eigen::Vector2d::Constant(1.0));
  EXPECT_NEAR(x[0], 0.3, 1e-12);
  EXPECT_NEAR(x[1], 0.7, 1e-12);
}

TEST(BoxLeastSquares, SatisfiesKktConditionsOnRandomProblems) {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial % 4;
    Eigen::MatrixXd B(12, n);
    for (int i = 0; i < B.size(); ++i) B.data()[i] = g(rng);
    Eigen::VectorXd m(12);
    for (int i = 0; i < 12; ++i) m[i] = g(rng);
    const Eigen::MatrixXd A = B.transpose() * B;
    const Eigen::VectorXd y = B.transpose() * m;
    Eigen::VectorXd lo = Eigen::VectorXd::Zero(n), hi = Eigen::VectorXd::Constant(n, trial % 2 ? 0.5 : INFINITY);
    const Eigen::VectorXd x = box_least_squares(A, y, lo, hi);
    const Eigen::VectorXd grad = A * x - y;  // of ½xᵀAx − yᵀx
    for (int i = 0; i < n; ++i) {
      ASSERT_GE(x[i], lo[i]);
      ASSERT_LE(x[i], hi[i]);
      if (x[i] > lo[i] + 1e-12 && x[i] < hi[i] - 1e-12) EXPECT_NEAR(grad[i], 0.0, 1e-9) << trial;
      else if (x[i] <= lo[i] + 1e-12) EXPECT_GE(grad[i], -1e-9) << trial;
      else EXPECT_LE(grad[i], 1e-9) << trial;
    }
  }
}

TEST(BoxLeastSquares, SingularSystemGivesAFiniteFeasibleAnswer) {
  Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
  A(0, 0) = 1;  // second basis identically zero
  const Eigen::VectorXd x =
      box_least_squares(A, Eigen::Vector2d(0.4, 0.0), Eigen::Vector2d::Zero(), Eigen::Vector2d::Constant(1.0));
  EXPECT_NEAR(x[0], 0.4, 1e-12);
  EXPECT_TRUE(x.allFinite());
  EXPECT_GE(x[1], 0.0);
}

}  // namespace
}  // namespace brdfkit::fit
