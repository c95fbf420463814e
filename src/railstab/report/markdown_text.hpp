#pragma once
#include <string>

namespace railstab {

// User text in Markdown: one line, no table-cell break, no code-span end.
inline std::string md_text(const std::string& text) {
  std::string out;
  for (char c : text) {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7F) out += ' ';
    else if (c == '|' || c == '`' || c == '\\' || c == '<' || c == '>')
      out += std::string("\\") + c;
    else out += c;
  }
  return out;
}

}  // namespace railstab
