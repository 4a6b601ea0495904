#pragma once
// Private: text from controllers and submissions made safe for where the grade shows it (a terminal,
// XML, HTML), and files embedded in a page.
#include "frob/run/terminal_text.hpp"

#include <cstddef>
#include <string>
#include <string_view>

namespace frob::course {

/// Columns a terminalSafe() string takes (one per code point).
[[nodiscard]] std::size_t widthOf(std::string_view text);
/// `text` as XML 1.0 or HTML character data or, with `attribute`, a double-quoted attribute value; what XML forbids becomes U+FFFD.
[[nodiscard]] std::string markupEscape(std::string_view text, bool attribute = false);
/// `bytes` in base64 (RFC 4648), for data: URLs.
[[nodiscard]] std::string base64(std::string_view bytes);

}  // namespace frob::course
