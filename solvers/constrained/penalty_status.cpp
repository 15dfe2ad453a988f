#include "sinew/solvers/constrained/penalty_status.hpp"

#include "sinew/core/format_number.hpp"

namespace sinew {

std::string penalty_message(double violation, double kappa)
{
    return "stationary point of the penalty at kappa = " + format_number(kappa) + ", constraint violation " +
           format_number(violation);
}

} // namespace sinew
