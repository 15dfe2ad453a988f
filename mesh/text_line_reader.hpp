#pragma once
// Line-by-line reading of the text mesh formats, with every failure reported
// as InputError "file:line: what is wrong".
#include <fstream>
#include <string>
#include <vector>

namespace sinew {

/// Reads a text file one non-blank line at a time and splits each line into
/// whitespace-separated tokens. Text from `comment` (if not '\0') to the end
/// of a line is dropped; '\r' of Windows line ends is ignored.
class TextLineReader {
public:
    /// Opens `path`; throws InputError "path: cannot open file" when it cannot.
    explicit TextLineReader(const std::string& path, char comment = '\0');

    /// Moves to the next line that has a token; false at the end of the file.
    bool next();
    /// next(), or InputError "file:line: file ends before <what>" (naming the
    /// last line read) at the end of the file.
    void require_next(const std::string& what);

    const std::string& token(std::size_t i) const { return tokens_.at(i); }
    std::size_t token_count() const { return tokens_.size(); }
    /// The current line as read (comment removed).
    const std::string& text() const { return text_; }
    int line_number() const { return line_number_; }
    const std::string& path() const { return path_; }

    /// "path:line", the prefix of every message about the current line.
    std::string where() const;
    /// Throws InputError "path:line: <message>".
    [[noreturn]] void fail(const std::string& message) const;

    /// Throws unless the line has exactly `count` tokens.
    void expect_token_count(std::size_t count, const std::string& what) const;
    /// Throws unless the line has at least `count` tokens.
    void expect_at_least(std::size_t count, const std::string& what) const;

    /// Throws unless the file can hold `count` more entries of at least
    /// `tokens_each` tokens (each token and its separator take 2 bytes or
    /// more): a header's count is checked against the file's size before
    /// anything is allocated for it. `what` names the entries ("points").
    void require_room(long long count, long long tokens_each, const std::string& what) const;
    /// The size of the file in bytes.
    long long file_size() const { return file_size_; }

    /// Token i as a finite double / an int; InputError naming the line and `what`.
    double number(std::size_t i, const std::string& what) const;
    int integer(std::size_t i, const std::string& what) const;

private:
    std::string path_;
    char comment_;
    std::ifstream in_;
    std::string text_;
    std::vector<std::string> tokens_;
    int line_number_ = 0;
    long long file_size_ = 0;
};

} // namespace sinew
