#include "sinew/problems/quasistatic/constraint_ranks.hpp"

namespace sinew {

std::vector<ConstraintSetRank> constraint_ranks(Scene& scene)
{
    QuasistaticProblem& problem = *scene.problem;
    const Eigen::VectorXd x = problem.starting_point();
    std::vector<ConstraintSetRank> ranks;
    int rows = 0;
    for (const auto& set : scene.constraints) {
        const int offset = problem.constraint_offset(*set);
        if (offset < 0)
            continue;
        ranks.push_back({set->name(), jacobian_rank(problem, x, offset, set->num_constraints())});
        rows += set->num_constraints();
    }
    if (!ranks.empty() && (ranks.size() > 1 || rows < problem.num_constraints()))
        ranks.push_back({"all constraints", jacobian_rank(problem, x, 0, problem.num_constraints())});
    return ranks;
}

std::string describe(const ConstraintSetRank& rank)
{
    return "constraints '" + rank.set + "' at the starting point: " + describe(rank.rank);
}

} // namespace sinew
