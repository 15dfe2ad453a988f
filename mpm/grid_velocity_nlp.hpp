#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/mpm/grid_velocity_map.hpp"
#include "sinew/mpm/linear_velocity_rows.hpp"
#include "sinew/mpm/particle_buckets.hpp"
#include "sinew/mpm/particles.hpp"
#include "sinew/mpm/sparse_grid.hpp"
#include "sinew/mpm/step_settings.hpp"
#include "sinew/problems/nlp.hpp"

#include <vector>

namespace sinew {

/// The implicit MLS-MPM step as an NLP over the velocities of the grid's
/// nodes with mass (incremental potential; Gast et al. 2015, "Optimization
/// integrator for large time steps", §4; DESIGN.md):
///
///     E(v) = Σ_i ½ m_i ‖v_i − v*_i‖² + Σ_p V_p⁰ ψ_p(F_p(v)),
///     v*_i = (m v)_i / m_i + Δt g,   F_p(v) = (I + Δt Σ_i v_i q_ipᵀ) F_pⁿ,
///
/// q_ip = w_ip D_p⁻¹ (x_i − x_p) the MLS weight gradient, so that F_p(v) is
/// exactly the F that grid_to_particles and the advection then give the
/// particle (C_p = Σ_i v_i q_ipᵀ). With b_ip = F_pⁿᵀ q_ip:
///
///     ∂E/∂v_i = m_i (v_i − v*_i) + Δt Σ_p V_p⁰ P_p b_ip,
///     ∂²E/∂v_i∂v_j = m_i δ_ij I + Δt² Σ_p V_p⁰ J_iᵀ (∂P/∂F)_p J_j,
///
/// J_i the D² × D map of a velocity change at node i to vec(F):
/// J_i(c + D l, c) = b_ip,l. With Projection::clamp each particle's ∂P/∂F is
/// projected (the model's own clamp), so every term and the sum are PSD.
///
/// The walls and colliders of the settings act inside the solve: a node they
/// hold moves in its NodeVelocityFrame, v_i = offset_i + B_i y_i (decided at
/// v*), and the unknowns are the y_i, node after node in slot order (none
/// for a node held at v_b). Derivatives in y: B_iᵀ ∂E/∂v_i and B_iᵀ (∂²E/∂v_i∂v_j) B_j.
/// The nodes, frames and couplings are a GridVelocityMap. Optional linear
/// equality rows B y = rhs (LinearVelocityRows: the grid inextensibility,
/// seed 004 §4) make it a constrained NLP, with a constant Jacobian and no
/// term in the Hessian; kkt-newton, relaxed-kkt, penalty, augmented-lagrangian
/// and Ipopt take it then.
/// Built after particles_to_grid, on the layout it returned; the particles,
/// models, grid and layout must outlive it and stay unchanged. The Hessian
/// is assembled on the layout's buckets, colour by colour (one result
/// whatever the thread count, as the transfers).
template <int Dim>
class GridVelocityNlp : public Nlp {
public:
    using NodeVector = Eigen::Matrix<double, Dim, 1>;
    using Matrix = Eigen::Matrix<double, Dim, Dim>;

    /// Unconstrained, on the map of the implicit step's predictor.
    GridVelocityNlp(const Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                    const SparseGrid<Dim>& grid, const ParticleBuckets<Dim>& layout, const MpmStepSettings<Dim>& settings);
    /// On `map` (built on the same particles and grid), with the equality rows `rows` (in the map's unknowns).
    GridVelocityNlp(const Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                    GridVelocityMap<Dim> map, const ParticleBuckets<Dim>& layout, double time_step,
                    LinearVelocityRows rows = {});

    std::string name() const override { return "mpm-grid-velocities"; }
    int num_variables() const override { return variables_; }
    /// y at v*, each node's predictor projected into its frame.
    Vector starting_point() const override;
    double objective(ConstVectorRef y) override;
    void gradient(ConstVectorRef y, VectorRef grad) override;
    const SparsityPattern& hessian_pattern() const override { return pattern_; }
    bool supports(Projection) const override { return true; }
    int num_constraints() const override { return rows_.rows(); }
    void constraint_bounds(VectorRef lower, VectorRef upper) const override;
    void constraints(ConstVectorRef y, VectorRef c) override;
    const SparsityPattern& jacobian_pattern() const override { return jacobian_pattern_; }
    void jacobian_values(ConstVectorRef y, VectorRef values) override;

    const GridVelocityMap<Dim>& map() const { return map_; }
    const LinearVelocityRows& rows() const { return rows_; }
    /// Nodes with mass.
    int nodes() const { return map_.nodes(); }
    /// The grid slot of node k.
    int slot(int node) const { return map_.slot(node); }
    /// v_k = offset_k + B_k y_k, node k's velocity at y.
    NodeVector velocity(int node, ConstVectorRef y) const { return map_.velocity(node, y); }
    /// F_p at y, the particle's deformation gradient after a step there.
    Matrix deformation(int particle, ConstVectorRef y) const;

protected:
    void hessian_values(ConstVectorRef y, double sigma, ConstVectorRef lambda, VectorRef values) override;
    void projected_hessian_values(ConstVectorRef y, double sigma, ConstVectorRef lambda, VectorRef values) override;

private:
    using Coupling = typename GridVelocityMap<Dim>::Coupling;

    void build_pattern();
    void build_jacobian_pattern();
    int free_components(int node) const { return map_.free_components(node); }
    int table_entry(int a, int b) const;
    /// values += B_aᵀ H_ab B_b into the block of nodes a ≥ b (lower triangle only when a = b).
    void add_block(int a, int b, const Matrix& H_ab, VectorRef values) const;
    void assemble_hessian(ConstVectorRef y, double sigma, Projection projection, VectorRef values);
    /// values += particle p's σ Δt² V_p⁰ J_sᵀ (∂P/∂F) J_t blocks; `lifted` is scratch of stencil_nodes_ entries.
    void add_particle_hessian(int p, double sigma, Projection projection,
                              std::vector<Eigen::Matrix<double, Dim * Dim, Dim>>& lifted, VectorRef values) const;
    /// Every node's velocity at y, into velocities_.
    void update_velocities(ConstVectorRef y);
    Matrix deformation_at_velocities(int particle) const;

    const Particles<Dim>& particles_;
    const std::vector<const ConstitutiveModel<Dim, Dim>*>& models_;
    GridVelocityMap<Dim> map_;
    const ParticleBuckets<Dim>& layout_;
    double time_step_;
    LinearVelocityRows rows_;
    int variables_ = 0;
    int stencil_nodes_ = 0;  ///< nodes a particle reaches: width^Dim
    int offset_width_ = 0;   ///< 2·width − 1: node offsets two particles' stencils can span
    std::vector<NodeVector> velocities_;  ///< scratch: v_i at the last y
    /// Per node a and offset o of node b from a (offset_width^Dim of them):
    /// the first value of block (a, b) for b ≤ a, −1 where no particle couples them.
    std::vector<int> block_table_;
    SparsityPattern pattern_;
    SparsityPattern jacobian_pattern_;  ///< rows_.B's entries, row by row
};

} // namespace sinew
