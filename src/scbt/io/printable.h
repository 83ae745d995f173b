// Text from outside (file names, file contents, specs) made safe to put into a one-line message
// or a CSV field.
#pragma once

#include <string>

namespace scbt {

// The text with control characters (newline, escape, NUL, ...) shown as \n, \x1b, \x00, ...:
// file names and contents in messages cannot break a message into lines, cut it short or drive
// the terminal.
std::string printable(const std::string& text);

// The text as one CSV field (RFC 4180): quoted, inner quotes doubled, when it holds a comma, a
// quote or a line break; line breaks become spaces so that a record stays one line.
std::string csv_field(const std::string& text);

}  // namespace scbt
