#include "roadscale/pipeline/sequential_pipeline.h"

#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

TEST(SequentialPipeline, FrameRecordCsvHasOneFieldPerHeaderColumn) {
  FrameRecord record;
  record.scale_status = "oracle";
  const auto count = [](const std::string& text) {
    return std::count(text.begin(), text.end(), ',');
  };
  EXPECT_EQ(count(FrameRecordCsvHeader()), count(FormatFrameRecordCsv(record)));
}

TEST(SequentialPipeline, RejectsAnOutputFolderThatCannotBeCreated) {
  testing::TempDir dir;
  const std::string blocker = testing::WriteTextFile(dir.File("file"), "x");
  CameraSetup camera;
  camera.camera = KittiOdometryCamera();
  struct NoScale : ScaleSource {
    std::string Name() const override { return "none"; }
    ScaleResult StepLength(const ScaleQuery&) override { return {}; }
  } scale;
  EXPECT_THROW([&] { SequentialPipeline pipeline(camera, scale, {}, blocker + "/out"); }(), Error);
}

}  // namespace
}  // namespace roadscale
