#include "sinew/energies/potentials/stiffness_damping_potential.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"

#include <cmath>
#include <limits>

namespace sinew {

StiffnessDampingPotential::StiffnessDampingPotential(std::shared_ptr<Potential> stiffness, double beta)
    : stiffness_(std::move(stiffness)), beta_(beta)
{
    if (!stiffness_)
        throw InputError("stiffness damping: no potential to take K from");
    if (!(std::isfinite(beta_) && beta_ >= 0.0))
        throw InputError("stiffness damping: beta " + format_number(beta_) + " must be finite and >= 0");
    const Stencils& stencils = stiffness_->hessian_stencils();
    local_size_ = dimension() * static_cast<int>(stencils.rows());
    if (local_size_ > 12)
        throw InputError("stiffness damping: stencils of " + std::to_string(stencils.rows()) + " nodes are not supported");
    lower_entries_ = local_size_ * (local_size_ + 1) / 2;
    // Disjoint slots: stiffness_->add_hessian then writes each K_e apart.
    own_slots_.resize(lower_entries_, stencils.cols());
    for (Eigen::Index s = 0; s < stencils.cols(); ++s)
        for (int k = 0; k < lower_entries_; ++k)
            own_slots_(k, s) = static_cast<int>(s) * lower_entries_ + k;
    lower_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(lower_entries_) * stencils.cols());
    velocity_offset_ = predictor_ = Eigen::VectorXd::Zero(num_coordinates());
}

void StiffnessDampingPotential::set_step(const Eigen::VectorXd& start, Eigen::VectorXd velocity_at_predictor,
                                         Eigen::VectorXd predictor, double slope)
{
    const Eigen::Index n = num_coordinates();
    if (start.size() != n || velocity_at_predictor.size() != n || predictor.size() != n || !start.allFinite() ||
        !velocity_at_predictor.allFinite() || !predictor.allFinite())
        throw InputError("stiffness damping: the step's vectors must have " + std::to_string(n) +
                         " finite entries");
    if (!(std::isfinite(slope) && slope > 0.0))
        throw InputError("stiffness damping: slope " + format_number(slope) + " must be finite and > 0");
    lower_.setZero();
    stiffness_->add_hessian(start, Projection::clamp, own_slots_, lower_);  // K_e(xₙ), PSD
    velocity_offset_ = std::move(velocity_at_predictor);
    predictor_ = std::move(predictor);
    slope_ = slope;
}

StiffnessDampingPotential::LocalMatrix StiffnessDampingPotential::local_stiffness(int s) const
{
    LocalMatrix K(local_size_, local_size_);
    const double* entries = lower_.data() + static_cast<Eigen::Index>(s) * lower_entries_;
    int k = 0;
    for (int q = 0; q < local_size_; ++q)
        for (int p = q; p < local_size_; ++p)
            K(p, q) = K(q, p) = entries[k++];
    return K;
}

Eigen::VectorXd StiffnessDampingPotential::local_velocity(ConstVectorRef y, int s) const
{
    const Stencils& stencils = stiffness_->hessian_stencils();
    const int d = dimension();
    Eigen::VectorXd v(local_size_);
    for (Eigen::Index a = 0; a < stencils.rows(); ++a) {
        const Eigen::Index first = static_cast<Eigen::Index>(stencils(a, s)) * d;
        // v(y) = v̄ + g (y − x̃)
        v.segment(a * d, d) = velocity_offset_.segment(first, d) +
                              slope_ * (y.segment(first, d) - predictor_.segment(first, d));
    }
    return v;
}

double StiffnessDampingPotential::value(ConstVectorRef y)
{
    double sum = 0.0;  // Σ_e v_eᵀ K_e v_e
    for (int s = 0; s < stiffness_->hessian_stencils().cols(); ++s) {
        const Eigen::VectorXd v = local_velocity(y, s);
        sum += v.dot(local_stiffness(s) * v);
    }
    const double energy = beta_ * sum / (2.0 * slope_);
    return std::isfinite(energy) ? energy : std::numeric_limits<double>::infinity();
}

void StiffnessDampingPotential::add_gradient(ConstVectorRef y, VectorRef gradient)
{
    const Stencils& stencils = stiffness_->hessian_stencils();
    const int d = dimension();
    for (int s = 0; s < stencils.cols(); ++s) {
        const Eigen::VectorXd force = beta_ * (local_stiffness(s) * local_velocity(y, s));  // β K_e v_e
        for (Eigen::Index a = 0; a < stencils.rows(); ++a)
            gradient.segment(static_cast<Eigen::Index>(stencils(a, s)) * d, d) += force.segment(a * d, d);
    }
}

void StiffnessDampingPotential::add_hessian(ConstVectorRef, Projection, const StencilSlots& slots, VectorRef values)
{
    // β g K_e, PSD already: the projection changes nothing.
    const double factor = beta_ * slope_;
    for (Eigen::Index s = 0; s < slots.cols(); ++s)
        for (int k = 0; k < lower_entries_; ++k)
            values[slots(k, s)] += factor * lower_[s * lower_entries_ + k];
}

} // namespace sinew
