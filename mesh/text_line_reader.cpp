#include "sinew/mesh/text_line_reader.hpp"

#include "sinew/core/input_error.hpp"
#include "sinew/core/parse_number.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

namespace sinew {

TextLineReader::TextLineReader(const std::string& path, char comment) : path_(path), comment_(comment)
{
    std::error_code error;
    if (std::filesystem::is_directory(path, error))
        throw InputError(path + ": is a folder, not a file");
    in_.open(path);
    if (!in_)
        throw InputError(path + ": cannot open file");
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    file_size_ = error ? 0 : static_cast<long long>(size);
}

bool TextLineReader::next()
{
    while (std::getline(in_, text_)) {
        ++line_number_;
        if (comment_ != '\0') {
            const auto start = text_.find(comment_);
            if (start != std::string::npos)
                text_.erase(start);
        }
        if (!text_.empty() && text_.back() == '\r')
            text_.pop_back();
        tokens_.clear();
        std::istringstream words(text_);
        for (std::string word; words >> word;)
            tokens_.push_back(word);
        if (!tokens_.empty())
            return true;
    }
    if (in_.bad())
        throw InputError(path_ + ": read error after line " + std::to_string(line_number_));
    tokens_.clear();
    return false;
}

void TextLineReader::require_next(const std::string& what)
{
    if (!next())
        throw InputError(path_ + ":" + std::to_string(line_number_) + ": file ends before " + what);
}

std::string TextLineReader::where() const
{
    return path_ + ":" + std::to_string(line_number_);
}

void TextLineReader::fail(const std::string& message) const
{
    throw InputError(where() + ": " + message);
}

void TextLineReader::expect_token_count(std::size_t count, const std::string& what) const
{
    if (tokens_.size() != count)
        fail(what + ": expected " + std::to_string(count) + " values, found " + std::to_string(tokens_.size()));
}

void TextLineReader::expect_at_least(std::size_t count, const std::string& what) const
{
    if (tokens_.size() < count)
        fail(what + ": expected at least " + std::to_string(count) + " values, found " +
             std::to_string(tokens_.size()));
}

void TextLineReader::require_room(long long count, long long tokens_each, const std::string& what) const
{
    const long long most = file_size_ / (2 * std::max(1LL, tokens_each));
    if (count > most)
        fail("the header declares " + std::to_string(count) + " " + what + ", but the file's " +
             std::to_string(file_size_) + " bytes hold at most " + std::to_string(most));
}

double TextLineReader::number(std::size_t i, const std::string& what) const
{
    return parse_finite_double(tokens_.at(i), where() + ": " + what);
}

int TextLineReader::integer(std::size_t i, const std::string& what) const
{
    return parse_int(tokens_.at(i), where() + ": " + what);
}

} // namespace sinew
