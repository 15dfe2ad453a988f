#pragma once
#include <vector>

namespace sinew {

/// A value over time, piecewise linear between keyframes (t_k, v_k) with
/// strictly increasing t_k, constant before the first and after the last.
/// No keyframe: the constant `fallback`.
class KeyframeCurve {
public:
    struct Keyframe {
        double time;
        double value;
    };

    explicit KeyframeCurve(double fallback = 1.0) : fallback_(fallback) {}
    /// InputError naming the keyframe for a non-finite entry or a time not
    /// after the one before.
    explicit KeyframeCurve(std::vector<Keyframe> keyframes);

    double at(double t) const;
    const std::vector<Keyframe>& keyframes() const { return keys_; }
    /// The least and the greatest value the curve takes (piecewise linear:
    /// those of its keyframes, or the fallback).
    double lowest() const;
    double highest() const;

private:
    std::vector<Keyframe> keys_;
    double fallback_ = 1.0;
};

} // namespace sinew
