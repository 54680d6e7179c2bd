#include "core/render/view_pictures.hpp"

#include <opencv2/imgcodecs.hpp>
#include <system_error>

#include "core/input_error.hpp"
#include "core/render/csmp_picture.hpp"
#include "core/render/gauss_map_picture.hpp"
#include "core/render/range_picture.hpp"
#include "core/render/shape_index_picture.hpp"
#include "core/render/spectrum_picture.hpp"

namespace cosmos {
namespace {

void write_png(const BgrPicture& picture, const std::filesystem::path& path) {
  // The picture's storage is laid out as CV_8UC3: wrap it, no copy.
  const cv::Mat mat(picture.height(), picture.width(), CV_8UC3,
                    const_cast<BgrColor*>(picture.data()));
  bool written = false;
  try {
    written = cv::imwrite(path.string(), mat);
  } catch (const cv::Exception& error) {
    throw InputError(path.string() + ": cannot write picture (" + error.msg + ")");
  }
  if (!written) throw InputError(path.string() + ": cannot write picture");
}

}  // namespace

void write_view_pictures(const RangeImage& image, const ViewAnalysis& analysis,
                         const std::filesystem::path& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error)
    throw InputError(dir.string() + ": cannot create output directory (" + error.message() + ")");

  const double dx = image.pixel_size_x_mm;
  const double dy = image.pixel_size_y_mm;
  write_png(render_range_picture(image), dir / "range.png");
  write_png(render_shape_index_picture(analysis.field, dx, dy), dir / "shape_index.png");
  write_png(render_csmp_picture(analysis.segmentation, dx, dy), dir / "csmps.png");
  write_png(render_gauss_map_picture(analysis.view), dir / "gauss_map.png");
  write_png(render_spectrum_picture(analysis.spectrum, analysis.moments), dir / "spectrum.png");
}

}  // namespace cosmos
