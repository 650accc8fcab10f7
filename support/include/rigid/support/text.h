// User-given text (a file name, an option's value) on the way out: every byte the
// user gave is shown, none can act. A terminal line gets control characters, the
// 8-bit CSI, bidirectional overrides and invalid UTF-8 as escapes; JSON, which
// escapes control characters itself, gets only the invalid UTF-8 (a JSON string
// must be UTF-8: nlohmann::json aborts on one that is not).
#pragma once

#include <cstdio>
#include <string>

namespace rigid::support {

namespace detail {

// The length of the valid UTF-8 sequence at s[i] (1..4) and its code point, or 0 if
// the byte does not start one (a stray continuation, an overlong form, a surrogate,
// beyond U+10FFFF, or cut short).
inline int utf8_sequence(const std::string& s, std::size_t i, char32_t& code) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b = byte(i);
  int length = 0;
  if (b < 0x80) {
    code = b;
    return 1;
  } else if (b >= 0xc2 && b <= 0xdf) {
    length = 2, code = b & 0x1f;
  } else if (b >= 0xe0 && b <= 0xef) {
    length = 3, code = b & 0x0f;
  } else if (b >= 0xf0 && b <= 0xf4) {
    length = 4, code = b & 0x07;
  } else {
    return 0;
  }
  if (i + length > s.size()) return 0;
  for (int k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xc0) != 0x80) return 0;
    code = (code << 6) | (byte(i + k) & 0x3f);
  }
  const bool overlong = (length == 3 && code < 0x800) || (length == 4 && code < 0x10000);
  if (overlong || (code >= 0xd800 && code <= 0xdfff) || code > 0x10ffff) return 0;
  return length;
}

inline std::string hex_escape(unsigned char b) {
  char buffer[5];
  std::snprintf(buffer, sizeof buffer, "\\x%02x", b);
  return buffer;
}

// `text` with each byte that starts no valid sequence as "\xNN" and each valid
// sequence as `shown(code, sequence)` returns it.
template <class Shown>
std::string escape_utf8(const std::string& text, Shown shown) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    char32_t code = 0;
    const int length = utf8_sequence(text, i, code);
    if (length == 0) {
      out += hex_escape(static_cast<unsigned char>(text[i]));
      ++i;
    } else {
      out += shown(code, text.substr(i, length));
      i += length;
    }
  }
  return out;
}

}  // namespace detail

/// For one terminal line: \n as "\n", other C0 controls, DEL and invalid UTF-8 bytes
/// as "\xNN", C1 controls (the 8-bit CSI U+009B among them) and the bidirectional
/// overrides and isolates (U+202A..U+202E, U+2066..U+2069) as "\u{NNNN}"; the rest
/// of valid UTF-8 as it is.
inline std::string terminal_safe(const std::string& text) {
  return detail::escape_utf8(text, [](char32_t code, const std::string& sequence) -> std::string {
    if (code == '\n') return "\\n";
    if (code < 0x20 || code == 0x7f) return detail::hex_escape(static_cast<unsigned char>(code));
    if ((code >= 0x80 && code <= 0x9f) || (code >= 0x202a && code <= 0x202e) ||
        (code >= 0x2066 && code <= 0x2069)) {
      char buffer[16];  // "\\u{" + up to 8 hex digits + "}"
      std::snprintf(buffer, sizeof buffer, "\\u{%04x}", static_cast<unsigned>(code));
      return buffer;
    }
    return sequence;
  });
}

/// Valid UTF-8 for a JSON string: each byte that is not part of a valid sequence as
/// the four characters "\xNN" (so "c\xff.csv" reads as the name given); the rest unchanged.
inline std::string utf8_safe(const std::string& text) {
  return detail::escape_utf8(text, [](char32_t, const std::string& sequence) { return sequence; });
}

}  // namespace rigid::support
