#include "sinew/runs/contact_summary.hpp"

#include <cmath>

namespace sinew {
namespace {

/// Column i of `positions` (2 or 3 rows) as a 3-vector.
Eigen::Vector3d position(const Eigen::MatrixXd& positions, Eigen::Index i)
{
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (Eigen::Index k = 0; k < positions.rows(); ++k)
        p[k] = positions(k, i);
    return p;
}

} // namespace

ContactSummary contact_summary(const OutputArrays& arrays, const Eigen::MatrixXd& positions)
{
    ContactSummary summary;
    const auto forces = arrays.points.find("contact_force");
    const auto depths = arrays.points.find("penetration");
    if (forces == arrays.points.end() && depths == arrays.points.end())
        return summary;
    summary.present = true;
    if (depths != arrays.points.end() && depths->second.size() > 0)
        summary.max_penetration = std::max(0.0, depths->second.maxCoeff());
    if (forces == arrays.points.end())
        return summary;
    const Eigen::MatrixXd& f = forces->second;
    const double largest = f.cols() > 0 ? f.colwise().norm().maxCoeff() : 0.0;
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    double weight = 0.0;
    for (Eigen::Index i = 0; i < f.cols(); ++i) {
        const double magnitude = f.col(i).norm();
        if (magnitude == 0.0)
            continue;
        summary.contact_nodes += magnitude > kContactNodeFraction * largest ? 1 : 0;
        summary.force += f.col(i);
        centre += magnitude * position(positions, i);
        weight += magnitude;
    }
    if (weight == 0.0)
        return summary;
    centre /= weight;
    const double norm = summary.force.norm();
    const Eigen::Vector3d n = norm > 0.0 ? Eigen::Vector3d(summary.force / norm) : Eigen::Vector3d::Zero();
    double moment = 0.0;
    for (Eigen::Index i = 0; i < f.cols(); ++i) {
        const double magnitude = f.col(i).norm();
        if (magnitude == 0.0)
            continue;
        Eigen::Vector3d r = position(positions, i) - centre;
        r -= r.dot(n) * n;  // in the plane normal to F
        moment += magnitude * r.squaredNorm();
    }
    summary.contact_radius = std::sqrt(2.5 * moment / weight);  // Σ|f| r² / Σ|f| = 2a²/5
    return summary;
}

} // namespace sinew
