#pragma once
// One part scanned alone: the part turned by R_belt_part, laid with its lowest point on the
// belt, centred across the belt (bounding-box centre at x = y = 0 of the belt frame), scanned
// by the simulated scanner, and returned as a cropped range image (range_image_scan.hpp)
// whose ground truth is T_scanner_part in the image's frame. What `cosmos sim scan` does.
#include <Eigen/Core>
#include <string>

#include "core/range_image.hpp"
#include "scanner/scanner_model.hpp"
#include "sim/mesh.hpp"
#include "sim/range_image_scan.hpp"
#include "sim/simulated_scanner.hpp"

namespace cosmos {

// Empty image (width 0) when the scanner measured nothing of the part.
RangeImage scan_single_part(const TriangleMesh& mesh, const std::string& part_name,
                            const Eigen::Matrix3d& R_belt_part, const ScannerParameters& parameters,
                            const ConditioningParameters& conditioning,
                            ScanMode mode = ScanMode::kProfile,
                            const ProfileObserver& observer = {});

}  // namespace cosmos
