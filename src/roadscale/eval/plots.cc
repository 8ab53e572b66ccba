#include "roadscale/eval/plots.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <utility>

#include <cairo-svg.h>
#include <cairo.h>

#include "roadscale/eval/metrics_json.h"
#include "roadscale/util/error.h"

namespace roadscale {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Colour {
  double r, g, b;
};
constexpr Colour kBlack{0.0, 0.0, 0.0};
constexpr Colour kGrey{0.85, 0.85, 0.85};
constexpr Colour kGroundTruth{0.85, 0.1, 0.1};
constexpr Colour kEstimate{0.1, 0.25, 0.85};

// A closed interval of data values.
struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();

  void Add(double value) {
    lo = std::min(lo, value);
    hi = std::max(hi, value);
  }
  double Span() const { return hi - lo; }
  // Widens an empty or zero-width range so that it can be drawn.
  Range Padded(double fraction, double minimum_half_width) const {
    Range padded = *this;
    if (!(lo <= hi)) padded = {0.0, 0.0};
    const double half = std::max(0.5 * padded.Span() * (1.0 + 2.0 * fraction), minimum_half_width);
    const double centre = 0.5 * (padded.lo + padded.hi);
    return {centre - half, centre + half};
  }
};

// A tick step of 1, 2 or 5 times a power of ten giving about `target` ticks over `span`.
double TickStep(double span, int target) {
  const double raw = span / target;
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double normalised = raw / magnitude;
  if (normalised < 1.5) return magnitude;
  if (normalised < 3.0) return 2.0 * magnitude;
  if (normalised < 7.0) return 5.0 * magnitude;
  return 10.0 * magnitude;
}

std::string TickLabel(double value, double step) {
  char buffer[32];
  const int decimals = step >= 1.0 ? 0 : static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  std::snprintf(buffer, sizeof(buffer), "%.*f", decimals,
                std::abs(value) < 1e-12 * step ? 0.0 : value);
  return buffer;
}

// Maps data coordinates to the device rectangle [left, right] x [top, bottom] (y up).
struct Axes {
  double left, top, right, bottom;
  Range x, y;

  double X(double value) const { return left + (value - x.lo) / x.Span() * (right - left); }
  double Y(double value) const { return bottom - (value - y.lo) / y.Span() * (bottom - top); }
};

void SetColour(cairo_t* cr, const Colour& colour) {
  cairo_set_source_rgb(cr, colour.r, colour.g, colour.b);
}

void ShowText(cairo_t* cr, const std::string& text, double x, double y, double align_x,
              double align_y, double angle = 0.0) {
  cairo_text_extents_t extents;
  cairo_text_extents(cr, text.c_str(), &extents);
  cairo_save(cr);
  cairo_translate(cr, x, y);
  cairo_rotate(cr, angle);
  cairo_move_to(cr, -extents.x_bearing - align_x * extents.width,
                -extents.y_bearing - align_y * extents.height);
  cairo_show_text(cr, text.c_str());
  cairo_restore(cr);
}

// How densely DrawAxes places ticks.
struct TickSpacing {
  bool integer_x = false;  // x ticks on whole numbers only (frame indexes)
  double y_px = 90.0;      // about one y tick per this many pixels
};

