#pragma once
#include "sinew/energies/potentials/potential.hpp"

#include <Eigen/Core>

#include <vector>

namespace sinew {

/// Constant (dead) forces f_k on nodes n_k:
///     E(x) = −Σ_k f_k·x_{n_k},   ∇_{x_i} E = −Σ_{k: n_k = i} f_k,   ∇²E = 0.
/// A node may carry several loads; they add.
class PointLoadPotential final : public Potential {
public:
    /// `forces` is dimension × nodes.size() (N). InputError for a node
    /// outside [0, num_nodes), a size mismatch or a non-finite force.
    PointLoadPotential(int dimension, int num_nodes, std::vector<int> nodes, Eigen::MatrixXd forces);

    std::string name() const override { return "point loads"; }
    int dimension() const override { return dimension_; }
    int num_nodes() const override { return num_nodes_; }
    double value(ConstVectorRef x) override;
    void add_gradient(ConstVectorRef x, VectorRef gradient) override;
    /// None: the potential is linear.
    const Stencils& hessian_stencils() const override { return no_stencils_; }
    void add_hessian(ConstVectorRef, Projection, const StencilSlots&, VectorRef) override {}
    /// Multiplies every force by s (load stepping; 1 = as given). InputError
    /// when s is not finite.
    void set_scale(double s);
    /// Multiplies the forces of loads [first, first + count) by s, the others
    /// keeping theirs (loads that follow their own curve in time).
    /// InputError when s is not finite or the range is outside the loads.
    void set_scale(double s, int first, int count);

private:
    int dimension_;
    int num_nodes_;
    std::vector<int> nodes_;
    Eigen::MatrixXd forces_;
    Eigen::VectorXd scales_;  ///< one per load, 1 = as given
    Stencils no_stencils_;
};

} // namespace sinew
