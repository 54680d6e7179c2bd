#pragma once
// Whether a recognized part explains a piece of surface: most of the piece's points lie on
// the part's surface so placed (within the blob loop's explained_distance_mm of its distance
// field). The test by which the piece joiner gives a piece to a part, and by which a leading
// piece that its successor's part explains is not recognized on its own.
#include <Eigen/Core>
#include <vector>

#include "core/rigid_transform.hpp"
#include "realtime/cell/part_recognition.hpp"

namespace cosmos {

struct PartInLoop {
  int part = -1;  // ModelBase::parts index
  RigidTransform T_loop_part;
};

// Half the piece's points on one of the parts' surfaces: that part's.
inline constexpr double kExplainedFraction = 0.5;

bool piece_explained_by(const std::vector<Eigen::Vector3d>& points_loop_mm,
                        const std::vector<PartInLoop>& parts,
                        const PartRecognitionContext& context);

}  // namespace cosmos
