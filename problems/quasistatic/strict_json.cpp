#include "sinew/problems/quasistatic/strict_json.hpp"

#include "sinew/core/input_error.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace sinew {
namespace {

/// v in the fewest digits that give it back ("1", "0.5", "1e+20", "inf").
std::string shortest(double v)
{
    std::ostringstream out;
    out << std::setprecision(17) << v;
    for (int digits = 1; digits <= 17; ++digits) {
        std::ostringstream trial;
        trial << std::setprecision(digits) << v;
        if (std::stod(trial.str()) == v || !std::isfinite(v))
            return trial.str();
    }
    return out.str();
}

} // namespace

JsonCursor::JsonCursor(const nlohmann::json& value, std::string document, std::string path)
    : value_(&value), document_(std::move(document)), path_(std::move(path))
{
}

std::string JsonCursor::where() const { return path_.empty() ? document_ : document_ + ": " + path_; }

void JsonCursor::fail(const std::string& message) const { throw InputError(where() + ": " + message); }

void JsonCursor::expect_object(std::initializer_list<const char*> allowed) const
{
    if (!value_->is_object())
        fail("expected an object");
    for (const auto& item : value_->items()) {
        const bool known = std::any_of(allowed.begin(), allowed.end(),
                                       [&](const char* key) { return item.key() == key; });
        if (!known) {
            std::string valid;
            for (const char* key : allowed)
                valid += std::string(valid.empty() ? "" : ", ") + key;
            throw InputError(where() + (path_.empty() ? ": " : ".") + item.key() + ": unknown key; valid keys: " +
                             valid);
        }
    }
}

bool JsonCursor::has(const std::string& key) const { return value_->is_object() && value_->contains(key); }

JsonCursor JsonCursor::at(const std::string& key) const
{
    if (!value_->is_object())
        fail("expected an object");
    if (!value_->contains(key))
        fail("missing key '" + key + "'");
    return JsonCursor(value_->at(key), document_, path_.empty() ? key : path_ + "." + key);
}

std::optional<JsonCursor> JsonCursor::find(const std::string& key) const
{
    if (!has(key))
        return std::nullopt;
    return at(key);
}

std::vector<std::string> JsonCursor::keys() const
{
    if (!value_->is_object())
        fail("expected an object");
    std::vector<std::string> out;
    for (const auto& item : value_->items())
        out.push_back(item.key());
    return out;
}

size_t JsonCursor::size() const
{
    if (!value_->is_array())
        fail("expected an array");
    return value_->size();
}

JsonCursor JsonCursor::operator[](size_t i) const
{
    return JsonCursor((*value_)[i], document_, path_ + "[" + std::to_string(i) + "]");
}

double JsonCursor::number() const
{
    if (!value_->is_number())
        fail("expected a number");
    const double v = value_->get<double>();
    if (!std::isfinite(v))
        fail("number is not finite");
    return v;
}

double JsonCursor::number_in(double lower, double upper) const
{
    const double v = number();
    if (v < lower || v > upper)
        fail("must lie in [" + shortest(lower) + ", " + shortest(upper) + "], got " + shortest(v));
    return v;
}

int JsonCursor::integer_in(int lower, int upper) const
{
    const double v = number();
    if (v != std::floor(v) || v < lower || v > upper)
        fail("expected a whole number in [" + std::to_string(lower) + ", " + std::to_string(upper) + "], got " +
             shortest(v));
    return static_cast<int>(v);
}

std::string JsonCursor::string() const
{
    if (!value_->is_string())
        fail("expected a string");
    return value_->get<std::string>();
}

bool JsonCursor::boolean() const
{
    if (!value_->is_boolean())
        fail("expected true or false");
    return value_->get<bool>();
}

Eigen::VectorXd JsonCursor::vector(int expected_size) const
{
    const size_t n = size();
    if (expected_size >= 0 && n != static_cast<size_t>(expected_size))
        fail("expected " + std::to_string(expected_size) + " numbers, got " + std::to_string(n));
    Eigen::VectorXd v(static_cast<Eigen::Index>(n));
    for (size_t i = 0; i < n; ++i)
        v[static_cast<Eigen::Index>(i)] = (*this)[i].number();
    return v;
}

Eigen::MatrixXd JsonCursor::matrix(int rows, int cols) const
{
    if (size() != static_cast<size_t>(rows))
        fail("expected " + std::to_string(rows) + " rows of " + std::to_string(cols) + " numbers");
    Eigen::MatrixXd m(rows, cols);
    for (int i = 0; i < rows; ++i)
        m.row(i) = (*this)[static_cast<size_t>(i)].vector(cols).transpose();
    return m;
}

nlohmann::json parse_json_text(const std::string& text, const std::string& document)
{
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        // e.what(): "[json.exception.parse_error.101] parse error at line 3, column 5: …"
        // (also out_of_range.406 for a number too large for a double).
        std::string message = e.what();
        const auto id_end = message.find("] ");
        if (id_end != std::string::npos)
            message = message.substr(id_end + 2);
        throw InputError(document + ": invalid JSON: " + message);
    }
}

} // namespace sinew
