// Every built-in scene up to 6k tets reaches the equilibrium recorded before
// the Newton core learned to reuse factorizations (issue 14). The 52k and
// 206k cantilevers are in test_large_equilibrium_invariance.cpp, the faces
// in test_face_equilibria.cpp (label heavy).
#include "recorded_equilibrium.hpp"

#include "sinew/problems/quasistatic/builtin_scene_files.hpp"

#include <fstream>

using sinew::testing::check_recorded_equilibrium;

TEST_CASE("every built-in scene has a recorded equilibrium")
{
    for (const sinew::BuiltinSceneFile& file : sinew::builtin_scene_files()) {
        if (file.dynamic)
            continue;  // stepped in time: tests/time
        CAPTURE(file.name);
        CHECK(std::ifstream(std::string(SINEW_EQUILIBRIA_DIR) + "/" + file.name + ".txt").good());
    }
}

TEST_CASE("cantilever-6k reaches its recorded equilibrium") { check_recorded_equilibrium("cantilever-6k"); }
TEST_CASE("twisted-cantilever-6k reaches its recorded equilibrium") { check_recorded_equilibrium("twisted-cantilever-6k"); }
TEST_CASE("muscle-spindle reaches its recorded equilibrium") { check_recorded_equilibrium("muscle-spindle"); }
TEST_CASE("qr-plate reaches its recorded equilibrium") { check_recorded_equilibrium("qr-plate"); }
TEST_CASE("codim-sheet reaches its recorded equilibrium") { check_recorded_equilibrium("codim-sheet"); }
TEST_CASE("draped-sheet reaches its recorded equilibrium") { check_recorded_equilibrium("draped-sheet"); }
TEST_CASE("inextensible-plate reaches its recorded equilibrium") { check_recorded_equilibrium("inextensible-plate"); }
TEST_CASE("locking-block reaches its recorded equilibrium") { check_recorded_equilibrium("locking-block"); }
TEST_CASE("helical-block-1k reaches its recorded equilibrium") { check_recorded_equilibrium("helical-block-1k"); }
TEST_CASE("helical-block-3k reaches its recorded equilibrium") { check_recorded_equilibrium("helical-block-3k"); }
TEST_CASE("helical-block-6k reaches its recorded equilibrium") { check_recorded_equilibrium("helical-block-6k"); }
TEST_CASE("hertz-sphere reaches its recorded equilibrium") { check_recorded_equilibrium("hertz-sphere"); }
TEST_CASE("block-on-sphere reaches its recorded equilibrium") { check_recorded_equilibrium("block-on-sphere"); }
TEST_CASE("block-on-sphere-vdb reaches its recorded equilibrium") { check_recorded_equilibrium("block-on-sphere-vdb"); }
