// Numbers in decks as the shortest text that reads back as the same double (std::to_chars): the
// input scripts stay readable for a person and exact for the code that reads them.
#pragma once

#include <charconv>
#include <ostream>

namespace pl::scaleout {

struct Exact {
    double value;
};

// Plain digits when they are short ("100000", "0.00035"), else the shortest form ("1e-18").
inline std::ostream& operator<<(std::ostream& out, Exact number) {
    constexpr long kPlainDigits = 12;
    char text[400];
    const auto plain = std::to_chars(text, text + sizeof text, number.value, std::chars_format::fixed);
    if (plain.ec == std::errc() && plain.ptr - text <= kPlainDigits) return out.write(text, plain.ptr - text);
    const auto shortest = std::to_chars(text, text + sizeof text, number.value);
    return out.write(text, shortest.ptr - text);
}

} // namespace pl::scaleout
