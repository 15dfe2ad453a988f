#include "sinew/time/time_integrator.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/time/integrators.hpp"

#include <cmath>

namespace sinew {

const std::vector<std::string>& integrator_names()
{
    static const std::vector<std::string> names{"implicit-euler", "bdf2", "newmark", "implicit-midpoint"};
    return names;
}

std::unique_ptr<TimeIntegrator> make_integrator(const std::string& name, double time_step)
{
    if (!(std::isfinite(time_step) && time_step > 0.0))
        throw InputError("time step " + format_number(time_step) + " must be finite and > 0");
    if (name == "implicit-euler")
        return std::make_unique<ImplicitEuler>(time_step);
    if (name == "bdf2")
        return std::make_unique<Bdf2>(time_step);
    if (name == "newmark")
        return std::make_unique<Newmark>(time_step);
    if (name == "implicit-midpoint")
        return std::make_unique<ImplicitMidpoint>(time_step);
    std::string valid;
    for (const std::string& n : integrator_names())
        valid += (valid.empty() ? "" : ", ") + n;
    throw InputError("unknown integrator '" + name + "'; valid: " + valid);
}

} // namespace sinew
