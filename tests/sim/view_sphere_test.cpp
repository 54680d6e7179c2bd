// The model base's view sphere (thesis §4.5): 320 directions from the twice-subdivided
// icosahedron that cover the sphere, and the rotation that presents a direction to the scanner.
#include "sim/view_sphere.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <random>

namespace cosmos {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b)) * kDegPerRad;
}

TEST(ViewSphere, HasThe320UnitDirectionsOfTheThesis) {
  const auto directions = view_directions();
  ASSERT_EQ(directions.size(), 320u);
  for (const auto& direction : directions) EXPECT_NEAR(direction.norm(), 1.0, 1e-12);
  EXPECT_EQ(view_directions(0).size(), 20u);
  EXPECT_EQ(view_directions(1).size(), 80u);
  EXPECT_EQ(view_directions(3).size(), 1280u);
}

TEST(ViewSphere, DirectionsAreDistinctAndBalanced) {
  const auto directions = view_directions();
  double min_separation_deg = 180.0;
  for (std::size_t i = 0; i < directions.size(); ++i) {
    for (std::size_t j = i + 1; j < directions.size(); ++j) {
      min_separation_deg = std::min(min_separation_deg, angle_deg(directions[i], directions[j]));
    }
  }
  std::cout << "[ measured ] smallest angle between two view directions: " << min_separation_deg
            << " deg\n";
  // A quasi-regular tessellation of 4π into 320 cells spaces neighbours about 11° apart.
  EXPECT_GT(min_separation_deg, 7.0);
  // The icosahedron is centrally symmetric, so the directions sum to zero.
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& direction : directions) sum += direction;
  EXPECT_LT(sum.norm(), 1e-9);
}

TEST(ViewSphere, EveryDirectionIsWithin12DegreesOfAView) {
  const auto directions = view_directions();
  std::mt19937 generator(20240615);
  std::normal_distribution<double> gaussian(0.0, 1.0);
  double max_angle_deg = 0.0;
  for (int sample = 0; sample < 10000; ++sample) {
    // Normalised Gaussian vectors are uniform on the sphere.
    const Eigen::Vector3d random =
        Eigen::Vector3d(gaussian(generator), gaussian(generator), gaussian(generator)).normalized();
    double nearest_deg = 180.0;
    for (const auto& direction : directions)
      nearest_deg = std::min(nearest_deg, angle_deg(random, direction));
    max_angle_deg = std::max(max_angle_deg, nearest_deg);
  }
  std::cout << "[ measured ] max angle from 10000 random directions to the nearest view: "
            << max_angle_deg << " deg\n";
  RecordProperty("max_angle_deg", std::to_string(max_angle_deg));
  EXPECT_LT(max_angle_deg, 12.0);
}

TEST(ViewSphere, OrderIsDeterministic) {
  const auto first = view_directions();
  const auto second = view_directions();
  ASSERT_EQ(first.size(), second.size());
  for (std::size_t i = 0; i < first.size(); ++i) EXPECT_EQ(first[i], second[i]) << "view " << i;
  // Children follow their parent face: the first 4 views of level 2 lie around the first
  // view of level 1.
  const auto coarse = view_directions(1);
  for (int child = 0; child < 4; ++child) EXPECT_LT(angle_deg(first[child], coarse[0]), 12.0);
}

TEST(ViewSphere, RotationLooksAlongEveryViewDirection) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  for (const auto& direction : view_directions()) {
    const Eigen::Matrix3d R_scanner_part = rotation_looking_along(direction);
    EXPECT_LT((R_scanner_part * direction - z).norm(), 1e-12);
    EXPECT_LT((R_scanner_part.transpose() * R_scanner_part - Eigen::Matrix3d::Identity()).norm(),
              1e-12);
    EXPECT_NEAR(R_scanner_part.determinant(), 1.0, 1e-12);
    // Shortest arc: the axis perpendicular to both the direction and +z stays where it is.
    const Eigen::Vector3d axis = direction.cross(z);
    if (axis.norm() > 1e-6) {
      EXPECT_LT((R_scanner_part * axis - axis).norm(), 1e-12);
    }
  }
}

TEST(ViewSphere, RotationHandlesPolesAndUnnormalisedDirections) {
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  EXPECT_LT((rotation_looking_along(z) - Eigen::Matrix3d::Identity()).norm(), 1e-15);
  EXPECT_LT((rotation_looking_along(-z) * -z - z).norm(), 1e-12);
  EXPECT_LT((rotation_looking_along(Eigen::Vector3d(0, 1e-14, -1)) * Eigen::Vector3d(0, 0, -1) - z)
                .norm(),
            1e-9);
  const Eigen::Vector3d long_direction(3.0, -4.0, 12.0);  // length 13
  EXPECT_LT((rotation_looking_along(long_direction) * long_direction - 13.0 * z).norm(), 1e-12);
  EXPECT_THROW(rotation_looking_along(Eigen::Vector3d::Zero()), std::invalid_argument);
  EXPECT_THROW(view_directions(-1), std::invalid_argument);
}

}  // namespace
}  // namespace cosmos
