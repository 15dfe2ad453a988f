#include "sinew/runs/step_gradient_target.hpp"

#include "sinew/solvers/solver.hpp"

namespace sinew {

bool step_sets(const SceneRunSettings& settings, const std::string& name)
{
    if (settings.options.backend.count(name) > 0)
        return false;
    for (const OptionDeclaration& option : find_solver(settings.solver).declared_options())
        if (option.name == name)
            return true;
    return false;
}

} // namespace sinew
