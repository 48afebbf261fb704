#include "io/toml_text.h"

#include "io/input_file.h"
#include "io/text_encoding.h"

namespace rc::io {

namespace {

bool is_bare_key_char(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-';
}

// Follows TOML's strings and comments; counts the components of each run `x.y."z".w` outside them.
// A value such as 1.5 counts as a run of two, well within the limit.
class KeyScanner {
 public:
  KeyScanner(std::string_view text, const std::string& path) : text_(text), path_(path) {}

  void run() {
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '#') {
        skip_to_line_end();
      } else if (c == '"' || c == '\'') {
        skip_string(c);
        component();
      } else if (is_bare_key_char(c)) {
        while (at_ < text_.size() && is_bare_key_char(text_[at_])) ++at_;
        component();
      } else {
        if (c == '.') {
          dot_ = run_ > 0;
        } else if (c != ' ' && c != '\t') {
          run_ = 0;
          dot_ = false;
        }
        if (c == '\n') ++line_;
        ++at_;
      }
    }
  }

 private:
  void component() {
    run_ = dot_ ? run_ + 1 : 1;
    dot_ = false;
    if (run_ > kTomlKeyDepthLimit) {
      throw InputFileError(path_ + ":" + std::to_string(line_) + ": a dotted key of more than " +
                           std::to_string(kTomlKeyDepthLimit) + " parts (io/toml_text.h, kTomlKeyDepthLimit)");
    }
  }

  void skip_to_line_end() {
    while (at_ < text_.size() && text_[at_] != '\n') ++at_;
  }

  // From the opening quote to past the closing one; """ and ''' strings may span lines. A string
  // left open ends the scan (toml++ reports it).
  void skip_string(char quote) {
    const std::string triple(3, quote);
    const bool multi_line = text_.substr(at_, 3) == triple;
    at_ += multi_line ? 3 : 1;
    while (at_ < text_.size()) {
      const char c = text_[at_];
      if (c == '\n') {
        ++line_;
        if (!multi_line) return;  // toml++ reports the unterminated string
      }
      if (c == '\\' && quote == '"') {
        at_ += 2;
        continue;
      }
      if (multi_line ? text_.substr(at_, 3) == triple : c == quote) {
        at_ += multi_line ? 3 : 1;
        return;
      }
      ++at_;
    }
  }

  std::string_view text_;
  const std::string& path_;
  std::size_t at_ = 0, line_ = 1;
  int run_ = 0;
  bool dot_ = false;
};

}  // namespace

void check_toml_text(std::string_view text, const std::string& path) {
  check_utf8(text, path);
  KeyScanner(text, path).run();
}

}  // namespace rc::io
