#include "sinew/problems/classic/classic_problems.hpp"

#include "sinew/problems/classic/hs003.hpp"
#include "sinew/problems/classic/hs004.hpp"
#include "sinew/problems/classic/hs005.hpp"
#include "sinew/problems/classic/hs006.hpp"
#include "sinew/problems/classic/hs007.hpp"
#include "sinew/problems/classic/hs009.hpp"
#include "sinew/problems/classic/hs027.hpp"
#include "sinew/problems/classic/hs028.hpp"
#include "sinew/problems/classic/hs035.hpp"
#include "sinew/problems/classic/hs038.hpp"
#include "sinew/problems/classic/hs039.hpp"
#include "sinew/problems/classic/hs040.hpp"
#include "sinew/problems/classic/hs041.hpp"
#include "sinew/problems/classic/hs042.hpp"
#include "sinew/problems/classic/hs043.hpp"
#include "sinew/problems/classic/hs045.hpp"
#include "sinew/problems/classic/hs053.hpp"
#include "sinew/problems/classic/hs056.hpp"
#include "sinew/problems/classic/hs060.hpp"
#include "sinew/problems/classic/hs061.hpp"
#include "sinew/problems/classic/hs062.hpp"
#include "sinew/problems/classic/hs063.hpp"
#include "sinew/problems/classic/hs065.hpp"
#include "sinew/problems/classic/hs071.hpp"
#include "sinew/problems/classic/hs076.hpp"
#include "sinew/problems/classic/hs077.hpp"
#include "sinew/problems/classic/hs078.hpp"
#include "sinew/problems/classic/hs079.hpp"
#include "sinew/problems/classic/hs081.hpp"
#include "sinew/problems/classic/hs100.hpp"
#include "sinew/problems/classic/hs110.hpp"
#include "sinew/problems/classic/hs112.hpp"
#include "sinew/problems/classic/rosenbrock.hpp"

