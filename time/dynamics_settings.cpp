#include "sinew/time/dynamics_settings.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {

// ⌈T/h⌉, with T/h = 20.000000000000004 (0.2/0.01) counted as 20.
long long DynamicsSettings::num_steps() const
{
    return std::max(1LL, static_cast<long long>(std::ceil(duration / time_step * (1.0 - 1e-12))));
}

} // namespace sinew
