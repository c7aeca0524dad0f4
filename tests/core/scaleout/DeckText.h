// Reading the text of an exported deck in the scale-out tests: words and lines of a file, and a file of
// the deck by name.
#pragma once

#include "scaleout/LammpsDeck.h"

#include <QtGlobal>
#include <sstream>
#include <string>
#include <vector>

namespace pl::deck_text {

inline std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

inline std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string l; std::getline(in, l);) out.push_back(l);
    return out;
}

inline const std::string& file(const scaleout::Deck& deck, const std::string& name) {
    for (const auto& f : deck.files)
        if (f.name == name) return f.content;
    qFatal("deck has no %s", name.c_str());
}

} // namespace pl::deck_text
