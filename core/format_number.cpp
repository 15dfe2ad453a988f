#include "sinew/core/format_number.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace sinew {

std::string format_number(double value)
{
    if (std::isnan(value))
        return "nan";
    if (std::isinf(value))
        return value > 0 ? "inf" : "-inf";
    // std::to_chars without a precision gives the shortest round-trip form;
    // 32 characters hold every double in it.
    char text[32];
    const std::to_chars_result written = std::to_chars(text, text + sizeof(text), value);
    return std::string(text, written.ptr);
}

std::string table_cell(const char* pattern, double value)
{
    if (!std::isfinite(value))
        return "-";
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

} // namespace sinew
