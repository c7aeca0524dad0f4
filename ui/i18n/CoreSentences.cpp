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

// The length of the parameter mark "{key}" starting at `at`, or 0 when none starts there.
std::size_t markAt(const std::string& s, std::size_t at) {
    if (s[at] != '{') return 0;
    std::size_t i = at + 1;
    while (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) != 0 || s[i] == '_')) ++i;
    return i > at + 1 && i < s.size() && s[i] == '}' ? i + 1 - at : 0;
}

} // namespace

SentenceTemplate sentenceTemplate(const std::string& sentence) {
    SentenceTemplate out;
    for (std::size_t i = 0; i < sentence.size();) {
        if (const std::size_t mark = markAt(sentence, i); mark > 0) {
            out.keys.push_back(sentence.substr(i + 1, mark - 2));
            const bool quoted = !out.text.empty() && out.text.back() == '\'' && i + mark < sentence.size() &&
                                sentence[i + mark] == '\'';
            if (quoted) out.text.pop_back();
            out.text.append(1, '{').append(std::to_string(out.keys.size())).append(1, '}');
            i += mark + (quoted ? 1 : 0);
            continue;
        }
        const std::size_t length = numberAt(sentence, i);
        if (length == 0) {
            out.text += sentence[i++];
            continue;
        }
        out.numbers.push_back(sentence.substr(i, length));
        out.text.append(1, '%').append(std::to_string(out.numbers.size()));
        i += length;
    }
    return out;
}

} // namespace pl::ui
