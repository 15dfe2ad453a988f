#include "sinew/problems/quasistatic/parts/scene_part.hpp"

#include "sinew/core/format_number.hpp"

namespace sinew {

void SceneAssembly::add_scaled(ScaledQuantity quantity, const JsonCursor& place)
{
    scene.scaled.push_back(std::move(quantity));
    scaled_places.push_back(place);
}

void check_scaled_quantities(const SceneAssembly& assembly)
{
    const Scene& scene = assembly.scene;
    for (size_t k = 0; k < scene.scaled.size(); ++k) {
        const ScaledQuantity& q = scene.scaled[k];
        const JsonCursor& place = assembly.scaled_places[k];
        if (q.curve && !scene.dynamics)
            place.fail("a curve over time needs the scene's \"dynamics\" (load steps scale by s = k/N)");
        if (!q.refusal)
            continue;
        if (q.curve) {
            const std::string why = q.refusal(q.curve->lowest(), q.curve->highest());
            if (!why.empty())
                place.fail(why);
        } else if (scene.dynamics) {
            const KeyframeCurve& s = scene.dynamics->load_factor;
            const std::string why = q.refusal(s.lowest(), s.highest());
            if (!why.empty())
                (assembly.load_curve_place ? *assembly.load_curve_place : place).fail(q.name + ": " + why);
        } else {
            const std::string why = q.refusal(0.0, 1.0);  // load steps s = k/N
            if (!why.empty())
                place.fail(why);
        }
    }
}

} // namespace sinew
