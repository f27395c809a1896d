// Text from outside (a scene file's or a flag's raw bytes, which an error message may quote) made safe to print on a
// terminal.
#pragma once

#include <string>
#include <string_view>

namespace rt
{
/// `text` safe for a terminal: no input can move the cursor, clear the screen or start a control sequence. Written as
/// \xNN, byte by byte: the C0 controls but line breaks and tabs (a message may list devices one per line), DEL, the C1
/// controls U+0080-U+009F as UTF-8 encodes them (0xC2 0x80-0x9F: CSI is U+009B), and every byte that is not part of
/// well-formed UTF-8 (a lone 0x9B is CSI to a terminal in an 8-bit mode; the Unicode Standard §3.9, table 3-7, for
/// what is well formed: no overlong forms, no surrogates, nothing past U+10FFFF). Well-formed UTF-8 from U+00A0 on
/// is kept.
std::string printableLine(std::string_view text);
} // namespace rt
