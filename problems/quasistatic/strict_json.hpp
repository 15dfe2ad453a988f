#pragma once
// Strict reading of a JSON document (scene files): every value is read
// through a JsonCursor that knows its path from the root, so each error names
// the document and the path ("beam.json: materials[0].parameters.A: expected a
// number"), and every object lists the keys it accepts, so an unknown key (a
// typo) is an error rather than silently ignored. Internal to the scene
// reader: sinew's other public headers do not expose nlohmann::json.
#include <nlohmann/json.hpp>

#include <Eigen/Core>

#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace sinew {

/// A parsed JSON document and the text of each of its non-integer numbers as
/// the user wrote it, by cursor path ("materials[0].parameters.A"), so that
/// messages and parameters quote "4.9e-324" as written, not as re-printed.
struct JsonDocument {
    std::string name;  ///< names the source in messages (a file path, a built-in scene)
    nlohmann::json root;
    std::map<std::string, std::string> number_text;
};

class JsonCursor {
public:
    /// The root of `document`, which must outlive the cursor.
    explicit JsonCursor(const JsonDocument& document);

    /// "document: path" (or "document" at the root), the prefix of messages.
    std::string where() const;
    /// Throws InputError "where(): message".
    [[noreturn]] void fail(const std::string& message) const;

    bool is_object() const { return value_->is_object(); }
    bool is_array() const { return value_->is_array(); }
    bool is_string() const { return value_->is_string(); }
    bool is_number() const { return value_->is_number(); }

    /// InputError unless the value is an object whose keys are all in `allowed`.
    void expect_object(std::initializer_list<const char*> allowed) const;
    void expect_object(const std::vector<std::string>& allowed) const;
    bool has(const std::string& key) const;
    /// The member `key` of an object; InputError when missing.
    JsonCursor at(const std::string& key) const;
    /// The member `key`, or nothing when absent.
    std::optional<JsonCursor> find(const std::string& key) const;
    /// The keys of an object, in document order of the parser (sorted).
    std::vector<std::string> keys() const;

    /// Element i of an array (bounds already known by size()).
    JsonCursor operator[](size_t i) const;
    /// Number of elements of an array; InputError when not an array.
    size_t size() const;

    /// A finite number; InputError otherwise.
    double number() const;
    /// The number as written in the document (for integers, as printed).
    std::string number_text() const;
    /// A finite number in [lower, upper].
    double number_in(double lower, double upper) const;
    /// A whole number in [lower, upper].
    int integer_in(int lower, int upper) const;
    std::string string() const;
    bool boolean() const;
    /// An array of `size` finite numbers (any size when size < 0).
    Eigen::VectorXd vector(int size = -1) const;
    /// An array of `size` numbers, each in [lower, upper].
    Eigen::VectorXd vector_in(int size, double lower, double upper) const;
    /// An array of `rows` arrays of `cols` finite numbers.
    Eigen::MatrixXd matrix(int rows, int cols) const;

private:
    JsonCursor(const nlohmann::json& value, const JsonDocument& document, std::string path);

    const nlohmann::json* value_;
    const JsonDocument* document_;
    std::string path_;
};

/// The deepest nesting of objects and arrays a document may have. A scene
/// needs four or five levels; the bound keeps a malformed file (100,000
/// nested arrays) from exhausting memory and the stack (docs/scenes.md).
constexpr size_t kMaxJsonDepth = 64;

/// Parses JSON text; InputError "document: line L, column C: …" for a syntax
/// error, "document: path: key 'k' appears twice" for a repeated key (which
/// a plain parser would resolve silently by keeping one of the two), and
/// "document: path: nested deeper than 64 levels" (kMaxJsonDepth).
JsonDocument parse_json_text(const std::string& text, const std::string& document);

} // namespace sinew
