#include "sinew/solvers/newton/forcing_term.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {

double ForcingTerm::next(double gradient_norm)
{
    double eta = eta_max;  // η₀
    if (previous_norm_ > 0.0) {
        eta = gamma * std::pow(gradient_norm / previous_norm_, alpha);  // γ (‖g_k‖/‖g_{k−1}‖)^α
        const double safeguard = gamma * std::pow(previous_eta_, alpha);
        if (safeguard > 0.1)
            eta = std::max(eta, safeguard);
        eta = std::min(eta, eta_max);
    } else {
        initial_norm_ = gradient_norm;
    }
    if (initial_norm_ > 0.0)
        eta = std::min(eta, gradient_norm / initial_norm_);  // η_k = O(‖g_k‖): quadratic
    previous_norm_ = gradient_norm;
    previous_eta_ = eta;
    return eta;
}

} // namespace sinew
