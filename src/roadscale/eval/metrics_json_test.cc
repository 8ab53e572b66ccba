#include "roadscale/eval/metrics_json.h"

#include <gtest/gtest.h>

#include "roadscale/testing/test_trajectories.h"

namespace roadscale {
namespace {

TEST(MetricsJson, HasExactlyTheDocumentedShape) {
  const std::vector<Rigid3d> gt = testing::CurvyDrive(400, 1.0);
  const std::vector<Rigid3d> est = testing::PerturbedEstimate(gt, 3, 0.05, 0.02, 1e-4);
  const nlohmann::ordered_json json = MetricsToJson(EvaluateTrajectory(gt, est));

  std::vector<std::string> keys;
  for (const auto& item : json.items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"frames", "kitti", "ate_m", "rpe", "length_ratio",
                                            "final_drift_m", "final_drift_pct"}));
  keys.clear();
  for (const auto& item : json["kitti"].items()) keys.push_back(item.key());
  EXPECT_EQ(keys,
            (std::vector<std::string>{"t_err_pct", "r_err_deg_per_m", "n_segments", "per_length"}));
  keys.clear();
  for (const auto& item : json["kitti"]["per_length"][0].items()) keys.push_back(item.key());
  EXPECT_EQ(keys,
            (std::vector<std::string>{"length_m", "n_segments", "t_err_pct", "r_err_deg_per_m"}));
  keys.clear();
  for (const auto& item : json["ate_m"].items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"none", "se3", "sim3", "sim3_scale"}));
  keys.clear();
  for (const auto& item : json["rpe"].items()) keys.push_back(item.key());
  EXPECT_EQ(keys, (std::vector<std::string>{"trans_rmse_m", "rot_rmse_deg"}));

  EXPECT_EQ(json["frames"], 400);
  // About 430 m of path: 100 to 400 m fit, 500 to 800 m do not.
  ASSERT_EQ(json["kitti"]["per_length"].size(), 8u);
  EXPECT_EQ(json["kitti"]["per_length"][0]["length_m"], 100);
  EXPECT_TRUE(json["kitti"]["per_length"][0]["t_err_pct"].is_number());
  EXPECT_TRUE(json["kitti"]["per_length"][7]["t_err_pct"].is_null());
  EXPECT_EQ(json["kitti"]["per_length"][7]["n_segments"], 0);
  EXPECT_TRUE(json["kitti"]["t_err_pct"].is_number());
  EXPECT_TRUE(json["ate_m"]["sim3_scale"].is_number());
}

TEST(MetricsJson, UnitsAndFloatDigits) {
  TrajectoryEvaluation evaluation;
  evaluation.frames = 3;
  evaluation.kitti.t_err = 0.0123f;
  evaluation.kitti.r_err = 1e-4f;
  evaluation.kitti.segments.resize(2);
  evaluation.errors.sim3_scale = 0.8;
  evaluation.errors.ate_sim3_m = 0.5;
  const nlohmann::ordered_json json = MetricsToJson(evaluation);
  // 100 * 0.0123f is 1.2300000339746475 in double; the float's digits are 1.23.
  EXPECT_EQ(json["kitti"]["t_err_pct"].get<double>(), 1.23);
  EXPECT_EQ(static_cast<float>(json["kitti"]["r_err_deg_per_m"].get<double>()),
            static_cast<float>(1e-4f * 180.0 / M_PI));
  EXPECT_EQ(json["kitti"]["n_segments"], 2);
  EXPECT_EQ(json["ate_m"]["sim3_scale"].get<double>(), 0.8);
  EXPECT_NE(FormatMetricsJson(evaluation).find("\"t_err_pct\": 1.23,"), std::string::npos);
}

TEST(MetricsJson, NullWhenNoLengthFits) {
  std::vector<Rigid3d> gt;
  for (int i = 0; i < 46; ++i) {
    gt.push_back(MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, i)));
  }
  const nlohmann::ordered_json json = MetricsToJson(EvaluateTrajectory(gt, gt));
  EXPECT_TRUE(json["kitti"]["t_err_pct"].is_null());
  EXPECT_TRUE(json["kitti"]["r_err_deg_per_m"].is_null());
  EXPECT_EQ(json["kitti"]["n_segments"], 0);
  for (const auto& length : json["kitti"]["per_length"]) {
    EXPECT_TRUE(length["t_err_pct"].is_null());
    EXPECT_EQ(length["n_segments"], 0);
  }
  EXPECT_EQ(json["ate_m"]["none"], 0.0);
  EXPECT_EQ(json["length_ratio"], 1.0);
}

}  // namespace
}  // namespace roadscale
