// The HIL frame tape gives back every frame of the simulated conveyor byte for byte, with the
// conveyor's beam and ground truth, and stays small.
#include "tests/hil/frame_tape.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include "realtime/config/hardware_config.hpp"
#include "tests/hil/conveyor_frames.hpp"
#include "tests/sim/twins/twin_test_conveyor.hpp"

namespace cosmos::hil {
namespace {

namespace fs = std::filesystem;

HardwareConfig twin_camera() {
  HardwareConfig hardware;
  hardware.camera = testing::simulator_camera();
  hardware.gpio = testing::simulated_gpio();
  return hardware;
}

TEST(FrameTape, GivesBackEveryFrameExactly) {
  const auto conveyor = testing::twin_test_conveyor();
  const HardwareConfig hardware = twin_camera();
  const fs::path file = fs::temp_directory_path() / "cosmos-frame-tape-test.tape";
  TapeHeader header;
  header.width_px = hardware.camera.width_px;
  header.height_px = hardware.camera.height_px;
  header.roi_top_px = hardware.camera.roi_top_px;
  header.last_profile = conveyor->last_profile();
  {
    ConveyorFrames frames(*conveyor, hardware);
    header.beam = frames.beam_interruptions();
    for (const PlacedSimPart& part : conveyor->placed_parts())
      header.parts.push_back({part.name, part.T_belt_part, part.first_profile, part.last_profile});
    FrameTapeWriter writer(file, header);
    FrameView frame;
    while (frames.next(frame)) writer.add(frame);
    writer.finish();
  }
  FrameTapeReader tape(file);
  ASSERT_EQ(tape.header().frames, conveyor->last_profile() + 1);
  EXPECT_EQ(tape.header().roi_top_px, hardware.camera.roi_top_px);
  EXPECT_GE(tape.header().backgrounds, 1);
  EXPECT_LE(tape.header().backgrounds, 8);
  ASSERT_EQ(tape.header().parts.size(), conveyor->placed_parts().size());
  for (std::size_t i = 0; i < header.parts.size(); ++i) {
    EXPECT_EQ(tape.header().parts[i].name, conveyor->placed_parts()[i].name);
    EXPECT_EQ(tape.header().parts[i].last_profile, conveyor->placed_parts()[i].last_profile);
    EXPECT_TRUE(tape.header().parts[i].T_belt_part.isApprox(conveyor->placed_parts()[i].T_belt_part,
                                                            1e-12));
  }
  ASSERT_EQ(tape.header().beam.size(), header.beam.size());
  EXPECT_EQ(tape.header().beam.back().leave_tick, header.beam.back().leave_tick);
  // A tape is a fraction of the raw frames: backgrounds once, then the stripes.
  const auto raw_bytes = static_cast<double>(header.frame_bytes()) * tape.header().frames;
  EXPECT_LT(static_cast<double>(fs::file_size(file)), 0.1 * raw_bytes);

  ConveyorFrames again(*conveyor, hardware);
  std::vector<std::uint8_t> decoded(header.frame_bytes());
  const auto row_bytes = static_cast<std::size_t>(header.width_px);
  FrameView frame;
  std::int64_t profile = 0, differing_rows = 0;
  while (again.next(frame)) {
    if (profile % 7 == 3) {  // skipping forward reads past frames unseen
      ++profile;
      continue;
    }
    tape.decode(profile, decoded.data(), row_bytes);
    for (int r = 0; r < frame.height_px; ++r)
      differing_rows += std::memcmp(frame.row(r), decoded.data() + r * row_bytes, row_bytes) != 0;
    ++profile;
  }
  EXPECT_EQ(differing_rows, 0);
  EXPECT_THROW(tape.decode(0, decoded.data(), row_bytes), std::runtime_error);  // only forward
  fs::remove(file);
}

}  // namespace
}  // namespace cosmos::hil
