// The test plan and scans of `cosmos eval` (evaluation_scans.hpp): the pose mode of the plan
// reaches every scan, and a resting scan lies on a stable face where a random one does not.
#include "sim/evaluation/evaluation_scans.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sim/procedural_meshes.hpp"

namespace cosmos {
namespace {

std::vector<EvaluationPart> one_known_box() {
  EvaluationPart box;
  box.name = "box";
  box.catalog_index = 0;
  box.base_index = 0;
  box.mesh = make_box(40.0, 30.0, 20.0);
  box.diameter_mm = std::sqrt(40.0 * 40.0 + 30.0 * 30.0 + 20.0 * 20.0);
  return {box};
}

// The largest |z| of the part's axes in the belt frame: 1 when a box face lies on the belt.
double most_vertical_axis(const RangeImage& image) {
  return image.ground_truth->rotation.row(2).cwiseAbs().maxCoeff();
}

TEST(EvaluationScans, PlanCarriesItsPoseModeAndIsFixedBySeed) {
  const std::vector<EvaluationPart> parts = one_known_box();
  const std::vector<EvaluationTest> random = evaluation_plan(parts, 4, 7);
  const std::vector<EvaluationTest> resting =
      evaluation_plan(parts, 4, 7, EvaluationPoseMode::kResting);
  ASSERT_EQ(random.size(), 4u);
  ASSERT_EQ(resting.size(), 4u);
  for (std::size_t i = 0; i < random.size(); ++i) {
    EXPECT_EQ(random[i].pose, EvaluationPoseMode::kRandom);
    EXPECT_EQ(resting[i].pose, EvaluationPoseMode::kResting);
    EXPECT_EQ(random[i].seed, resting[i].seed);
    EXPECT_EQ(random[i].index, static_cast<int>(i));
  }
}

TEST(EvaluationScans, RestingScansLieOnAFaceAndRandomOnesDoNot) {
  const std::vector<EvaluationPart> parts = one_known_box();
  ScannerParameters scanner;
  scanner.z_noise_mm = 0.0;
  const ConditioningParameters conditioning;
  const int kTests = 6;
  const std::vector<EvaluationTest> resting =
      evaluation_plan(parts, kTests, 3, EvaluationPoseMode::kResting);
  const std::vector<EvaluationTest> random = evaluation_plan(parts, kTests, 3);
  int random_on_a_face = 0;
  for (int i = 0; i < kTests; ++i) {
    const RangeImage lying = scan_evaluation_test(resting[i], parts, scanner, conditioning);
    ASSERT_TRUE(lying.ground_truth.has_value()) << "test " << i;
    EXPECT_NEAR(most_vertical_axis(lying), 1.0, 1e-9) << "test " << i;
    const RangeImage tumbled = scan_evaluation_test(random[i], parts, scanner, conditioning);
    ASSERT_TRUE(tumbled.ground_truth.has_value()) << "test " << i;
    random_on_a_face += most_vertical_axis(tumbled) > 1.0 - 1e-6 ? 1 : 0;
  }
  EXPECT_EQ(random_on_a_face, 0);
}

}  // namespace
}  // namespace cosmos
