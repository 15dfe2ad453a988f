#include "sinew/core/parse_number.hpp"

#include "sinew/core/input_error.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace sinew {

double parse_finite_double(const std::string& text, const std::string& what)
{
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(begin, &end);
    if (text.empty() || end != begin + text.size())
        throw InputError(what + ": '" + text + "' is not a number");
    // ERANGE also flags a result that underflowed to a subnormal or to zero:
    // that is the nearest double and is accepted; only an overflow is not.
    if (!std::isfinite(value))
        throw InputError(what + ": '" + text + "' is not a finite number");
    return value;
}

int parse_int(const std::string& text, const std::string& what)
{
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const long value = std::strtol(begin, &end, 10);
    if (text.empty() || end != begin + text.size())
        throw InputError(what + ": '" + text + "' is not an integer");
    if (errno == ERANGE || value > std::numeric_limits<int>::max() || value < std::numeric_limits<int>::min())
        throw InputError(what + ": '" + text + "' is out of range");
    return static_cast<int>(value);
}

} // namespace sinew
