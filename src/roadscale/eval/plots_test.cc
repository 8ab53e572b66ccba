#include "roadscale/eval/plots.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>

#include <cairo.h>

#include <gtest/gtest.h>

#include "roadscale/testing/temp_dir.h"
#include "roadscale/testing/test_trajectories.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

TEST(Plots, WritesPngAndSvgOfEachFigure) {
  const std::vector<Rigid3d> gt = testing::CurvyDrive(1200, 1.0);
  const std::vector<Rigid3d> est = testing::PerturbedEstimate(gt, 11, 0.05, 0.02, 2e-4);
  testing::TempDir dir;
  const std::string folder = dir.File("plots/nested");
  const std::vector<std::string> written =
      WriteEvaluationPlots(folder, gt, est, EvaluateKittiOdometry(gt, est));
  ASSERT_EQ(written.size(), 6u);
  for (const std::string name : {"trajectory_top_view", "t_err_vs_length", "r_err_vs_length"}) {
    const std::string png = folder + "/" + name + ".png";
    const std::string svg = folder + "/" + name + ".svg";
    ASSERT_TRUE(std::filesystem::exists(png)) << png;
    ASSERT_TRUE(std::filesystem::exists(svg)) << svg;
    cairo_surface_t* image = cairo_image_surface_create_from_png(png.c_str());
    EXPECT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS) << png;
    EXPECT_EQ(cairo_image_surface_get_width(image), 800) << png;
    cairo_surface_destroy(image);
    const std::string svg_text = testing::ReadFileBytes(svg);
    EXPECT_NE(svg_text.find("<svg"), std::string::npos) << svg;
    EXPECT_NE(svg_text.find("<path"), std::string::npos) << svg;
  }
}

// Bounding box of the pixels of one colour, outside the legend (right of the plot).
struct PixelBox {
  int min_x = 1 << 30, max_x = -1, min_y = 1 << 30, max_y = -1;
  int Width() const { return max_x - min_x + 1; }
  int Height() const { return max_y - min_y + 1; }
};

TEST(Plots, TopViewDrawsXAgainstZWithEqualAxes) {
  // The ground truth (red) runs 99 m along +z, the estimate (blue) 99 m along +x: red must
  // be a vertical line, blue a horizontal one, equally long on the image.
  std::vector<Rigid3d> gt;
  std::vector<Rigid3d> est;
  for (int i = 0; i < 100; ++i) {
    gt.push_back(MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, i)));
    est.push_back(MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(i, 0, 0)));
  }
  testing::TempDir dir;
  WriteEvaluationPlots(dir.path().string(), gt, est, EvaluateKittiOdometry(gt, est));
  cairo_surface_t* image =
      cairo_image_surface_create_from_png(dir.File("trajectory_top_view.png").c_str());
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  const int width = cairo_image_surface_get_width(image);
  const int height = cairo_image_surface_get_height(image);
  const int stride = cairo_image_surface_get_stride(image);
  const unsigned char* data = cairo_image_surface_get_data(image);
  PixelBox red;
  PixelBox blue;
  const auto add = [](PixelBox& box, int x, int y) {
    box.min_x = std::min(box.min_x, x);
    box.max_x = std::max(box.max_x, x);
    box.min_y = std::min(box.min_y, y);
    box.max_y = std::max(box.max_y, y);
  };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (x > width - 220 && y < 140) continue;  // legend
      uint32_t pixel;
      std::memcpy(&pixel, data + y * stride + 4 * x, sizeof(pixel));
      const int r = (pixel >> 16) & 0xff;
      const int g = (pixel >> 8) & 0xff;
      const int b = pixel & 0xff;
      if (r > 180 && g < 80 && b < 80) add(red, x, y);
      if (b > 180 && r < 80 && g < 120) add(blue, x, y);
    }
  }
  cairo_surface_destroy(image);
  ASSERT_GE(red.max_x, 0);
  ASSERT_GE(blue.max_x, 0);
  EXPECT_LT(red.Width(), 6);
  EXPECT_GT(red.Height(), 400);
  EXPECT_LT(blue.Height(), 6);
  EXPECT_GT(blue.Width(), 400);
  EXPECT_NEAR(red.Height(), blue.Width(), 3);
  // z grows upwards, x to the right, both from the shared start (under the 10 px start
  // marker, which hides the first 5 px of each line).
  EXPECT_NEAR(red.max_y, blue.max_y, 8);
  EXPECT_NEAR(red.min_x, blue.min_x, 8);
  EXPECT_LT(red.min_y, blue.min_y - 400);
  EXPECT_GT(blue.max_x, red.max_x + 400);
}

