#include "roadscale/synth/road_plane_file.h"

#include <string>

#include <gtest/gtest.h>

#include "roadscale/testing/temp_dir.h"
#include "roadscale/util/error.h"

namespace roadscale::synth {
namespace {

TEST(RoadPlaneFile, RowsReadBackAsWritten) {
  testing::TempDir dir;
  const RoadPlaneRow a{0, Eigen::Vector3d(0.01, 0.9999, -0.0099).normalized(), 1.65};
  const RoadPlaneRow b{1, Eigen::Vector3d(0.0, 1.0, 0.0), 1.65};
  const std::string path =
      testing::WriteTextFile(dir.File("road_planes.txt"),
                             std::string(RoadPlaneFileHeader()) + "\n" + FormatRoadPlaneRow(a) +
                                 "\n\n" + FormatRoadPlaneRow(b) + "\n");
  const std::vector<RoadPlaneRow> rows = ReadRoadPlanes(path);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[1].frame, 1);
  EXPECT_NEAR((rows[0].normal - a.normal).norm(), 0.0, 1e-12);
  EXPECT_NEAR(rows[0].height, 1.65, 1e-12);
}

TEST(RoadPlaneFile, BadRowsNameTheLine) {
  testing::TempDir dir;
  auto error_of = [&](const std::string& text) {
    const std::string path = testing::WriteTextFile(dir.File("p.txt"), text);
    try {
      ReadRoadPlanes(path);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(error_of("0 0 1 0 1.65\n0 0 1 0 1.65\n").find("p.txt:2"), std::string::npos);
  EXPECT_NE(error_of("0 0 1 0\n").find("5 numbers"), std::string::npos);
  EXPECT_NE(error_of("0 0 2 0 1.65\n").find("unit"), std::string::npos);
  EXPECT_NE(error_of("0 0 1 0 -1\n").find("positive"), std::string::npos);
  EXPECT_NE(error_of("0 0 1 zero 1\n").find("p.txt:1"), std::string::npos);
  EXPECT_THROW(ReadRoadPlanes(dir.File("missing.txt")), Error);
}

}  // namespace
}  // namespace roadscale::synth
