// A model's snapshot state described once, as its parameters are (ParamSpec): a table of named fields —
// numbers of the model, arrays of the model and arrays of its particle state — that save and restore
// both read, so a field cannot be saved and then forgotten on the way back. What is not a plain field
// (a neighbour list's structure, a window of triples, values derived from the restored state) stays
// in the model's own saveState() / restoreState() beside the table.
#pragma once

#include "StateRecord.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

namespace pl {

// Model: the model class (the table is built inside it, so member pointers may name private members).
// State: its structure of arrays, one entry per particle.
template <class Model, class State> class StateTable {
public:
    // The length an array of the model must have when restored, from the model as its preset built it.
    using Length = std::size_t (*)(const Model& model);

    // A number of the model: an integer type (exact up to 2⁵³ in the record's doubles), bool (1 or 0)
    // or double.
    template <class T> StateTable& scalar(std::string key, T Model::*member) {
        static_assert(std::is_arithmetic_v<T>);
        scalars_.push_back({std::move(key), member});
        return *this;
    }
    // An array of the model; length: what it must hold on restore (nullptr: any length).
    StateTable& array(std::string key, std::vector<double> Model::*member, Length length = nullptr) {
        arrays_.push_back({std::move(key), member, length});
        return *this;
    }
    // An array with one entry per particle.
    template <class T> StateTable& perParticle(std::string key, std::vector<T> State::*member) {
        particles_.push_back({std::move(key), member});
        return *this;
    }

    void save(const Model& model, const State& state, StateRecord& record) const {
        for (const Scalar& s : scalars_)
            std::visit([&](auto member) { record.put(s.key, static_cast<double>(model.*member)); }, s.member);
        for (const Array& a : arrays_) record.put(a.key, model.*a.member);
        for (const Particles& p : particles_)
            std::visit([&](auto member) { record.put(p.key, state.*member); }, p.member);
    }

    // The particles the record holds: the length of its first per-particle array. Throws PresetError
    // when it is missing.
    std::size_t particlesIn(const StateRecord& record) const {
        return particles_.empty() ? 0 : record.array<double>(particles_.front().key).size();
    }

    // Every field checked — present, of its length, each value one its type can hold — before anything is
    // written: throws PresetError naming the field, and then the model is as it was. Returns the
    // particle state, with count entries in each per-particle array (the model moves it into place).
    State read(const Model& model, const StateRecord& record, std::size_t count) const {
        for (const Scalar& s : scalars_)
            std::visit(
                [&](auto member) {
                    using T = std::remove_reference_t<decltype(std::declval<Model&>().*member)>;
                    const double value = record.scalar(s.key); // throws unless present and finite
                    if constexpr (std::is_integral_v<T> && !std::is_same_v<T, bool>)
                        if (!(value >= static_cast<double>(std::numeric_limits<T>::lowest()) &&
                              value < static_cast<double>(std::numeric_limits<T>::max()) + 1.0) ||
                            value != std::floor(value))
                            throw PresetError("state." + s.key,
                                              "state." + s.key + " must be a whole number from " +
                                                  std::to_string(std::numeric_limits<T>::lowest()) + " to " +
                                                  std::to_string(std::numeric_limits<T>::max()));
                },
                s.member);
        for (const Array& a : arrays_) record.array<double>(a.key, a.length ? a.length(model) : SIZE_MAX);
        State state;
        for (const Particles& p : particles_)
            std::visit(
                [&](auto member) {
                    using T = typename std::remove_reference_t<decltype(state.*member)>::value_type;
                    state.*member = record.array<T>(p.key, count);
                },
                p.member);
        return state;
    }

    // After read(): the model's numbers and arrays from the record (cannot throw then).
    void restore(Model& model, const StateRecord& record) const {
        for (const Scalar& s : scalars_)
            std::visit(
                [&](auto member) {
                    using T = std::remove_reference_t<decltype(model.*member)>;
                    const double value = record.scalar(s.key);
                    if constexpr (std::is_same_v<T, bool>)
                        model.*member = value != 0.0;
                    else
                        model.*member = static_cast<T>(value);
                },
                s.member);
        for (const Array& a : arrays_) model.*a.member = record.array<double>(a.key);
    }

private:
    struct Scalar {
        std::string key;
        std::variant<double Model::*, bool Model::*, std::int64_t Model::*, std::uint64_t Model::*,
                     std::uint32_t Model::*, long long Model::*>
            member;
    };
    struct Array {
        std::string key;
        std::vector<double> Model::*member;
        Length length;
    };
    struct Particles {
        std::string key;
        std::variant<std::vector<double> State::*, std::vector<std::uint8_t> State::*,
                     std::vector<std::uint32_t> State::*>
            member;
    };
    std::vector<Scalar> scalars_;
    std::vector<Array> arrays_;
    std::vector<Particles> particles_;
};

} // namespace pl
