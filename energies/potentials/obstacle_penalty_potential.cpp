#include "sinew/energies/potentials/obstacle_penalty_potential.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/potentials/hessian_pattern.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

std::string node_label(int node) { return "obstacle penalty: node " + std::to_string(node); }

Stencils node_stencils(int num_nodes, const std::vector<int>& nodes)
{
    if (nodes.empty()) {
        Stencils all(1, num_nodes);
        for (int i = 0; i < num_nodes; ++i)
            all(0, i) = i;
        return all;
    }
    std::vector<char> seen(static_cast<std::size_t>(num_nodes), 0);
    Stencils listed(1, static_cast<Eigen::Index>(nodes.size()));
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const int node = nodes[k];
        if (node < 0 || node >= num_nodes)
            throw InputError(node_label(node) + " is outside [0, " + std::to_string(num_nodes) + ")");
        if (seen[node])
            throw InputError(node_label(node) + " is listed twice");
        seen[node] = 1;
        listed(0, static_cast<Eigen::Index>(k)) = node;
    }
    return listed;
}

/// The lower triangle of the symmetric `dimension` × `dimension` block of H,
/// with its negative eigenvalues clamped when `clamp`.
void add_block(const Eigen::Matrix3d& H, int dimension, bool clamp, const int* slots, double* values)
{
    if (dimension == 3) {
        Eigen::Matrix3d block = H;
        if (clamp) {
            const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(block);
            block = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() *
                    eigen.eigenvectors().transpose();
        }
        add_lower_triangle(block, slots, values);
    } else {
        Eigen::Matrix2d block = H.topLeftCorner<2, 2>();
        if (clamp) {
            const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(block);
            block = eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() *
                    eigen.eigenvectors().transpose();
        }
        add_lower_triangle(block, slots, values);
    }
}

} // namespace

std::string to_string(ContactCurvature curvature)
{
    return curvature == ContactCurvature::gauss_newton ? "gauss-newton" : "projected";
}

ObstaclePenaltyPotential::ObstaclePenaltyPotential(int dimension, int num_nodes, std::shared_ptr<const PlacedBody> body,
                                                   double stiffness, std::vector<int> nodes,
                                                   ContactCurvature curvature)
    : dimension_(dimension), num_nodes_(num_nodes), body_(std::move(body)), stiffness_(stiffness),
      curvature_(curvature)
{
    if (dimension != 2 && dimension != 3)
        throw InputError("obstacle penalty: dimension " + std::to_string(dimension) + " is not 2 or 3");
    if (num_nodes < 0)
        throw InputError("obstacle penalty: node count " + std::to_string(num_nodes) + " is not valid");
    if (!(std::isfinite(stiffness) && stiffness > 0.0))
        throw InputError("obstacle penalty: stiffness " + std::to_string(stiffness) + " must be finite and > 0");
    if (!body_)
        throw InputError("obstacle penalty: no body");
    if (body_->dimension() != dimension)
        throw InputError("obstacle penalty: body '" + body_->name() + "' is " + std::to_string(body_->dimension()) +
                         "D, the scene " + std::to_string(dimension) + "D");
    nodes_ = node_stencils(num_nodes, nodes);
}

ObstaclePenaltyPotential::ObstaclePenaltyPotential(int dimension, int num_nodes, const AnalyticObstacle& obstacle,
                                                   double stiffness, std::vector<int> nodes)
    : ObstaclePenaltyPotential(dimension, num_nodes,
                               std::make_shared<const PlacedBody>(analytic_body(obstacle, dimension)), stiffness,
                               std::move(nodes))
{
}

BodyDistance ObstaclePenaltyPotential::at_node(ConstVectorRef x, int node) const
{
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    p.head(dimension_) = x.segment(dimension_ * node, dimension_);
    return body_->distance(p);
}

double ObstaclePenaltyPotential::value(ConstVectorRef x)
{
    double sum = 0.0;
    for (int k = 0; k < nodes_.cols(); ++k) {
        const double phi = at_node(x, nodes_(0, k)).distance;
        if (!std::isfinite(phi))
            return kInfinity;
        const double depth = std::max(0.0, -phi);  // δ
        sum += 0.5 * stiffness_ * depth * depth;   // ε/2 δ²
    }
    return sum;
}