TEST(Plots, TopViewLegendHidesNoData) {
  // The ground truth (red) runs 99 m along +x at the bottom; the estimate (blue) diagonally
  // to (99, 99), into the top right corner of the plot, where a legend inside the plot sat.
  // Both end at x = 99 m: the ends of their lines must be at the same image column.
  std::vector<Rigid3d> gt;
  std::vector<Rigid3d> est;
  for (int i = 0; i < 100; ++i) {
    gt.push_back(MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(i, 0, 0)));
    est.push_back(MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(i, 0, i)));
  }
  testing::TempDir dir;
  WriteEvaluationPlots(dir.path().string(), gt, est, EvaluateKittiOdometry(gt, est));
  cairo_surface_t* image =
      cairo_image_surface_create_from_png(dir.File("trajectory_top_view.png").c_str());
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS);
  const int stride = cairo_image_surface_get_stride(image);
  const unsigned char* data = cairo_image_surface_get_data(image);
  int red_right = -1;
  int blue_right = -1;
  int blue_top = 1 << 30;
  for (int y = 0; y < cairo_image_surface_get_height(image); ++y) {
    for (int x = 0; x < cairo_image_surface_get_width(image); ++x) {
      uint32_t pixel;
      std::memcpy(&pixel, data + y * stride + 4 * x, sizeof(pixel));
      const int r = (pixel >> 16) & 0xff;
      const int g = (pixel >> 8) & 0xff;
      const int b = pixel & 0xff;
      if (r > 180 && g < 80 && b < 80) red_right = std::max(red_right, x);
      if (b > 180 && r < 80 && g < 120) {
        blue_right = std::max(blue_right, x);
        blue_top = std::min(blue_top, y);
      }
    }
  }
  cairo_surface_destroy(image);
  ASSERT_GT(red_right, 400);
  EXPECT_NEAR(blue_right, red_right, 3);
  EXPECT_LT(blue_top, 90);  // the diagonal's end, 5 % of the plot below its top at 40 px
}

TEST(Plots, ErrorPlotsAreWrittenWhenNoLengthFits) {
  std::vector<Rigid3d> gt;
  for (int i = 0; i < 46; ++i) {
    gt.push_back(MakeRigid3d(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0, 0, i)));
  }
  testing::TempDir dir;
  WriteEvaluationPlots(dir.path().string(), gt, gt, EvaluateKittiOdometry(gt, gt));
  EXPECT_GT(std::filesystem::file_size(dir.File("t_err_vs_length.png")), 1000u);
  EXPECT_GT(std::filesystem::file_size(dir.File("r_err_vs_length.svg")), 1000u);
}

TEST(Plots, UnwritableFolderIsAnError) {
  testing::TempDir dir;
  const std::string file = testing::WriteTextFile(dir.File("not_a_folder"), "x");
  std::vector<Rigid3d> gt(3, Rigid3d::Identity());
  try {
    WriteEvaluationPlots(file + "/plots", gt, gt, EvaluateKittiOdometry(gt, gt));
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("not_a_folder"), std::string::npos) << e.what();
  }
}

// Cairo numbers its SVG surfaces by a process-wide counter; the rest of a document depends
// only on the drawing.
std::string WithoutSurfaceNumbers(const std::string& svg) {
  return std::regex_replace(svg, std::regex("surface[0-9]+"), "surface");
}

TEST(Plots, InMemorySvgIsTheWrittenFile) {
  const std::vector<Rigid3d> gt = testing::CurvyDrive(300, 1.0);
  const std::vector<Rigid3d> est = testing::PerturbedEstimate(gt, 3, 0.05, 0.02, 2e-4);
  const KittiOdometryResult kitti = EvaluateKittiOdometry(gt, est);
  testing::TempDir dir;
  WriteEvaluationPlots(dir.path().string(), gt, est, kitti);
  EXPECT_EQ(WithoutSurfaceNumbers(RenderTopViewSvg(gt, est)),
            WithoutSurfaceNumbers(testing::ReadFileBytes(dir.File("trajectory_top_view.svg"))));
  EXPECT_EQ(WithoutSurfaceNumbers(RenderKittiErrorSvg(kitti, KittiErrorKind::kTranslation)),
            WithoutSurfaceNumbers(testing::ReadFileBytes(dir.File("t_err_vs_length.svg"))));
  EXPECT_EQ(WithoutSurfaceNumbers(RenderKittiErrorSvg(kitti, KittiErrorKind::kRotation)),
            WithoutSurfaceNumbers(testing::ReadFileBytes(dir.File("r_err_vs_length.svg"))));
}

