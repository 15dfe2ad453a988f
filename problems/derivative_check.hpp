#pragma once
#include "sinew/problems/nlp.hpp"

#include <cstdint>
#include <string>

namespace sinew {

/// Entries of a derivative below this fraction of its largest entry are
/// compared against that fraction of it instead of their own size (docs/solvers.md).
inline constexpr double kRelativeErrorFloor = 1e-3;
/// The check is dense in n: it refuses problems with more variables than this
/// (a 4000 x 4000 matrix of doubles is 128 MB) ...
inline constexpr int kMaxCheckedVariables = 4000;
/// ... or whose dense check would hold more than this many bytes
/// (dense_check_bytes(); 1 GiB, 576 MB for n = 4000 and m = 0).
inline constexpr std::uint64_t kMaxDenseCheckBytes = std::uint64_t{1} << 30;

/// Bytes check_derivatives() holds for n variables and m constraints: ∇²L and
/// its differenced twin (two n × n matrices of doubles), J (m × n doubles) and
/// one 40-byte record per compared entry (n(n+1)/2 + m·n + n of them).
std::uint64_t dense_check_bytes(int n, int m);

/// Empty when check_derivatives() takes `nlp`; otherwise one line saying why
/// not, naming n, m and the bytes the dense check would need.
std::string dense_check_refusal(const Nlp& nlp);

/// Empty when every entry of both sparsity patterns lies inside its matrix
/// (and, for the Hessian, in the lower triangle); otherwise names the first
/// entry that does not. Shared by check_derivatives() and taylor_test().
std::string find_pattern_problem(const Nlp& nlp);

/// The worst disagreement found in one derivative (gradient, Jacobian or
/// Hessian) between the analytic values and central finite differences.
struct DerivativeDiscrepancy {
    /// |analytic − fd| / max(|fd|, error_floor), error_floor =
    /// kRelativeErrorFloor · (largest |analytic| of this derivative, or
    /// largest |fd| when every analytic value is 0).
    double worst_relative_error = 0.0;
    double error_floor = 0.0;
    int row = -1;                       ///< where it is (-1: nothing compared)
    int col = -1;                       ///< column; 0 for the gradient
    double analytic = 0.0;
    double finite_difference = 0.0;
    int entries_compared = 0;
    /// Entries central differences at the check's step disagree with
    /// (beyond the tolerance) that a closer study of their column settled
    /// (study_column(), difference_study.hpp): within the differences'
    /// round-off noise, at a kink (one one-sided difference agrees, the two
    /// sides do not), or where both one-sided differences agree.
    /// Their errors are then those the study found.
    int within_noise = 0;
    int at_kink = 0;
    int both_sides_agree = 0;
};

struct DerivativeCheckReport {
    DerivativeDiscrepancy gradient;  ///< ∇f, row = variable index
    DerivativeDiscrepancy jacobian;  ///< ∂c/∂x, (constraint, variable)
    DerivativeDiscrepancy hessian;   ///< ∇²L lower triangle, (row >= col)
    /// A pattern entry outside the matrix or (Hessian) above the diagonal;
    /// when set nothing else was compared.
    std::string pattern_problem;
    /// Entries the Hessian pattern lacks but finite differences find nonzero
    /// (beyond tolerance) are counted in `hessian` too, so a missing entry shows.
    bool passed(double tolerance) const;
    std::string to_text() const;  ///< a short human-readable report
};

struct DerivativeCheckOptions {
    double step = 1e-6;      ///< central-difference step, scaled by max(1, |x_i|)
    double sigma = 1.0;      ///< objective factor in ∇²L
    unsigned seed = 7;       ///< for the random multipliers λ in ∇²L
    /// Entries whose relative error exceeds this are studied more closely
    /// (noise, kinks, smaller steps) before they count as disagreeing.
    double tolerance = 1e-5;
};

/// Compares gradient, Jacobian and Hessian of the Lagrangian (with random λ)
/// at x against central differences of f, c and ∇L. Dense in n: InputError
/// with dense_check_refusal()'s message for a problem it does not take (more
/// than kMaxCheckedVariables variables or kMaxDenseCheckBytes of memory); the
/// Taylor test (taylor_test.hpp) is sparse and checks such problems.
DerivativeCheckReport check_derivatives(Nlp& nlp, Nlp::ConstVectorRef x,
                                        const DerivativeCheckOptions& options = {});

} // namespace sinew
