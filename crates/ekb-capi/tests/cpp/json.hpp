// A small JSON reader for the tests: enough for what `ekb export` and `ekb check --format
// json` write (objects, arrays, strings with escapes, numbers, true, false, null).
#ifndef EKB_TEST_JSON_HPP
#define EKB_TEST_JSON_HPP

#include <cstdint>
#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace json {

struct Value {
    enum class Kind { null, boolean, number, string, array, object } kind = Kind::null;
    bool boolean = false;
    double number = 0;
    std::string string;
    std::vector<Value> array;
    std::map<std::string, Value> object;

    bool isNull() const { return kind == Kind::null; }
    const Value &operator[](const std::string &key) const {
        static const Value null;
        auto found = object.find(key);
        return found == object.end() ? null : found->second;
    }
};

class Parser {
public:
    explicit Parser(const std::string &text) : text_(text) {}

    Value parse() {
        Value value = parseValue();
        skipSpace();
        if (at_ != text_.size()) fail("text after the value");
        return value;
    }

private:
    [[noreturn]] void fail(const std::string &what) const {
        throw std::runtime_error("JSON: " + what + " at byte " + std::to_string(at_));
    }

    void skipSpace() {
        while (at_ < text_.size() && (text_[at_] == ' ' || text_[at_] == '\n' || text_[at_] == '\r' || text_[at_] == '\t'))
            ++at_;
    }

    bool consume(const char *word) {
        std::string w(word);
        if (text_.compare(at_, w.size(), w) != 0) return false;
        at_ += w.size();
        return true;
    }

    Value parseValue() {
        skipSpace();
        if (at_ >= text_.size()) fail("end of text");
        Value value;
        char c = text_[at_];
        if (c == '{') {
            value.kind = Value::Kind::object;
            ++at_;
            skipSpace();
            if (consume("}")) return value;
            do {
                skipSpace();
                std::string key = parseString();
                skipSpace();
                if (!consume(":")) fail("expected ':'");
                value.object[key] = parseValue();
                skipSpace();
            } while (consume(","));
            if (!consume("}")) fail("expected '}'");
        } else if (c == '[') {
            value.kind = Value::Kind::array;
            ++at_;
            skipSpace();
            if (consume("]")) return value;
            do {
                value.array.push_back(parseValue());
                skipSpace();
            } while (consume(","));
            if (!consume("]")) fail("expected ']'");
        } else if (c == '"') {
            value.kind = Value::Kind::string;
            value.string = parseString();
        } else if (consume("true")) {
            value.kind = Value::Kind::boolean;
            value.boolean = true;
        } else if (consume("false")) {
            value.kind = Value::Kind::boolean;
        } else if (consume("null")) {
        } else {
            value.kind = Value::Kind::number;
            const char *start = text_.c_str() + at_;
            char *end = nullptr;
            value.number = std::strtod(start, &end);
            if (end == start) fail("expected a value");
            at_ += static_cast<std::size_t>(end - start);
        }
        return value;
    }

    unsigned hex4() {
        if (at_ + 4 > text_.size()) fail("short \\u escape");
        unsigned code = static_cast<unsigned>(std::stoul(text_.substr(at_, 4), nullptr, 16));
        at_ += 4;
        return code;
    }

    static void utf8(std::string &out, std::uint32_t code) {
        if (code < 0x80) {
            out += static_cast<char>(code);
        } else if (code < 0x800) {
            out += static_cast<char>(0xC0 | (code >> 6));
            out += static_cast<char>(0x80 | (code & 0x3F));
        } else if (code < 0x10000) {
            out += static_cast<char>(0xE0 | (code >> 12));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (code & 0x3F));
        } else {
            out += static_cast<char>(0xF0 | (code >> 18));
            out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
            out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
            out += static_cast<char>(0x80 | (code & 0x3F));
        }
    }

    std::string parseString() {
        if (!consume("\"")) fail("expected a string");
        std::string out;
        while (at_ < text_.size() && text_[at_] != '"') {
            char c = text_[at_++];
            if (c != '\\') {
                out += c;
                continue;
            }
            if (at_ >= text_.size()) fail("end of text in an escape");
            char e = text_[at_++];
            switch (e) {
            case 'n': out += '\n'; break;
            case 't': out += '\t'; break;
            case 'r': out += '\r'; break;
            case 'b': out += '\b'; break;
            case 'f': out += '\f'; break;
            case 'u': {
                std::uint32_t code = hex4();
                if (code >= 0xD800 && code < 0xDC00 && consume("\\u")) {
                    std::uint32_t low = hex4();
                    code = 0x10000 + ((code - 0xD800) << 10) + (low - 0xDC00);
                }
                utf8(out, code);
                break;
            }
            default: out += e; break;
            }
        }
        if (!consume("\"")) fail("unterminated string");
        return out;
    }

    const std::string &text_;
    std::size_t at_ = 0;
};

inline Value parse(const std::string &text) { return Parser(text).parse(); }

}  // namespace json

#endif
