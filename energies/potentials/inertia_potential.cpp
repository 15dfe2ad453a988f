#include "sinew/energies/potentials/inertia_potential.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"

#include <cmath>
#include <limits>

namespace sinew {

InertiaPotential::InertiaPotential(std::string name, int dimension, Eigen::VectorXd node_masses)
    : name_(std::move(name)), dimension_(dimension), masses_(std::move(node_masses))
{
    if (dimension_ != 2 && dimension_ != 3)
        throw InputError(name_ + ": dimension " + std::to_string(dimension_) + " is not 2 or 3");
    for (Eigen::Index i = 0; i < masses_.size(); ++i)
        if (!(std::isfinite(masses_[i]) && masses_[i] >= 0.0))
            throw InputError(name_ + ": mass of node " + std::to_string(i) + " is " + format_number(masses_[i]) +
                             ", expected finite and >= 0");
    center_ = Eigen::VectorXd::Zero(num_coordinates());
    nodes_.resize(1, masses_.size());
    for (int i = 0; i < num_nodes(); ++i)
        nodes_(0, i) = i;
}

void InertiaPotential::set_step(Eigen::VectorXd center, double scaling)
{
    if (center.size() != num_coordinates() || !center.allFinite())
        throw InputError(name_ + ": the step's centre has " + std::to_string(center.size()) +
                         " entries or is not finite; expected " + std::to_string(num_coordinates()) + " finite");
    if (!(std::isfinite(scaling) && scaling > 0.0))
        throw InputError(name_ + ": scaling " + format_number(scaling) + " must be finite and > 0");
    center_ = std::move(center);
    scaling_ = scaling;
}

double InertiaPotential::value(ConstVectorRef y)
{
    double sum = 0.0;  // Σ m_i ‖y_i − z_i‖²
    for (int i = 0; i < num_nodes(); ++i)
        sum += masses_[i] * (y.segment(i * dimension_, dimension_) - center_.segment(i * dimension_, dimension_))
                                .squaredNorm();
    const double energy = 0.5 * sum / scaling_;
    return std::isfinite(energy) ? energy : std::numeric_limits<double>::infinity();
}

void InertiaPotential::add_gradient(ConstVectorRef y, VectorRef gradient)
{
    for (int i = 0; i < num_nodes(); ++i) {
        const int first = i * dimension_;
        gradient.segment(first, dimension_) +=
            (masses_[i] / scaling_) * (y.segment(first, dimension_) - center_.segment(first, dimension_));
    }
}

void InertiaPotential::add_hessian(ConstVectorRef, Projection, const StencilSlots& slots, VectorRef values)
{
    // (m_i/s) I per node: the lower triangle's diagonal entries of each stencil.
    for (int i = 0; i < num_nodes(); ++i) {
        int k = 0;
        for (int q = 0; q < dimension_; ++q) {
            values[slots(k, i)] += masses_[i] / scaling_;
            k += dimension_ - q;
        }
    }
}

} // namespace sinew
