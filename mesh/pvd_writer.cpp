#include "sinew/mesh/pvd_writer.hpp"

#include "sinew/core/input_error.hpp"

#include <fstream>
#include <iomanip>
#include <limits>

namespace sinew {

void write_pvd(const std::string& path, const std::vector<PvdEntry>& entries)
{
    std::ofstream out(path);
    if (!out)
        throw InputError(path + ": cannot write file");
    out << std::setprecision(std::numeric_limits<double>::max_digits10);
    out << "<?xml version=\"1.0\"?>\n"
        << "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
        << "  <Collection>\n";
    for (const PvdEntry& e : entries)
        out << "    <DataSet timestep=\"" << e.time << "\" group=\"\" part=\"0\" file=\"" << e.file << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
    if (!out)
        throw InputError(path + ": cannot write file");
}

} // namespace sinew