// Frame, grid, tick labels and axis titles.
void DrawAxes(cairo_t* cr, const Axes& axes, const std::string& x_title, const std::string& y_title,
              const std::string& title, const TickSpacing& spacing = {}) {
  cairo_set_font_size(cr, 13.0);
  cairo_set_line_width(cr, 1.0);
  double widest_y_label = 0.0;
  const auto draw_ticks = [&](const Range& range, double device_span, bool is_x) {
    const double px_per_tick = is_x ? 90.0 : spacing.y_px;
    double step = TickStep(range.Span(), std::max(2, static_cast<int>(device_span / px_per_tick)));
    if (is_x && spacing.integer_x) step = std::max(step, 1.0);
    for (double value = std::ceil(range.lo / step) * step; value <= range.hi + 1e-9 * step;
         value += step) {
      SetColour(cr, kGrey);
      if (is_x) {
        cairo_move_to(cr, axes.X(value), axes.top);
        cairo_line_to(cr, axes.X(value), axes.bottom);
      } else {
        cairo_move_to(cr, axes.left, axes.Y(value));
        cairo_line_to(cr, axes.right, axes.Y(value));
      }
      cairo_stroke(cr);
      SetColour(cr, kBlack);
      if (is_x) {
        ShowText(cr, TickLabel(value, step), axes.X(value), axes.bottom + 6.0, 0.5, 0.0);
      } else {
        const std::string label = TickLabel(value, step);
        cairo_text_extents_t extents;
        cairo_text_extents(cr, label.c_str(), &extents);
        widest_y_label = std::max(widest_y_label, extents.width);
        ShowText(cr, label, axes.left - 6.0, axes.Y(value), 1.0, 0.5);
      }
    }
  };
  draw_ticks(axes.x, axes.right - axes.left, true);
  draw_ticks(axes.y, axes.bottom - axes.top, false);
  SetColour(cr, kBlack);
  cairo_rectangle(cr, axes.left, axes.top, axes.right - axes.left, axes.bottom - axes.top);
  cairo_stroke(cr);
  cairo_set_font_size(cr, 15.0);
  ShowText(cr, x_title, 0.5 * (axes.left + axes.right), axes.bottom + 30.0, 0.5, 0.0);
  // Left of the widest tick label, whatever the numbers' width.
  ShowText(cr, y_title, axes.left - widest_y_label - 32.0, 0.5 * (axes.top + axes.bottom), 0.5, 0.0,
           -0.5 * kPi);
  cairo_set_font_size(cr, 16.0);
  ShowText(cr, title, 0.5 * (axes.left + axes.right), axes.top - 12.0, 0.5, 1.0);
}

struct LegendEntry {
  std::string label;
  Colour colour;
  bool square = false;  // a square marker instead of a line
};

// Wide enough for the longest label, and at least 150 px.
double LegendWidth(cairo_t* cr, const std::vector<LegendEntry>& entries) {
  cairo_set_font_size(cr, 13.0);
  double widest = 0.0;
  for (const LegendEntry& entry : entries) {
    cairo_text_extents_t extents;
    cairo_text_extents(cr, entry.label.c_str(), &extents);
    widest = std::max(widest, extents.x_advance);
  }
  return std::max(150.0, 46.0 + widest + 10.0);
}

// A boxed legend whose top right corner is at (right, top).
void DrawLegend(cairo_t* cr, double right, double top, const std::vector<LegendEntry>& entries) {
  const double width = LegendWidth(cr, entries);
  cairo_set_font_size(cr, 13.0);
  const double row = 20.0;
  const double x = right - width;
  const double y = top;
  cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, 0.85);
  cairo_rectangle(cr, x, y, width, row * static_cast<double>(entries.size()) + 8.0);
  cairo_fill_preserve(cr);
  SetColour(cr, kBlack);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
  for (size_t i = 0; i < entries.size(); ++i) {
    const double centre_y = y + 4.0 + row * (static_cast<double>(i) + 0.5);
    SetColour(cr, entries[i].colour);
    if (entries[i].square) {
      cairo_rectangle(cr, x + 18.0, centre_y - 5.0, 10.0, 10.0);
      cairo_fill(cr);
    } else {
      cairo_set_line_width(cr, 2.5);
      cairo_move_to(cr, x + 8.0, centre_y);
      cairo_line_to(cr, x + 38.0, centre_y);
      cairo_stroke(cr);
    }
    SetColour(cr, kBlack);
    ShowText(cr, entries[i].label, x + 46.0, centre_y, 0.0, 0.5);
  }
}

void DrawPath(cairo_t* cr, const Axes& axes, const std::vector<Rigid3d>& poses,
              const Colour& colour) {
  SetColour(cr, colour);
  cairo_set_line_width(cr, 2.0);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (size_t i = 0; i < poses.size(); ++i) {
    const Eigen::Vector3d& p = poses[i].translation();
    if (i == 0) {
      cairo_move_to(cr, axes.X(p.x()), axes.Y(p.z()));
    } else {
      cairo_line_to(cr, axes.X(p.x()), axes.Y(p.z()));
    }
  }
  cairo_stroke(cr);
}

