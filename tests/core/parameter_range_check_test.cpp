// The declared ranges checked on parameters set in code (core/parameter_range_check.hpp): every
// default of the method's structs lies in its own range, and the first field out of range is
// named with its dotted key.
#include "core/parameter_range_check.hpp"

#include <gtest/gtest.h>

#include "core/cosmos_parameters.hpp"
#include "core/modelbase/view_grouping.hpp"
#include "core/recognition/recognizer.hpp"
#include "core/registration/registration_points.hpp"

namespace cosmos {
namespace {

TEST(ParameterRangeCheck, EveryDefaultIsInItsDeclaredRange) {
  EXPECT_EQ(first_out_of_range(CosmosParameters{}, "cosmos"), std::nullopt);
  EXPECT_EQ(first_out_of_range(RecognitionParameters{}, "recognition"), std::nullopt);
  EXPECT_EQ(first_out_of_range(RegistrationPointParameters{}, "registration"), std::nullopt);
  EXPECT_EQ(first_out_of_range(ViewGroupingParameters{}, "grouping"), std::nullopt);
}

TEST(ParameterRangeCheck, NamesTheFirstFieldOutOfRangeWithItsValue) {
  CosmosParameters cosmos;
  cosmos.fit.window_size = 17;
  cosmos.spectrum.bin_width = 0;
  EXPECT_EQ(first_out_of_range(cosmos, "cosmos"),
            "cosmos.fit.window_size: must be in [3, 15], got 17");
  cosmos.fit.window_size = 5;
  EXPECT_EQ(first_out_of_range(cosmos, "cosmos"),
            "cosmos.spectrum.bin_width: must be in (0, 1], got 0");

  RecognitionParameters recognition;
  recognition.search.refinement_gate.min_fraction = 1.5;
  EXPECT_EQ(first_out_of_range(recognition, ""),
            "search.refinement_gate.min_fraction: must be in [0, 1], got 1.5");
}

}  // namespace
}  // namespace cosmos
