#include "sinew/solvers/declared_options.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"
#include "sinew/core/parse_number.hpp"

#include <algorithm>
#include <sstream>

namespace sinew {
namespace {

std::string range_text(const OptionDeclaration& d)
{
    if (d.type == OptionDeclaration::Type::choice) {
        std::string words;
        for (const std::string& c : d.choices)
            words += (words.empty() ? "" : ", ") + c;
        return "one of: " + words;
    }
    std::string text = d.lower_exclusive ? "(" : "[";
    text += d.lower <= -1e300 ? "-inf" : format_number(d.lower);
    text += ", ";
    text += d.upper >= 1e300 ? "inf" : format_number(d.upper);
    return text + (d.upper_exclusive ? ")" : "]");
}

void check_value(const std::string& solver, const OptionDeclaration& d, const std::string& value)
{
    const std::string what = solver + " option " + d.name;
    if (d.type == OptionDeclaration::Type::choice) {
        if (std::find(d.choices.begin(), d.choices.end(), value) == d.choices.end())
            throw InputError(what + " = '" + value + "' is invalid; it must be " + range_text(d));
        return;
    }
    const double number = d.type == OptionDeclaration::Type::integer ? parse_int(value, what)
                                                                      : parse_finite_double(value, what);
    const bool below = d.lower_exclusive ? !(number > d.lower) : !(number >= d.lower);
    const bool above = d.upper_exclusive ? !(number < d.upper) : !(number <= d.upper);
    if (below || above)
        throw InputError(what + " = " + value + " is out of range; it must lie in " + range_text(d));
}

} // namespace

OptionDeclaration real_option(std::string name, std::string default_value, std::string doc, double lower,
                              double upper, bool lower_exclusive, bool upper_exclusive)
{
    OptionDeclaration d;
    d.name = std::move(name);
    d.type = OptionDeclaration::Type::real;
    d.default_value = std::move(default_value);
    d.doc = std::move(doc);
    d.lower = lower;
    d.upper = upper;
    d.lower_exclusive = lower_exclusive;
    d.upper_exclusive = upper_exclusive;
    return d;
}

OptionDeclaration integer_option(std::string name, std::string default_value, std::string doc, int lower, int upper)
{
    OptionDeclaration d = real_option(std::move(name), std::move(default_value), std::move(doc), lower, upper);
    d.type = OptionDeclaration::Type::integer;
    return d;
}

OptionDeclaration choice_option(std::string name, std::string default_value, std::string doc,
                                std::vector<std::string> choices)
{
    OptionDeclaration d;
    d.name = std::move(name);
    d.type = OptionDeclaration::Type::choice;
    d.default_value = std::move(default_value);
    d.doc = std::move(doc);
    d.choices = std::move(choices);
    return d;
}

double OptionValues::real(const std::string& name) const { return parse_finite_double(text(name), name); }

int OptionValues::integer(const std::string& name) const { return parse_int(text(name), name); }

const std::string& OptionValues::text(const std::string& name) const { return values_.at(name); }

std::map<std::string, std::string> OptionValues::nested(const std::string& prefix) const
{
    const auto found = nested_.find(prefix);
    return found == nested_.end() ? std::map<std::string, std::string>{} : found->second;
}

OptionValues read_options(const std::string& solver, const std::vector<OptionDeclaration>& declared,
                          const std::vector<std::string>& nested_prefixes,
                          const std::map<std::string, std::string>& given)
{
    OptionValues options;
    for (const OptionDeclaration& d : declared)
        options.values_[d.name] = d.default_value;
    for (const auto& entry : given) {
        const std::string& name = entry.first;  // a named variable: Clang 14 cannot capture a structured binding
        const std::string& value = entry.second;
        const auto dot = name.find('.');
        if (dot != std::string::npos) {
            const std::string prefix = name.substr(0, dot);
            if (std::find(nested_prefixes.begin(), nested_prefixes.end(), prefix) != nested_prefixes.end()) {
                options.nested_[prefix][name.substr(dot + 1)] = value;
                continue;
            }
        }
        const auto found = std::find_if(declared.begin(), declared.end(),
                                        [&](const OptionDeclaration& d) { return d.name == name; });
        if (found == declared.end()) {
            std::string valid;
            for (const OptionDeclaration& d : declared)
                valid += (valid.empty() ? "" : ", ") + d.name;
            for (const std::string& prefix : nested_prefixes)
                valid += (valid.empty() ? "" : ", ") + prefix + ".<option>";
            throw InputError("unknown " + solver + " option '" + name + "'; valid options: " +
                             (valid.empty() ? "none" : valid));
        }
        check_value(solver, *found, value);
        options.values_[name] = value;
    }
    return options;
}

std::string describe_options(const std::vector<OptionDeclaration>& declared)
{
    std::ostringstream out;
    for (const OptionDeclaration& d : declared) {
        const char* type = d.type == OptionDeclaration::Type::real      ? "real"
                           : d.type == OptionDeclaration::Type::integer ? "integer"
                                                                        : "choice";
        out << "  " << d.name << " (" << type << ", " << range_text(d) << ", default " << d.default_value
            << ")\n      " << d.doc << "\n";
    }
    return out.str();
}

} // namespace sinew
