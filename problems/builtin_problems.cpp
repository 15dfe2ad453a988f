#include "sinew/problems/builtin_problems.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/problems/classic/classic_problems.hpp"
#include "sinew/problems/quasistatic/builtin_scenes.hpp"

#include <algorithm>

namespace sinew {

const std::vector<BuiltinProblem>& builtin_problems()
{
    static const std::vector<BuiltinProblem> problems = [] {
        std::vector<BuiltinProblem> all = classic_problems();
        for (auto& scene : quasistatic_scenes())
            all.push_back(std::move(scene));
        return all;
    }();
    return problems;
}

const BuiltinProblem& find_builtin_problem(const std::string& name)
{
    const auto& problems = builtin_problems();
    for (const auto& p : problems)
        if (p.name == name)
            return p;
    std::string choices;
    for (const auto& p : problems)
        choices += (choices.empty() ? "" : ", ") + p.name;
    throw InputError("unknown problem '" + name + "'; valid problems: " + choices);
}

std::vector<std::string> builtin_suites()
{
    std::vector<std::string> suites;
    for (const auto& p : builtin_problems())
        if (std::find(suites.begin(), suites.end(), p.suite) == suites.end())
            suites.push_back(p.suite);
    return suites;
}

} // namespace sinew