void DrawTopView(cairo_t* cr, double width, double height, const std::vector<Rigid3d>& gt,
                 const std::vector<Rigid3d>& est, const std::vector<size_t>& keyframes) {
  Range x;
  Range z;
  for (const auto* poses : {&gt, &est}) {
    for (const Rigid3d& pose : *poses) {
      x.Add(pose.translation().x());
      z.Add(pose.translation().z());
    }
  }
  std::vector<LegendEntry> legend;
  if (!gt.empty()) legend.push_back({"Ground truth", kGroundTruth});
  legend.push_back({"Estimate", kEstimate});
  if (!keyframes.empty()) legend.push_back({"Keyframes (circles)", kEstimate});
  legend.push_back({"Start", kBlack, true});
  // The legend sits right of the plot: with equal axes a trajectory reaches into any corner
  // of the plot (KITTI 00 ends in the top right), so a legend inside would hide data.
  const double legend_width = LegendWidth(cr, legend) + 20.0;
  Axes axes{80.0,
            40.0,
            width - 20.0 - legend_width,
            height - 60.0,
            x.Padded(0.05, 1.0),
            z.Padded(0.05, 1.0)};
  // Equal axes: one metre is as long in x as in z; the tighter direction sets the scale and
  // the other range grows around its centre.
  const double metres_per_unit =
      std::max(axes.x.Span() / (axes.right - axes.left), axes.y.Span() / (axes.bottom - axes.top));
  const auto widen = [&](Range& range, double device_span) {
    const double half = 0.5 * device_span * metres_per_unit;
    const double centre = 0.5 * (range.lo + range.hi);
    range = {centre - half, centre + half};
  };
  widen(axes.x, axes.right - axes.left);
  widen(axes.y, axes.bottom - axes.top);

  DrawAxes(cr, axes, "x [m]", "z [m]", "Trajectory (top view)");
  DrawPath(cr, axes, gt, kGroundTruth);
  DrawPath(cr, axes, est, kEstimate);
  SetColour(cr, kEstimate);
  cairo_set_line_width(cr, 1.0);
  for (size_t k : keyframes) {
    if (k >= est.size()) continue;
    const Eigen::Vector3d& centre = est[k].translation();
    cairo_new_sub_path(cr);
    cairo_arc(cr, axes.X(centre.x()), axes.Y(centre.z()), 3.0, 0.0, 2.0 * M_PI);
  }
  cairo_stroke(cr);
  // Without ground truth the estimate's start is marked.
  const std::vector<Rigid3d>& first = gt.empty() ? est : gt;
  if (!first.empty()) {
    SetColour(cr, kBlack);
    const Eigen::Vector3d& start = first.front().translation();
    cairo_rectangle(cr, axes.X(start.x()) - 5.0, axes.Y(start.z()) - 5.0, 10.0, 10.0);
    cairo_fill(cr);
  }
  DrawLegend(cr, width - 10.0, axes.top, legend);
}

void DrawErrorPlot(cairo_t* cr, double width, double height, const KittiOdometryResult& kitti,
                   bool translation) {
  std::vector<std::pair<double, double>> points;
  Range x;
  Range y;
  y.Add(0.0);
  for (const KittiLengthResult& length : kitti.per_length) {
    x.Add(length.length_m);
    const std::optional<float>& err = translation ? length.t_err : length.r_err;
    if (!err) continue;
    const double value = translation ? KittiTErrPercent(*err) : KittiRErrDegPerMetre(*err);
    points.emplace_back(length.length_m, value);
    y.Add(value);
  }
  Range y_range = y;
  y_range.lo = 0.0;
  y_range.hi = y.hi > 0.0 ? 1.1 * y.hi : 1.0;
  // Half the spacing of the lengths on each side, so that the end points are not on the
  // frame.
  const size_t n_lengths = kitti.per_length.size();
  const double x_pad = n_lengths >= 2 ? 0.5 * x.Span() / static_cast<double>(n_lengths - 1) : 0.0;
  Axes axes{100.0, 40.0, width - 30.0, height - 60.0, x.Padded(0.0, 50.0), y_range};
  axes.x.lo -= x_pad;
  axes.x.hi += x_pad;

  DrawAxes(
      cr, axes, "Path length [m]", translation ? "Translation error [%]" : "Rotation error [deg/m]",
      translation ? "Translation error vs. segment length" : "Rotation error vs. segment length");
  if (points.empty()) {
    SetColour(cr, kBlack);
    cairo_set_font_size(cr, 15.0);
    char message[160];
    std::snprintf(
        message, sizeof(message), "no segment of %g m fits a %.1f m trajectory",
        kitti.per_length.empty() ? 0.0 : static_cast<double>(kitti.per_length.front().length_m),
        static_cast<double>(kitti.gt_path_length_m));
    ShowText(cr, message, 0.5 * (axes.left + axes.right), 0.5 * (axes.top + axes.bottom), 0.5, 0.5);
    return;
  }
  SetColour(cr, kEstimate);
  cairo_set_line_width(cr, 2.0);
  for (size_t i = 0; i < points.size(); ++i) {
    const double px = axes.X(points[i].first);
    const double py = axes.Y(points[i].second);
    if (i == 0) {
      cairo_move_to(cr, px, py);
    } else {
      cairo_line_to(cr, px, py);
    }
  }
  cairo_stroke(cr);
  for (const auto& [length, value] : points) {
    cairo_rectangle(cr, axes.X(length) - 4.0, axes.Y(value) - 4.0, 8.0, 8.0);
    cairo_stroke(cr);
  }
}

