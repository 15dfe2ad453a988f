#pragma once
// One registry for every kind of registered part (scene parts, constraint
// types): parts register when the library loads, each under a unique name,
// and are handed out in a fixed order that does not depend on the order in
// which the library's files happened to register them.
#include "sinew/core/input_error.hpp"

#include <algorithm>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace sinew {

/// `name_of(part)` is the unique name, `rank_of(part)` the order.
template <typename Part>
class PartRegistry {
public:
    using Pointer = std::shared_ptr<const Part>;

    /// InputError when a part of the same name is registered already.
    template <typename NameOf>
    void add(Pointer part, const NameOf& name_of, const std::string& what)
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        for (const Pointer& p : parts_)
            if (name_of(*p) == name_of(*part))
                throw InputError(what + " '" + name_of(*part) + "' is registered twice");
        parts_.push_back(std::move(part));
    }

    /// Every part, by increasing rank.
    template <typename RankOf>
    std::vector<Pointer> sorted(const RankOf& rank_of) const
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        std::vector<Pointer> parts = parts_;
        std::stable_sort(parts.begin(), parts.end(),
                         [&](const Pointer& a, const Pointer& b) { return rank_of(*a) < rank_of(*b); });
        return parts;
    }

private:
    mutable std::mutex mutex_;
    std::vector<Pointer> parts_;
};

} // namespace sinew
