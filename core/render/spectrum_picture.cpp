#include "core/render/spectrum_picture.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <sstream>
#include <string>

#include "core/render/picture_drawing.hpp"
#include "core/render/shape_category_palette.hpp"

namespace cosmos {
namespace {

using namespace render;

constexpr int kPlotLeftPx = 80;
constexpr int kPlotRightPx = 800;
constexpr int kPlotTopPx = 90;
constexpr int kPlotBottomPx = 440;
constexpr int kPlanarAxisPx = 880;
constexpr int kPlanarBarLeftPx = 900;
constexpr int kPlanarBarRightPx = 950;

int plot_x(double shape_index) {
  return kPlotLeftPx + static_cast<int>(std::lround(std::clamp(shape_index, 0.0, 1.0) *
                                                    (kPlotRightPx - kPlotLeftPx)));
}
int plot_y(double value, double top_value) {
  const double unit = top_value > 0 ? std::clamp(value / top_value, 0.0, 1.0) : 0.0;
  return kPlotBottomPx - static_cast<int>(std::lround(unit * (kPlotBottomPx - kPlotTopPx)));
}

std::string format_general(double value) {
  if (!std::isfinite(value)) return "n/a";
  std::ostringstream text;
  text.precision(3);
  text << value;
  return text.str();
}

void draw_title(cv::Mat& canvas, const ShapeSpectrum& spectrum, const MomentVector& moments) {
  draw_text(canvas,
            "Shape spectrum   visible area " + format_fixed(spectrum.visible_area_mm2, 1) +
                " mm^2, planar " + format_fixed(100 * spectrum.planar_fraction, 1) + " %",
            {kPlotLeftPx, 28}, 0.6);
  draw_text(canvas,
            "m1 (mean) " + format_general(moments[0]) + "    m2 (variance) " +
                format_general(moments[1]) + "    m3 " + format_general(moments[2]) + "    m4 " +
                format_general(moments[3]),
            {kPlotLeftPx, 54}, 0.5, rgb(60, 60, 60));
}

void draw_x_axis(cv::Mat& canvas) {
  // Category boundaries (Fig. 3.3), behind the bars.
  for (int k = 1; k < kShapeCategories; ++k) {
    const int x = plot_x(kShapeCategoryTable[static_cast<std::size_t>(k)].lower);
    cv::line(canvas, {x, kPlotTopPx}, {x, kPlotBottomPx}, scalar(kFaintInk));
  }
  for (int k = 0; k <= 4; ++k) {
    const int x = plot_x(k / 4.0);
    cv::line(canvas, {x, kPlotBottomPx}, {x, kPlotBottomPx + 5}, scalar(kInk));
    draw_text_centred(canvas, format_fixed(k / 4.0, 2), {x, kPlotBottomPx + 17}, 0.45);
  }
  for (const ShapeCategory& category : kShapeCategoryTable) {
    const int x = plot_x((category.lower + category.upper) / 2);
    // The category colour, darkened so that light hues (saddle ridge) stay readable on white.
    const BgrColor ink{static_cast<std::uint8_t>(category.color.blue * 0.7),
                       static_cast<std::uint8_t>(category.color.green * 0.7),
                       static_cast<std::uint8_t>(category.color.red * 0.7)};
    draw_text_centred(canvas, std::string(category.name), {x, kPlotBottomPx + 40}, 0.38, ink);
  }
  draw_text_centred(canvas, "shape index S_I",
                    {(kPlotLeftPx + kPlotRightPx) / 2, kPlotBottomPx + 72}, 0.55);
}

// Returns the value at the top of the axis: the first round tick at or above max_value.
double draw_y_axis(cv::Mat& canvas, double max_value_percent) {
  const double wanted = max_value_percent > 0 ? max_value_percent : 1.0;
  std::vector<double> ticks = nice_ticks(0, wanted, 5);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : wanted;
  const double top_value = std::ceil(wanted / step - 1e-9) * step;
  if (ticks.back() < top_value - step * 1e-9) ticks.push_back(top_value);
  for (double tick : ticks) {
    const int y = plot_y(tick, top_value);
    cv::line(canvas, {kPlotLeftPx - 5, y}, {kPlotLeftPx, y}, scalar(kInk));
    if (tick > 0)
      cv::line(canvas, {kPlotLeftPx + 1, y}, {kPlotRightPx, y}, scalar(rgb(238, 238, 238)));
    draw_text_right(canvas, format_tick(tick, step), {kPlotLeftPx - 8, y + 5}, 0.45);
  }
  draw_text(canvas, "% of visible area per S_I bin", {kPlotLeftPx - 60, kPlotTopPx - 14}, 0.45);
  return top_value;
}

void draw_bins(cv::Mat& canvas, const ShapeSpectrum& spectrum, double top_value) {
  const double width = spectrum.bin_width > 0
                           ? spectrum.bin_width
                           : 1.0 / std::max<std::size_t>(spectrum.bins.size(), 1);
  std::vector<cv::Point> outline{{kPlotLeftPx, kPlotBottomPx}};
  for (std::size_t i = 0; i < spectrum.bins.size(); ++i) {
    const double lower = i * width;
    if (lower >= 1.0) break;
    const double value = std::isfinite(spectrum.bins[i]) ? 100 * spectrum.bins[i] : 0.0;
    const int x0 = plot_x(lower);
    const int x1 = plot_x(lower + width);
    const int y = plot_y(value, top_value);
    if (value > 0 && y < kPlotBottomPx) {
      const BgrColor color = shape_category_color(std::min(lower + width / 2, 1.0));
      cv::rectangle(canvas, {x0, y}, {std::max(x0, x1 - 1), kPlotBottomPx - 1}, scalar(color),
                    cv::FILLED);
    }
    outline.emplace_back(x0, y);
    outline.emplace_back(x1, y);
  }
  outline.emplace_back(outline.back().x, kPlotBottomPx);
  cv::polylines(canvas, outline, false, scalar(rgb(60, 60, 60)), 1);
  cv::rectangle(canvas, {kPlotLeftPx, kPlotTopPx}, {kPlotRightPx, kPlotBottomPx}, scalar(kInk));
}

void draw_planar_bar(cv::Mat& canvas, double planar_fraction) {
  const double percent =
      std::isfinite(planar_fraction) ? std::clamp(100 * planar_fraction, 0.0, 100.0) : 0.0;
  cv::line(canvas, {kPlanarAxisPx, kPlotTopPx}, {kPlanarAxisPx, kPlotBottomPx}, scalar(kInk));
  for (int tick = 0; tick <= 100; tick += 25) {
    const int y = plot_y(tick, 100);
    cv::line(canvas, {kPlanarAxisPx - 4, y}, {kPlanarAxisPx, y}, scalar(kInk));
    draw_text_right(canvas, std::to_string(tick), {kPlanarAxisPx - 7, y + 5}, 0.4);
  }
  const int y = plot_y(percent, 100);
  if (percent > 0) {
    cv::rectangle(canvas, {kPlanarBarLeftPx, y}, {kPlanarBarRightPx, kPlotBottomPx},
                  scalar(kPlanarColor), cv::FILLED);
  }
  cv::rectangle(canvas, {kPlanarBarLeftPx, y}, {kPlanarBarRightPx, kPlotBottomPx}, scalar(kInk));
  const int centre = (kPlanarBarLeftPx + kPlanarBarRightPx) / 2;
  draw_text_centred(canvas, format_fixed(percent, 1) + "%", {centre, y - 12}, 0.42);
  draw_text_centred(canvas, "planar", {centre, kPlotBottomPx + 17}, 0.5);
  draw_text_centred(canvas, "(S_I = 2)", {centre, kPlotBottomPx + 40}, 0.36, rgb(90, 90, 90));
}

}  // namespace

BgrPicture render_spectrum_picture(const ShapeSpectrum& spectrum, const MomentVector& moments) {
  cv::Mat canvas = blank_canvas(kSpectrumWidthPx, kSpectrumHeightPx);
  double max_percent = 0;
  for (double bin : spectrum.bins) {
    if (std::isfinite(bin)) max_percent = std::max(max_percent, 100 * bin);
  }
  draw_title(canvas, spectrum, moments);
  draw_x_axis(canvas);
  const double top_value = draw_y_axis(canvas, max_percent);
  draw_bins(canvas, spectrum, top_value);
  draw_planar_bar(canvas, spectrum.planar_fraction);
  return to_picture(canvas);
}

}  // namespace cosmos
