#pragma once
// The "constraints" array of a scene holds constraint sets of registered
// types: each ConstraintPart reads one "type" and declares its keys once,
// as scene parts do (scene_part.hpp).
#include "sinew/problems/quasistatic/parts/scene_part.hpp"

namespace sinew {

class ConstraintPart {
public:
    virtual ~ConstraintPart() = default;
    /// The "type" it reads.
    virtual std::string type() const = 0;
    virtual std::string doc() const = 0;
    /// Listed by increasing order ("valid: fiber_inextensibility, …").
    virtual int order() const = 0;
    /// Its keys beside "type", paths inside the array element.
    virtual std::vector<SceneKey> keys() const = 0;
    /// The set described by `c` (an element of the array).
    virtual std::shared_ptr<ConstraintSet> read(const JsonCursor& c, SceneAssembly& assembly) const = 0;
};

/// InputError for a second part of the same type.
void register_constraint_part(std::shared_ptr<const ConstraintPart> part);
/// By order.
std::vector<std::shared_ptr<const ConstraintPart>> constraint_parts();

template <typename Part>
struct ConstraintRegistration {
    ConstraintRegistration() { register_constraint_part(std::make_shared<Part>()); }
};

} // namespace sinew