// Tableau's qualitative palette, for figures with any number of lines or statuses.
constexpr Colour kPalette[] = {{0.12, 0.47, 0.71}, {1.00, 0.50, 0.05}, {0.17, 0.63, 0.17},
                               {0.84, 0.15, 0.16}, {0.58, 0.40, 0.74}, {0.55, 0.34, 0.29},
                               {0.89, 0.47, 0.76}, {0.50, 0.50, 0.50}, {0.74, 0.74, 0.13},
                               {0.09, 0.75, 0.81}};

Colour PaletteColour(size_t index) { return kPalette[index % (sizeof(kPalette) / sizeof(Colour))]; }

void DrawCentredMessage(cairo_t* cr, const Axes& axes, const std::string& message) {
  SetColour(cr, kBlack);
  cairo_set_font_size(cr, 15.0);
  ShowText(cr, message, 0.5 * (axes.left + axes.right), 0.5 * (axes.top + axes.bottom), 0.5, 0.5);
}

// The frame axis of per-frame figures: frames first..last, half a frame of margin so that
// the end frames are not on the frame line.
Range FrameRange(size_t frames) {
  const double last = frames == 0 ? 0.0 : static_cast<double>(frames - 1);
  return {-0.5, std::max(last + 0.5, 4.5)};
}

void DrawFrameLines(cairo_t* cr, double width, double height, const FrameLinePlot& plot) {
  size_t frames = 0;
  Range y;
  std::vector<LegendEntry> legend;
  for (size_t i = 0; i < plot.lines.size(); ++i) {
    frames = std::max(frames, plot.lines[i].values.size());
    for (double value : plot.lines[i].values) {
      if (std::isfinite(value)) y.Add(value);
    }
    legend.push_back({plot.lines[i].label, PaletteColour(i)});
  }
  const bool has_values = y.lo <= y.hi;
  Range y_range{0.0, 1.0};
  if (has_values && plot.y_from_zero && y.lo >= 0.0) {
    y_range.hi = y.hi > 0.0 ? 1.08 * y.hi : 1.0;
  } else if (has_values) {
    const double magnitude = std::max(std::abs(y.lo), std::abs(y.hi));
    y_range = y.Padded(0.05, magnitude > 0.0 ? 0.02 * magnitude : 1.0);
  }
  // The legend sits right of the plot, so that it never hides a line.
  const double legend_width = legend.empty() ? 0.0 : LegendWidth(cr, legend) + 20.0;
  const Axes axes{100.0,  40.0, width - 20.0 - legend_width, height - 60.0, FrameRange(frames),
                  y_range};
  DrawAxes(cr, axes, "Frame", plot.y_title, plot.title, TickSpacing{true, 50.0});
  if (!legend.empty()) DrawLegend(cr, width - 10.0, axes.top, legend);
  if (!has_values) {
    DrawCentredMessage(cr, axes, "no values");
    return;
  }
  cairo_save(cr);
  cairo_rectangle(cr, axes.left, axes.top, axes.right - axes.left, axes.bottom - axes.top);
  cairo_clip(cr);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (size_t i = 0; i < plot.lines.size(); ++i) {
    const std::vector<double>& values = plot.lines[i].values;
    SetColour(cr, PaletteColour(i));
    cairo_set_line_width(cr, 1.5);
    const auto finite = [&](size_t frame) {
      return frame < values.size() && std::isfinite(values[frame]);
    };
    for (size_t frame = 0; frame < values.size(); ++frame) {
      if (!finite(frame)) continue;
      const double px = axes.X(static_cast<double>(frame));
      const double py = axes.Y(values[frame]);
      const bool joined_before = frame > 0 && finite(frame - 1);
      if (joined_before) {
        cairo_line_to(cr, px, py);
      } else if (finite(frame + 1)) {
        cairo_move_to(cr, px, py);
      } else {
        // A value with no neighbour would be an invisible line: a dot instead.
        cairo_stroke(cr);
        cairo_arc(cr, px, py, 2.5, 0.0, 2.0 * kPi);
        cairo_fill(cr);
      }
    }
    cairo_stroke(cr);
  }
  cairo_restore(cr);
}

