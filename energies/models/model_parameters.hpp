#pragma once
#include <map>
#include <string>
#include <vector>

namespace sinew {

/// One parameter of a constitutive model: its name (as in the seeds where they
/// name it), default, unit and the range it must lie in. A parameter with
/// `choices` takes one of those words; its value is the index of the word.
struct ParameterSpec {
    std::string name;
    double default_value = 0.0;
    std::string unit;         ///< "Pa", "1", …
    std::string description;  ///< one line
    double lower = -1e300;    ///< smallest valid value
    double upper = 1e300;     ///< largest valid value
    bool lower_exclusive = false;  ///< value must be > lower rather than >=
    std::vector<std::string> choices;
};

/// Parameter values by name, every parameter of the model present.
using ParameterValues = std::map<std::string, double>;
/// Parameters as the user gave them (text), before validation.
using ParameterText = std::map<std::string, std::string>;

/// Fills defaults and validates: an unknown name, a non-finite or malformed
/// number, a value out of range or an unknown choice throws InputError naming
/// the model and the parameter.
ParameterValues resolve_parameters(const std::string& model, const std::vector<ParameterSpec>& specs,
                                   const ParameterText& given);

/// Same, from numbers (for code that builds models directly).
ParameterValues resolve_parameters(const std::string& model, const std::vector<ParameterSpec>& specs,
                                   const ParameterValues& given);

} // namespace sinew
