#include "frob/run/terminal_text.hpp"

#include "frob/run/format.hpp"

namespace frob::course {

void appendUtf8(std::string& out, char32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

bool isControl(char32_t c) { return c < 0x20 || (c >= 0x7F && c <= 0x9F); }

// Marks that reorder the text around them (right-to-left overrides and isolates): a reason could
// show a line that reads otherwise than its bytes.
namespace {
bool reorders(char32_t c) { return c == 0x061C || c == 0x200E || c == 0x200F || (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069); }
}  // namespace

// An escape sequence (CSI, OSC, DCS, in 7 or 8 bits) or a bare carriage return from a controller's
// message could recolour or clear the screen, write the clipboard or overwrite a line already shown.
std::string terminalSafe(std::string_view text, bool lines) {
  std::string out;
  out.reserve(text.size());
  forEachCodePoint(text, [&](char32_t c, std::size_t at, std::size_t) {
    if (c == kInvalidUtf8) {
      out += format("\\x%02x", static_cast<unsigned char>(text[at]));
    } else if (c >= 0x80 && (isControl(c) || reorders(c))) {
      out += format("\\u%04x", static_cast<unsigned>(c));
    } else if (isControl(c) && c != '\t' && !(lines && c == '\n')) {
      out += format("\\x%02x", static_cast<unsigned>(c));
    } else {
      appendUtf8(out, c);
    }
  });
  return out;
}

}  // namespace frob::course
