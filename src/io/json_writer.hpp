#pragma once
// Minimal streaming JSON writer: objects, arrays, strings, numbers, booleans.
// Refuses non-finite numbers (JSON has none), naming the key, so a NaN never
// reaches an output file silently.
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
  void write_string(const std::string& s) {
    out_ << '"';
    for (char ch : s) {
      if (ch == '"' || ch == '\\') out_ << '\\' << ch;
      else if (ch == '\n') out_ << "\\n";
      else out_ << ch;
    }
    out_ << '"';
  }
  std::ostream& out_;
  std::vector<bool> first_;
  bool after_key_ = false;
  std::string pending_key_;
};

}  // namespace railstab
