#include "PrintableLine.h"

namespace rt
{
namespace
{
/// The length of the well-formed UTF-8 sequence of a printable character (not a C1 control) that starts at
/// text[at], or 0 where none does (Unicode §3.9, table 3-7).
std::size_t printableSequence(std::string_view text, std::size_t at)
{
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[at + k]); };
    const unsigned char lead = byte(0);
    const std::size_t length = lead >= 0xC2 && lead <= 0xDF   ? 2
                               : lead >= 0xE0 && lead <= 0xEF ? 3
                               : lead >= 0xF0 && lead <= 0xF4 ? 4
                                                              : 0;
    if (length == 0 || at + length > text.size())
        return 0;
    for (std::size_t k = 1; k < length; ++k)
        if ((byte(k) & 0xC0) != 0x80)
            return 0;
    // The second byte's range where the table narrows it: C1 controls, overlong forms, surrogates, past U+10FFFF.
    const unsigned char second = byte(1);
    if ((lead == 0xC2 && second < 0xA0) || (lead == 0xE0 && second < 0xA0) || (lead == 0xED && second > 0x9F) ||
        (lead == 0xF0 && second < 0x90) || (lead == 0xF4 && second > 0x8F))
        return 0;
    return length;
}
} // namespace

std::string printableLine(std::string_view text)
{
    static constexpr char kHex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();)
    {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte < 0x80 && ((byte >= 0x20 && byte != 0x7f) || byte == '\n' || byte == '\t'))
        {
            out += text[i++];
            continue;
        }
        if (const std::size_t length = byte >= 0x80 ? printableSequence(text, i) : 0; length > 0)
        {
            out.append(text.substr(i, length));
            i += length;
            continue;
        }
        out += "\\x";
        out += kHex[byte >> 4];
        out += kHex[byte & 15];
        ++i;
    }
    return out;
}
} // namespace rt
