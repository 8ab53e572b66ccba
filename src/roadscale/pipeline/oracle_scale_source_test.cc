#include "roadscale/pipeline/oracle_scale_source.h"

#include <gtest/gtest.h>

#include "roadscale/util/error.h"

namespace roadscale {
namespace {

TEST(OracleScaleSource, GivesTheGroundTruthStepLength) {
  Trajectory gt;
  gt.world_from_cam.push_back(Rigid3d::Identity());
  gt.world_from_cam.push_back(MakeRigid3d(Eigen::Matrix3d::Identity(), {0.0, 0.0, 0.8}));
  gt.world_from_cam.push_back(MakeRigid3d(Eigen::Matrix3d::Identity(), {0.3, 0.0, 1.2}));
  OracleScaleSource oracle(gt);
  EXPECT_EQ(oracle.Name(), "oracle");
  ScaleQuery query;
  query.position = 1;
  ScaleResult result = oracle.StepLength(query);
  EXPECT_TRUE(result.valid);
  EXPECT_DOUBLE_EQ(result.step_length_m, 0.8);
  query.position = 2;
  EXPECT_DOUBLE_EQ(oracle.StepLength(query).step_length_m, 0.5);
  query.position = 3;
  EXPECT_THROW(oracle.StepLength(query), Error);
  query.position = 0;
  EXPECT_THROW(oracle.StepLength(query), Error);
}

}  // namespace
}  // namespace roadscale
