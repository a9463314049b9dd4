// dream::barriers against the official Robotarium V2 barrier certificates:
// tests/data/robotarium_v2_barriers.json holds rps's outputs on random states
// (tests/robotarium_reference/generate_barrier_reference.py); the
// barriers_reference_live test points DREAM_BARRIER_REFERENCE at a fresh one.
#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <fstream>
#include <iostream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "dream/barriers/interior_point_qp.h"
#include "dream/barriers/single_integrator_barrier.h"
#include "dream/barriers/unicycle_barrier.h"
#include "../support/source_tree.h"

namespace dream::barriers {
namespace {

/// The bar: the same commands as rps's within 1e-5. The same
/// iteration gives ~1e-10; a different one (an exact QP) misses by 1e-2.
constexpr double kTolerance = 1e-5;

std::string FixturePath() {
  const char* live = std::getenv("DREAM_BARRIER_REFERENCE");
  if (live != nullptr && *live != '\0') return live;
  return dream::testing::SourceDir() + "/tests/data/robotarium_v2_barriers.json";
}

nlohmann::json LoadFixture() {
  std::ifstream in(FixturePath());
  if (!in) throw std::runtime_error(FixturePath() + ": cannot open");
  return nlohmann::json::parse(in);
}

template <int Rows>
Eigen::Matrix<double, Rows, Eigen::Dynamic> Matrix(const nlohmann::json& rows) {
  const int cols = rows.empty() ? 0 : static_cast<int>(rows[0].size());
  Eigen::Matrix<double, Rows, Eigen::Dynamic> m(Rows, cols);
  for (int r = 0; r < Rows; ++r) {
    for (int c = 0; c < cols; ++c) m(r, c) = rows[r][c].get<double>();
  }
  return m;
}

std::optional<BoundaryBox> Boundary(const nlohmann::json& params, BoundaryBox fallback) {
  if (!params.contains("boundary_points")) return fallback;
  const auto& b = params["boundary_points"];
  return BoundaryBox{b[0].get<double>(), b[1].get<double>(), b[2].get<double>(), b[3].get<double>()};
}

double Param(const nlohmann::json& params, const char* name, double fallback) {
  return params.contains(name) ? params[name].get<double>() : fallback;
}

BarrierResult RunCase(const nlohmann::json& c) {
  const std::string function = c["function"];
  const nlohmann::json& p = c["params"];
  if (function.rfind("create_si_", 0) == 0) {
    SingleIntegratorBarrierParams params = function == "create_si_barrier_certificate_with_boundary"
                                               ? SingleIntegratorBarrierParams::RpsWithBoundary()
                                               : SingleIntegratorBarrierParams::Rps();
    params.safety_radius_m = Param(p, "safety_radius", params.safety_radius_m);
    params.barrier_gain = Param(p, "barrier_gain", params.barrier_gain);
    params.magnitude_limit_mps = Param(p, "magnitude_limit", params.magnitude_limit_mps);
    if (params.boundary) params.boundary = Boundary(p, *params.boundary);
    SingleIntegratorBarrier barrier(params);
    return barrier.Apply(Matrix<2>(c["dx"]), Matrix<2>(c["x"]));
  }
  UnicycleBarrierParams params = function == "create_uni_barrier_certificate_with_boundary"
                                     ? UnicycleBarrierParams::RpsWithBoundary()
                                     : UnicycleBarrierParams::Rps();
  params.safety_radius_m = Param(p, "safety_radius", params.safety_radius_m);
  params.barrier_gain = Param(p, "barrier_gain", params.barrier_gain);
  params.projection_distance_m = Param(p, "projection_distance", params.projection_distance_m);
  params.magnitude_limit_mps = Param(p, "velocity_magnitude_limit", params.magnitude_limit_mps);
  if (params.boundary) params.boundary = Boundary(p, *params.boundary);
  UnicycleBarrier barrier(params);
  const Eigen::Matrix2Xd obstacles = c.contains("obstacles") ? Matrix<2>(c["obstacles"]) : Eigen::Matrix2Xd();
  return barrier.Apply(Matrix<2>(c["dx"]), Matrix<3>(c["x"]), obstacles);
}

TEST(BarriersReferenceTest, SameCommandsAsRpsOnRandomStates) {
  const nlohmann::json fixture = LoadFixture();
  const auto& cases = fixture["cases"];
  ASSERT_GE(cases.size(), 20u) << FixturePath();
  int changed = 0;
  int failed = 0;
  double worst = 0.0;
  for (size_t i = 0; i < cases.size(); ++i) {
    const nlohmann::json& c = cases[i];
    SCOPED_TRACE("case " + std::to_string(i) + " (" + c["function"].get<std::string>() + ", " +
                 std::to_string(c["x"][0].size()) + " robots)");
    const BarrierResult result = RunCase(c);
    const Eigen::Matrix2Xd expected = Matrix<2>(c["expected"]);
    ASSERT_EQ(result.commands.cols(), expected.cols());
    EXPECT_EQ(result.qp_failed, c["qp_failed"].get<bool>());
    EXPECT_LE((result.commands - expected).cwiseAbs().maxCoeff(), kTolerance) << "ours\n"
                                                                              << result.commands << "\nrps\n"
                                                                              << expected;
    worst = std::max(worst, (result.commands - expected).cwiseAbs().maxCoeff());
    failed += result.qp_failed;
    changed += (Matrix<2>(c["dx"]) - expected).cwiseAbs().maxCoeff() > 1e-3;
  }
  std::cout << cases.size() << " cases from " << FixturePath() << ", largest difference from rps " << worst << "\n";
  // The fixture must exercise the barrier: commands it bent and QPs that failed.
  EXPECT_GE(changed, 10);
  EXPECT_GE(failed, 1);
}

TEST(BarriersTest, FewerThanTwoRobotsPassUnchanged) {
  UnicycleBarrier barrier(UnicycleBarrierParams::RpsWithBoundary());
  Eigen::Matrix2Xd command(2, 1);
  command << 5.0, 9.0;  // far over any limit: rps returns it as given
  Eigen::Matrix3Xd pose(3, 1);
  pose << 1.59, 0.0, 0.0;
  const BarrierResult result = barrier.Apply(command, pose);
  EXPECT_FALSE(result.qp_failed);
  EXPECT_EQ(result.commands, command);
}

TEST(BarriersTest, TwoRobotsHeadOnAreSlowed) {
  UnicycleBarrier barrier(UnicycleBarrierParams::RpsWithBoundary());
  Eigen::Matrix3Xd poses(3, 2);
  poses << -0.12, 0.12, 0.0, 0.0, 0.0, M_PI;
  Eigen::Matrix2Xd commands(2, 2);
  commands << 0.2, 0.2, 0.0, 0.0;
  const BarrierResult result = barrier.Apply(commands, poses);
  ASSERT_FALSE(result.qp_failed);
  EXPECT_LT(result.commands(0, 0), 0.05);
  EXPECT_LT(result.commands(0, 1), 0.05);
}

TEST(BarriersTest, BadParametersAndSizesAreRefusedByName) {
  UnicycleBarrierParams params = UnicycleBarrierParams::RpsWithBoundary();
  params.projection_distance_m = 0.0;
  try {
    UnicycleBarrier barrier(params);
    FAIL() << "a zero projection distance was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("projection_distance_m = 0"), std::string::npos) << e.what();
  }
  SingleIntegratorBarrierParams si = SingleIntegratorBarrierParams::RpsWithBoundary();
  si.boundary->x_min_m = 2.0;
  EXPECT_THROW(SingleIntegratorBarrier{si}, std::invalid_argument);
  SingleIntegratorBarrier barrier(SingleIntegratorBarrierParams::Rps());
  EXPECT_THROW(barrier.Apply(Eigen::Matrix2Xd::Zero(2, 3), Eigen::Matrix2Xd::Zero(2, 2)), std::invalid_argument);
  const int too_many = SingleIntegratorBarrier::kMaxPoints + 1;
  EXPECT_THROW(barrier.Apply(Eigen::Matrix2Xd::Zero(2, too_many), Eigen::Matrix2Xd::Zero(2, too_many)),
               std::invalid_argument);
}

TEST(BarriersTest, NotFiniteStatesMakeTheQpFailAndTheRobotsStop) {
  UnicycleBarrier barrier(UnicycleBarrierParams::RpsWithBoundary());
  Eigen::Matrix3Xd poses(3, 2);
  poses << 0.0, NAN, 0.0, 0.0, 0.0, 0.0;
  const BarrierResult result = barrier.Apply(Eigen::Matrix2Xd::Constant(2, 2, 0.1), poses);
  EXPECT_TRUE(result.qp_failed);
  EXPECT_TRUE(result.commands.isZero());
}

TEST(InteriorPointQpTest, ExactSettingsReachTheKnownOptimum) {
  // min (x-1)^2 + (y-2)^2  s.t. x + y <= 1: optimum (0, 1).
  QpSettings settings;
  settings.feasibility_tolerance = 1e-10;
  settings.relative_gap_tolerance = 1e-10;
  settings.absolute_gap_tolerance = 1e-12;
  InteriorPointQp qp(settings);
  LinearInequalities g(1);
  g.AddRow(0, 1.0, 1.0, 1.0);
  const QpSolution solution = qp.Solve(Eigen::Vector2d(2, 2), Eigen::Vector2d(-2, -4), g);
  ASSERT_EQ(solution.status, QpStatus::kOptimal);
  EXPECT_NEAR(solution.x[0], 0.0, 1e-7);
  EXPECT_NEAR(solution.x[1], 1.0, 1e-7);
}

}  // namespace
}  // namespace dream::barriers
