#include "tests/hil/frame_tape.hpp"

#include <cstring>
#include <sstream>
#include <stdexcept>

namespace cosmos::hil {
namespace {

constexpr char kMagic[] = "cosmos-hil-tape 1";
// Equal bytes shorter than this between two differing ones stay inside one run: a run's
// header costs six bytes.
constexpr std::size_t kJoinGap = 6;

template <class T>
void put(std::vector<std::uint8_t>& out, T value) {
  for (std::size_t i = 0; i < sizeof(T); ++i)
    out.push_back(static_cast<std::uint8_t>((static_cast<std::uint64_t>(value) >> (8 * i)) & 0xff));
}

template <class T>
T get(std::istream& in, const std::filesystem::path& file) {
  std::uint8_t bytes[sizeof(T)];
  if (!in.read(reinterpret_cast<char*>(bytes), sizeof(T))) {
    throw std::runtime_error(file.string() + ": the tape ends inside a frame");
  }
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i)
    value |= static_cast<std::uint64_t>(bytes[i]) << (8 * i);
  return static_cast<T>(value);
}

std::size_t equal_bytes(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  std::size_t equal = 0;
  for (std::size_t i = 0; i < a.size(); ++i) equal += a[i] == b[i] ? 1 : 0;
  return equal;
}

}  // namespace

FrameTapeWriter::FrameTapeWriter(const std::filesystem::path& file, TapeHeader header)
    : file_(file), header_(std::move(header)) {}

void FrameTapeWriter::add(const FrameView& frame) {
  const auto row_bytes = static_cast<std::size_t>(header_.width_px * header_.bytes_per_pixel);
  if (frame.width_px != header_.width_px || frame.height_px != header_.height_px ||
      frame.bytes_per_pixel() != header_.bytes_per_pixel) {
    throw std::runtime_error("frame tape: a frame of another size or format");
  }
  packed_.resize(header_.frame_bytes());
  for (int r = 0; r < frame.height_px; ++r)
    std::memcpy(packed_.data() + static_cast<std::size_t>(r) * row_bytes, frame.row(r), row_bytes);
  std::size_t best = 0, best_equal = 0;
  for (std::size_t i = 0; i < backgrounds_.size(); ++i) {
    const std::size_t equal = equal_bytes(backgrounds_[i], packed_);
    if (equal > best_equal) {
      best = i;
      best_equal = equal;
    }
  }
  if (best_equal * 2 < packed_.size()) {  // mostly new bytes: a background not seen yet
    backgrounds_.push_back(packed_);
    best = backgrounds_.size() - 1;
  }
  const std::vector<std::uint8_t>& background = backgrounds_[best];
  frames_.push_back(static_cast<std::uint8_t>(best));
  const std::size_t count_at = frames_.size();
  put<std::uint32_t>(frames_, 0);
  std::uint32_t runs = 0;
  for (std::size_t i = 0; i < packed_.size();) {
    if (packed_[i] == background[i]) {
      ++i;
      continue;
    }
    std::size_t end = i + 1, last_different = i;
    while (end < packed_.size() && end - last_different <= kJoinGap && end - i < 0xffff) {
      if (packed_[end] != background[end]) last_different = end;
      ++end;
    }
    const std::size_t length = last_different + 1 - i;
    put<std::uint32_t>(frames_, static_cast<std::uint32_t>(i));
    put<std::uint16_t>(frames_, static_cast<std::uint16_t>(length));
    frames_.insert(frames_.end(), packed_.begin() + static_cast<std::ptrdiff_t>(i),
                   packed_.begin() + static_cast<std::ptrdiff_t>(i + length));
    ++runs;
    i += length;
  }
  std::memcpy(frames_.data() + count_at, &runs, sizeof runs);  // little-endian host
  ++header_.frames;
}

void FrameTapeWriter::finish() {
  header_.backgrounds = static_cast<int>(backgrounds_.size());
  const std::filesystem::path partial = file_.string() + ".partial";
  {
    std::ofstream out(partial, std::ios::binary);
    out.precision(17);
    out << kMagic << '\n'
        << "frame " << header_.width_px << ' ' << header_.height_px << ' '
        << header_.bytes_per_pixel << ' ' << header_.roi_top_px << ' ' << header_.roi_left_px
        << '\n'
        << "conveyor " << header_.last_profile << ' ' << header_.ticks_per_profile << '\n';
    for (const BeamInterruption& beam : header_.beam)
      out << "beam " << beam.enter_tick << ' ' << beam.leave_tick << '\n';
    for (const TapePart& part : header_.parts) {
      out << "part " << part.name << ' ' << part.first_profile << ' ' << part.last_profile;
      const Eigen::Matrix4d m = part.T_belt_part.matrix();
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) out << ' ' << m(r, c);
      out << '\n';
    }
    for (const TapeModel& model : header_.models) {
      out << "model " << model.name << ' ' << model.diameter_mm << ' ' << model.points_mm.size();
      for (const Eigen::Vector3d& point : model.points_mm)
        out << ' ' << point.x() << ' ' << point.y() << ' ' << point.z();
      out << '\n';
    }
    out << "records " << header_.backgrounds << ' ' << header_.frames << '\n' << "end\n";
    for (const std::vector<std::uint8_t>& background : backgrounds_)
      out.write(reinterpret_cast<const char*>(background.data()),
                static_cast<std::streamsize>(background.size()));
    out.write(reinterpret_cast<const char*>(frames_.data()),
              static_cast<std::streamsize>(frames_.size()));
    if (!out) throw std::runtime_error(file_.string() + ": cannot write the tape");
  }
  std::filesystem::rename(partial, file_);
}

