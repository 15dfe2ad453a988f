#include "sinew/time/state_measures.hpp"

#include <Eigen/Geometry>

namespace sinew {
namespace {

/// Node i's coordinates as a 3-vector (z = 0 in 2D).
Eigen::Vector3d node_vector(const Eigen::VectorXd& q, int i, int dimension)
{
    Eigen::Vector3d out = Eigen::Vector3d::Zero();
    out.head(dimension) = q.segment(static_cast<Eigen::Index>(i) * dimension, dimension);
    return out;
}

} // namespace

double kinetic_energy(const Eigen::VectorXd& masses, const Eigen::VectorXd& v, int dimension)
{
    double sum = 0.0;
    for (int i = 0; i < masses.size(); ++i)
        sum += masses[i] * node_vector(v, i, dimension).squaredNorm();
    return 0.5 * sum;
}

Eigen::Vector3d linear_momentum(const Eigen::VectorXd& masses, const Eigen::VectorXd& v, int dimension)
{
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int i = 0; i < masses.size(); ++i)
        p += masses[i] * node_vector(v, i, dimension);
    return p;
}

Eigen::Vector3d angular_momentum(const Eigen::VectorXd& masses, const Eigen::VectorXd& x, const Eigen::VectorXd& v,
                                 int dimension)
{
    Eigen::Vector3d L = Eigen::Vector3d::Zero();
    for (int i = 0; i < masses.size(); ++i)
        L += masses[i] * node_vector(x, i, dimension).cross(node_vector(v, i, dimension));
    return L;
}

} // namespace sinew
