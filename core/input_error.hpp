#pragma once
#include <stdexcept>
#include <string>

namespace sinew {

/// Bad input from the user: a file, a key, a parameter, a number, a name.
/// The message is one line that names what is wrong and where (file and
/// line, JSON path, parameter name). The CLI prints it and exits with code 2.
class InputError : public std::runtime_error {
public:
    explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

} // namespace sinew