FrameTapeReader::FrameTapeReader(const std::filesystem::path& file)
    : file_(file), in_(file, std::ios::binary) {
  std::string line;
  if (!in_ || !std::getline(in_, line) || line != kMagic) {
    throw std::runtime_error(file.string() + ": not a HIL frame tape");
  }
  while (std::getline(in_, line) && line != "end") {
    std::istringstream fields(line);
    std::string key;
    fields >> key;
    if (key == "frame") {
      fields >> header_.width_px >> header_.height_px >> header_.bytes_per_pixel >>
          header_.roi_top_px >> header_.roi_left_px;
    } else if (key == "conveyor") {
      fields >> header_.last_profile >> header_.ticks_per_profile;
    } else if (key == "beam") {
      BeamInterruption beam;
      fields >> beam.enter_tick >> beam.leave_tick;
      header_.beam.push_back(beam);
    } else if (key == "part") {
      TapePart part;
      fields >> part.name >> part.first_profile >> part.last_profile;
      Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 4; ++c) fields >> m(r, c);
      part.T_belt_part.matrix() = m;
      header_.parts.push_back(part);
    } else if (key == "model") {
      TapeModel model;
      std::size_t count = 0;
      fields >> model.name >> model.diameter_mm >> count;
      model.points_mm.resize(count);
      for (Eigen::Vector3d& point : model.points_mm) fields >> point.x() >> point.y() >> point.z();
      header_.models.push_back(std::move(model));
    } else if (key == "records") {
      fields >> header_.backgrounds >> header_.frames;
    }
    if (!fields) throw std::runtime_error(file.string() + ": bad tape header line: " + line);
  }
  for (int i = 0; i < header_.backgrounds; ++i) {
    std::vector<std::uint8_t> background(header_.frame_bytes());
    if (!in_.read(reinterpret_cast<char*>(background.data()),
                  static_cast<std::streamsize>(background.size()))) {
      throw std::runtime_error(file.string() + ": the tape ends inside its backgrounds");
    }
    backgrounds_.push_back(std::move(background));
  }
  frame_.resize(header_.frame_bytes());
}

void FrameTapeReader::skip_frame() {
  get<std::uint8_t>(in_, file_);
  const auto runs = get<std::uint32_t>(in_, file_);
  for (std::uint32_t r = 0; r < runs; ++r) {
    get<std::uint32_t>(in_, file_);
    in_.seekg(get<std::uint16_t>(in_, file_), std::ios::cur);
  }
  ++next_profile_;
}

void FrameTapeReader::decode(std::int64_t profile, std::uint8_t* rows, std::size_t bytes_per_line) {
  if (profile < next_profile_ || profile >= header_.frames) {
    throw std::runtime_error(file_.string() + ": frame " + std::to_string(profile) +
                             " asked for after frame " + std::to_string(next_profile_ - 1) +
                             " of " + std::to_string(header_.frames));
  }
  while (next_profile_ < profile) skip_frame();
  const auto background = get<std::uint8_t>(in_, file_);
  if (background >= backgrounds_.size()) throw std::runtime_error(file_.string() + ": bad frame");
  frame_ = backgrounds_[background];
  const auto runs = get<std::uint32_t>(in_, file_);
  for (std::uint32_t r = 0; r < runs; ++r) {
    const auto offset = get<std::uint32_t>(in_, file_);
    const auto length = get<std::uint16_t>(in_, file_);
    if (static_cast<std::size_t>(offset) + length > frame_.size() ||
        !in_.read(reinterpret_cast<char*>(frame_.data() + offset), length)) {
      throw std::runtime_error(file_.string() + ": bad frame " + std::to_string(profile));
    }
  }
  const auto row_bytes = static_cast<std::size_t>(header_.width_px * header_.bytes_per_pixel);
  for (int r = 0; r < header_.height_px; ++r) {
    std::memcpy(rows + static_cast<std::size_t>(r) * bytes_per_line,
                frame_.data() + static_cast<std::size_t>(r) * row_bytes, row_bytes);
  }
  ++next_profile_;
}

}  // namespace cosmos::hil
