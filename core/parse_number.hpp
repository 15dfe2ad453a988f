#pragma once
#include <string>

namespace sinew {

/// Parses the whole of `text` as a finite double; throws InputError naming
/// `what` (e.g. "option tol") when it is not a number or is not finite.
double parse_finite_double(const std::string& text, const std::string& what);

/// Parses the whole of `text` as an int; throws InputError naming `what`.
int parse_int(const std::string& text, const std::string& what);

} // namespace sinew
