#pragma once
// The simulated conveyor recorded on the host for the HIL guest: its camera-mode frames (the
// hardware config's ROI and pixel format) and what the guest needs to know of it, so the
// guest only streams frames and never runs the simulator (ray casting and noise drawing are
// floating point, which qemu's TCG emulates slowly).
//
// The frames are stored exactly and small: the simulator draws each frame's background (the
// ambient light and read noise) from a few pre-rendered backgrounds (sim/camera_frame_
// renderer.hpp), so a frame is its background's index and the runs of bytes that differ from
// it, the laser stripe. Besides the frames: the conveyor's last profile and ticks per profile,
// its photo-eye beam interruptions (conveyor ticks), the ground truth of every placed part
// (name, belt-frame pose, the profiles its bounding box spans) and, for the pose checks, each
// part model's vertices (part frame, mm) and diameter (the largest vertex distance).
//
// Layout: a text header ("cosmos-hil-tape 1", key-value lines, "end"), then the backgrounds
// and the frames as binary records (little-endian).
#include <Eigen/Geometry>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "firmware_bridge/camera.hpp"
#include "sim/twins/simulated_gpio_lines.hpp"

namespace cosmos::hil {

struct TapePart {
  std::string name;
  Eigen::Isometry3d T_belt_part = Eigen::Isometry3d::Identity();
  std::int64_t first_profile = 0;
  std::int64_t last_profile = -1;
};

struct TapeModel {
  std::string name;
  double diameter_mm = 0;
  std::vector<Eigen::Vector3d> points_mm;
};

struct TapeHeader {
  int width_px = 0;
  int height_px = 0;  // the ROI's rows
  int bytes_per_pixel = 1;
  int roi_top_px = 0;  // the sensor row of the frames' row 0
  int roi_left_px = 0;
  std::int64_t last_profile = -1;
  int ticks_per_profile = 4;
  std::vector<BeamInterruption> beam;
  std::vector<TapePart> parts;
  std::vector<TapeModel> models;
  int backgrounds = 0;
  std::int64_t frames = 0;

  const TapeModel* model(const std::string& name) const {
    for (const TapeModel& model : models)
      if (model.name == name) return &model;
    return nullptr;
  }
  std::size_t frame_bytes() const {
    return static_cast<std::size_t>(width_px) * static_cast<std::size_t>(bytes_per_pixel) *
           static_cast<std::size_t>(height_px);
  }
};

// Records frames in profile order (profile 0 first); the header's frame and background counts
// are filled in by finish().
class FrameTapeWriter {
 public:
  FrameTapeWriter(const std::filesystem::path& file, TapeHeader header);
  void add(const FrameView& frame);
  // Writes the file (throws std::runtime_error when it cannot).
  void finish();

 private:
  std::filesystem::path file_;
  TapeHeader header_;
  std::vector<std::vector<std::uint8_t>> backgrounds_;
  std::vector<std::uint8_t> frames_;  // encoded records
  std::vector<std::uint8_t> packed_;  // this frame, rows packed
};

class FrameTapeReader {
 public:
  explicit FrameTapeReader(const std::filesystem::path& file);
  const TapeHeader& header() const { return header_; }
  // The profile the next decode() reads; frames are read in order.
  std::int64_t next_profile() const { return next_profile_; }
  // Reads frame next_profile() into rows of `bytes_per_line` starting at `rows`; skips to
  // `profile` first (only forward). Throws past the last frame.
  void decode(std::int64_t profile, std::uint8_t* rows, std::size_t bytes_per_line);

 private:
  void skip_frame();

  std::filesystem::path file_;
  std::ifstream in_;
  TapeHeader header_;
  std::vector<std::vector<std::uint8_t>> backgrounds_;
  std::vector<std::uint8_t> frame_;
  std::int64_t next_profile_ = 0;
};

}  // namespace cosmos::hil
