#pragma once
// The parsers under fuzzing read files (as the CLI and the cell do): each input is written to
// a file of the harness's own in a per-process directory (in /dev/shm when there is one, so
// that the write costs no disk), and read back through the very function a user's file goes
// through.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

namespace cosmos::fuzz {

// Removed when the fuzzer exits (libFuzzer ends with exit(), which runs this destructor).
struct FuzzDirectory {
  std::filesystem::path path;
  FuzzDirectory() {
    std::error_code error;
    const std::filesystem::path shm = "/dev/shm";
    const std::filesystem::path base =
        std::filesystem::is_directory(shm, error) ? shm : std::filesystem::temp_directory_path();
    path = base / ("cosmos-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(path);
  }
  ~FuzzDirectory() {
    std::error_code error;
    std::filesystem::remove_all(path, error);
  }
};

inline const std::filesystem::path& fuzz_directory() {
  static const FuzzDirectory directory;
  return directory.path;
}

// Writes `size` bytes to `name` in the fuzz directory and returns its path.
inline std::filesystem::path write_input(const std::string& name, const std::uint8_t* data,
                                         std::size_t size) {
  const std::filesystem::path path = fuzz_directory() / name;
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return path;
}

}  // namespace cosmos::fuzz
