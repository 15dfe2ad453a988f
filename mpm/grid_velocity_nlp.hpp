#pragma once
#include "sinew/energies/models/constitutive_model.hpp"
#include "sinew/mpm/node_velocity_frame.hpp"
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
/// Built after particles_to_grid, on the layout it returned; the particles,
/// models, grid and layout must outlive it and stay unchanged. The Hessian
/// is assembled on the layout's buckets, colour by colour (one result
/// whatever the thread count, as the transfers).
template <int Dim>
class GridVelocityNlp final : public Nlp {
public:
    using NodeVector = Eigen::Matrix<double, Dim, 1>;
    using Matrix = Eigen::Matrix<double, Dim, Dim>;

    GridVelocityNlp(const Particles<Dim>& particles, const std::vector<const ConstitutiveModel<Dim, Dim>*>& models,
                    const SparseGrid<Dim>& grid, const ParticleBuckets<Dim>& layout, const MpmStepSettings<Dim>& settings);

    std::string name() const override { return "mpm-grid-velocities"; }
    int num_variables() const override { return variables_; }
    /// y at v*, each node's predictor projected into its frame.
    Vector starting_point() const override;
    double objective(ConstVectorRef y) override;
    void gradient(ConstVectorRef y, VectorRef grad) override;
    const SparsityPattern& hessian_pattern() const override { return pattern_; }
    bool supports(Projection) const override { return true; }

    /// Nodes with mass.
    int nodes() const { return static_cast<int>(node_slot_.size()); }
    /// The grid slot of node k.
    int slot(int node) const { return node_slot_[static_cast<std::size_t>(node)]; }
    /// v_k = offset_k + B_k y_k, node k's velocity at y.
    NodeVector velocity(int node, ConstVectorRef y) const;
    /// F_p at y, the particle's deformation gradient after a step there.
    Matrix deformation(int particle, ConstVectorRef y) const;

protected:
    void hessian_values(ConstVectorRef y, double sigma, ConstVectorRef lambda, VectorRef values) override;
    void projected_hessian_values(ConstVectorRef y, double sigma, ConstVectorRef lambda, VectorRef values) override;

private:
    /// A node particle p reaches: its index among the nodes with mass (−1 without) and b_ip = F_pⁿᵀ q_ip.
    struct Coupling {
        int node = -1;
        NodeVector b = NodeVector::Zero();
    };

    void build_nodes(const SparseGrid<Dim>& grid, const MpmStepSettings<Dim>& settings);
    void build_couplings(const SparseGrid<Dim>& grid, SplineOrder order);
    void build_pattern();
    int free_components(int node) const { return static_cast<int>(frames_[static_cast<std::size_t>(node)].basis.cols()); }
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
    const ParticleBuckets<Dim>& layout_;
    double time_step_;
    int variables_ = 0;
    int stencil_nodes_ = 0;  ///< nodes a particle reaches: width^Dim
    int offset_width_ = 0;   ///< 2·width − 1: node offsets two particles' stencils can span
    std::vector<int> node_slot_;                                ///< node → grid slot
    std::vector<typename SparseGrid<Dim>::Index> node_index_;   ///< node → grid index
    std::vector<double> node_mass_;                             ///< m_i
    std::vector<NodeVector> target_;                            ///< v*_i
    std::vector<NodeVelocityFrame<Dim>> frames_;                ///< v_i = offset + B y_i
    std::vector<int> first_variable_;                           ///< node → index of y_i's first entry
    std::vector<NodeVector> velocities_;                        ///< scratch: v_i at the last y
    std::vector<Coupling> couplings_;  ///< particle p's at [p·stencil_nodes, (p + 1)·stencil_nodes)
    /// Per node a and offset o of node b from a (offset_width^Dim of them):
    /// the first value of block (a, b) for b ≤ a, −1 where no particle couples them.
    std::vector<int> block_table_;
    SparsityPattern pattern_;
};

} // namespace sinew
