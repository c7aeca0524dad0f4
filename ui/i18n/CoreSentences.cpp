// CoreSentences: a scanner rather than a regular expression, since a number must not continue a name
// (std::regex has no look-behind).
#include "CoreSentences.h"

#include <cctype>

namespace pl::ui {

namespace {

bool isDigit(char c) {
    return std::isdigit(static_cast<unsigned char>(c)) != 0;
}

bool continuesAName(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.';
}

// The length of the number starting at `at`, or 0 when none starts there.
std::size_t numberAt(const std::string& s, std::size_t at) {
    if (at > 0 && continuesAName(s[at - 1])) return 0;
    std::size_t i = at;
    if (i < s.size() && (s[i] == '-' || s[i] == '+')) ++i;
    const std::size_t digits = i;
    while (i < s.size() && isDigit(s[i])) ++i;
    if (i == digits) return 0;
    if (i + 1 < s.size() && s[i] == '.' && isDigit(s[i + 1])) {
        ++i;
        while (i < s.size() && isDigit(s[i])) ++i;
    }
    if (i + 1 < s.size() && (s[i] == 'e' || s[i] == 'E')) {
        std::size_t j = i + 1;
        if (j < s.size() && (s[j] == '-' || s[j] == '+')) ++j;
        if (j < s.size() && isDigit(s[j])) {
            while (j < s.size() && isDigit(s[j])) ++j;
            i = j;
        }
    }
    if (i < s.size() && continuesAName(s[i]) && s[i] != '.') return 0; // "2d", "10x"
    return i - at;
}

} // namespace

SentenceTemplate sentenceTemplate(const std::string& sentence) {
    SentenceTemplate out;
    for (std::size_t i = 0; i < sentence.size();) {
        const std::size_t length = numberAt(sentence, i);
        if (length == 0) {
            out.text += sentence[i++];
            continue;
        }
        out.numbers.push_back(sentence.substr(i, length));
        out.text += "%" + std::to_string(out.numbers.size());
        i += length;
    }
    return out;
}

} // namespace pl::ui
