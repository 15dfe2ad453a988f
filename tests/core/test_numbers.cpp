// Reading numbers from text (command line, mesh files, options) and writing
// them into messages.
#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/core/parse_number.hpp"

#include <catch2/catch.hpp>

#include <cfloat>
#include <cmath>
#include <limits>

using namespace sinew;
using Catch::Contains;

TEST_CASE("parse_finite_double takes every finite double, subnormals included")
{
    CHECK(parse_finite_double("4.9e-324", "x") == std::numeric_limits<double>::denorm_min());
    CHECK(parse_finite_double("2.2250738585072009e-308", "x") > 0.0);   // the largest subnormal
    CHECK(parse_finite_double("1e-400", "x") == 0.0);                   // rounds to zero, as 0.1 rounds
    CHECK(parse_finite_double("-1.7976931348623157e308", "x") == -DBL_MAX);
    CHECK(parse_finite_double("1.5", "x") == 1.5);
}

TEST_CASE("parse_finite_double refuses what is not a finite double, naming it")
{
    for (const char* text : {"1e309", "-1e400", "inf", "nan", "", "1.5x", "x"}) {
        CAPTURE(text);
        CHECK_THROWS_WITH(parse_finite_double(text, "option tol"),
                          Contains("option tol") && Contains(std::string("'") + text + "'"));
    }
}

TEST_CASE("parse_int refuses out-of-range and non-integer text")
{
    CHECK(parse_int("-2147483648", "n") == std::numeric_limits<int>::min());
    for (const char* text : {"2147483648", "1.0", "", "12a"}) {
        CAPTURE(text);
        CHECK_THROWS_AS(parse_int(text, "n"), InputError);
    }
}

TEST_CASE("format_number writes the shortest text that reads back, never hundreds of digits")
{
    CHECK(format_number(1.0) == "1");
    CHECK(format_number(0.5) == "0.5");
    CHECK(format_number(-0.1) == "-0.1");
    CHECK(format_number(1e300) == "1e+300");
    CHECK(format_number(DBL_MAX) == "1.7976931348623157e+308");
    CHECK(format_number(std::numeric_limits<double>::denorm_min()) == "5e-324");
    CHECK(format_number(HUGE_VAL) == "inf");
    CHECK(format_number(-HUGE_VAL) == "-inf");
    CHECK(format_number(std::nan("")) == "nan");
    for (const double v : {1.0 / 3.0, 8.333333333333334e299, 2.2250738585072014e-308, 123456.789}) {
        CAPTURE(v);
        CHECK(std::stod(format_number(v)) == v);
        CHECK(format_number(v).size() <= 24);
    }
}
