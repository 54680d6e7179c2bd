#pragma once
// §6.7.2: an initial T_model_scene from the principal axes of the two views, for when the
// COSMOS match gives none. The eigenvectors of each view's control-point scatter matrix are
// the columns of M_scene and M_model; R = M_model M_scene^-1 and t = centroid_model -
// R centroid_scene. Eigenvectors have no sign, so the four proper rotations that the sign
// choices allow are each scored by one correspondence pass (score_alignment) and the best
// is kept: the thesis leaves that choice open. Good only when the views see most of the same
// surface and its in-plane extent is not round (distinct eigenvalues).
#include <vector>

#include "core/registration/registration_points.hpp"
#include "core/registration/view_registration.hpp"
#include "core/rigid_transform.hpp"

namespace cosmos {

enum class PrincipalAxesStatus { kOk, kTooFewPoints, kAmbiguousAxes };

struct PrincipalAxesEstimate {
  PrincipalAxesStatus status = PrincipalAxesStatus::kTooFewPoints;
  RigidTransform T_model_scene;
  AlignmentScore score;  // of the chosen candidate
  // Smallest relative gap between consecutive eigenvalues over both views: near 0 the axes,
  // hence R, are ill-defined.
  double min_relative_eigenvalue_gap = 0.0;
};

// The four candidates themselves (the sign choices), unscored, for a caller that ranks them
// another way; empty when either view has fewer than 3 points.
std::vector<RigidTransform> principal_axes_candidates(const RegistrationPoints& scene,
                                                      const RegistrationPoints& model);

// ambiguous_axes when the relative gap is below `min_relative_gap` (the estimate is still
// filled in).
PrincipalAxesEstimate estimate_by_principal_axes(const RegistrationPoints& scene,
                                                 const RegistrationPoints& model,
                                                 const RegistrationParameters& parameters,
                                                 double min_relative_gap = 0.05);

}  // namespace cosmos
