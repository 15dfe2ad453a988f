#include "sinew/mpm/grid_condition.hpp"

#include "sinew/core/input_error.hpp"

namespace sinew {

GridCondition grid_condition(const std::string& name)
{
    if (name == "sticky")
        return GridCondition::sticky;
    if (name == "slip")
        return GridCondition::slip;
    if (name == "separate")
        return GridCondition::separate;
    throw InputError("grid condition '" + name + "' is unknown; it must be one of: sticky, slip, separate");
}

} // namespace sinew
