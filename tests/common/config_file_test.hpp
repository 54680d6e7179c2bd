#pragma once
// The fixture of the config-file tests: a private directory with one YAML file in it, written
// per test, and the one-line error a loader gives for it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.hpp"
#include "tests/common/scratch_directory_test.hpp"

namespace cosmos::testing {

class ConfigFileTest : public ScratchDirectoryTest {
 protected:
  explicit ConfigFileTest(std::string file_name = "cell.yaml") : file_name_(std::move(file_name)) {}

  std::filesystem::path path() const { return file(file_name_); }

  std::filesystem::path write(const std::string& text) const {
    std::ofstream(path()) << text;
    return path();
  }

  // The InputError `load` throws for a file holding `text`, or "" when it loads.
  template <class Load>
  std::string error_when_loading(const std::string& text, Load load) const {
    try {
      load(write(text));
    } catch (const InputError& error) {
      return error.what();
    }
    return "";
  }

 private:
  std::string file_name_;
};

}  // namespace cosmos::testing
