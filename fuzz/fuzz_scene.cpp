// parse_scene (problems/quasistatic/scene_reader.hpp) on JSON text, then
// resolve_scene_run (runs/scene_runner.hpp), which checks the scene's solver
// name and its declared options, nested ones included.
// base_folder is a folder that does not exist (and holds nothing): a mesh
// "file" or a "tetrahedralize" surface named by a relative path fails at once
// with InputError (cannot open), so no input reads a real mesh file or starts
// TetGen. Generators run: a scene asking for up to 2e7 elements is accepted
// and slow (libFuzzer reports a slow unit or a timeout; docs/fuzzing.md).
#include "fuzz_support.hpp"

#include "sinew/problems/quasistatic/scene_reader.hpp"
#include "sinew/runs/scene_runner.hpp"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    static const std::string no_folder = sinew_fuzz::scratch_path("no-such-folder");
    const std::string text(reinterpret_cast<const char*>(data), size);
    sinew_fuzz::expect_input_error_only([&] {
        const sinew::Scene scene = sinew::parse_scene(text, "fuzz.json", no_folder);
        sinew::resolve_scene_run(scene, sinew::SceneRunRequest{});
    });
    return 0;
}
