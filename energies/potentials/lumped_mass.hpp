#pragma once
#include "sinew/mesh/mesh.hpp"

#include <Eigen/Core>

#include <vector>

namespace sinew {

/// Lumped (diagonal) node masses: each element's mass ρ_g W_e (ρ of its
/// group, W_e its rest measure) split equally among its nodes,
///     m_i = Σ_{e ∋ i} ρ_g(e) W_e / (nodes per element).
/// Densities are per unit rest measure: kg/m³ for tets, kg/m² for triangles
/// (2D plates of unit thickness, membranes). Summed in element order.
///
/// InputError for inconsistent mesh arrays, a degenerate element, a density
/// count that differs from the number of groups (max group index + 1, or the
/// number of group names), or a negative or non-finite density.
Eigen::VectorXd lumped_masses(const Mesh& mesh, const std::vector<double>& group_densities);

} // namespace sinew
