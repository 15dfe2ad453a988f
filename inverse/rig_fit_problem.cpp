#include "sinew/inverse/rig_fit_problem.hpp"

#include "sinew/core/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sinew {
namespace {

constexpr int kOrthogonalityRows = 6;
/// ‖MᵀM − I‖²_F = Σ_p w_p c_p² over the 6 pairs i ≤ j (Orthogonality's order).
constexpr double kFrobeniusWeights[kOrthogonalityRows] = {1.0, 2.0, 2.0, 1.0, 2.0, 1.0};

/// The constraints c(θ) of both maps (12) and their dense Jacobian (12 × n).
struct OrthogonalityRows {
    Eigen::VectorXd c;
    Eigen::MatrixXd jacobian;
};

OrthogonalityRows orthogonality_rows(Orthogonality& cranium, Orthogonality& jaw, const Eigen::VectorXd& theta)
{
    OrthogonalityRows rows;
    rows.c.resize(2 * kOrthogonalityRows);
    rows.jacobian = Eigen::MatrixXd::Zero(2 * kOrthogonalityRows, theta.size());
    int offset = 0;
    for (Orthogonality* set : {&cranium, &jaw}) {
        set->values(theta, rows.c.segment(offset, kOrthogonalityRows));
        Eigen::VectorXd values(set->jacobian_pattern().nonzeros());
        set->jacobian_values(theta, values);
        for (int q = 0; q < set->jacobian_pattern().nonzeros(); ++q)
            rows.jacobian(offset + set->jacobian_pattern().rows[q], set->jacobian_pattern().cols[q]) += values[q];
        offset += kOrthogonalityRows;
    }
    return rows;
}

/// The penalty form's residuals over both maps, weighted so that the
/// penalty is ½‖r‖²: r_p = √(k w_p) c_p, and their Jacobian (12 × n, dense).
OrthogonalityRows penalty_residuals(Orthogonality& cranium, Orthogonality& jaw, const Eigen::VectorXd& theta,
                                    double stiffness)
{
    OrthogonalityRows residuals = orthogonality_rows(cranium, jaw, theta);
    for (int p = 0; p < 2 * kOrthogonalityRows; ++p) {
        const double scale = std::sqrt(stiffness * kFrobeniusWeights[p % kOrthogonalityRows]);
        residuals.c[p] *= scale;
        residuals.jacobian.row(p) *= scale;
    }
    return residuals;
}

/// Adds a set's Σλ∇²c into the dense symmetric H (lower-triangle pattern mirrored).
void add_constraint_curvature(Orthogonality& set, const Eigen::VectorXd& theta, const Eigen::VectorXd& lambda,
                              Projection projection, Eigen::MatrixXd& H)
{
    const SparsityPattern& pattern = set.hessian_pattern();
    Eigen::VectorXd values(pattern.nonzeros());
    set.hessian_values(theta, lambda, projection, values);
    for (int q = 0; q < pattern.nonzeros(); ++q) {
        const int r = pattern.rows[q], c = pattern.cols[q];
        H(r, c) += values[q];
        if (r != c)
            H(c, r) += values[q];
    }
}

} // namespace

std::string to_string(OrthogonalityForm form)
{
    switch (form) {
    case OrthogonalityForm::constraints:
        return "constraints";
    case OrthogonalityForm::penalty:
        return "penalty";
    case OrthogonalityForm::rotation_vectors:
        break;
    }
    return "rotation vectors";
}

OrthogonalityForm orthogonality_form(const std::string& name)
{
    for (const OrthogonalityForm form :
         {OrthogonalityForm::constraints, OrthogonalityForm::penalty, OrthogonalityForm::rotation_vectors})
        if (to_string(form) == name)
            return form;
    throw InputError("rig fit: unknown orthogonality form '" + name +
                     "' (constraints, penalty or rotation vectors)");
}

RigFitProblem::RigFitProblem(std::shared_ptr<MuscleRig> rig, Eigen::VectorXd targets, RigFitSettings settings,
                             std::optional<RigParameters> start)
    : RigFitProblem(*rig, std::move(targets), settings, std::move(start))
{
    owned_rig_ = std::move(rig);
}

