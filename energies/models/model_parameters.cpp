#include "sinew/energies/models/model_parameters.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/core/parse_number.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace sinew {
namespace {

const ParameterSpec& find_spec(const std::string& model, const std::vector<ParameterSpec>& specs,
                               const std::string& name)
{
    for (const auto& spec : specs)
        if (spec.name == name)
            return spec;
    std::string valid;
    for (const auto& spec : specs)
        valid += (valid.empty() ? "" : ", ") + spec.name;
    throw InputError("model " + model + ": unknown parameter '" + name + "'; valid parameters: " +
                     (valid.empty() ? "(none)" : valid));
}

/// `written` is the value as the user wrote it (quoted as such), or empty.
void check_range(const std::string& model, const ParameterSpec& spec, double value, const std::string& written = "")
{
    const bool below = spec.lower_exclusive ? value <= spec.lower : value < spec.lower;
    if (!std::isfinite(value) || below || value > spec.upper) {
        std::string message = "model " + model + ": parameter " + spec.name + " = " +
                              (written.empty() ? format_number(value) : written) + " is out of range; it must be " +
                              (spec.lower_exclusive ? "> " : ">= ") + format_number(spec.lower);
        if (spec.upper < 1e300)
            message += " and <= " + format_number(spec.upper);
        throw InputError(message);
    }
}

ParameterValues defaults(const std::vector<ParameterSpec>& specs)
{
    ParameterValues values;
    for (const auto& spec : specs)
        values[spec.name] = spec.default_value;
    return values;
}

} // namespace

ParameterValues resolve_parameters(const std::string& model, const std::vector<ParameterSpec>& specs,
                                   const ParameterText& given)
{
    ParameterValues values = defaults(specs);
    for (const auto& [name, text] : given) {
        const ParameterSpec& spec = find_spec(model, specs, name);
        if (!spec.choices.empty()) {
            const auto it = std::find(spec.choices.begin(), spec.choices.end(), text);
            if (it == spec.choices.end()) {
                std::string valid;
                for (const auto& c : spec.choices)
                    valid += (valid.empty() ? "" : ", ") + c;
                throw InputError("model " + model + ": parameter " + name + " = '" + text +
                                 "' is not one of: " + valid);
            }
            values[name] = static_cast<double>(it - spec.choices.begin());
            continue;
        }
        const double value = parse_finite_double(text, "model " + model + ": parameter " + name);
        check_range(model, spec, value, text);
        values[name] = value;
    }
    return values;
}

ParameterValues resolve_parameters(const std::string& model, const std::vector<ParameterSpec>& specs,
                                   const ParameterValues& given)
{
    ParameterValues values = defaults(specs);
    for (const auto& [name, value] : given) {
        const ParameterSpec& spec = find_spec(model, specs, name);
        if (!spec.choices.empty()) {
            if (value != std::floor(value) || value < 0 || value >= static_cast<double>(spec.choices.size()))
                throw InputError("model " + model + ": parameter " + name + " must be a choice index below " +
                                 std::to_string(spec.choices.size()));
        } else {
            check_range(model, spec, value);
        }
        values[name] = value;
    }
    return values;
}

} // namespace sinew
