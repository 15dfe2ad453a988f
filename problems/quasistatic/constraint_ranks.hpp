#pragma once
#include "sinew/problems/jacobian_rank.hpp"
#include "sinew/problems/quasistatic/scene.hpp"

#include <string>
#include <vector>

namespace sinew {

/// The rank of one constraint set's rows of a scene's Jacobian.
struct ConstraintSetRank {
    std::string set;  ///< the set's name, or "all constraints"
    JacobianRank rank;
};

/// At the problem's starting point: the rank of each of the scene's
/// constraint sets (inextensible fibers, threads) over the NLP's variables
/// (prescribed coordinates eliminated or not, as the problem has them), and,
/// when the NLP has other rows too (Dirichlet equalities) or several sets,
/// of all rows together. Where a block is rank-deficient the exact KKT
/// system is singular (issue 13: the locking block).
std::vector<ConstraintSetRank> constraint_ranks(Scene& scene);

/// "constraints 'weak fiber inextensibility' at the starting point: 18 rows, rank 18 (σ_min/σ_max = …)".
std::string describe(const ConstraintSetRank& rank);

} // namespace sinew
