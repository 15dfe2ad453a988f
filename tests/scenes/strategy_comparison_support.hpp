#pragma once
// Built-in scenes as comparison subjects and the strategies chosen for them,
// shared by the strategy-comparison tests.
#include "sinew/problems/quasistatic/builtin_scenes.hpp"
#include "sinew/runs/comparison_subjects.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace sinew::test {

inline ComparisonSubject builtin_scene(const std::string& name)
{
    return scene_subject([name] { return make_builtin_scene(name); });
}

inline std::vector<ComparedStrategy> strategies(const ComparisonSubject& subject,
                                                const std::vector<std::string>& solvers,
                                                const std::vector<double>& kappas = {})
{
    std::vector<std::string> refusals;
    auto chosen = comparison_strategies(*subject.make_nlp(), solvers, kappas, refusals);
    REQUIRE(refusals.empty());
    return chosen;
}

/// Tolerances tight enough that the agreement is the problem's, not the
/// stopping tests'. The augmented Lagrangian's x is only as close as its
/// feasibility allows: the weak-form rows Σ V_e(a₀ᵀC_e a₀ − 1) (seed 004
/// §4.2.2) carry the cell volume (1.25e-4 m³ in the helical block), and at
/// max |c| = 1e-10 its x is still 1e-7 m off (measured), so 1e-12.
inline SolverOptions tight_options()
{
    SolverOptions options;
    options.tolerance = 1e-10;
    options.constraint_tolerance = 1e-12;
    return options;
}

} // namespace sinew::test
