#pragma once
#include "sinew/mpm/node_velocity_frame.hpp"
#include "sinew/mpm/particles.hpp"
#include "sinew/mpm/sparse_grid.hpp"
#include "sinew/mpm/step_settings.hpp"

#include <Eigen/Core>

#include <vector>

namespace sinew {

/// The unknowns of a step's grid velocities and how the particles see them,
/// shared by the implicit step's NLP, the inextensibility's rows and its
/// Schur-complement projection:
///
/// - the nodes with mass, in slot order, each with m_i, its predictor v*_i
///   and its NodeVelocityFrame (the walls and colliders decided at v*):
///   v_i = offset_i + B_i y_i, the y_i stacked node after node (none for a
///   node held at v_b);
/// - per particle, the nodes of its stencil with b_ip = F_pⁿᵀ q_ip, q_ip =
///   w_ip D_p⁻¹ (x_i − x_p) the MLS weight gradient, so that a step to the
///   velocities v gives F_p(v) = Fⁿ + Δt Σ_i v_i b_ipᵀ (the F that
///   grid_to_particles and the advection then give the particle) and the
///   particle's velocity gradient C_p = Σ_i v_i q_ipᵀ.
template <int Dim>
class GridVelocityMap {
public:
    using NodeVector = Eigen::Matrix<double, Dim, 1>;
    using Index = typename SparseGrid<Dim>::Index;

    /// Where v* comes from: the implicit step's (m v)_i/m_i + Δt g, after
    /// particles_to_grid; or the explicit step's grid velocity after its
    /// grid update (forces and gravity included).
    enum class Predictor { momentum_and_gravity, grid_velocity };

    /// A node particle p reaches: its index among the nodes with mass (−1 without) and b_ip.
    struct Coupling {
        int node = -1;
        NodeVector b = NodeVector::Zero();
    };

    /// Every particle must lie where its stencil's nodes exist in `grid`
    /// (InputError otherwise, as checked_stencil says).
    GridVelocityMap(const Particles<Dim>& particles, const SparseGrid<Dim>& grid, const MpmStepSettings<Dim>& settings,
                    Predictor predictor);

    int nodes() const { return static_cast<int>(slot_.size()); }
    int variables() const { return variables_; }
    int slot(int node) const { return slot_[static_cast<std::size_t>(node)]; }
    const Index& index(int node) const { return index_[static_cast<std::size_t>(node)]; }
    double mass(int node) const { return mass_[static_cast<std::size_t>(node)]; }
    const NodeVector& target(int node) const { return target_[static_cast<std::size_t>(node)]; }
    const NodeVelocityFrame<Dim>& frame(int node) const { return frames_[static_cast<std::size_t>(node)]; }
    int first_variable(int node) const { return first_variable_[static_cast<std::size_t>(node)]; }
    int free_components(int node) const { return static_cast<int>(frame(node).basis.cols()); }

    /// Nodes a particle's stencil reaches: width^Dim.
    int stencil_nodes() const { return stencil_nodes_; }
    /// Particle p's stencil_nodes() couplings.
    const Coupling* couplings(int particle) const
    {
        return &couplings_[static_cast<std::size_t>(particle) * static_cast<std::size_t>(stencil_nodes_)];
    }

    /// v_k = offset_k + B_k y_k, node k's velocity at y.
    NodeVector velocity(int node, const Eigen::Ref<const Eigen::VectorXd>& y) const;
    /// y at v*, each node's predictor projected into its frame.
    Eigen::VectorXd predictor() const;
    /// The mass of each unknown: m_i for each of node i's free components
    /// (the bases are orthonormal, so the kinetic metric in y is M̃ = diag(m)).
    Eigen::VectorXd variable_masses() const;
    /// grid.velocity ← v(y) at every node with mass.
    void write_velocities(const Eigen::Ref<const Eigen::VectorXd>& y, SparseGrid<Dim>& grid) const;

private:
    void build_nodes(const SparseGrid<Dim>& grid, const MpmStepSettings<Dim>& settings, Predictor predictor);
    void build_couplings(const Particles<Dim>& particles, const SparseGrid<Dim>& grid, SplineOrder order);

    int variables_ = 0;
    int stencil_nodes_ = 0;
    std::vector<int> slot_;                       ///< node → grid slot
    std::vector<Index> index_;                    ///< node → grid index
    std::vector<double> mass_;                    ///< m_i
    std::vector<NodeVector> target_;              ///< v*_i
    std::vector<NodeVelocityFrame<Dim>> frames_;  ///< v_i = offset + B y_i
    std::vector<int> first_variable_;             ///< node → index of y_i's first entry
    std::vector<Coupling> couplings_;             ///< particle p's at [p·stencil_nodes, (p + 1)·stencil_nodes)
};

} // namespace sinew
