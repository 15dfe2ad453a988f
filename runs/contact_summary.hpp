#pragma once
#include "sinew/energies/output_arrays.hpp"

#include <Eigen/Core>

namespace sinew {

/// What contact with rigid bodies amounts to at a solution, read from the
/// "contact_force" and "penetration" point arrays that penalty potentials
/// and gap constraint sets write (docs/contact.md), so that it serves both
/// formulations alike.
/// A node is in contact when its force exceeds this fraction of the largest.
inline constexpr double kContactNodeFraction = 1e-6;

struct ContactSummary {
    bool present = false;                             ///< the scene has contact terms
    Eigen::Vector3d force = Eigen::Vector3d::Zero();  ///< F = Σ_i f_i, the bodies' push on the mesh, N
    double max_penetration = 0.0;                     ///< the deepest colliding node, m
    /// nodes carrying more than kContactNodeFraction of the largest |f_i|
    /// (an interior point's multipliers leave μ/s > 0 on every row)
    int contact_nodes = 0;
    /// a = √(5/2 · Σ|f_i| r_i² / Σ|f_i|), r_i the distance of node i from the
    /// force-weighted centre, in the plane normal to F: for Hertz's pressure
    /// p ∝ √(1 − r²/a²) the second moment is exactly 2a²/5, so a converges
    /// with the mesh instead of jumping from node ring to node ring. m.
    double contact_radius = 0.0;
};

/// The summary of `arrays` with node positions `positions` (dimension × n).
ContactSummary contact_summary(const OutputArrays& arrays, const Eigen::MatrixXd& positions);

} // namespace sinew
