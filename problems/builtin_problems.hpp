#pragma once
#include "sinew/problems/nlp.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sinew {

/// A problem sinew ships, runnable by name from the CLI and the bench harness.
struct BuiltinProblem {
    std::string name;         ///< e.g. "hs071"
    std::string suite;        ///< bench suite it belongs to, e.g. "classic"
    std::string description;  ///< one line
    std::function<std::unique_ptr<Nlp>()> make;
    /// Published optimal objective f*, where the literature gives one.
    std::optional<double> reference_objective;
    /// Where f* comes from (book, problem number).
    std::string reference_source;
    /// For a built-in scene, its name (scenes/<name>.json; the CLI solves it
    /// as a scene, with VTU output); empty for other problems.
    std::string scene;
};

/// Every built-in problem, in a fixed order.
const std::vector<BuiltinProblem>& builtin_problems();

/// The built-in problem called `name`; InputError listing the valid names otherwise.
const BuiltinProblem& find_builtin_problem(const std::string& name);

/// Names of the bench suites, in order of first appearance.
std::vector<std::string> builtin_suites();

} // namespace sinew
