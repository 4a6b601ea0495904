#pragma once
/// Text that came from outside (a controller's prints and failures, file names, a reason) made
/// harmless for a terminal: every control character (C0 but tab and line feed, DEL, C1 whether
/// written in UTF-8 or as a lone byte) and every malformed byte shown as a visible escape, never
/// acted on; and the UTF-8 decoding that, and the markup writers, rest on.

#include <string>
#include <string_view>

namespace frob::course {

/// What forEachCodePoint() gives for a byte that does not start well-formed UTF-8.
inline constexpr char32_t kInvalidUtf8 = 0xFFFFFFFF;

/// Calls f(c, at, bytes) for each code point c of `text`, at byte `at`; each byte that does not start a well-formed UTF-8
/// sequence (a stray continuation, an overlong form, a surrogate, past U+10FFFF, cut short) gives kInvalidUtf8.
template <class F>
void forEachCodePoint(std::string_view text, F&& f) {
  std::size_t i = 0;
  while (i < text.size()) {
    const auto b0 = static_cast<unsigned char>(text[i]);
    if (b0 < 0x80) {
      f(static_cast<char32_t>(b0), i, 1);
      ++i;
      continue;
    }
    std::size_t len = 0;
    char32_t c = 0, least = 0;
    if ((b0 & 0xE0) == 0xC0) {
      len = 2, c = b0 & 0x1F, least = 0x80;
    } else if ((b0 & 0xF0) == 0xE0) {
      len = 3, c = b0 & 0x0F, least = 0x800;
    } else if ((b0 & 0xF8) == 0xF0) {
      len = 4, c = b0 & 0x07, least = 0x10000;
    }
    bool ok = len > 0 && i + len <= text.size();
    for (std::size_t k = 1; ok && k < len; ++k) {
      const auto b = static_cast<unsigned char>(text[i + k]);
      ok = (b & 0xC0) == 0x80;
      c = (c << 6) | (b & 0x3F);
    }
    if (!ok || c < least || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) {
      f(kInvalidUtf8, i, 1);
      ++i;
      continue;
    }
    f(c, i, len);
    i += len;
  }
}

/// Appends code point `c` to `out` in UTF-8.
void appendUtf8(std::string& out, char32_t c);
/// Whether `c` is a control character: C0, DEL or C1.
[[nodiscard]] bool isControl(char32_t c);
/// `text` safe to print on a terminal: control characters, marks that reorder text (U+202E) and malformed bytes become visible
/// escapes ("\x1b", "\u009b", "\xff"); tabs stay, and line feeds when `lines` (else "\x0a").
[[nodiscard]] std::string terminalSafe(std::string_view text, bool lines = false);

}  // namespace frob::course