#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sinew {
namespace {

constexpr double kPi = 3.14159265358979323846;

const char* const kHockSchittkowski =
    "W. Hock, K. Schittkowski, Test Examples for Nonlinear Programming Codes, "
    "Lecture Notes in Economics and Mathematical Systems 187, Springer, 1981";

/// A Hock-Schittkowski problem in `suite`; `note` (may be empty) qualifies the
/// published f*, e.g. how many digits it was printed with.
BuiltinProblem hock_schittkowski_in(const std::string& suite, const std::string& name, int number,
                                    const std::string& kind, std::function<std::unique_ptr<Nlp>()> make,
                                    double published_optimum, const std::string& note = "")
{
    return {name,
            suite,
            "HS " + std::to_string(number) + ": " + kind,
            std::move(make),
            published_optimum,
            std::string(kHockSchittkowski) + ", problem " + std::to_string(number) + (note.empty() ? "" : "; " + note),
            ""};
}

BuiltinProblem hock_schittkowski(const std::string& name, int number, const std::string& kind,
                                 std::function<std::unique_ptr<Nlp>()> make, double published_optimum)
{
    return hock_schittkowski_in("classic", name, number, kind, std::move(make), published_optimum);
}

/// Suite "constrained": problems with equality constraints and/or bounds only,
/// no general inequalities.
BuiltinProblem constrained(const std::string& name, int number, const std::string& kind,
                           std::function<std::unique_ptr<Nlp>()> make, double published_optimum,
                           const std::string& note = "")
{
    return hock_schittkowski_in("constrained", name, number, kind, std::move(make), published_optimum, note);
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
        constrained("hs003", 3, "2 variables, bounds (singular Hessian, f linear along (1, 1))",
                    [] { return std::make_unique<Hs003>(); }, 0.0),
        constrained("hs004", 4, "2 variables, bounds (both active at the optimum)",
                    [] { return std::make_unique<Hs004>(); }, 8.0 / 3.0),
        constrained("hs005", 5, "2 variables, bounds (nonconvex)",
                    [] { return std::make_unique<Hs005>(); }, -std::sqrt(3.0) / 2.0 - kPi / 3.0),
        constrained("hs007", 7, "2 variables, 1 equality (nonconvex)",
                    [] { return std::make_unique<Hs007>(); }, -std::sqrt(3.0)),
        constrained("hs009", 9, "2 variables, 1 equality (nonconvex, infinitely many minimizers)",
                    [] { return std::make_unique<Hs009>(); }, -0.5),
        constrained("hs027", 27, "3 variables, 1 equality (nonconvex)",
                    [] { return std::make_unique<Hs027>(); }, 0.04),
        constrained("hs038", 38, "4 variables, bounds (Colville, nonconvex)",
                    [] { return std::make_unique<Hs038>(); }, 0.0),
        constrained("hs039", 39, "4 variables, 2 equalities (nonconvex constraints)",
                    [] { return std::make_unique<Hs039>(); }, -1.0),
        constrained("hs040", 40, "4 variables, 3 equalities (nonconvex)",
                    [] { return std::make_unique<Hs040>(); }, -0.25),
        constrained("hs041", 41, "4 variables, bounds, 1 equality (nonconvex)",
                    [] { return std::make_unique<Hs041>(); }, 52.0 / 27.0),
        constrained("hs042", 42, "4 variables, 2 equalities (nonconvex constraint)",
                    [] { return std::make_unique<Hs042>(); }, 28.0 - 10.0 * std::sqrt(2.0)),
        constrained("hs045", 45, "5 variables, bounds (nonconvex, every upper bound active)",
                    [] { return std::make_unique<Hs045>(); }, 1.0),
        constrained("hs053", 53, "5 variables, bounds, 3 equalities (convex QP)",
                    [] { return std::make_unique<Hs053>(); }, 176.0 / 43.0),
        constrained("hs056", 56, "7 variables, 4 equalities (nonconvex)",
                    [] { return std::make_unique<Hs056>(); }, -3.456),
        constrained("hs060", 60, "3 variables, bounds, 1 equality (nonconvex constraint)",
                    [] { return std::make_unique<Hs060>(); }, 0.03256820025, "f* as printed, 10 digits"),
        constrained("hs061", 61, "3 variables, 2 equalities (nonconvex constraints)",
                    [] { return std::make_unique<Hs061>(); }, -143.6461422, "f* as printed, 10 digits"),
        constrained("hs062", 62, "3 variables, bounds, 1 equality",
                    [] { return std::make_unique<Hs062>(); }, -26272.51448, "f* as printed, 10 digits"),
        constrained("hs063", 63, "3 variables, bounds, 2 equalities (nonconvex)",
                    [] { return std::make_unique<Hs063>(); }, 961.7151721, "f* as printed, 10 digits"),
        constrained("hs077", 77, "5 variables, 2 equalities (nonconvex)",
                    [] { return std::make_unique<Hs077>(); }, 0.24150513, "f* as printed, 8 digits"),
        constrained("hs078", 78, "5 variables, 3 equalities (nonconvex)",
                    [] { return std::make_unique<Hs078>(); }, -2.91970041, "f* as printed, 9 digits"),
        constrained("hs079", 79, "5 variables, 3 equalities (nonconvex)",
                    [] { return std::make_unique<Hs079>(); }, 0.0787768209, "f* as printed, 9 digits"),
        constrained("hs081", 81, "5 variables, bounds, 3 equalities (nonconvex)",
                    [] { return std::make_unique<Hs081>(); }, 0.0539498478, "f* as printed, 9 digits"),
        constrained("hs110", 110, "10 variables, bounds (Paviani, nonconvex)",
                    [] { return std::make_unique<Hs110>(); }, -45.77846971, "f* as printed, 10 digits"),
        constrained("hs112", 112, "10 variables, bounds, 3 equalities (chemical equilibrium, convex)",
                    [] { return std::make_unique<Hs112>(); }, -47.76109026,
                    "f* as printed in the later listings, 10 digits, right to 7 (the KKT point gives "
                    "-47.7610908594); the 1981 book prints -47.707579 at a point that is not a minimizer"),
    };
}

} // namespace sinew
