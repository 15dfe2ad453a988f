#include "sinew/inverse/rotation_vector_fit_problem.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/core/rotation_vector.hpp"

#include <Eigen/LU>

namespace sinew {
namespace {

constexpr int kMapEntries = 9;
/// Offsets of one bone's block in θ (map then translation: 12) and in φ (ω then translation: 6).
constexpr int kAffineBlock = RigParameters::kAffineParameters;
constexpr int kRotationBlock = 6;

/// φ of a map and translation: ω, t. InputError unless M is a rotation.
void pack_rotation(const Eigen::Matrix3d& M, const Eigen::Vector3d& t, const std::string& bone, double* out)
{
    if ((M.transpose() * M - Eigen::Matrix3d::Identity()).norm() > 1e-9 || M.determinant() < 0.0)
        throw InputError("rig fit (rotation vectors): the starting " + bone + " map is not a rotation");
    Eigen::Map<Eigen::Vector3d> omega(out), translation(out + 3);
    omega = rotation_vector(M);
    translation = t;
}

} // namespace

RotationVectorFitProblem::RotationVectorFitProblem(MuscleRig& rig, Eigen::VectorXd targets, RigFitSettings settings,
                                                   std::optional<RigParameters> start)
    : affine_(rig, std::move(targets), [&] {
          settings.orthogonality = OrthogonalityForm::constraints;  // values only; no constraint is passed on
          return settings;
      }(), start)
{
    const RigParameters from = start ? *start : RigParameters::neutral(rig.num_muscles());
    const int m = rig.num_muscles();
    start_.resize(num_variables());
    start_.head(m) = from.activations;
    pack_rotation(from.cranium_map, from.cranium_translation, "cranium", start_.data() + m);
    pack_rotation(from.jaw_map, from.jaw_translation, "jaw", start_.data() + m + kRotationBlock);
    const int n = num_variables();
    for (int c = 0; c < n; ++c)
        for (int r = c; r < n; ++r)
            hessian_pattern_.add(r, c);
}

void RotationVectorFitProblem::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setConstant(-kInfinity);
    upper.setConstant(kInfinity);
    lower.head(affine_.rig().num_muscles()).setZero();  // α ∈ [0, 1]
    upper.head(affine_.rig().num_muscles()).setOnes();
}

Eigen::VectorXd RotationVectorFitProblem::affine_parameters(ConstVectorRef phi) const
{
    const int m = affine_.rig().num_muscles();
    Eigen::VectorXd theta(m + 2 * kAffineBlock);
    theta.head(m) = phi.head(m);
    for (int bone = 0; bone < 2; ++bone) {
        const int from = m + bone * kRotationBlock, to = m + bone * kAffineBlock;
        const Eigen::Matrix3d R = rotation_matrix(phi.segment<3>(from));  // M = R(ω)
        for (int k = 0; k < kMapEntries; ++k)
            theta[to + k] = R(k / 3, k % 3);
        theta.segment<3>(to + kMapEntries) = phi.segment<3>(from + 3);
    }
    return theta;
}

Eigen::MatrixXd RotationVectorFitProblem::parameter_jacobian(ConstVectorRef phi) const
{
    const int m = affine_.rig().num_muscles();
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(m + 2 * kAffineBlock, num_variables());
    D.topLeftCorner(m, m).setIdentity();
    for (int bone = 0; bone < 2; ++bone) {
        const int from = m + bone * kRotationBlock, to = m + bone * kAffineBlock;
        const std::array<Eigen::Matrix3d, 3> dR = rotation_matrix_derivatives(phi.segment<3>(from));
        for (int i = 0; i < 3; ++i)
            for (int k = 0; k < kMapEntries; ++k)
                D(to + k, from + i) = dR[i](k / 3, k % 3);  // ∂M_k/∂ω_i
        D.block<3, 3>(to + kMapEntries, from + 3).setIdentity();
    }
    return D;
}

void RotationVectorFitProblem::gradient(ConstVectorRef phi, VectorRef grad)
{
    const Eigen::VectorXd theta = affine_parameters(phi);
    Eigen::VectorXd affine_gradient(theta.size());
    affine_.gradient(theta, affine_gradient);
    grad = parameter_jacobian(phi).transpose() * affine_gradient;  // ∇_φ f = Dᵀ ∇_θ f
}

void RotationVectorFitProblem::hessian_values(ConstVectorRef phi, double sigma, ConstVectorRef, VectorRef values)
{
    const Eigen::MatrixXd JD = affine_.landmark_jacobian(affine_parameters(phi)) * parameter_jacobian(phi);
    Eigen::MatrixXd H = JD.transpose() * JD;  // (JD)ᵀ(JD) + τ E_α
    H.diagonal().head(affine_.rig().num_muscles()).array() += affine_.settings().tikhonov;
    H *= sigma;
    int q = 0;
    for (int c = 0; c < H.cols(); ++c)
        for (int r = c; r < H.rows(); ++r)
            values[q++] = H(r, c);
}

} // namespace sinew
