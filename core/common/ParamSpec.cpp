// Validation, parsing and formatting of parameter values against their ParamSpec.
#include "ParamSpec.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace pl {

namespace {

std::string number(double v) {
    return formatNumber(v, 12);
}

bool isKeyChar(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// Calls write(key, quoted) for every {key} and '{key}' in message and puts its result in their place.
std::string replaceMarks(std::string_view message,
                         const std::function<std::string(const std::string&, bool quoted)>& write) {
    std::string out;
    std::size_t i = 0;
    while (i < message.size()) {
        const std::size_t open = message[i] == '\'' && i + 1 < message.size() ? i + 1 : i;
        std::size_t close = open + 1;
        while (close < message.size() && isKeyChar(message[close])) ++close;
        const bool isMark =
            message[open] == '{' && close > open + 1 && close < message.size() && message[close] == '}';
        const bool quoted = isMark && open > i && close + 1 < message.size() && message[close + 1] == '\'';
        if (!isMark || (open > i && !quoted)) {
            out += message[i++];
            continue;
        }
        out += write(std::string(message.substr(open + 1, close - open - 1)), quoted);
        i = close + (quoted ? 2 : 1);
    }
    return out;
}

std::string mark(const std::string& key) {
    return "'{" + key + "}' ";
}

std::string kindName(ParamKind kind) {
    switch (kind) {
    case ParamKind::Real:
        return "a number";
    case ParamKind::Integer:
        return "an integer";
    case ParamKind::Boolean:
        return "true or false";
    case ParamKind::Choice:
        return "a string";
    case ParamKind::Color:
        return "a colour string \"#rrggbb\"";
    }
    return "a value";
}

bool isHexColor(const std::string& s) {
    return s.size() == 7 && s[0] == '#' && std::all_of(s.begin() + 1, s.end(), [](char c) {
               return std::isxdigit(static_cast<unsigned char>(c));
           });
}

} // namespace

std::string nameParameters(std::string_view message,
                           const std::function<std::string(const std::string&)>& name) {
    return replaceMarks(message, [&](const std::string& key, bool quoted) {
        (void)quoted; // a label needs no quotes
        return name(key);
    });
}

std::string withKeys(std::string_view message) {
    // The command line has always quoted a key where the message marks it '{key}': keep the quotes.
    return replaceMarks(message,
                        [](const std::string& key, bool quoted) { return quoted ? "'" + key + "'" : key; });
}

std::string formatNumber(double v, int significant) {
    std::ostringstream out;
    out.precision(significant);
    out << v;
    return out.str();
}

ParamSpec makeSpec(std::string key, std::string label, std::string unit, std::string group,
                   std::string tooltip, double min, double max, double step, ParamValue defaultValue,
                   bool appliesLive) {
    ParamSpec s;
    s.key = std::move(key);
    s.label = std::move(label);
    s.unit = std::move(unit);
    s.group = std::move(group);
    s.tooltip = std::move(tooltip);
    s.min = min;
    s.max = max;
    s.step = step;
    s.defaultValue = std::move(defaultValue);
    s.appliesLive = appliesLive;
    return s;
}

ParamSpec makeChoice(std::string key, std::string label, std::string group, std::string tooltip,
                     std::vector<std::string> choices, bool appliesLive) {
    ParamSpec s = makeSpec(std::move(key), std::move(label), "", std::move(group), std::move(tooltip), 0, 0,
                           0, choices.front(), appliesLive);
    s.kind = ParamKind::Choice;
    s.choices = std::move(choices);
    return s;
}

ParamSpec makeChoice(std::string key, std::string label, std::string group, std::string tooltip,
                     bool appliesLive) {
    ParamSpec s = makeSpec(std::move(key), std::move(label), "", std::move(group), std::move(tooltip), 0, 0,
                           0, std::string(), appliesLive);
    s.kind = ParamKind::Choice;
    return s;
}

std::string describeAllowed(const ParamSpec& spec) {
    switch (spec.kind) {
    case ParamKind::Real:
    case ParamKind::Integer: {
        std::string range = "[" + number(spec.min) + ", " + number(spec.max) + "]";
        if (spec.nonZero) range += " except 0";
        if (!spec.unit.empty()) range += " " + spec.unit;
        return range;
    }
    case ParamKind::Boolean:
        return "true or false";
    case ParamKind::Color:
        return "\"#rrggbb\"";
    case ParamKind::Choice: {
        std::string list = "one of: ";
        for (std::size_t i = 0; i < spec.choices.size(); ++i) list += (i ? ", " : "") + spec.choices[i];
        return list;
    }
    }
    return {};
}

std::string checkValue(const ParamSpec& spec, const ParamValue& value) {
    return withKeys(describeProblem(spec, value));
}

std::string describeProblem(const ParamSpec& spec, const ParamValue& value) {
    const std::string prefix = mark(spec.key);
    const std::string allowed = "allowed: " + describeAllowed(spec);
    switch (spec.kind) {
    case ParamKind::Real:
    case ParamKind::Integer: {
        if (!std::holds_alternative<double>(value))
            return prefix + "must be " + kindName(spec.kind) + ", got " + formatValue(value) + " (" +
                   allowed + ")";
        const double v = std::get<double>(value);
        if (!std::isfinite(v)) return prefix + "must be finite, got " + number(v) + " (" + allowed + ")";
        if (spec.kind == ParamKind::Integer && v != std::floor(v))
            return prefix + "must be an integer, got " + number(v) + " (" + allowed + ")";
        if (v < spec.min || v > spec.max)
            return prefix + "is out of range: " + number(v) + " (" + allowed + ")";
        if (spec.nonZero && v == 0.0) return prefix + "must not be 0 (" + allowed + ")";
        return {};
    }
    case ParamKind::Boolean:
        if (!std::holds_alternative<bool>(value))
            return prefix + "must be true or false, got " + formatValue(value);
        return {};
    case ParamKind::Choice: {
        if (!std::holds_alternative<std::string>(value))
            return prefix + "must be a string, got " + formatValue(value) + " (" + allowed + ")";
        const auto& s = std::get<std::string>(value);
        if (std::find(spec.choices.begin(), spec.choices.end(), s) == spec.choices.end())
            return prefix + "has no option \"" + s + "\" (" + allowed + ")";
        return {};
    }
    case ParamKind::Color:
        if (!std::holds_alternative<std::string>(value) || !isHexColor(std::get<std::string>(value)))
            return prefix + "must be a colour like \"#3a7bd5\", got " + formatValue(value);
        return {};
    }
    return {};
}

ParamValue parseValue(const ParamSpec& spec, std::string_view text) {
    switch (spec.kind) {
    case ParamKind::Real:
    case ParamKind::Integer: {
        const std::string s(text);
        // Decimal notation only, the whole text: strtod alone would take " 1" and "0x10" as well.
        const char* begin = s.data() + (!s.empty() && s[0] == '+' ? 1 : 0);
        const char* last = s.data() + s.size();
        double v = 0.0;
        const auto [stop, error] = std::from_chars(begin, last, v);
        const bool signedTwice = begin != s.data() && begin != last && *begin == '-';
        if (s.empty() || signedTwice || stop != last ||
            (error != std::errc() && error != std::errc::result_out_of_range))
            throw ParamError(spec.key, mark(spec.key) + "must be " + kindName(spec.kind) + ", got \"" + s +
                                           "\" (allowed: " + describeAllowed(spec) + ")");
        if (error == std::errc::result_out_of_range) v = std::strtod(s.c_str(), nullptr); // ±inf or ~0
        return v; // range, NaN and integrality are checkValue's job
    }
    case ParamKind::Boolean: {
        if (text == "true" || text == "1" || text == "on" || text == "yes") return true;
        if (text == "false" || text == "0" || text == "off" || text == "no") return false;
        throw ParamError(spec.key,
                         mark(spec.key) + "must be true or false, got \"" + std::string(text) + "\"");
    }
    case ParamKind::Choice:
    case ParamKind::Color:
        return std::string(text);
    }
    return std::string(text);
}

std::string formatValue(const ParamValue& value) {
    if (const auto* d = std::get_if<double>(&value)) return number(*d);
    if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
    return "\"" + std::get<std::string>(value) + "\"";
}

const ParamSpec* findSpec(const std::vector<ParamSpec>& specs, std::string_view key) {
    for (const auto& s : specs)
        if (s.key == key) return &s;
    return nullptr;
}

} // namespace pl
