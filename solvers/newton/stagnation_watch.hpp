#pragma once
#include <vector>

namespace sinew {

/// Whether a descent iteration has stopped making progress. Near a point
/// where ∇f is kinked (the signed distance inside a faceted body, which a
/// penalty or augmented Lagrangian lets nodes reach) or noisy (round-off of
/// a stiff penalty's κ c ∇c), every step is accepted, by Armijo or by the
/// line search's round-off test, and none gets the gradient to its target:
/// without a watch such a solve runs to its iteration limit (3000 iterations
/// of augmented-lagrangian on block-on-sphere). The iteration stagnates when
/// over the last `window` accepted steps f fell by no more than its
/// round-off band, 1e-12·max(1, |f|) (the line search's), and the smallest
/// gradient norm seen did not halve.
class StagnationWatch {
public:
    explicit StagnationWatch(int window = kDefaultWindow);

    /// Records the point an accepted step reached (its f and gradient norm;
    /// the first call, the starting point); true when the iteration stagnates.
    bool stagnant(double f, double gradient_norm);

    int window() const { return window_; }

    static constexpr int kDefaultWindow = 20;

private:
    struct Mark {
        double f = 0.0;
        double best_gradient = 0.0;  ///< the smallest gradient norm up to this point
    };
    int window_;
    std::vector<Mark> marks_;  ///< the last window + 1 points, a ring
    int recorded_ = 0;
};

} // namespace sinew