void ObstaclePenaltyPotential::add_gradient(ConstVectorRef x, VectorRef gradient)
{
    for (int k = 0; k < nodes_.cols(); ++k) {
        const int node = nodes_(0, k);
        const BodyDistance d = at_node(x, node);
        if (d.distance < 0.0)  // −ε δ ∇φ
            gradient.segment(dimension_ * node, dimension_) += stiffness_ * d.distance * d.gradient.head(dimension_);
    }
}

void ObstaclePenaltyPotential::add_hessian(ConstVectorRef x, Projection projection, const StencilSlots& slots,
                                           VectorRef values)
{
    for (int k = 0; k < nodes_.cols(); ++k) {
        const BodyDistance d = at_node(x, nodes_(0, k));
        if (!(d.distance < 0.0))
            continue;
        const double depth = -d.distance;
        const Eigen::Matrix3d normal_part = stiffness_ * d.gradient * d.gradient.transpose();  // ε ∇φ∇φᵀ
        if (projection == Projection::clamp && curvature_ == ContactCurvature::gauss_newton) {
            add_block(normal_part, dimension_, false, &slots(0, k), values.data());
            continue;
        }
        const Eigen::Matrix3d H = normal_part - stiffness_ * depth * d.hessian;  // ε(∇φ∇φᵀ − δ∇²φ)
        add_block(H, dimension_, projection == Projection::clamp, &slots(0, k), values.data());
    }
}

double ObstaclePenaltyPotential::max_penetration(ConstVectorRef x) const
{
    double deepest = 0.0;
    for (int k = 0; k < nodes_.cols(); ++k)
        deepest = std::max(deepest, -at_node(x, nodes_(0, k)).distance);
    return deepest;
}

Eigen::Vector3d ObstaclePenaltyPotential::total_force(ConstVectorRef x) const
{
    Eigen::Vector3d force = Eigen::Vector3d::Zero();
    for (int k = 0; k < nodes_.cols(); ++k) {
        const BodyDistance d = at_node(x, nodes_(0, k));
        if (d.distance < 0.0)
            force -= stiffness_ * d.distance * d.gradient;  // ε δ ∇φ
    }
    return force;
}

Eigen::MatrixXd ObstaclePenaltyPotential::placement_gradient_derivatives(ConstVectorRef x) const
{
    if (dimension_ != 3)
        throw InputError("obstacle penalty: placement derivatives need a 3D scene");
    Eigen::MatrixXd columns = Eigen::MatrixXd::Zero(x.size(), 12);
    const Eigen::Matrix3d& inverse = body_->inverse_map();
    for (int k = 0; k < nodes_.cols(); ++k) {
        const int node = nodes_(0, k);
        const BodyDistance d = at_node(x, node);
        if (!(d.distance < 0.0))
            continue;
        const double depth = -d.distance;  // δ
        const Eigen::Vector3d& g = d.gradient;
        const Eigen::Vector3d y = inverse * (x.segment<3>(3 * node) - body_->translation());  // A⁻¹(x_i − t)
        const auto rows = Eigen::seqN(3 * node, 3);
        for (int a = 0; a < 3; ++a) {
            // ∂φ/∂t_a = −g_a, ∂g/∂t_a = −H e_a
            columns(rows, 9 + a) = stiffness_ * (-g[a] * g + depth * d.hessian.col(a));
            for (int b = 0; b < 3; ++b)  // ∂φ/∂A_ab = −g_a y_b, ∂g/∂A_ab = −g_a A⁻ᵀe_b − y_b H e_a
                columns(rows, 3 * a + b) =
                    stiffness_ * (-g[a] * y[b] * g + depth * (g[a] * inverse.row(b).transpose() + y[b] * d.hessian.col(a)));
        }
    }
    return columns;
}

void ObstaclePenaltyPotential::add_output_data(ConstVectorRef x, OutputArrays& arrays)
{
    Eigen::MatrixXd& depth = arrays.point_array("penetration", 1, 0.0);
    Eigen::MatrixXd& force = arrays.point_array("contact_force", 3, 0.0);
    for (int k = 0; k < nodes_.cols(); ++k) {
        const int node = nodes_(0, k);
        const BodyDistance d = at_node(x, node);
        if (d.distance < 0.0) {
            depth(0, node) = std::max(depth(0, node), -d.distance);
            force.col(node) -= stiffness_ * d.distance * d.gradient;
        }
    }
}

} // namespace sinew