RigFitProblem::RigFitProblem(MuscleRig& rig, Eigen::VectorXd targets, RigFitSettings settings,
                             std::optional<RigParameters> start)
    : rig_(rig),
      targets_(std::move(targets)),
      settings_(settings),
      cranium_("cranium", rig.num_muscles()),
      jaw_("jaw", rig.num_muscles() + RigParameters::kAffineParameters)
{
    if (targets_.size() != 3 * rig.num_landmarks())
        throw InputError("rig fit: " + std::to_string(targets_.size()) + " target coordinates for " +
                         std::to_string(rig.num_landmarks()) + " landmarks (3 each)");
    for (Eigen::Index i = 0; i < targets_.size(); ++i)
        if (!std::isfinite(targets_[i]))
            throw InputError("rig fit: target coordinate " + std::to_string(i % 3) + " of landmark " +
                             std::to_string(i / 3) + " is not finite");
    if (!(settings_.tikhonov >= 0.0) || !std::isfinite(settings_.tikhonov))
        throw InputError("rig fit: the Tikhonov weight must be finite and >= 0");
    if (!(settings_.penalty_weight > 0.0) || !std::isfinite(settings_.penalty_weight))
        throw InputError("rig fit: the penalty weight must be finite and > 0");
    if (settings_.orthogonality == OrthogonalityForm::rotation_vectors)
        throw InputError("rig fit: the rotation-vector form is RotationVectorFitProblem's, not RigFitProblem's");
    start_ = (start ? *start : RigParameters::neutral(rig.num_muscles())).packed();
    if (start_.size() != rig.num_parameters())
        throw InputError("rig fit: the starting parameters have " + std::to_string(start_.size()) +
                         " entries, expected " + std::to_string(rig.num_parameters()));
    penalty_stiffness_ = settings_.penalty_weight * rig.num_landmarks() * rig.size() * rig.size();
    if (settings_.orthogonality == OrthogonalityForm::constraints) {
        for (Orthogonality* set : {&cranium_, &jaw_}) {
            const int offset = set == &cranium_ ? 0 : kOrthogonalityRows;
            for (int q = 0; q < set->jacobian_pattern().nonzeros(); ++q)
                jacobian_pattern_.add(offset + set->jacobian_pattern().rows[q], set->jacobian_pattern().cols[q]);
        }
    }
    const int n = num_variables();
    for (int c = 0; c < n; ++c)
        for (int r = c; r < n; ++r)
            hessian_pattern_.add(r, c);
}

int RigFitProblem::num_constraints() const
{
    return settings_.orthogonality == OrthogonalityForm::constraints ? 2 * kOrthogonalityRows : 0;
}

void RigFitProblem::variable_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setConstant(-kInfinity);
    upper.setConstant(kInfinity);
    lower.head(rig_.num_muscles()).setZero();  // α ∈ [0, 1]
    upper.head(rig_.num_muscles()).setOnes();
}

void RigFitProblem::constraint_bounds(VectorRef lower, VectorRef upper) const
{
    lower.setZero();
    upper.setZero();
}

bool RigFitProblem::evaluate(ConstVectorRef theta)
{
    if (!theta.allFinite())
        return false;
    RigParameters parameters = RigParameters::unpacked(theta, rig_.num_muscles());
    parameters.activations = parameters.activations.cwiseMax(0.0).cwiseMin(1.0);
    return rig_.evaluate(parameters).ok;
}

void RigFitProblem::require(ConstVectorRef theta)
{
    if (!evaluate(theta))
        throw std::runtime_error("rig fit: derivatives asked for at parameters where the equilibrium solve fails");
}

Eigen::VectorXd RigFitProblem::residual(ConstVectorRef theta)
{
    require(theta);
    return rig_.landmark_positions() - targets_;  // S x̂(θ) − x*
}

const Eigen::MatrixXd& RigFitProblem::landmark_jacobian(ConstVectorRef theta)
{
    require(theta);
    if (!landmark_jacobian_at_ || *landmark_jacobian_at_ != theta) {
        landmark_jacobian_ = rig_.landmark_jacobian();
        landmark_jacobian_at_ = theta;
    }
    return landmark_jacobian_;
}

