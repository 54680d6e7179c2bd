#include "calibration/frame_list.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <sstream>
#include <string>

#include "core/input_error.hpp"

namespace cosmos {

namespace fs = std::filesystem;

cv::Mat read_grey_image(const fs::path& file) {
  if (!fs::exists(file)) throw InputError(file.string() + ": no such image");
  cv::Mat image = cv::imread(file.string(), cv::IMREAD_ANYDEPTH | cv::IMREAD_GRAYSCALE);
  if (image.empty()) throw InputError(file.string() + ": not a readable image");
  return image;
}

std::vector<fs::path> png_files(const fs::path& directory) {
  if (!fs::is_directory(directory)) throw InputError(directory.string() + ": no such directory");
  std::vector<fs::path> files;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory))
    if (entry.path().extension() == ".png") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  if (files.empty()) throw InputError(directory.string() + ": no .png images");
  return files;
}

std::vector<StripeFrame> read_frame_list(const fs::path& directory) {
  const fs::path list = directory / "frames.csv";
  std::ifstream in(list);
  if (!in) throw InputError(list.string() + ": cannot open (a frame directory needs frames.csv)");
  std::vector<StripeFrame> frames;
  std::string line;
  int line_number = 0;
  while (std::getline(in, line)) {
    ++line_number;
    if (line_number == 1 || line.empty()) continue;  // the header
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream fields(line);
    std::string file;
    StripeFrame frame;
    if (!(fields >> file >> frame.encoder_ticks >> frame.roi_top_px)) {
      throw InputError(list.string() + ":" + std::to_string(line_number) +
                       ": expected file,encoder_ticks,roi_top_px");
    }
    frame.image = read_grey_image(directory / file);
    frames.push_back(std::move(frame));
  }
  if (frames.empty()) throw InputError(list.string() + ": lists no frames");
  return frames;
}

void write_frame_list(const fs::path& directory, const std::vector<StripeFrame>& frames) {
  fs::create_directories(directory);
  std::ofstream out(directory / "frames.csv");
  out << "file,encoder_ticks,roi_top_px\n";
  for (std::size_t i = 0; i < frames.size(); ++i) {
    char name[32];
    std::snprintf(name, sizeof name, "frame-%04zu.png", i);
    cv::imwrite((directory / name).string(), frames[i].image);
    out << name << ',' << frames[i].encoder_ticks << ',' << frames[i].roi_top_px << '\n';
  }
  if (!out) throw InputError((directory / "frames.csv").string() + ": cannot write");
}

}  // namespace cosmos
