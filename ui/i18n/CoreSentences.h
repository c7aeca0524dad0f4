// Core sentences with numbers in them ("kT = 0.52, KS distance 0.012", "the whole domain: 32000
// molecules"): the catalogue holds each as a template with %1, %2, … in place of its numbers, so the
// sentence is translated once and the numbers are written in the UI's language. Qt-free, so the
// generator of the catalogue's core texts (CoreStrings.cpp) makes the same templates.
#pragma once

#include <string>
#include <vector>

namespace pl::ui {

struct SentenceTemplate {
    std::string text;                 // the sentence with %1, %2, … for its numbers, {1}, {2}, … for keys
    std::vector<std::string> numbers; // as written: "-1.138e-14", "32000"
    std::vector<std::string> keys;    // the parameters a refusal names: "dt", "count_a"
};

// The numbers are free-standing decimals: an optional sign, digits, an optional fraction and exponent,
// not part of a name ("u_x", "M4", "2d" stay text). A parameter marked {key} or '{key}' (ParamSpec.h)
// becomes {1}, {2}, … without quotes, so that one template serves every parameter and the UI writes
// each by its translated label.
SentenceTemplate sentenceTemplate(const std::string& sentence);

} // namespace pl::ui
