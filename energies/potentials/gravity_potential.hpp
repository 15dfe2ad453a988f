#pragma once
#include "sinew/energies/potentials/potential.hpp"

#include <Eigen/Core>

namespace sinew {

/// The potential of gravity on lumped node masses (lumped_mass.hpp):
///     E(x) = −Σ_i m_i g·x_i,   ∇_{x_i} E = −m_i g,   ∇²E = 0,
/// g the acceleration of gravity (m/s², e.g. (0, 0, −9.81)).
class GravityPotential final : public Potential {
public:
    /// `node_masses` one per node (kg); `gravity` has `dimension` entries.
    /// InputError for a negative or non-finite mass, or a gravity vector of
    /// the wrong size or non-finite.
    GravityPotential(int dimension, Eigen::VectorXd node_masses, Eigen::VectorXd gravity);

    std::string name() const override { return "gravity"; }
    int dimension() const override { return dimension_; }
    int num_nodes() const override { return static_cast<int>(masses_.size()); }
    double value(ConstVectorRef x) override;
    void add_gradient(ConstVectorRef x, VectorRef gradient) override;
    /// None: the potential is linear.
    const Stencils& hessian_stencils() const override { return no_stencils_; }
    void add_hessian(ConstVectorRef, Projection, const StencilSlots&, VectorRef) override {}

    const Eigen::VectorXd& masses() const { return masses_; }
    /// Multiplies g by s (load stepping; 1 = as given). InputError when s is
    /// not finite.
    void set_scale(double s);

private:
    int dimension_;
    Eigen::VectorXd masses_;
    Eigen::VectorXd gravity_;
    double scale_ = 1.0;
    Stencils no_stencils_;
};

} // namespace sinew
