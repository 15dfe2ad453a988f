#include "sinew/energies/potentials/gravity_potential.hpp"

#include "sinew/core/input_error.hpp"

#include <cmath>
#include <limits>

namespace sinew {

GravityPotential::GravityPotential(int dimension, Eigen::VectorXd node_masses, Eigen::VectorXd gravity)
    : dimension_(dimension), masses_(std::move(node_masses)), gravity_(std::move(gravity)), no_stencils_(1, 0)
{
    if (dimension_ < 1)
        throw InputError("gravity: dimension " + std::to_string(dimension_) + " is not valid");
    if (gravity_.size() != dimension_)
        throw InputError("gravity: the vector g has " + std::to_string(gravity_.size()) + " components, expected " +
                         std::to_string(dimension_));
    if (!gravity_.allFinite())
        throw InputError("gravity: the vector g is not finite");
    for (int i = 0; i < masses_.size(); ++i)
        if (!(std::isfinite(masses_[i]) && masses_[i] >= 0.0))
            throw InputError("gravity: mass of node " + std::to_string(i) + " is " + std::to_string(masses_[i]) +
                             "; it must be finite and >= 0");
}

double GravityPotential::value(ConstVectorRef x)
{
    double sum = 0.0;
    for (int i = 0; i < masses_.size(); ++i)
        sum -= scale_ * masses_[i] * gravity_.dot(x.segment(i * dimension_, dimension_));
    return std::isfinite(sum) ? sum : std::numeric_limits<double>::infinity();
}

void GravityPotential::add_gradient(ConstVectorRef, VectorRef gradient)
{
    for (int i = 0; i < masses_.size(); ++i)
        gradient.segment(i * dimension_, dimension_) -= scale_ * masses_[i] * gravity_;
}

void GravityPotential::set_scale(double scale)
{
    if (!std::isfinite(scale))
        throw InputError("gravity: scale is not finite");
    scale_ = scale;
}

} // namespace sinew
