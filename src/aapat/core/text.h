// The two string helpers every spec parser needs: comma lists and trimming.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace aapat {

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

// "a,b,c" -> {"a", "b", "c"}; an empty text has no items.
inline std::vector<std::string_view> split(std::string_view text, char sep = ',') {
  std::vector<std::string_view> items;
  while (!text.empty()) {
    const auto at = text.find(sep);
    items.push_back(text.substr(0, at));
    text = at == std::string_view::npos ? std::string_view{} : text.substr(at + 1);
  }
  return items;
}

// The first control character (below U+0020, or U+007F) in `text`, as its
// byte offset, or npos: names, descriptions and provenance are one line of
// text, so that no exporter can be made to write a line of code from them.
inline size_t control_character_at(std::string_view text) {
  for (size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x20 || c == 0x7f) return i;
  }
  return std::string_view::npos;
}

// `text` as one line for a comment or a header of an export: every control
// character (a newline, a carriage return, ...) becomes a space. The one
// escaping every exporter applies to names and provenance, in every language
// (their comments all end at the line's end).
inline std::string one_line(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    const auto u = static_cast<unsigned char>(c);
    if (u < 0x20 || u == 0x7f) c = ' ';
  }
  return out;
}

// The longest prefix of `text` of at most `max_bytes` that ends on a UTF-8
// character's boundary: a name shortened for a label never ends in half a
// character.
inline std::string_view utf8_prefix(std::string_view text, size_t max_bytes) {
  if (text.size() <= max_bytes) return text;
  size_t cut = max_bytes;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return text.substr(0, cut);
}

// An error message as a face shows it: at most kMaxMessageBytes, cut at a
// UTF-8 character's boundary with the count of what was left out, so that a
// 100 KB argument echoed in a message does not flood a terminal or a log.
inline constexpr size_t kMaxMessageBytes = 1000;
inline std::string shortened_message(std::string_view message,
                                     size_t max_bytes = kMaxMessageBytes) {
  if (message.size() <= max_bytes) return std::string(message);
  const std::string_view kept = utf8_prefix(message, max_bytes);
  return std::string(kept) + "... (" + std::to_string(message.size() - kept.size()) +
         " more bytes)";
}

}  // namespace aapat
