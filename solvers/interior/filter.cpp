#include "sinew/solvers/interior/filter.hpp"

#include <algorithm>

namespace sinew {

bool Filter::accepts(double theta, double phi) const
{
    for (const auto& [theta_j, phi_j] : entries_)
        if (!(theta < theta_j || phi < phi_j))
            return false;
    return true;
}

void Filter::add(double theta, double phi)
{
    const double t = (1.0 - kGammaTheta) * theta;
    const double p = phi - kGammaPhi * theta;
    entries_.erase(std::remove_if(entries_.begin(), entries_.end(),
                                  [&](const auto& e) { return e.first >= t && e.second >= p; }),
                   entries_.end());
    entries_.emplace_back(t, p);
}

bool improves_on(double theta, double phi, double theta_k, double phi_k)
{
    return theta <= (1.0 - Filter::kGammaTheta) * theta_k || phi <= phi_k - Filter::kGammaPhi * theta_k;
}

} // namespace sinew
