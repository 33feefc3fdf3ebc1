#pragma once
/// \file
/// Text taken from a file (a token, a node name, a URI) made safe to show: in a terminal an
/// escape sequence from a hostile file could recolour, retitle or rewrite what the user
/// reads, a carriage return could overwrite the line before it, and a bidirectional
/// override could show the characters in another order than they are; bytes that are not
/// UTF-8 break Python's strings and Qt's labels. Every message TrimLab prints (the batch
/// verbs' stdout and stderr, the window's status bar and message boxes, the Python
/// module's exceptions) goes through printableText on its way out, so no message needs to
/// remember which of its parts came from a file.

#include <string>
#include <string_view>

namespace trimlab {

/// `utf8` with every character that a terminal or a label would act on instead of show
/// replaced by a visible escape: the C0 controls except line feed and tab ("\x1b" for ESC,
/// "\r" for a carriage return), DEL, the C1 controls U+0080 to U+009F, the bidirectional
/// embeddings, overrides and isolates (U+202A to U+202E, U+2066 to U+2069, shown as
/// "\u202e"), and each byte that does not belong to well-formed UTF-8 ("\xff"). All other
/// text, multi-byte characters included, is kept as it is. A backslash is kept too: the
/// escapes are for a person to read, not to be decoded back.
[[nodiscard]] std::string printableText(std::string_view utf8);

} // namespace trimlab
