#pragma once
#include <string>

namespace sinew {

/// `value` in the fewest digits that read back to the same double ("1",
/// "0.5", "1e+20", "5e-324", "1.7976931348623157e+308", "inf", "nan"), for
/// messages: never the 300 digits of std::to_string(1e300).
std::string format_number(double value);

/// A table cell: `value` printed with the printf `pattern` (one double
/// conversion, such as "%.3f" or "%.2e"), or "-" when it is not finite.
std::string table_cell(const char* pattern, double value);

} // namespace sinew
