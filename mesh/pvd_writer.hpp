#pragma once
#include <string>
#include <vector>

namespace sinew {

/// One data set of a ParaView collection: a file (relative to the .pvd) and
/// the time it shows.
struct PvdEntry {
    double time = 0.0;
    std::string file;
};

/// Writes a ParaView collection (.pvd: VTKFile type "Collection") listing
/// `entries` with their times, which ParaView plays as a time series.
/// InputError "path: cannot write file" when the file cannot be written.
void write_pvd(const std::string& path, const std::vector<PvdEntry>& entries);

} // namespace sinew
