#include "sinew/inverse/rig_identifiability.hpp"

#include "sinew/core/format_number.hpp"

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

namespace sinew {
namespace {

/// A = [J; √τ E_α; ∂c/∂θ].
Eigen::MatrixXd stacked_rows(RigFitProblem& problem, const Eigen::VectorXd& theta)
{
    const Eigen::MatrixXd& J = problem.landmark_jacobian(theta);
    const Eigen::MatrixXd C = problem.orthogonality_jacobian(theta);
    const int n = static_cast<int>(theta.size()), muscles = problem.rig().num_muscles();
    const double tau = problem.settings().tikhonov;
    const int tikhonov_rows = tau > 0.0 ? muscles : 0;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(J.rows() + tikhonov_rows + C.rows(), n);
    A.topRows(J.rows()) = J;
    for (int i = 0; i < tikhonov_rows; ++i)
        A(J.rows() + i, i) = std::sqrt(tau);
    A.bottomRows(C.rows()) = C;
    return A;
}

std::string describe(const RigIdentifiability& result)
{
    std::string text = std::to_string(result.parameters) + " parameters, rank " + std::to_string(result.rank);
    if (result.determined())
        return text + " (σ_min/σ_max = " + table_cell("%.1e", result.singular_value_ratio) + ")";
    text += ": the landmarks do not determine " + std::to_string(result.parameters - result.rank) +
            " directions (moving most: ";
    for (std::size_t i = 0; i < result.undetermined.size(); ++i)
        text += (i ? ", " : "") + result.undetermined[i];
    return text + "); add landmarks, or a Tikhonov term for the activations";
}

} // namespace

RigIdentifiability rig_identifiability(RigFitProblem& problem, const Eigen::VectorXd& theta)
{
    Eigen::MatrixXd A = stacked_rows(problem, theta);
    for (Eigen::Index j = 0; j < A.cols(); ++j) {
        const double norm = A.col(j).norm();
        if (norm > 0.0)
            A.col(j) /= norm;
    }
    // A thin SVD sees min(rows, cols) singular values; a wide A has at least
    // cols − rows zero ones more, which the full V carries.
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
    const Eigen::VectorXd& sigma = svd.singularValues();
    RigIdentifiability result;
    result.parameters = static_cast<int>(A.cols());
    const double largest = sigma.size() > 0 ? sigma[0] : 0.0;
    for (Eigen::Index i = 0; i < sigma.size(); ++i)
        result.rank += sigma[i] > kIdentifiabilityTolerance * largest ? 1 : 0;
    result.singular_value_ratio =
        sigma.size() == result.parameters && largest > 0.0 ? sigma[sigma.size() - 1] / largest : 0.0;
    const std::vector<std::string>& muscles = problem.rig().definition().muscle_names;
    for (int k = result.rank; k < result.parameters; ++k) {
        Eigen::Index moving = 0;
        svd.matrixV().col(k).cwiseAbs().maxCoeff(&moving);
        const std::string name = rig_parameter_name(static_cast<int>(moving), muscles);
        if (std::find(result.undetermined.begin(), result.undetermined.end(), name) == result.undetermined.end())
            result.undetermined.push_back(name);
    }
    result.message = describe(result);
    return result;
}

} // namespace sinew