void DrawFrameStatus(cairo_t* cr, double width, double height,
                     const std::vector<std::string>& status) {
  // Statuses in order of first appearance, with their frame counts.
  std::vector<std::pair<std::string, size_t>> counts;
  std::vector<size_t> index_of_frame;
  for (const std::string& s : status) {
    size_t k = 0;
    while (k < counts.size() && counts[k].first != s) ++k;
    if (k == counts.size()) counts.emplace_back(s, 0);
    ++counts[k].second;
    index_of_frame.push_back(k);
  }
  // Cells fill the strip: frames -0.5 .. n - 0.5.
  const Range frame_range{-0.5, static_cast<double>(std::max<size_t>(status.size(), 1)) - 0.5};
  const Axes axes{100.0, 40.0, width - 20.0, height - 90.0, frame_range, {0.0, 1.0}};
  cairo_set_font_size(cr, 16.0);
  SetColour(cr, kBlack);
  ShowText(cr, "Status per frame", 0.5 * (axes.left + axes.right), axes.top - 12.0, 0.5, 1.0);
  // One rectangle per run of equal statuses.
  for (size_t begin = 0; begin < status.size();) {
    size_t end = begin + 1;
    while (end < status.size() && index_of_frame[end] == index_of_frame[begin]) ++end;
    SetColour(cr, PaletteColour(index_of_frame[begin]));
    const double x0 = axes.X(static_cast<double>(begin) - 0.5);
    const double x1 = axes.X(static_cast<double>(end) - 0.5);
    cairo_rectangle(cr, x0, axes.top, x1 - x0, axes.bottom - axes.top);
    cairo_fill(cr);
    begin = end;
  }
  SetColour(cr, kBlack);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, axes.left, axes.top, axes.right - axes.left, axes.bottom - axes.top);
  cairo_stroke(cr);
  cairo_set_font_size(cr, 13.0);
  const double step = std::max(
      1.0, TickStep(axes.x.Span(), std::max(2, static_cast<int>((axes.right - axes.left) / 90.0))));
  for (double value = std::ceil(axes.x.lo / step) * step; value <= axes.x.hi; value += step) {
    cairo_move_to(cr, axes.X(value), axes.bottom);
    cairo_line_to(cr, axes.X(value), axes.bottom + 4.0);
    cairo_stroke(cr);
    ShowText(cr, TickLabel(value, step), axes.X(value), axes.bottom + 6.0, 0.5, 0.0);
  }
  cairo_set_font_size(cr, 15.0);
  ShowText(cr, "Frame", 0.5 * (axes.left + axes.right), axes.bottom + 24.0, 0.5, 0.0);
  // The legend: a row of swatches with "status: frames".
  cairo_set_font_size(cr, 13.0);
  double x = axes.left;
  const double y = height - 22.0;
  for (size_t k = 0; k < counts.size(); ++k) {
    const std::string label = counts[k].first + ": " + std::to_string(counts[k].second);
    SetColour(cr, PaletteColour(k));
    cairo_rectangle(cr, x, y - 6.0, 12.0, 12.0);
    cairo_fill(cr);
    SetColour(cr, kBlack);
    ShowText(cr, label, x + 17.0, y, 0.0, 0.5);
    cairo_text_extents_t extents;
    cairo_text_extents(cr, label.c_str(), &extents);
    x += 17.0 + extents.x_advance + 24.0;
  }
  if (status.empty()) DrawCentredMessage(cr, axes, "no frames");
}

using DrawFunction = std::function<void(cairo_t*, double, double)>;

void RenderWhiteBackground(cairo_t* cr) {
  cairo_set_source_rgb(cr, 1.0, 1.0, 1.0);
  cairo_paint(cr);
}

// Draws on a white background; returns the drawing's status.
cairo_status_t DrawFigure(cairo_surface_t* surface, int width, int height,
                          const DrawFunction& draw) {
  cairo_t* cr = cairo_create(surface);
  RenderWhiteBackground(cr);
  draw(cr, width, height);
  const cairo_status_t status = cairo_status(cr);
  cairo_destroy(cr);
  return status;
}

void CheckCairo(cairo_status_t status, const std::string& path) {
  if (status != CAIRO_STATUS_SUCCESS) {
    ThrowFileError(path, std::string("cannot write the plot: ") + cairo_status_to_string(status));
  }
}

