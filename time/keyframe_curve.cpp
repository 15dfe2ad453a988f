#include "sinew/time/keyframe_curve.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace sinew {

KeyframeCurve::KeyframeCurve(std::vector<Keyframe> keyframes) : keys_(std::move(keyframes))
{
    for (size_t k = 0; k < keys_.size(); ++k) {
        const std::string label = "keyframe " + std::to_string(k);
        if (!std::isfinite(keys_[k].time) || !std::isfinite(keys_[k].value))
            throw InputError(label + " is not finite");
        if (k > 0 && !(keys_[k].time > keys_[k - 1].time))
            throw InputError(label + ": time " + format_number(keys_[k].time) + " is not after the previous " +
                             format_number(keys_[k - 1].time) + " (keyframes must be in increasing time)");
    }
}

double KeyframeCurve::at(double t) const
{
    if (keys_.empty())
        return fallback_;
    if (t <= keys_.front().time)
        return keys_.front().value;
    if (t >= keys_.back().time)
        return keys_.back().value;
    const auto after = std::upper_bound(keys_.begin(), keys_.end(), t,
                                        [](double time, const Keyframe& k) { return time < k.time; });
    const Keyframe& b = *after;
    const Keyframe& a = *(after - 1);
    const double w = (t - a.time) / (b.time - a.time);
    return (1.0 - w) * a.value + w * b.value;
}

double KeyframeCurve::lowest() const
{
    double least = keys_.empty() ? fallback_ : keys_.front().value;
    for (const Keyframe& k : keys_)
        least = std::min(least, k.value);
    return least;
}

double KeyframeCurve::highest() const
{
    double greatest = keys_.empty() ? fallback_ : keys_.front().value;
    for (const Keyframe& k : keys_)
        greatest = std::max(greatest, k.value);
    return greatest;
}

} // namespace sinew
