#include "sinew/energies/constraints/prescribed_coordinates.hpp"

namespace sinew {

PrescribedCoordinates::PrescribedCoordinates(std::vector<int> coordinates, Eigen::VectorXd targets)
    : coordinates_(std::move(coordinates)), targets_(std::move(targets))
{
    for (int k = 0; k < static_cast<int>(coordinates_.size()); ++k)
        jacobian_.add(k, coordinates_[k]);
}

void PrescribedCoordinates::values(ConstVectorRef x, VectorRef c)
{
    for (int k = 0; k < static_cast<int>(coordinates_.size()); ++k)
        c[k] = x[coordinates_[k]] - targets_[k];  // c_k = x_{i_k} − x̄_k
}

} // namespace sinew