TEST(Plots, TopViewWithoutGroundTruthDrawsTheEstimate) {
  const std::vector<Rigid3d> est = testing::CurvyDrive(100, 1.0);
  ASSERT_NE(RenderTopViewSvg(est, est, 400, 400).find("stroke:rgb(85%,10%,10%)"),
            std::string::npos);
  const std::string svg = RenderTopViewSvg({}, est, 400, 400);
  EXPECT_EQ(svg.find("stroke:rgb(85%,10%,10%)"), std::string::npos);  // no ground-truth red
  EXPECT_NE(svg.find("stroke:rgb(10%,25%,85%)"), std::string::npos);  // the estimate's blue
  EXPECT_NE(RenderTopViewSvg({}, {Rigid3d::Identity()}).find("<svg"), std::string::npos);
}

TEST(Plots, TopViewMarksTheKeyframes) {
  const std::vector<Rigid3d> est = testing::CurvyDrive(100, 1.0);
  const std::string plain = RenderTopViewSvg(est, est, 400, 400);
  const std::string marked = RenderTopViewSvg(est, est, 400, 400, {0, 10, 20, 30, 500});
  // Two more blue strokes: the circles (the index beyond the estimate skipped) and their
  // legend entry.
  const auto count = [](const std::string& svg, const std::string& what) {
    size_t n = 0;
    for (size_t at = svg.find(what); at != std::string::npos; at = svg.find(what, at + 1)) ++n;
    return n;
  };
  const std::string blue = "stroke:rgb(10%,25%,85%)";
  EXPECT_EQ(count(marked, blue), count(plain, blue) + 2);
}

// The `d` attribute of the first path whose style contains `style_part`.
std::string PathData(const std::string& svg, const std::string& style_part) {
  const size_t style = svg.find(style_part);
  if (style == std::string::npos) return "";
  const size_t begin = svg.find("d=\"", style) + 3;
  return svg.substr(begin, svg.find('"', begin) - begin);
}

TEST(Plots, FrameLinesBreakAtMissingValuesAndDotLoneValues) {
  const double nan = std::nan("");
  const FrameLinePlot plot{
      "Test", "Value", {{"a", {1, 2, nan, 3, 4}}, {"b", {nan, 5, nan, nan}}}, false};
  const std::string svg = RenderFrameLinesSvg(plot, 400, 200);
  // Line a (first palette colour, 1.5 px): two pieces of one segment each.
  const std::string a = PathData(svg,
                                 "stroke-width:1.5;stroke-linecap:butt;stroke-linejoin:round;"
                                 "stroke:rgb(12%,47%,71%)");
  EXPECT_EQ(std::count(a.begin(), a.end(), 'M'), 2) << a;
  EXPECT_EQ(std::count(a.begin(), a.end(), 'L'), 2) << a;
  // b has one value, at frame 1: a filled dot (curves) in the second colour.
  const std::string b = PathData(svg, "fill:rgb(100%,50%,5%)");
  EXPECT_GT(std::count(b.begin(), b.end(), 'C'), 0) << b;
  // A single frame, and no value at all, still draw.
  EXPECT_NE(RenderFrameLinesSvg({"One", "v", {{"a", {2.0}}}, true}).find("<svg"),
            std::string::npos);
  EXPECT_NE(RenderFrameLinesSvg({"None", "v", {{"a", {nan, nan}}}, false}).find("<svg"),
            std::string::npos);
  EXPECT_NE(RenderFrameLinesSvg({"Empty", "v", {}, false}).find("<svg"), std::string::npos);
}

TEST(Plots, StatusStripHasOneCellPerRunOfEqualStatuses) {
  const std::string svg = RenderFrameStatusSvg({"ok", "ok", "held", "ok", "stationary"});
  // Cells: ok (frames 0-1), held, ok, stationary; plus one legend swatch per status.
  const auto count = [&](const std::string& fill) {
    size_t n = 0;
    for (size_t at = svg.find(fill); at != std::string::npos; at = svg.find(fill, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("fill:rgb(12%,47%,71%)"), 3u);  // ok: 2 cells + swatch
  EXPECT_EQ(count("fill:rgb(100%,50%,5%)"), 2u);  // held
  EXPECT_EQ(count("fill:rgb(17%,63%,17%)"), 2u);  // stationary
  EXPECT_NE(RenderFrameStatusSvg({}).find("<svg"), std::string::npos);
}

TEST(Plots, FigureOfNoSizeIsAnError) { EXPECT_THROW(RenderFrameStatusSvg({"ok"}, 0, 100), Error); }

}  // namespace
}  // namespace roadscale
