#include "sinew/mesh/base64.hpp"

namespace sinew {

std::string base64(const unsigned char* bytes, std::size_t size)
{
    static const char alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((size + 2) / 3 * 4);
    for (std::size_t i = 0; i < size; i += 3) {
        // Three bytes b0 b1 b2 make four 6-bit digits; missing bytes are padding.
        const unsigned b0 = bytes[i];
        const unsigned b1 = i + 1 < size ? bytes[i + 1] : 0u;
        const unsigned b2 = i + 2 < size ? bytes[i + 2] : 0u;
        const unsigned triple = (b0 << 16) | (b1 << 8) | b2;
        out += alphabet[(triple >> 18) & 63u];
        out += alphabet[(triple >> 12) & 63u];
        out += i + 1 < size ? alphabet[(triple >> 6) & 63u] : '=';
        out += i + 2 < size ? alphabet[triple & 63u] : '=';
    }
    return out;
}

} // namespace sinew
