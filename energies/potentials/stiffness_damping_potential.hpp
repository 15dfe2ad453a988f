#pragma once
#include "sinew/energies/potentials/potential.hpp"

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace sinew {

/// Stiffness-proportional Rayleigh damping βK as a dissipation potential of
/// a time step. With the step's velocity v(y) = v̄ + g(y − x̃) (affine in y,
/// from the integrator) and K = Σ_e K_e the PSD-projected Hessian of
/// `stiffness` frozen at the step's start xₙ:
///
///     Ψ(y) = β vᵀ K v / (2g),   ∇Ψ = β K v,   ∇²Ψ = β g K,
///
/// so the step's stationarity carries the damping force −βK v, and Ψ ≥ 0.
/// The stencils are those of `stiffness` (its elements); each element's
/// local K_e is kept from set_step.
class StiffnessDampingPotential final : public Potential {
public:
    /// InputError for a null potential or β not finite and >= 0.
    StiffnessDampingPotential(std::shared_ptr<Potential> stiffness, double beta);

    std::string name() const override { return "stiffness damping"; }
    int dimension() const override { return stiffness_->dimension(); }
    int num_nodes() const override { return stiffness_->num_nodes(); }
    double value(ConstVectorRef y) override;
    void add_gradient(ConstVectorRef y, VectorRef gradient) override;
    const Stencils& hessian_stencils() const override { return stiffness_->hessian_stencils(); }
    void add_hessian(ConstVectorRef y, Projection projection, const StencilSlots& slots, VectorRef values) override;

    /// Freezes K at `start` (xₙ) and sets v(y) = `velocity_at_predictor` +
    /// `slope`·(y − `predictor`). InputError for sizes or values that are
    /// not finite, or a slope that is not > 0.
    void set_step(const Eigen::VectorXd& start, Eigen::VectorXd velocity_at_predictor, Eigen::VectorXd predictor,
                  double slope);

private:
    using LocalMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 12, 12>;
    /// K_e of stencil s, unpacked from the kept lower triangle.
    LocalMatrix local_stiffness(int s) const;
    /// v(y) on the coordinates of stencil s.
    Eigen::VectorXd local_velocity(ConstVectorRef y, int s) const;

    std::shared_ptr<Potential> stiffness_;
    double beta_;
    int local_size_;     ///< n = dimension × nodes per stencil
    int lower_entries_;  ///< n(n+1)/2
    StencilSlots own_slots_;      ///< each stencil's entries in its own block of lower_
    Eigen::VectorXd lower_;       ///< the K_e, lower triangles, stencil by stencil
    Eigen::VectorXd velocity_offset_, predictor_;
    double slope_ = 1.0;
};

} // namespace sinew
