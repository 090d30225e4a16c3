#include "JsonSpans.h"

#include <nlohmann/json.hpp>

#include <cstring>
#include <stdexcept>

namespace tools {

namespace {

class Scanner {
public:
    explicit Scanner(std::string_view text) : text_(text) {}

    JsonSpan document() {
        if (text_.substr(0, 3) == "\xEF\xBB\xBF") at_ = 3;  // a UTF-8 byte order mark
        JsonSpan root = value();
        skipSpace();
        if (at_ != text_.size()) fail("text after the document");
        return root;
    }

private:
    [[noreturn]] void fail(const char* what) const {
        throw std::invalid_argument("JSON scan: " + std::string(what) + " at byte " + std::to_string(at_));
    }
    void skipSpace() {
        while (at_ < text_.size() && std::strchr(" \t\r\n", text_[at_]) && text_[at_] != '\0') ++at_;
    }
    char peek() const { return at_ < text_.size() ? text_[at_] : '\0'; }
    void expect(char c) {
        skipSpace();
        if (peek() != c) fail("unexpected character");
        ++at_;
    }
    // A string token, from its opening quote to just after its closing one.
    void skipString() {
        ++at_;
        while (at_ < text_.size() && text_[at_] != '"') at_ += text_[at_] == '\\' ? 2 : 1;
        if (at_ >= text_.size()) fail("unterminated string");
        ++at_;
    }

    JsonSpan value() {
        skipSpace();
        JsonSpan span;
        span.begin = at_;
        const char c = peek();
        if (c == '{') {
            span.kind = '{';
            ++at_;
            skipSpace();
            if (peek() == '}') ++at_;
            else
                for (;;) {
                    skipSpace();
                    if (peek() != '"') fail("expected a key");
                    const std::size_t keyBegin = at_;
                    skipString();
                    std::string key = nlohmann::json::parse(text_.substr(keyBegin, at_ - keyBegin)).get<std::string>();
                    expect(':');
                    span.members.emplace_back(std::move(key), value());
                    skipSpace();
                    if (peek() == ',') { ++at_; continue; }
                    expect('}');
                    break;
                }
        } else if (c == '[') {
            span.kind = '[';
            ++at_;
            skipSpace();
            if (peek() == ']') ++at_;
            else
                for (;;) {
                    span.items.push_back(value());
                    skipSpace();
                    if (peek() == ',') { ++at_; continue; }
                    expect(']');
                    break;
                }
        } else if (c == '"') {
            span.kind = '"';
            skipString();
        } else if (c != '\0' && std::strchr("-0123456789tfn", c)) {
            span.kind = 'v';
            while (at_ < text_.size() && !std::strchr(",]} \t\r\n", text_[at_])) ++at_;
        } else {
            fail("expected a value");
        }
        span.end = at_;
        return span;
    }

    std::string_view text_;
    std::size_t at_ = 0;
};

} // namespace

const JsonSpan* JsonSpan::member(const std::string& key) const {
    for (auto it = members.rbegin(); it != members.rend(); ++it)
        if (it->first == key) return &it->second;
    return nullptr;
}

JsonSpan scanJson(std::string_view text) { return Scanner(text).document(); }

} // namespace tools
