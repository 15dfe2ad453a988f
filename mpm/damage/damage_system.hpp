#pragma once
// The implicit damage step's linear system on the damage grid (seed 004
// Alg. 9, §2.2).
#include "sinew/mpm/damage/damage_grid.hpp"
#include "sinew/mpm/particles.hpp"

#include <Eigen/Core>

#include <vector>

namespace sinew {

/// (A + B) d = c over the damage grid's slots, from the backward-Euler step
/// of ηḋ = (1 − d)D̃ − (d − l₀²Δd) in weak form (seed 004 §2.2, Alg. 9), with
/// V_p = V_p⁰ det F_p the particle's current volume and τ_p = Δt/η_p:
///   c_i  = Σ_p V_p (τ_p D̃_p + d_iⁿ) w_ip
///   A_ii = Σ_p V_p (1 + τ_p (D̃_p + 1)) w_ip           (lumped, diagonal)
///   B_ij = Σ_p V_p τ_p l₀,p² ∇w_ip · ∇w_jp            (the discrete Laplacian)
/// with cubic B-spline weights. A + B is symmetric, positive on every slot
/// some particle weighs (A_ii > 0 there), B·1 = 0. The particles' stencils
/// are kept, so a product costs one pass over them.
template <int Dim>
class DamageSystem {
public:
    using Vector = Eigen::Matrix<double, Dim, 1>;

    /// `driving` holds D̃_p by particle; `grid` the field damage_to_grid
    /// left (dⁿ on the nodes).
    DamageSystem(const Particles<Dim>& particles, const std::vector<double>& driving, double dt,
                 const DamageGrid<Dim>& grid);

    int size() const { return static_cast<int>(rhs_.size()); }
    /// out = (A + B) d.
    void multiply(const Eigen::VectorXd& d, Eigen::VectorXd& out) const;
    const Eigen::VectorXd& rhs() const { return rhs_; }
    /// A's diagonal: the seed's Jacobi preconditioner.
    const Eigen::VectorXd& lumped_diagonal() const { return lumped_; }
    /// diag(A + B).
    const Eigen::VectorXd& full_diagonal() const { return full_; }

private:
    static constexpr int kNodes = Dim == 2 ? 16 : 64;  ///< nodes of a cubic stencil
    std::vector<int> slot_;        ///< by particle, kNodes each
    std::vector<Vector> gradient_;  ///< ∇w_ip, the same layout
    std::vector<double> diffusion_;  ///< V_p τ_p l₀,p² by particle
    Eigen::VectorXd rhs_, lumped_, full_;
};

} // namespace sinew
