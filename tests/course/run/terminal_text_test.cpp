// Text from outside printed to a terminal: every control character shown, none acted on.
#include "frob/run/terminal_text.hpp"

#include <gtest/gtest.h>

namespace frob::course {
namespace {

TEST(TerminalText, EveryKindOfEscapeIsShownNotActedOn) {
  EXPECT_EQ(terminalSafe("\x1b[2J"), "\\x1b[2J");                                 // CSI: clear the screen
  EXPECT_EQ(terminalSafe("\x1b]52;c;ZXZpbA==\x07"), "\\x1b]52;c;ZXZpbA==\\x07");  // OSC 52: write the clipboard
  EXPECT_EQ(terminalSafe("\x1bPq#0\x1b\\"), "\\x1bPq#0\\x1b\\");                  // DCS, ended by ST
  EXPECT_EQ(terminalSafe("\xc2\x9b"
                         "31m"),
            "\\u009b31m");  // CSI as a C1 control in UTF-8
  EXPECT_EQ(terminalSafe("\x9b"
                         "31m"),
            "\\x9b31m");                                                     // ... and as a lone byte
  EXPECT_EQ(terminalSafe("graded\rTotal 7 / 7"), "graded\\x0dTotal 7 / 7");  // a bare carriage return
  EXPECT_EQ(terminalSafe(std::string_view("\x7f\x08\x00", 3)), "\\x7f\\x08\\x00");
  EXPECT_EQ(terminalSafe("caf\xc3\xa9 \xe9t\xc3"), "caf\xc3\xa9 \\xe9t\\xc3");  // UTF-8 stays; malformed bytes are shown
  // A right-to-left override or isolate would show "passed" for bytes that say "deliaf".
  EXPECT_EQ(terminalSafe("\xe2\x80\xae"
                         "deliaf \xe2\x81\xa7x\xe2\x81\xa9 \xe2\x80\x8f"),
            "\\u202edeliaf \\u2067x\\u2069 \\u200f");
}

TEST(TerminalText, TabsStayAndLineFeedsWhenAsked) {
  EXPECT_EQ(terminalSafe("a\tb\nc"), "a\tb\\x0ac");
  EXPECT_EQ(terminalSafe("a\tb\nc", true), "a\tb\nc");
  EXPECT_EQ(terminalSafe("a\r\nb", true), "a\\x0d\nb");
}

}  // namespace
}  // namespace frob::course
