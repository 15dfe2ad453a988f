#include "sinew/energies/constraints/body_gaps.hpp"

#include "sinew/core/input_error.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::vector<int> checked_nodes(std::vector<int> nodes, int num_nodes)
{
    if (nodes.empty()) {
        for (int i = 0; i < num_nodes; ++i)
            nodes.push_back(i);
        return nodes;
    }
    std::vector<char> seen(static_cast<std::size_t>(num_nodes), 0);
    for (int node : nodes) {
        if (node < 0 || node >= num_nodes)
            throw InputError("body gaps: node " + std::to_string(node) + " is outside [0, " +
                             std::to_string(num_nodes) + ")");
        if (seen[node])
            throw InputError("body gaps: node " + std::to_string(node) + " is listed twice");
        seen[node] = 1;
    }
    return nodes;
}

} // namespace

BodyGaps::BodyGaps(int dimension, int num_nodes, std::shared_ptr<const PlacedBody> body,
                   const Eigen::VectorXd& rest_coordinates, std::vector<int> nodes, double length, double margin)
    : dimension_(dimension), num_nodes_(num_nodes), body_(std::move(body)), length_(length), margin_(margin)
{
    if (dimension != 2 && dimension != 3)
        throw InputError("body gaps: dimension " + std::to_string(dimension) + " is not 2 or 3");
    if (!body_)
        throw InputError("body gaps: no body");
    if (body_->dimension() != dimension)
        throw InputError("body gaps: body '" + body_->name() + "' is " + std::to_string(body_->dimension()) +
                         "D, the scene " + std::to_string(dimension) + "D");
    if (rest_coordinates.size() != static_cast<Eigen::Index>(dimension) * num_nodes || !rest_coordinates.allFinite())
        throw InputError("body gaps: rest coordinates must be " + std::to_string(dimension * num_nodes) +
                         " finite numbers");
    if (!(std::isfinite(length) && length > 0.0))
        throw InputError("body gaps: length scale " + std::to_string(length) + " must be finite and > 0");
    if (!(std::isfinite(margin) && margin >= 0.0))
        throw InputError("body gaps: margin " + std::to_string(margin) + " must be finite and >= 0");
    nodes_ = checked_nodes(std::move(nodes), num_nodes);
    candidates_ = candidates_at(rest_coordinates);
    build_patterns();
}

BodyDistance BodyGaps::at_node(ConstVectorRef x, int node) const
{
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    p.head(dimension_) = x.segment(dimension_ * node, dimension_);
    return body_->distance(p);
}

std::vector<int> BodyGaps::candidates_at(ConstVectorRef x) const
{
    std::vector<int> chosen;
    for (int node : nodes_)
        if (at_node(x, node).distance < margin_)
            chosen.push_back(node);
    return chosen;
}

bool BodyGaps::refresh(ConstVectorRef x)
{
    std::vector<int> chosen = candidates_at(x);
    if (chosen == candidates_)
        return false;
    candidates_ = std::move(chosen);
    build_patterns();
    return true;
}

bool BodyGaps::rows_suffice(ConstVectorRef x) const
{
    std::vector<char> candidate(static_cast<std::size_t>(num_nodes_), 0);
    for (int node : candidates_)
        candidate[node] = 1;
    for (int node : nodes_)
        if (!candidate[node] && at_node(x, node).distance < 0.0)
            return false;
    return true;
}

void BodyGaps::build_patterns()
{
    jacobian_ = SparsityPattern();
    hessian_ = SparsityPattern();
    for (int row = 0; row < num_constraints(); ++row) {
        const int first = dimension_ * candidates_[row];
        for (int m = 0; m < dimension_; ++m)
            jacobian_.add(row, first + m);
        for (int q = 0; q < dimension_; ++q)  // lower triangle of the node's block, column by column
            for (int p = q; p < dimension_; ++p)
                hessian_.add(first + p, first + q);
    }
}

void BodyGaps::bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setConstant(kInfinity);
}

void BodyGaps::values(ConstVectorRef x, VectorRef c)
{
    for (int row = 0; row < num_constraints(); ++row)
        c[row] = at_node(x, candidates_[row]).distance / length_;  // φ(x_i)/L
}

void BodyGaps::jacobian_values(ConstVectorRef x, VectorRef values)
{
    for (int row = 0; row < num_constraints(); ++row)
        values.segment(dimension_ * row, dimension_) =
            at_node(x, candidates_[row]).gradient.head(dimension_) / length_;  // ∇φ/L
}

void BodyGaps::hessian_values(ConstVectorRef x, ConstVectorRef lambda, Projection projection, VectorRef values)
{
    const int per_row = dimension_ * (dimension_ + 1) / 2;
    for (int row = 0; row < num_constraints(); ++row) {
        Eigen::Matrix3d term = lambda[row] / length_ * at_node(x, candidates_[row]).hessian;  // λ_i∇²φ/L
        if (projection == Projection::clamp) {
            const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(term);
            term = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() *
                   eigen.eigenvectors().transpose();
        }
        int k = per_row * row;
        for (int q = 0; q < dimension_; ++q)
            for (int p = q; p < dimension_; ++p)
                values[k++] = term(p, q);
    }
}

double BodyGaps::max_penetration(ConstVectorRef x) const
{
    double deepest = 0.0;
    for (int node : nodes_)
        deepest = std::max(deepest, -at_node(x, node).distance);
    return deepest;
}

Eigen::Vector3d BodyGaps::total_force(ConstVectorRef x, ConstVectorRef multipliers) const
{
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    if (multipliers.size() != num_constraints())
        return force;
    for (int row = 0; row < num_constraints(); ++row)
        force -= multipliers[row] / length_ * at_node(x, candidates_[row]).gradient;  // −λ_i∇φ/L
    return force;
}

void BodyGaps::add_output_data(ConstVectorRef x, ConstVectorRef multipliers, OutputArrays& arrays)
{
    Eigen::MatrixXd& gap = arrays.point_array("gap", 1, 0.0);
    for (int node = 0; node < num_nodes_; ++node)
        gap(0, node) = at_node(x, node).distance;
    Eigen::MatrixXd& depth = arrays.point_array("penetration", 1, 0.0);
    for (int node : nodes_)
        depth(0, node) = std::max(depth(0, node), -gap(0, node));
    if (multipliers.size() != num_constraints())
        return;
    Eigen::MatrixXd& force = arrays.point_array("contact_force", 3, 0.0);
    for (int row = 0; row < num_constraints(); ++row) {
        const int node = candidates_[row];
        force.col(node) -= multipliers[row] / length_ * at_node(x, node).gradient;
    }
}

} // namespace sinew