Eigen::MatrixXd RigFitProblem::orthogonality_jacobian(ConstVectorRef theta)
{
    return orthogonality_rows(cranium_, jaw_, theta).jacobian;
}

double RigFitProblem::penalty(ConstVectorRef theta)
{
    if (settings_.orthogonality != OrthogonalityForm::penalty)
        return 0.0;
    // k/2 (‖M_cᵀM_c − I‖²_F + ‖M_jᵀM_j − I‖²_F) = ½‖r‖².
    return 0.5 * penalty_residuals(cranium_, jaw_, theta, penalty_stiffness_).c.squaredNorm();
}

double RigFitProblem::objective(ConstVectorRef theta)
{
    if (!evaluate(theta))
        return kInfinity;
    const Eigen::VectorXd r = rig_.landmark_positions() - targets_;
    const Eigen::VectorXd alpha = theta.head(rig_.num_muscles());
    return 0.5 * r.squaredNorm() + 0.5 * settings_.tikhonov * alpha.squaredNorm() + penalty(theta);
}

void RigFitProblem::gradient(ConstVectorRef theta, VectorRef grad)
{
    const Eigen::VectorXd r = residual(theta);
    grad = rig_.landmark_gradient(r);  // Jᵀr by the adjoint
    grad.head(rig_.num_muscles()) += settings_.tikhonov * theta.head(rig_.num_muscles());
    if (settings_.orthogonality == OrthogonalityForm::penalty) {
        const OrthogonalityRows penalty = penalty_residuals(cranium_, jaw_, theta, penalty_stiffness_);
        grad += penalty.jacobian.transpose() * penalty.c;
    }
}

void RigFitProblem::constraints(ConstVectorRef theta, VectorRef c)
{
    cranium_.values(theta, c.head(kOrthogonalityRows));
    jaw_.values(theta, c.tail(kOrthogonalityRows));
}

void RigFitProblem::jacobian_values(ConstVectorRef theta, VectorRef values)
{
    const int cranium_entries = cranium_.jacobian_pattern().nonzeros();
    cranium_.jacobian_values(theta, values.head(cranium_entries));
    jaw_.jacobian_values(theta, values.tail(jaw_.jacobian_pattern().nonzeros()));
}

void RigFitProblem::hessian_values(ConstVectorRef theta, double sigma, ConstVectorRef lambda, VectorRef values)
{
    fill_hessian(theta, sigma, lambda, Projection::none, values);
}

void RigFitProblem::projected_hessian_values(ConstVectorRef theta, double sigma, ConstVectorRef lambda,
                                             VectorRef values)
{
    fill_hessian(theta, sigma, lambda, Projection::clamp, values);
}

void RigFitProblem::fill_hessian(ConstVectorRef theta, double sigma, ConstVectorRef lambda, Projection projection,
                                 VectorRef values)
{
    const Eigen::MatrixXd& J = landmark_jacobian(theta);
    const int n = num_variables(), m = rig_.num_muscles();
    // Gauss-Newton: JᵀJ + τ I_α (+ k J_Rᵀ W J_R), then Σλ∇²c exactly.
    Eigen::MatrixXd H = J.transpose() * J;
    H.diagonal().head(m).array() += settings_.tikhonov;
    if (settings_.orthogonality == OrthogonalityForm::penalty) {
        const OrthogonalityRows penalty = penalty_residuals(cranium_, jaw_, theta, penalty_stiffness_);
        H += penalty.jacobian.transpose() * penalty.jacobian;
    }
    H *= sigma;
    if (num_constraints() > 0) {
        add_constraint_curvature(cranium_, theta, lambda.head(kOrthogonalityRows), projection, H);
        add_constraint_curvature(jaw_, theta, lambda.tail(kOrthogonalityRows), projection, H);
    }
    int q = 0;
    for (int c = 0; c < n; ++c)
        for (int r = c; r < n; ++r)
            values[q++] = H(r, c);
}

} // namespace sinew