void WritePng(const std::string& path, int width, int height, const DrawFunction& draw) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height);
  const cairo_status_t draw_status = DrawFigure(surface, width, height, draw);
  const cairo_status_t write_status = draw_status == CAIRO_STATUS_SUCCESS
                                          ? cairo_surface_write_to_png(surface, path.c_str())
                                          : draw_status;
  cairo_surface_destroy(surface);
  CheckCairo(write_status, path);
}

cairo_status_t AppendToString(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

// The SVG document of a figure, in memory; `name` names the figure in errors.
std::string RenderSvg(const std::string& name, int width, int height, const DrawFunction& draw) {
  if (width <= 0 || height <= 0) {
    throw Error(name + ": cannot draw a plot of " + std::to_string(width) + " x " +
                std::to_string(height) + " pixels");
  }
  std::string svg;
  cairo_surface_t* surface =
      cairo_svg_surface_create_for_stream(AppendToString, &svg, width, height);
  const cairo_status_t draw_status = DrawFigure(surface, width, height, draw);
  cairo_surface_finish(surface);
  const cairo_status_t status =
      draw_status == CAIRO_STATUS_SUCCESS ? cairo_surface_status(surface) : draw_status;
  cairo_surface_destroy(surface);
  if (status != CAIRO_STATUS_SUCCESS) {
    throw Error(name + ": cannot draw the plot: " + cairo_status_to_string(status));
  }
  return svg;
}

void WriteSvg(const std::string& path, int width, int height, const DrawFunction& draw) {
  const std::string svg = RenderSvg(path, width, height, draw);
  std::ofstream file(path, std::ios::binary);
  file.write(svg.data(), static_cast<std::streamsize>(svg.size()));
  file.close();
  if (!file) ThrowFileError(path, "cannot write the plot");
}

}  // namespace

std::vector<std::string> WriteEvaluationPlots(const std::string& directory,
                                              const std::vector<Rigid3d>& gt_world_from_cam,
                                              const std::vector<Rigid3d>& est_world_from_cam,
                                              const KittiOdometryResult& kitti) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) ThrowFileError(directory, "cannot create the plot folder: " + error.message());

  const std::vector<std::pair<std::string, std::pair<int, DrawFunction>>> figures = {
      {"trajectory_top_view",
       {800, [&](cairo_t* cr, double w,
                 double h) { DrawTopView(cr, w, h, gt_world_from_cam, est_world_from_cam, {}); }}},
      {"t_err_vs_length",
       {500, [&](cairo_t* cr, double w, double h) { DrawErrorPlot(cr, w, h, kitti, true); }}},
      {"r_err_vs_length",
       {500, [&](cairo_t* cr, double w, double h) { DrawErrorPlot(cr, w, h, kitti, false); }}},
  };
  std::vector<std::string> written;
  for (const auto& [name, size_and_draw] : figures) {
    const auto& [height, draw] = size_and_draw;
    const std::string stem = (std::filesystem::path(directory) / name).string();
    WritePng(stem + ".png", 800, height, draw);
    written.push_back(stem + ".png");
    WriteSvg(stem + ".svg", 800, height, draw);
    written.push_back(stem + ".svg");
  }
  return written;
}

std::string RenderTopViewSvg(const std::vector<Rigid3d>& gt_world_from_cam,
                             const std::vector<Rigid3d>& est_world_from_cam, int width, int height,
                             const std::vector<size_t>& keyframes) {
  return RenderSvg("trajectory_top_view", width, height, [&](cairo_t* cr, double w, double h) {
    DrawTopView(cr, w, h, gt_world_from_cam, est_world_from_cam, keyframes);
  });
}

std::string RenderKittiErrorSvg(const KittiOdometryResult& kitti, KittiErrorKind kind, int width,
                                int height) {
  const bool translation = kind == KittiErrorKind::kTranslation;
  return RenderSvg(
      translation ? "t_err_vs_length" : "r_err_vs_length", width, height,
      [&](cairo_t* cr, double w, double h) { DrawErrorPlot(cr, w, h, kitti, translation); });
}

std::string RenderFrameLinesSvg(const FrameLinePlot& plot, int width, int height) {
  return RenderSvg(plot.title, width, height,
                   [&](cairo_t* cr, double w, double h) { DrawFrameLines(cr, w, h, plot); });
}

std::string RenderFrameStatusSvg(const std::vector<std::string>& status, int width, int height) {
  return RenderSvg("status per frame", width, height,
                   [&](cairo_t* cr, double w, double h) { DrawFrameStatus(cr, w, h, status); });
}

}  // namespace roadscale
