#pragma once
// Minimal streaming JSON writer: objects, arrays, strings, numbers, booleans.
// Refuses non-finite numbers (JSON has none), naming the key, so a NaN never
// reaches an output file silently. Strings are escaped per RFC 8259, so any
// name (quotes, backslashes, control characters, invalid UTF-8) gives valid
// JSON.
#include <cmath>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace railstab {

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) { out_.precision(12); }

  JsonWriter& begin_object() { return open('{'); }
  JsonWriter& end_object() { return close('}'); }
  JsonWriter& begin_array() { return open('['); }
  JsonWriter& end_array() { return close(']'); }

  JsonWriter& key(const std::string& k) {
    separate();
    write_string(k);
    out_ << ": ";
    pending_key_ = k;
    after_key_ = true;
    return *this;
  }
  JsonWriter& value(double v) {
    if (!std::isfinite(v))
      throw std::runtime_error("non-finite value for JSON key '" + pending_key_ + "'");
    separate();
    out_ << v;
    return *this;
  }
  JsonWriter& value(int v) { separate(); out_ << v; return *this; }
  JsonWriter& value(bool v) { separate(); out_ << (v ? "true" : "false"); return *this; }
  JsonWriter& value(const std::string& v) { separate(); write_string(v); return *this; }
  JsonWriter& value(const char* v) { return value(std::string(v)); }
  JsonWriter& null() { separate(); out_ << "null"; return *this; }
  template <class T> JsonWriter& field(const std::string& k, const T& v) { return key(k).value(v); }

 private:
  JsonWriter& open(char c) {
    separate();
    out_ << c;
    first_.push_back(true);
    return *this;
  }
  JsonWriter& close(char c) {
    first_.pop_back();
    out_ << '\n' << std::string(2 * first_.size(), ' ') << c;
    if (first_.empty()) out_ << '\n';
    return *this;
  }
  void separate() {
    if (after_key_) {
      after_key_ = false;
      return;
    }
    if (first_.empty()) return;
    if (!first_.back()) out_ << ',';
    first_.back() = false;
    out_ << '\n' << std::string(2 * first_.size(), ' ');
  }
  // RFC 8259 section 7: '"' and '\\' escaped, control characters U+0000-U+001F
  // as \n, \t, ... or \u00XX. JSON text must be UTF-8 (section 8.1), so a
  // byte that does not start a valid UTF-8 sequence (a Latin-1 name, a cut
  // sequence) is written as U+FFFD rather than passed through.
  void write_string(const std::string& s) {
    static const char* hex = "0123456789abcdef";
    out_ << '"';
    for (size_t i = 0; i < s.size();) {
      const unsigned char c = static_cast<unsigned char>(s[i]);
      if (c == '"' || c == '\\') {
        out_ << '\\' << char(c);
      } else if (c < 0x20) {
        switch (c) {
          case '\b': out_ << "\\b"; break;
          case '\f': out_ << "\\f"; break;
          case '\n': out_ << "\\n"; break;
          case '\r': out_ << "\\r"; break;
          case '\t': out_ << "\\t"; break;
          default: out_ << "\\u00" << hex[c >> 4] << hex[c & 0xF];
        }
      } else if (c < 0x80) {
        out_ << char(c);
      } else {
        const size_t n = utf8_sequence_length(s, i);
        if (n == 0) {
          out_ << "\\ufffd";
          ++i;
          continue;
        }
        out_ << s.substr(i, n);
        i += n;
        continue;
      }
      ++i;
    }
    out_ << '"';
  }
  // Length of the well-formed UTF-8 sequence at s[i] (RFC 3629 table: no
  // overlong forms, no surrogates, nothing above U+10FFFF), 0 if none.
  static size_t utf8_sequence_length(const std::string& s, size_t i) {
    auto byte = [&](size_t k) { return k < s.size() ? static_cast<unsigned char>(s[k]) : 0u; };
    auto in = [](unsigned b, unsigned lo, unsigned hi) { return b >= lo && b <= hi; };
    const unsigned b0 = byte(i), b1 = byte(i + 1), b2 = byte(i + 2), b3 = byte(i + 3);
    if (in(b0, 0xC2, 0xDF)) return in(b1, 0x80, 0xBF) ? 2 : 0;
    if (b0 == 0xE0) return in(b1, 0xA0, 0xBF) && in(b2, 0x80, 0xBF) ? 3 : 0;
    if (in(b0, 0xE1, 0xEC) || in(b0, 0xEE, 0xEF))
      return in(b1, 0x80, 0xBF) && in(b2, 0x80, 0xBF) ? 3 : 0;
    if (b0 == 0xED) return in(b1, 0x80, 0x9F) && in(b2, 0x80, 0xBF) ? 3 : 0;
    if (b0 == 0xF0)
      return in(b1, 0x90, 0xBF) && in(b2, 0x80, 0xBF) && in(b3, 0x80, 0xBF) ? 4 : 0;
    if (in(b0, 0xF1, 0xF3))
      return in(b1, 0x80, 0xBF) && in(b2, 0x80, 0xBF) && in(b3, 0x80, 0xBF) ? 4 : 0;
    if (b0 == 0xF4)
      return in(b1, 0x80, 0x8F) && in(b2, 0x80, 0xBF) && in(b3, 0x80, 0xBF) ? 4 : 0;
    return 0;
  }
  std::ostream& out_;
  std::vector<bool> first_;
  bool after_key_ = false;
  std::string pending_key_;
};

}  // namespace railstab
