// Parameter descriptions: the single list from which presets, the CLI's --set and the UI panels are made.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace pl {

enum class ParamKind { Real, Integer, Boolean, Choice, Color };

// Integers are carried as exact doubles; choices and colours ("#rrggbb") as strings.
using ParamValue = std::variant<double, bool, std::string>;
using ParamValues = std::map<std::string, ParamValue>;

struct ParamSpec {
    std::string key;     // stable identifier used in preset files and on the command line
    std::string label;   // short human name
    std::string unit;    // empty when dimensionless
    std::string group;   // panel section
    std::string tooltip; // one sentence: what it does and a typical value
    ParamKind kind = ParamKind::Real;
    double min = 0.0; // inclusive bounds for Real and Integer
    double max = 0.0;
    double step = 0.0; // suggested UI increment
    ParamValue defaultValue = 0.0;
    std::vector<std::string> choices; // for Choice
    bool nonZero = false;             // Real values that may be negative but never 0 (a signed time step)
    bool appliesLive = false;         // false: takes effect on the next reset
};

// Messages about parameters name them as {key}, or as '{key}' where the command line quotes the key.
// withKeys writes the keys themselves (presets, the command line); nameParameters lets a front end
// write each parameter its own way (the panel uses the spec's label, and drops the quotes).
std::string withKeys(std::string_view message);
std::string nameParameters(std::string_view message,
                           const std::function<std::string(const std::string&)>& name);

// v with `significant` significant digits, so a small value never reads as 0 ("1.5e-05", "0.0123").
std::string formatNumber(double v, int significant = 6);

// A parameter value that failed validation; key() names the offending parameter. what() names every
// parameter by its key; message() keeps the {key} marks for nameParameters.
class ParamError : public std::runtime_error {
public:
    ParamError(std::string key, const std::string& message)
        : std::runtime_error(withKeys(message)), key_(std::move(key)), message_(message) {}
    const std::string& key() const { return key_; }
    const std::string& message() const { return message_; }

private:
    std::string key_;
    std::string message_;
};

// A Real spec (models turn it into Integer or Boolean through the bind* helpers below).
ParamSpec makeSpec(std::string key, std::string label, std::string unit, std::string group,
                   std::string tooltip, double min, double max, double step, ParamValue defaultValue,
                   bool appliesLive = false);
// A Choice spec; the first choice is the default.
ParamSpec makeChoice(std::string key, std::string label, std::string group, std::string tooltip,
                     std::vector<std::string> choices, bool appliesLive = false);
// A Choice spec whose choices and default bindChoice fills in from the enum's table.
ParamSpec makeChoice(std::string key, std::string label, std::string group, std::string tooltip,
                     bool appliesLive = false);

// "[1e-06, 1000] M" or "one of: a, b, c" — used in every error message about a value.
std::string describeAllowed(const ParamSpec& spec);

// Empty when value is acceptable for spec, else a sentence naming the parameter as '{key}', the value
// and what is allowed (see nameParameters); checkValue writes the key itself.
std::string describeProblem(const ParamSpec& spec, const ParamValue& value);
std::string checkValue(const ParamSpec& spec, const ParamValue& value);

// Parses command-line text ("0.5", "true", "rk4") into a value of spec's kind; throws ParamError.
ParamValue parseValue(const ParamSpec& spec, std::string_view text);

std::string formatValue(const ParamValue& value);

const ParamSpec* findSpec(const std::vector<ParamSpec>& specs, std::string_view key);

// Binds one spec to one member of a parameter struct P.
template <class P> struct ParamField {
    ParamSpec spec;
    std::function<ParamValue(const P&)> get;
    std::function<void(P&, const ParamValue&)> set;
};

template <class P> ParamField<P> bindReal(double P::*member, ParamSpec spec) {
    spec.kind = ParamKind::Real;
    return {std::move(spec), [member](const P& p) { return ParamValue{p.*member}; },
            [member](P& p, const ParamValue& v) { p.*member = std::get<double>(v); }};
}

