#include "sinew/problems/quasistatic/rigid_body_modes.hpp"

#include <Eigen/QR>

#include <stdexcept>

namespace sinew {

NearNullSpace rigid_body_modes(const Eigen::VectorXd& positions, int dimension, const std::vector<int>& variables)
{
    if (dimension != 2 && dimension != 3)
        throw std::logic_error("rigid_body_modes: dimension must be 2 or 3");
    const int n = static_cast<int>(variables.size());
    const int rotations = dimension == 3 ? 3 : 1;
    Eigen::MatrixXd modes = Eigen::MatrixXd::Zero(n, dimension + rotations);
    if (n == 0)
        return {modes, dimension};

    Eigen::VectorXd centroid = Eigen::VectorXd::Zero(dimension);  // x̄ over the nodes of `variables`
    for (int row = 0; row < n; row += dimension)
        centroid += positions.segment(variables[row] - variables[row] % dimension, dimension);
    centroid /= static_cast<double>(n / dimension);

    for (int row = 0; row < n; ++row) {
        const int coordinate = variables[row];
        const int axis = coordinate % dimension;
        const Eigen::VectorXd r = positions.segment(coordinate - axis, dimension) - centroid;  // x_i − x̄
        modes(row, axis) = 1.0;  // translation e_axis
        if (dimension == 2) {
            modes(row, 2) = axis == 0 ? -r(1) : r(0);  // (−y, x): the rotation in the plane
            continue;
        }
        // Column 3 + k: ω = e_k, (e_k × r)_axis.
        const int next = (axis + 1) % 3, previous = (axis + 2) % 3;
        modes(row, 3 + previous) = -r(next);  // (e_previous × r)_axis = −r_next
        modes(row, 3 + next) = r(previous);   // (e_next × r)_axis = r_previous
    }
    // Orthonormal columns spanning the same space (an AMG's coarse basis
    // wants them well conditioned; PETSc asks for orthonormal vectors).
    Eigen::HouseholderQR<Eigen::MatrixXd> qr(modes);
    Eigen::MatrixXd basis = qr.householderQ() * Eigen::MatrixXd::Identity(n, modes.cols());
    return {basis, dimension};
}

} // namespace sinew
