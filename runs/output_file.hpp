#pragma once
#include <string>

namespace sinew {

/// InputError naming `path` and the reason when a file could not be written
/// there (missing folder, no permission, a folder of that name). Creates and
/// changes nothing: a command checks this before its solve.
void check_writable(const std::string& path);

/// Writes `content` to `path` atomically: into a temporary file in the same
/// folder, renamed over `path` once complete, so that `path` holds either its
/// old content or the whole new one, never a truncated file. InputError
/// naming the path and the system's reason when it cannot.
void write_text_file(const std::string& path, const std::string& content);

} // namespace sinew
