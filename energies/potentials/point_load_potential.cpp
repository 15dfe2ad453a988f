#include "sinew/energies/potentials/point_load_potential.hpp"

#include "sinew/core/input_error.hpp"

#include <cmath>
#include <limits>

namespace sinew {

PointLoadPotential::PointLoadPotential(int dimension, int num_nodes, std::vector<int> nodes, Eigen::MatrixXd forces)
    : dimension_(dimension), num_nodes_(num_nodes), nodes_(std::move(nodes)), forces_(std::move(forces)),
      scales_(Eigen::VectorXd::Ones(static_cast<Eigen::Index>(nodes_.size()))), no_stencils_(1, 0)
{
    if (dimension_ < 1 || num_nodes_ < 0)
        throw InputError("point loads: dimension " + std::to_string(dimension_) + " and node count " +
                         std::to_string(num_nodes_) + " are not valid");
    if (forces_.rows() != dimension_ || forces_.cols() != static_cast<Eigen::Index>(nodes_.size()))
        throw InputError("point loads: forces are " + std::to_string(forces_.rows()) + "x" +
                         std::to_string(forces_.cols()) + ", expected " + std::to_string(dimension_) + "x" +
                         std::to_string(nodes_.size()) + " (one column per loaded node)");
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        if (nodes_[k] < 0 || nodes_[k] >= num_nodes_)
            throw InputError("point loads: load " + std::to_string(k) + " is on node " + std::to_string(nodes_[k]) +
                             ", outside [0, " + std::to_string(num_nodes_) + ")");
        if (!forces_.col(static_cast<Eigen::Index>(k)).allFinite())
            throw InputError("point loads: force of load " + std::to_string(k) + " (node " +
                             std::to_string(nodes_[k]) + ") is not finite");
    }
}

double PointLoadPotential::value(ConstVectorRef x)
{
    double sum = 0.0;  // −Σ_k s_k f_k·x_{n_k}
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const auto load = static_cast<Eigen::Index>(k);
        sum -= scales_[load] * forces_.col(load).dot(x.segment(nodes_[k] * dimension_, dimension_));
    }
    return std::isfinite(sum) ? sum : std::numeric_limits<double>::infinity();
}

void PointLoadPotential::add_gradient(ConstVectorRef, VectorRef gradient)
{
    for (std::size_t k = 0; k < nodes_.size(); ++k) {
        const auto load = static_cast<Eigen::Index>(k);
        gradient.segment(nodes_[k] * dimension_, dimension_) -= scales_[load] * forces_.col(load);
    }
}

void PointLoadPotential::set_scale(double scale) { set_scale(scale, 0, static_cast<int>(nodes_.size())); }

void PointLoadPotential::set_scale(double scale, int first, int count)
{
    if (!std::isfinite(scale))
        throw InputError("point loads: scale is not finite");
    if (first < 0 || count < 0 || first + static_cast<long long>(count) > static_cast<long long>(nodes_.size()))
        throw InputError("point loads: loads [" + std::to_string(first) + ", " + std::to_string(first + count) +
                         ") are outside the " + std::to_string(nodes_.size()) + " loads");
    scales_.segment(first, count).setConstant(scale);
}

} // namespace sinew
