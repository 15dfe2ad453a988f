#include "sinew/mesh/grid_extent.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/mesh/mesh_validation.hpp"

#include <cmath>
#include <limits>

namespace sinew {

void check_grid_extent(const std::string& generator, const Eigen::VectorXd& lower, const Eigen::VectorXd& upper,
                       const Eigen::VectorXi& cells)
{
    for (Eigen::Index k = 0; k < cells.size(); ++k) {
        const std::string axis(1, "xyz"[k]);
        const auto fail = [&](const std::string& message) { throw InputError(generator + ": " + message); };
        if (cells[k] < 1)
            fail("n" + axis + " = " + std::to_string(cells[k]) + ", expected at least 1 cell");
        for (const double end : {lower[k], upper[k]})
            if (!(std::abs(end) <= kMaxCoordinate))
                fail(axis + " extent: " + format_number(end) + " is not a number within ±" +
                     format_number(kMaxCoordinate));
        if (!(lower[k] < upper[k]))
            fail("lower " + axis + " = " + format_number(lower[k]) + " must be below upper " + axis + " = " +
                 format_number(upper[k]));
        // The width must stand out from the corners' rounding, or neighbouring
        // nodes coincide: h > 2^-40·max(|lower|, |upper|), and h is normal.
        const double width = (upper[k] - lower[k]) / cells[k];
        const double magnitude = std::max(std::abs(lower[k]), std::abs(upper[k]));
        if (!(width >= std::numeric_limits<double>::min() && width > 0x1p-40 * magnitude))
            fail(axis + ": cells of width " + format_number(width) + " are too thin to resolve at coordinates of " +
                 format_number(magnitude));
    }
}

} // namespace sinew
