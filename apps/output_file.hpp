#pragma once
#include <string>

namespace sinew::cli {

/// Writes `content` to `path`; InputError naming the path and the system's
/// reason when it cannot (missing folder, no permission).
void write_text_file(const std::string& path, const std::string& content);

} // namespace sinew::cli
