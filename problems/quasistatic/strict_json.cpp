#include "sinew/problems/quasistatic/strict_json.hpp"

#include "sinew/core/format_number.hpp"
#include "sinew/core/input_error.hpp"

#include <algorithm>
#include <cmath>

namespace sinew {
namespace {

/// Builds a JsonDocument from nlohmann's parse events (SAX): the tree, the
/// written text of each non-integer number, and a refusal of repeated keys,
/// each with the cursor path of where it happens.
class DocumentBuilder : public nlohmann::json_sax<nlohmann::json> {
public:
    explicit DocumentBuilder(JsonDocument& document) : document_(document) {}

    bool null() override { return place(nullptr); }
    bool boolean(bool value) override { return place(value); }
    bool number_integer(number_integer_t value) override { return place(value); }
    bool number_unsigned(number_unsigned_t value) override { return place(value); }
    bool number_float(number_float_t value, const string_t& text) override
    {
        document_.number_text[next_path()] = text;
        return place(value);
    }
    bool string(string_t& value) override { return place(value); }
    bool binary(binary_t& value) override { return place(nlohmann::json::binary_t(value)); }
    bool start_object(std::size_t) override { return open(nlohmann::json::object()); }
    bool key(string_t& key) override
    {
        Level& level = levels_.back();
        if (level.value->contains(key))
            throw InputError(document_.name + ": " + join(level.path, key) + ": key '" + key +
                             "' appears twice in the object");
        level.key = key;
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(nlohmann::json::array()); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& error) override
    {
        // what(): "[json.exception.parse_error.101] parse error at line 3, column 5: …"
        // (also out_of_range.406 for a number too large for a double).
        std::string message = error.what();
        const auto id_end = message.find("] ");
        if (id_end != std::string::npos)
            message = message.substr(id_end + 2);
        throw InputError(document_.name + ": invalid JSON: " + message);
    }

private:
    struct Level {
        nlohmann::json* value;  ///< an object or an array still open
        std::string path;
        std::string key;        ///< objects: the key of the next value
    };

    static std::string join(const std::string& path, const std::string& key)
    {
        return path.empty() ? key : path + "." + key;
    }

    /// The cursor path of the value about to be placed.
    std::string next_path() const
    {
        if (levels_.empty())
            return "";
        const Level& level = levels_.back();
        if (level.value->is_array())
            return level.path + "[" + std::to_string(level.value->size()) + "]";
        return join(level.path, level.key);
    }

    /// Puts `value` where the next value goes and returns where it is. The
    /// pointers held in levels_ stay valid: a container only grows while it
    /// is the innermost open one.
    nlohmann::json* put(nlohmann::json&& value)
    {
        if (levels_.empty()) {
            document_.root = std::move(value);
            return &document_.root;
        }
        nlohmann::json& parent = *levels_.back().value;
        if (parent.is_array()) {
            parent.push_back(std::move(value));
            return &parent.back();
        }
        nlohmann::json& slot = parent[levels_.back().key];
        slot = std::move(value);
        return &slot;
    }

    bool place(nlohmann::json&& value)
    {
        put(std::move(value));
        return true;
    }

    bool open(nlohmann::json&& container)
    {
        std::string path = next_path();
        if (levels_.size() >= kMaxJsonDepth)
            throw InputError(document_.name + ": " + (path.empty() ? std::string("the document") : path) +
                             ": nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
        levels_.push_back(Level{put(std::move(container)), std::move(path), ""});
        return true;
    }

    bool close()
    {
        levels_.pop_back();
        return true;
    }

    JsonDocument& document_;
    std::vector<Level> levels_;
};

} // namespace

JsonCursor::JsonCursor(const JsonDocument& document) : JsonCursor(document.root, document, "") {}

JsonCursor::JsonCursor(const nlohmann::json& value, const JsonDocument& document, std::string path)
    : value_(&value), document_(&document), path_(std::move(path))
{
}

std::string JsonCursor::where() const
{
    return path_.empty() ? document_->name : document_->name + ": " + path_;
}

void JsonCursor::fail(const std::string& message) const { throw InputError(where() + ": " + message); }

void JsonCursor::expect_object(std::initializer_list<const char*> allowed) const
{
    expect_object(std::vector<std::string>(allowed.begin(), allowed.end()));
}

void JsonCursor::expect_object(const std::vector<std::string>& allowed) const
{
    if (!value_->is_object())
        fail("expected an object");
    for (const auto& item : value_->items()) {
        if (std::find(allowed.begin(), allowed.end(), item.key()) == allowed.end()) {
            std::string valid;
            for (const std::string& key : allowed)
                valid += (valid.empty() ? "" : ", ") + key;
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
    return JsonCursor(value_->at(key), *document_, path_.empty() ? key : path_ + "." + key);
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
    return JsonCursor((*value_)[i], *document_, path_ + "[" + std::to_string(i) + "]");
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

std::string JsonCursor::number_text() const
{
    const double v = number();
    const auto written = document_->number_text.find(path_);
    return written != document_->number_text.end() ? written->second : format_number(v);
}

double JsonCursor::number_in(double lower, double upper) const
{
    const double v = number();
    if (v < lower || v > upper)
        fail("must lie in [" + format_number(lower) + ", " + format_number(upper) + "], got " + number_text());
    return v;
}

int JsonCursor::integer_in(int lower, int upper) const
{
    const double v = number();
    if (v != std::floor(v) || v < lower || v > upper)
        fail("expected a whole number in [" + std::to_string(lower) + ", " + std::to_string(upper) + "], got " +
             number_text());
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

Eigen::VectorXd JsonCursor::vector_in(int expected_size, double lower, double upper) const
{
    Eigen::VectorXd v = vector(expected_size);
    for (int i = 0; i < expected_size; ++i)
        (*this)[static_cast<size_t>(i)].number_in(lower, upper);
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

JsonDocument parse_json_text(const std::string& text, const std::string& document)
{
    JsonDocument parsed;
    parsed.name = document;
    DocumentBuilder builder(parsed);
    nlohmann::json::sax_parse(text, &builder);
    return parsed;
}

} // namespace sinew
