#pragma once
#include "sinew/energies/potentials/potential.hpp"

#include <Eigen/Core>

namespace sinew {

/// The inertia term of a time step (DESIGN.md "Time: a step is an NLP"), on
/// lumped node masses m_i (lumped_mass.hpp):
///
///     E(y) = Σ_i m_i ‖y_i − z_i‖² / (2s),   ∇E = m_i (y_i − z_i)/s,   ∇²E = (m_i/s) I,
///
/// with z = x̃ the integrator's predictor and s = c·h² its force scaling.
/// Mass-proportional Rayleigh damping αM has the same form: with the step's
/// velocity v(y) = v̄ + g(y − x̃), vᵀ(αM)v/(2g) = Σ m_i‖y_i − z_i‖²/(2s) with
/// z = x̃ − v̄/g and s = 1/(αg), so a second instance carries it.
/// Until set_step is called, z = 0 and s = 1.
class InertiaPotential final : public Potential {
public:
    /// `name` says which term this is ("inertia", "mass damping"). InputError
    /// for a negative or non-finite mass.
    InertiaPotential(std::string name, int dimension, Eigen::VectorXd node_masses);

    std::string name() const override { return name_; }
    int dimension() const override { return dimension_; }
    int num_nodes() const override { return static_cast<int>(masses_.size()); }
    double value(ConstVectorRef y) override;
    void add_gradient(ConstVectorRef y, VectorRef gradient) override;
    /// One stencil per node: the Hessian is diagonal.
    const Stencils& hessian_stencils() const override { return nodes_; }
    void add_hessian(ConstVectorRef y, Projection projection, const StencilSlots& slots, VectorRef values) override;

    /// z and s for the next step. InputError for a z of the wrong size or
    /// not finite, or an s that is not finite and > 0.
    void set_step(Eigen::VectorXd center, double scaling);
    const Eigen::VectorXd& masses() const { return masses_; }

private:
    std::string name_;
    int dimension_;
    Eigen::VectorXd masses_;
    Eigen::VectorXd center_;  ///< z
    double scaling_ = 1.0;    ///< s
    Stencils nodes_;
};

} // namespace sinew
