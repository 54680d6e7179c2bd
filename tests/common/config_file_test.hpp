#pragma once
// The fixture of the config-file tests: a private directory with one YAML file in it, written
// per test, and the one-line error a loader gives for it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/input_error.hpp"

namespace cosmos::testing {

class ConfigFileTest : public ::testing::Test {
 protected:
  explicit ConfigFileTest(std::string file_name = "cell.yaml") : file_name_(std::move(file_name)) {}

  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           ("cosmos_config_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
            std::to_string(::getpid()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path path() const { return dir_ / file_name_; }

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

  std::filesystem::path dir_;

 private:
  std::string file_name_;
};

}  // namespace cosmos::testing
