#pragma once
#include "sinew/problems/nlp.hpp"

#include <limits>
#include <string>

namespace sinew {

/// The numerical rank of a block of constraint rows of an NLP's Jacobian.
struct JacobianRank {
    int rows = 0;
    int rank = -1;  ///< −1: not computed (more than kMaxRankRows rows)
    double singular_value_ratio = std::numeric_limits<double>::quiet_NaN();  ///< σ_min / σ_max of the rows
};

/// Rank is checked densely, from the eigenvalues of the rows' J Jᵀ, up to
/// this many rows (a few tenths of a second).
inline constexpr int kMaxRankRows = 1500;

/// The rank of rows [first, first + count) of J(x): σ_i² are the eigenvalues
/// of the count × count matrix J Jᵀ, and a σ_i counts when σ_i > 1e-6 σ_max
/// (σ_i below √ε σ_max cannot be told from zero through J Jᵀ).
JacobianRank jacobian_rank(Nlp& nlp, Nlp::ConstVectorRef x, int first, int count);

/// "18 rows, rank 18 (σ_min/σ_max = 2.1e-02)", "288 rows, rank 150: rank-deficient (…)",
/// or "20000 rows: rank not checked (more than 1500)".
std::string describe(const JacobianRank& rank);

} // namespace sinew
