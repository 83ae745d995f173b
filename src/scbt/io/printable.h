// Text from outside (file names, file contents) made safe to put into a one-line message.
#pragma once

#include <string>

namespace scbt {

// The text with control characters (newline, escape, NUL, ...) shown as \n, \x1b, \x00, ...:
// file names and contents in messages cannot break a message into lines, cut it short or drive
// the terminal.
std::string printable(const std::string& text);

}  // namespace scbt
