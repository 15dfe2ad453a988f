#pragma once
// A scene file is a list of parts (DESIGN.md, "A scene is composed of
// declared parts"): each top-level key is read by one registered ScenePart,
// which declares its keys once (type, range or choices, default, one line of
// doc) and builds its piece of the scene. parse_scene is a loop over the
// parts; a new part is a new file and one registration, and never an edit of
// the reader or of another part.
#include "sinew/energies/constraints/constraint_set.hpp"
#include "sinew/energies/potentials/potential.hpp"
#include "sinew/problems/quasistatic/dirichlet_set.hpp"
#include "sinew/problems/quasistatic/quasistatic_problem.hpp"
#include "sinew/problems/quasistatic/scene.hpp"
#include "sinew/problems/quasistatic/strict_json.hpp"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sinew {

/// One JSON key of a part, declared once. `path` is inside the part's value
/// ("time_step", "damping.mass"; "" for the value itself, "[]" for the
/// elements of an array, "[].type" for a key of each element).
struct SceneKey {
    std::string path;
    std::string type;  ///< number, integer, string, boolean, vector, matrix, array, object, selection, …
    std::string range;  ///< "(0, inf)", "[0, 1]", "implicit-euler | bdf2", … ("" when any value of the type)
    std::string default_value;  ///< "" when required or when absence means "none"
    std::string doc;            ///< one line
    bool required = false;
    double lower = -HUGE_VAL;  ///< numbers and integers: the closed range read_number enforces
    double upper = HUGE_VAL;
};

/// `key` with the closed range [lower, upper] that DeclaredKeys enforces.
inline SceneKey ranged(SceneKey key, double lower, double upper)
{
    key.lower = lower;
    key.upper = upper;
    return key;
}

/// What the parts build together while a scene is read: the scene itself,
/// and the pieces composed into its NLP once every part has been read.
struct SceneAssembly {
    SceneAssembly(Scene& s, std::string folder) : scene(s), base_folder(std::move(folder)) {}

    Scene& scene;
    std::string base_folder;  ///< where relative paths start ("" for the working directory)
    double tolerance = 0.0;   ///< node selections: 1e-9 of the scene's size
    std::optional<JsonCursor> mesh_place;  ///< the "mesh" value: where errors of its elements are reported
    std::vector<double> densities;          ///< per mesh group (materials)
    std::vector<char> group_has_fiber;      ///< per mesh group (materials)
    std::vector<std::shared_ptr<Potential>> terms;  ///< the potentials, elastic first
    std::vector<DirichletSet> dirichlet_sets;
    QuasistaticOptions options;
    /// Where each of scene.scaled is written, for its messages: its own
    /// curve when it has one, else the quantity.
    std::vector<JsonCursor> scaled_places;
    std::optional<JsonCursor> load_curve_place;  ///< dynamics.load_curve, when given

    /// Adds a quantity a load factor scales (Scene::scaled), written at `place`.
    void add_scaled(ScaledQuantity quantity, const JsonCursor& place);
};

/// Once every part is read: a quantity with its own curve needs the scene's
/// dynamics, and every quantity must admit the factors it will take (its
/// curve's, dynamics.load_curve's, or a load step's s ∈ [0, 1]). InputError
/// at the curve or the quantity otherwise.
void check_scaled_quantities(const SceneAssembly& assembly);

class ScenePart {
public:
    virtual ~ScenePart() = default;
    /// The top-level key the part reads.
    virtual std::string key() const = 0;
    /// One line for the listing.
    virtual std::string doc() const = 0;
    /// scene, potential, constraints or run.
    virtual std::string kind() const = 0;
    virtual bool required() const { return false; }
    /// Whether the part applies to a scene without a mesh (an "mpm" scene):
    /// its name, description, run settings and the "mpm" section itself.
    virtual bool mesh_free() const { return false; }
    /// Whether the part acts on the particles of an "mpm" section, and so
    /// means nothing in a scene without one (damage, inextensibility).
    virtual bool needs_mpm() const { return false; }
    /// Parts are read by increasing stage, after the parts whose pieces they
    /// use: the mesh (10), materials (20), potentials (30…), boundary
    /// conditions (40…), constraint sets (50), run settings (60…). Each part
    /// has its own stage, so the order does not depend on registration.
    virtual int stage() const = 0;
    /// Every key the part reads, once.
    virtual std::vector<SceneKey> keys() const = 0;
    /// Reads `value` (the part's key is present) into the assembly.
    virtual void read(const JsonCursor& value, SceneAssembly& assembly) const = 0;
};

/// Adds a part. InputError for a second part with the same key.
void register_scene_part(std::shared_ptr<const ScenePart> part);
/// The registered parts by stage: the order they are read in and listed in
/// messages ("valid keys: name, description, mesh, …").
std::vector<std::shared_ptr<const ScenePart>> scene_parts();

/// Every part's keys as markdown, one table for the scene's top level and
/// one per part with keys inside its value: the text of `sinew list
/// --scene-keys` and of docs/scenes.md, "Every key".
std::string scene_keys_markdown();

/// Registers a part when the library loads: one line in the part's file,
/// `const SceneRegistration<GravityPart> registered;`.
template <typename Part>
struct SceneRegistration {
    SceneRegistration() { register_scene_part(std::make_shared<Part>()); }
};

/// The declared keys of a part, for reading: unknown keys, ranges and
/// choices come from the declarations, so each is written once.
class DeclaredKeys {
public:
    explicit DeclaredKeys(std::vector<SceneKey> keys) : keys_(std::move(keys)) {}
    /// InputError unless `object` is an object whose keys are all declared
    /// directly under `path` ("" for the part's value).
    void expect_object(const JsonCursor& object, const std::string& path = "") const;
    /// The number at `path` in its declared closed range [lower, upper].
    double number(const JsonCursor& value, const std::string& path) const;
    /// The whole number at `path` in its declared range.
    int integer(const JsonCursor& value, const std::string& path) const;
    const SceneKey& at(const std::string& path) const;

private:
    std::vector<SceneKey> keys_;
};

} // namespace sinew
