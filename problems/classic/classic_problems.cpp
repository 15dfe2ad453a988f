#include "sinew/problems/classic/classic_problems.hpp"

#include "sinew/problems/classic/hs006.hpp"
#include "sinew/problems/classic/hs028.hpp"
#include "sinew/problems/classic/hs035.hpp"
#include "sinew/problems/classic/hs043.hpp"
#include "sinew/problems/classic/hs065.hpp"
#include "sinew/problems/classic/hs071.hpp"
#include "sinew/problems/classic/hs076.hpp"
#include "sinew/problems/classic/hs100.hpp"
#include "sinew/problems/classic/rosenbrock.hpp"

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sinew {
namespace {

const char* const kHockSchittkowski =
    "W. Hock, K. Schittkowski, Test Examples for Nonlinear Programming Codes, "
    "Lecture Notes in Economics and Mathematical Systems 187, Springer, 1981";

BuiltinProblem hock_schittkowski(const std::string& name, int number, const std::string& kind,
                                 std::function<std::unique_ptr<Nlp>()> make, double published_optimum)
{
    return {name,
            "classic",
            "HS " + std::to_string(number) + ": " + kind,
            std::move(make),
            published_optimum,
            std::string(kHockSchittkowski) + ", problem " + std::to_string(number),
            ""};
}

} // namespace

std::vector<BuiltinProblem> classic_problems()
{
    const std::string rosenbrock_source =
        "f* = 0 at x = (1, ..., 1), where every term vanishes; More, Garbow, Hillstrom, ACM TOMS 7 (1981) 17-41, "
        "problem 21 (extended Rosenbrock); H. H. Rosenbrock, The Computer Journal 3 (1960) 175-184";
    return {
        {"rosenbrock2", "classic", "Rosenbrock: 2 variables, unconstrained",
         [] { return std::make_unique<Rosenbrock>(2); }, 0.0, rosenbrock_source, ""},
        {"rosenbrock1000", "classic", "extended Rosenbrock: 1000 variables, unconstrained, block-diagonal Hessian",
         [] { return std::make_unique<Rosenbrock>(1000); }, 0.0, rosenbrock_source, ""},
        hock_schittkowski("hs071", 71, "4 variables, bounds, 1 equality, 1 inequality",
                          [] { return std::make_unique<Hs071>(); }, 17.0140173),
        hock_schittkowski("hs006", 6, "2 variables, 1 equality",
                          [] { return std::make_unique<Hs006>(); }, 0.0),
        hock_schittkowski("hs028", 28, "3 variables, 1 equality",
                          [] { return std::make_unique<Hs028>(); }, 0.0),
        hock_schittkowski("hs035", 35, "3 variables, bounds, 1 inequality",
                          [] { return std::make_unique<Hs035>(); }, 1.0 / 9.0),
        hock_schittkowski("hs043", 43, "4 variables, 3 inequalities",
                          [] { return std::make_unique<Hs043>(); }, -44.0),
        hock_schittkowski("hs065", 65, "3 variables, bounds, 1 inequality",
                          [] { return std::make_unique<Hs065>(); }, 0.9535288567),
        hock_schittkowski("hs076", 76, "4 variables, bounds, 3 inequalities",
                          [] { return std::make_unique<Hs076>(); }, -4.681818181),
        hock_schittkowski("hs100", 100, "7 variables, 4 inequalities",
                          [] { return std::make_unique<Hs100>(); }, 680.6300573),
    };
}

} // namespace sinew
