#pragma once
#include <cstddef>
#include <string>

namespace sinew {

/// The standard base64 encoding (RFC 4648, with '=' padding) of `size` bytes.
std::string base64(const unsigned char* bytes, std::size_t size);

} // namespace sinew
