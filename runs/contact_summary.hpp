#pragma once
#include "sinew/energies/output_arrays.hpp"

#include <Eigen/Core>
#include <nlohmann/json.hpp>

namespace sinew {

/// What contact with rigid bodies amounts to at a solution, read from the
/// "contact_force" and "penetration" point arrays that penalty potentials
/// and gap constraint sets write (docs/contact.md), so that it serves both
/// formulations alike.
struct ContactSummary {
    bool present = false;                             ///< the scene has contact terms
    Eigen::Vector3d force = Eigen::Vector3d::Zero();  ///< F = Σ_i f_i, the bodies' push on the mesh, N
    double max_penetration = 0.0;                     ///< the deepest colliding node, m
    int contact_nodes = 0;                            ///< nodes with f_i ≠ 0
    /// a = √(5/2 · Σ|f_i| r_i² / Σ|f_i|), r_i the distance of node i from the
    /// force-weighted centre, in the plane normal to F: for Hertz's pressure
    /// p ∝ √(1 − r²/a²) the second moment is exactly 2a²/5, so a converges
    /// with the mesh instead of jumping from node ring to node ring. m.
    double contact_radius = 0.0;
};

/// The summary of `arrays` with node positions `positions` (dimension × n).
ContactSummary contact_summary(const OutputArrays& arrays, const Eigen::MatrixXd& positions);

/// {"force": [...], "max_penetration", "contact_nodes", "contact_radius"}.
nlohmann::json to_json(const ContactSummary& summary);

} // namespace sinew
