#include "sinew/energies/potentials/obstacle_penalty_potential.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/energies/potentials/hessian_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace sinew {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// Where a node stands against the obstacle: depth δ = max(0, −φ), the unit
/// ∇φ, and the curvature κ with ∇²φ = κ (I − ∇φ∇φᵀ) (0 for a plane, 1/ρ for
/// a sphere).
template <int Dim>
struct Contact {
    double signed_distance = 0.0;
    double depth = 0.0;
    Eigen::Matrix<double, Dim, 1> direction = Eigen::Matrix<double, Dim, 1>::Zero();
    double curvature = 0.0;
};

template <int Dim>
Contact<Dim> contact(const AnalyticObstacle& obstacle, const Eigen::Matrix<double, Dim, 1>& x)
{
    Contact<Dim> c;
    if (const auto* plane = std::get_if<PlaneObstacle>(&obstacle)) {
        c.direction = plane->normal;
        c.signed_distance = c.direction.dot(x) - plane->offset;
    } else {
        const auto& sphere = std::get<SphereObstacle>(obstacle);
        const Eigen::Matrix<double, Dim, 1> v = x - Eigen::Matrix<double, Dim, 1>(sphere.center);
        const double rho = v.norm();
        c.signed_distance = rho - sphere.radius;
        if (rho > 0.0) {
            c.direction = v / rho;
            c.curvature = 1.0 / rho;
        }
    }
    c.depth = std::max(0.0, -c.signed_distance);
    return c;
}

std::string node_label(int node) { return "obstacle penalty: node " + std::to_string(node); }

AnalyticObstacle checked_obstacle(AnalyticObstacle obstacle, int dimension)
{
    if (auto* plane = std::get_if<PlaneObstacle>(&obstacle)) {
        if (plane->normal.size() != dimension)
            throw InputError("plane obstacle: normal has " + std::to_string(plane->normal.size()) +
                             " components, expected " + std::to_string(dimension));
        const double length = plane->normal.norm();
        if (!std::isfinite(plane->offset) || !std::isfinite(length) || !(length > 0.0))
            throw InputError("plane obstacle: normal must be nonzero and finite, offset finite");
        plane->normal /= length;
        plane->offset /= length;
    } else {
        auto& sphere = std::get<SphereObstacle>(obstacle);
        if (sphere.center.size() != dimension)
            throw InputError("sphere obstacle: center has " + std::to_string(sphere.center.size()) +
                             " components, expected " + std::to_string(dimension));
        if (!sphere.center.allFinite())
            throw InputError("sphere obstacle: center is not finite");
        if (!(std::isfinite(sphere.radius) && sphere.radius > 0.0))
            throw InputError("sphere obstacle: radius " + std::to_string(sphere.radius) +
                             " must be finite and > 0");
    }
    return obstacle;
}

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

} // namespace

ObstaclePenaltyPotential::ObstaclePenaltyPotential(int dimension, int num_nodes, AnalyticObstacle obstacle,
                                                   double stiffness, std::vector<int> nodes)
    : dimension_(dimension), num_nodes_(num_nodes), stiffness_(stiffness)
{
    if (dimension != 2 && dimension != 3)
        throw InputError("obstacle penalty: dimension " + std::to_string(dimension) + " is not 2 or 3");
    if (num_nodes < 0)
        throw InputError("obstacle penalty: node count " + std::to_string(num_nodes) + " is not valid");
    if (!(std::isfinite(stiffness) && stiffness > 0.0))
        throw InputError("obstacle penalty: stiffness " + std::to_string(stiffness) + " must be finite and > 0");
    obstacle_ = checked_obstacle(std::move(obstacle), dimension);
    nodes_ = node_stencils(num_nodes, nodes);
}

double ObstaclePenaltyPotential::value(ConstVectorRef x)
{
    double sum = 0.0;
    for (int k = 0; k < nodes_.cols(); ++k) {
        const int node = nodes_(0, k);
        const double phi = dimension_ == 3 ? contact<3>(obstacle_, x.segment<3>(3 * node)).signed_distance
                                           : contact<2>(obstacle_, x.segment<2>(2 * node)).signed_distance;
        if (!std::isfinite(phi))
            return kInfinity;
        const double depth = std::max(0.0, -phi);
        sum += 0.5 * stiffness_ * depth * depth;
    }
    return sum;
}

template <int Dim>
void ObstaclePenaltyPotential::add_gradient_in(ConstVectorRef x, VectorRef gradient) const
{
    for (int k = 0; k < nodes_.cols(); ++k) {
        const int node = nodes_(0, k);
        const Contact<Dim> c = contact<Dim>(obstacle_, x.segment<Dim>(Dim * node));
        if (c.depth > 0.0)
            gradient.segment<Dim>(Dim * node) -= stiffness_ * c.depth * c.direction;
    }
}

void ObstaclePenaltyPotential::add_gradient(ConstVectorRef x, VectorRef gradient)
{
    if (dimension_ == 3)
        add_gradient_in<3>(x, gradient);
    else
        add_gradient_in<2>(x, gradient);
}

template <int Dim>
void ObstaclePenaltyPotential::add_hessian_in(ConstVectorRef x, Projection projection, const StencilSlots& slots,
                                              VectorRef values) const
{
    using Matrix = Eigen::Matrix<double, Dim, Dim>;
    for (int k = 0; k < nodes_.cols(); ++k) {
        const Contact<Dim> c = contact<Dim>(obstacle_, x.segment<Dim>(Dim * nodes_(0, k)));
        if (!(c.depth > 0.0))
            continue;
        const Matrix normal_part = c.direction * c.direction.transpose();
        Matrix H = stiffness_ * normal_part;
        // −ε δ ∇²φ = −ε δ κ (I − ∇φ∇φᵀ): negative semidefinite, dropped by the projection.
        if (projection == Projection::none)
            H -= stiffness_ * c.depth * c.curvature * (Matrix::Identity() - normal_part);
        add_lower_triangle(H, &slots(0, k), values.data());
    }
}

void ObstaclePenaltyPotential::add_hessian(ConstVectorRef x, Projection projection, const StencilSlots& slots,
                                           VectorRef values)
{
    if (dimension_ == 3)
        add_hessian_in<3>(x, projection, slots, values);
    else
        add_hessian_in<2>(x, projection, slots, values);
}

} // namespace sinew
