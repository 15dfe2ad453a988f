#pragma once
// The shape every built-in NLP's sparsity patterns must have, shared by the
// classic and the constrained problem tests.
#include "sinew/problems/nlp.hpp"

#include <catch2/catch.hpp>

#include <set>
#include <utility>

namespace sinew::test {

/// Hessian pattern: nonempty, in range, lower triangular, no duplicates.
/// Jacobian pattern: empty exactly when m = 0, in range, no duplicates.
inline void check_pattern_shape(const Nlp& nlp)
{
    const int n = nlp.num_variables();
    const int m = nlp.num_constraints();

    const SparsityPattern& hessian = nlp.hessian_pattern();
    REQUIRE(hessian.rows.size() == hessian.cols.size());
    REQUIRE(hessian.nonzeros() > 0);
    std::set<std::pair<int, int>> seen;
    for (int k = 0; k < hessian.nonzeros(); ++k) {
        const int row = hessian.rows[k];
        const int col = hessian.cols[k];
        CAPTURE(k, row, col);
        CHECK(col >= 0);
        CHECK(row < n);
        CHECK(row >= col);
        CHECK(seen.insert({row, col}).second);
    }

    const SparsityPattern& jacobian = nlp.jacobian_pattern();
    REQUIRE(jacobian.rows.size() == jacobian.cols.size());
    CHECK((m == 0) == (jacobian.nonzeros() == 0));
    seen.clear();
    for (int k = 0; k < jacobian.nonzeros(); ++k) {
        const int row = jacobian.rows[k];
        const int col = jacobian.cols[k];
        CAPTURE(k, row, col);
        CHECK(row >= 0);
        CHECK(row < m);
        CHECK(col >= 0);
        CHECK(col < n);
        CHECK(seen.insert({row, col}).second);
    }
}

} // namespace sinew::test