template <class P> ParamField<P> bindInteger(long long P::*member, ParamSpec spec) {
    spec.kind = ParamKind::Integer;
    return {std::move(spec), [member](const P& p) { return ParamValue{static_cast<double>(p.*member)}; },
            [member](P& p, const ParamValue& v) { p.*member = static_cast<long long>(std::get<double>(v)); }};
}

template <class P> ParamField<P> bindBool(bool P::*member, ParamSpec spec) {
    spec.kind = ParamKind::Boolean;
    return {std::move(spec), [member](const P& p) { return ParamValue{p.*member}; },
            [member](P& p, const ParamValue& v) { p.*member = std::get<bool>(v); }};
}

template <class P> ParamField<P> bindText(std::string P::*member, ParamSpec spec) {
    return {std::move(spec), [member](const P& p) { return ParamValue{p.*member}; },
            [member](P& p, const ParamValue& v) { p.*member = std::get<std::string>(v); }};
}

// The names of a choice enum E, in the order the panel lists them. Each choice enum declares its table
// next to itself as `const ChoiceTable<E>& choiceTable(E)`, found by argument-dependent lookup, so C++
// compares enums while preset files, the command line and the panel keep the names.
template <class E> using ChoiceTable = std::vector<std::pair<E, std::string>>;

// The name of a choice value, e.g. nameOf(GasForceMethod::AllPairs) == "all-pairs".
template <class E> const std::string& nameOf(E value) {
    for (const auto& [v, name] : choiceTable(E{}))
        if (v == value) return name;
    throw std::logic_error("a choice value without a name in its table");
}

// The choice value of a name, or nothing when the table does not list it.
template <class E> std::optional<E> choiceNamed(std::string_view name) {
    for (const auto& [v, n] : choiceTable(E{}))
        if (n == name) return v;
    return std::nullopt;
}

// Binds a Choice spec to an enum member; the choices come from E's table and the default from P's.
template <class P, class E> ParamField<P> bindChoice(E P::*member, ParamSpec spec) {
    spec.kind = ParamKind::Choice;
    spec.choices.clear();
    for (const auto& entry : choiceTable(E{})) spec.choices.push_back(entry.second);
    spec.defaultValue = nameOf(P{}.*member);
    return {std::move(spec), [member](const P& p) { return ParamValue{nameOf(p.*member)}; },
            [member](P& p, const ParamValue& v) {
                const auto value = choiceNamed<E>(std::get<std::string>(v));
                if (!value) throw std::logic_error("an unchecked choice reached bindChoice");
                p.*member = *value;
            }};
}

template <class P> std::vector<ParamSpec> specsOf(const std::vector<ParamField<P>>& fields) {
    std::vector<ParamSpec> specs;
    for (const auto& f : fields) specs.push_back(f.spec);
    return specs;
}

template <class P> ParamValues valuesOf(const P& params, const std::vector<ParamField<P>>& fields) {
    ParamValues values;
    for (const auto& f : fields) values[f.spec.key] = f.get(params);
    return values;
}

// Returns base with values applied. Every value is checked before any is applied, so on ParamError the
// caller's parameters are untouched.
template <class P>
P withValues(const P& base, const std::vector<ParamField<P>>& fields, const ParamValues& values) {
    std::vector<std::pair<const ParamField<P>*, const ParamValue*>> checked;
    for (const auto& [key, value] : values) {
        const ParamField<P>* field = nullptr;
        for (const auto& f : fields)
            if (f.spec.key == key) field = &f;
        if (!field) throw ParamError(key, "unknown parameter '" + key + "'");
        if (auto problem = describeProblem(field->spec, value); !problem.empty())
            throw ParamError(key, problem);
        checked.emplace_back(field, &value);
    }
    P result = base;
    for (const auto& [field, value] : checked) field->set(result, *value);
    return result;
}

} // namespace pl
