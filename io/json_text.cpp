#include "io/json_text.h"

#include <map>
#include <vector>

#include "io/text_encoding.h"

namespace rc::io {

namespace {

// One open array or object of the scan: its keys so far (with their lines) and where it sits.
struct Frame {
  bool object = false;
  bool expect_key = false;  // in an object, after '{' or ','
  std::size_t index = 0;    // in an array, the element being read
  std::string name;         // "banks", "meshes[0]": its place, for messages
  std::string last_key;
  std::map<std::string, std::size_t> keys;  // key -> line
};

void append_utf8(std::string& out, unsigned long cp) {
  if (cp < 0x80) {
    out += static_cast<char>(cp);
  } else if (cp < 0x800) {
    out += static_cast<char>(0xC0 | (cp >> 6));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else if (cp < 0x10000) {
    out += static_cast<char>(0xE0 | (cp >> 12));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (cp >> 18));
    out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (cp & 0x3F));
  }
}

// A scan of the text that follows its structure (strings, brackets, commas) without judging the
// syntax, which nlohmann's parser does afterwards; it only finds what the parser would let through.
class Scanner {
 public:
  Scanner(std::string_view text, const std::string& path) : text_(text), path_(path) {}

  void run() {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\n') ++line_;
      if (c == '{' || c == '[') open(c == '{');
      else if ((c == '}' || c == ']') && !stack_.empty()) stack_.pop_back();
      else if (c == ',') comma();
      else if (c == '"') {
        string();
        continue;
      } else if (c == '/' && at_ + 1 < text_.size() && (text_[at_ + 1] == '/' || text_[at_ + 1] == '*')) {
        fail(line_, std::string("JSON has no comments ('") + c + text_[at_ + 1] + "' here); remove it");
      } else if (c == '#') {
        fail(line_, "JSON has no comments ('#' here); remove it");
      }
      ++at_;
    }
  }

 private:
  [[noreturn]] void fail(std::size_t line, const std::string& problem) const {
    throw JsonTextError(path_ + ": line " + std::to_string(line) + ": " + problem);
  }

  std::string place() const {
    std::string where;
    for (const Frame& f : stack_) where += f.name;
    return where.empty() ? "the top level" : where;
  }

  // The name of a value opened here: its key in an object, its index in an array.
  std::string child_name() const {
    if (stack_.empty()) return "";
    const Frame& f = stack_.back();
    if (f.object) return (stack_.size() > 1 ? "." : "") + f.last_key;
    return "[" + std::to_string(f.index) + "]";
  }

  void open(bool object) {
    if (stack_.size() >= static_cast<std::size_t>(kJsonDepthLimit)) {
      fail(line_, "nested deeper than the limit of " + std::to_string(kJsonDepthLimit) +
                      " arrays and objects (io/json_text.h, kJsonDepthLimit)");
    }
    Frame f;
    f.object = object;
    f.expect_key = object;
    f.name = child_name();
    stack_.push_back(std::move(f));
  }

  void comma() {
    if (stack_.empty()) return;
    Frame& f = stack_.back();
    if (f.object) f.expect_key = true;
    else ++f.index;
  }

  // A string from its opening quote; a key is checked against its object's other keys.
  void string() {
    const std::size_t line = line_;
    std::string value;
    ++at_;
    while (at_ < text_.size() && text_[at_] != '"') {
      if (text_[at_] == '\n') ++line_;
      if (text_[at_] == '\\' && at_ + 1 < text_.size()) {
        escape(value);
      } else {
        value += text_[at_++];
      }
    }
    ++at_;  // the closing quote (or the end of an unterminated string, which the parser reports)
    if (stack_.empty() || !stack_.back().object || !stack_.back().expect_key) return;
    Frame& f = stack_.back();
    f.expect_key = false;
    f.last_key = value;
    const auto [it, added] = f.keys.emplace(value, line);
    if (!added) {
      fail(line, "key \"" + printable_utf8(value) + "\" given twice in " + place() + " (first on line " +
                     std::to_string(it->second) + "); JSON readers keep only one, so remove the other");
    }
  }

  // One escape sequence into `value` (from the backslash); \uXXXX pairs become UTF-8, so that
  // "a" and "\u0061" are the same key, as the parser sees them.
  void escape(std::string& value) {
    const char e = text_[at_ + 1];
    at_ += 2;
    switch (e) {
      case 'b': value += '\b'; return;
      case 'f': value += '\f'; return;
      case 'n': value += '\n'; return;
      case 'r': value += '\r'; return;
      case 't': value += '\t'; return;
      case 'u': break;
      default: value += e; return;
    }
    unsigned long cp = hex4();
    if (cp >= 0xD800 && cp <= 0xDBFF && text_.substr(at_, 2) == "\\u") {
      at_ += 2;
      const unsigned long low = hex4();
      cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
    }
    append_utf8(value, cp);
  }

  unsigned long hex4() {
    unsigned long v = 0;
    for (int k = 0; k < 4 && at_ < text_.size(); ++k, ++at_) {
      const char h = text_[at_];
      const int d = h >= '0' && h <= '9' ? h - '0' : h >= 'a' && h <= 'f' ? h - 'a' + 10 : h >= 'A' && h <= 'F' ? h - 'A' + 10 : -1;
      if (d < 0) return v;  // a malformed escape: the parser reports it
      v = v * 16 + static_cast<unsigned long>(d);
    }
    return v;
  }

  std::string_view text_;
  const std::string& path_;
  std::size_t at_ = 0, line_ = 1;
  std::vector<Frame> stack_;
};

// nlohmann's message without its "[json.exception.parse_error.101] parse error at line 1, column 2: "
// prefix, whose position is in the message we build.
std::string parser_reason(const std::string& what) {
  const std::size_t colon = what.find(": ");
  return colon == std::string::npos ? what : what.substr(colon + 2);
}

}  // namespace

std::string_view check_json_text(std::string_view text, const std::string& path) {
  if (const std::string problem = utf8_problem(text); !problem.empty())
    throw JsonTextError(path + ": " + problem + "; save it as UTF-8");
  if (text.substr(0, 3) == kUtf8ByteOrderMark) text.remove_prefix(3);
  Scanner(text, path).run();
  return text;
}

void throw_json_syntax_error(const nlohmann::json::parse_error& e, std::string_view text, const std::string& path) {
  // e.byte is 1-based: the byte the parser stopped at.
  const std::size_t offset = e.byte > 0 ? e.byte - 1 : 0;
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) throw JsonTextError(path + ": empty (no JSON value)");
  const TextPosition p = position_of(text, offset);
  throw JsonTextError(path + ": line " + std::to_string(p.line) + ", column " + std::to_string(p.column) +
                      ": not valid JSON: " + parser_reason(e.what()));
}

void throw_json_number_error(const nlohmann::json::out_of_range& e, std::string_view text, const std::string& path) {
  const std::string what = e.what();  // "... number overflow parsing '2e308'"
  const std::size_t open = what.find('\''), close = what.rfind('\'');
  const std::string number = open != std::string::npos && close > open ? what.substr(open + 1, close - open - 1) : "";
  const std::size_t at = number.empty() ? std::string_view::npos : text.find(number);
  const std::string where = at == std::string_view::npos ? "" : "line " + std::to_string(position_of(text, at).line) + ": ";
  throw JsonTextError(path + ": " + where + "the number " + (number.empty() ? std::string("") : "'" + number + "' ") +
                      "is beyond the range of a double (numbers must be finite)");
}

}  // namespace rc::io
