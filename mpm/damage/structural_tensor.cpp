#include "sinew/mpm/damage/structural_tensor.hpp"

#include "sinew/energies/models/rotation_variant_svd.hpp"

namespace sinew {

template <int Dim>
Eigen::Matrix<double, Dim, Dim> structural_tensor(const PhaseFieldPoint<Dim>& point,
                                                  const Eigen::Matrix<double, Dim, Dim>& F)
{
    using Matrix = Eigen::Matrix<double, Dim, Dim>;
    using Vector = Eigen::Matrix<double, Dim, 1>;
    const RotationVariantSvd<Dim> svd = rotation_variant_svd<Dim>(F);
    const Matrix R = svd.U * svd.V.transpose();  // F = R S
    Matrix A = Matrix::Identity();
    const Vector a1 = R * point.director1;
    A += point.weight1 * a1 * a1.transpose();  // α₁ (R a₁)(R a₁)ᵀ
    if (point.directors_used == 2) {
        const Vector a2 = R * point.director2;
        A += point.weight2 * a2 * a2.transpose();  // α₂ (R a₂)(R a₂)ᵀ
    }
    return A;
}

template Eigen::Matrix<double, 2, 2> structural_tensor<2>(const PhaseFieldPoint<2>&, const Eigen::Matrix<double, 2, 2>&);
template Eigen::Matrix<double, 3, 3> structural_tensor<3>(const PhaseFieldPoint<3>&, const Eigen::Matrix<double, 3, 3>&);

} // namespace sinew
