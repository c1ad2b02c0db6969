// Deriving the D-H table from link frames: the paper's TABLE command. The
// table is never typed in; it follows from the x and z axes the description
// gives for every link at the home position.
#pragma once

#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "model/kinematics/dh.h"
#include "model/kinematics/error.h"

namespace rs::kinematics {

/// The D-H table of a chain from its home frames F_0..F_n (all in the same
/// coordinates, orthonormal, e.g. from frameFromPoints) and the types of
/// joints 1..n: for each joint θ (home), α, a, d (home).
///
/// Frame i must obey the D-H rules with respect to frame i-1: x_i is
/// perpendicular to z_{i-1} (|cos| ≤ tol.cosine) and meets it (the lines
/// pass within tol.distance). Every broken rule is reported, one error per
/// frame, with the frame's number as `index`; a wrong number of frames is a
/// CountMismatch with index -1.
///
/// Parallel z axes: the frames as given decide. D-H leaves the common normal
/// of parallel z_{i-1} and z_i free to slide along the axes; here nothing is
/// chosen, because the description's x_i is that normal: d_i is measured
/// from o_{i-1} to the point where x_i meets z_{i-1}. (The conventional
/// frame choice, used by the library robots, puts x_i level with o_{i-1},
/// so d_i = 0.) Intersecting axes give a_i = 0, coincident ones a_i = 0 and
/// α_i = 0 or 180. Values within 1e-12 of zero come back as exactly 0.
Built<std::vector<DhRow>> deriveDh(std::span<const Eigen::Isometry3d> frames, std::span<const JointType> types,
                                    const Tolerances& tol = {});

}  // namespace rs::kinematics
