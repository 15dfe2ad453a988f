#pragma once
#include <map>
#include <string>
#include <vector>

namespace sinew {

/// One option of a solver, declared once like a model's parameters (DESIGN.md,
/// "Options"): validated with its name and the bad value in the message and
/// listed by `sinew list --solver NAME`.
struct OptionDeclaration {
    enum class Type { real, integer, choice };
    std::string name;
    Type type = Type::real;
    std::string default_value;         ///< as text
    std::string doc;                   ///< one line
    double lower = -1e300;             ///< reals and integers: the range
    double upper = 1e300;
    bool lower_exclusive = false;      ///< value must be > lower rather than >=
    bool upper_exclusive = false;      ///< value must be < upper rather than <=
    std::vector<std::string> choices;  ///< Type::choice: the valid words
};

/// A real option in [lower, upper] (or open at an end whose flag is set).
OptionDeclaration real_option(std::string name, std::string default_value, std::string doc, double lower,
                              double upper, bool lower_exclusive = false, bool upper_exclusive = false);
/// An integer option in [lower, upper].
OptionDeclaration integer_option(std::string name, std::string default_value, std::string doc, int lower, int upper);
/// An option that takes one of `choices`.
OptionDeclaration choice_option(std::string name, std::string default_value, std::string doc,
                                std::vector<std::string> choices);

/// A solver's options after validation: every declared option present, plus
/// the options of each nested solver under its prefix ("inner." …), unparsed.
class OptionValues {
public:
    double real(const std::string& name) const;
    int integer(const std::string& name) const;
    const std::string& text(const std::string& name) const;
    /// The options given as `prefix`.name, prefix removed, for a nested solver.
    std::map<std::string, std::string> nested(const std::string& prefix) const;

private:
    friend OptionValues read_options(const std::string&, const std::vector<OptionDeclaration>&,
                                     const std::vector<std::string>&, const std::map<std::string, std::string>&);
    std::map<std::string, std::string> values_;
    std::map<std::string, std::map<std::string, std::string>> nested_;
};

/// Fills defaults and validates `given` against `declared`: InputError for an
/// unknown name (listing the valid ones), a malformed or out-of-range value
/// (echoing it) or an unknown choice. Names `prefix`.rest with `prefix` in
/// `nested_prefixes` ("inner") are kept for that nested solver to check.
OptionValues read_options(const std::string& solver, const std::vector<OptionDeclaration>& declared,
                          const std::vector<std::string>& nested_prefixes,
                          const std::map<std::string, std::string>& given);

/// One line per option: name, type, range or choices, default, doc.
std::string describe_options(const std::vector<OptionDeclaration>& declared);

} // namespace sinew
