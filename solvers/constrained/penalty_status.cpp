#include "sinew/solvers/constrained/penalty_status.hpp"

#include "sinew/core/format_number.hpp"

namespace sinew {

std::string penalty_message(double violation, double kappa)
{
    return "stationary point of the penalty at kappa = " + format_number(kappa) + ", constraint violation " +
           format_number(violation);
}

std::string multiplier_method_message(double violation, double measure, double kappa)
{
    if (measure > violation)
        return penalty_message(violation, kappa) + ", and the multipliers still move by kappa * " +
               format_number(measure) + " (|c - P(c + lambda/kappa)|)";
    return penalty_message(violation, kappa) + ", and it stalls";
}

} // namespace sinew
