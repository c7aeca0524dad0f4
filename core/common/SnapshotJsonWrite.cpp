// The snapshot writer without a tree: the state's numbers printed straight into pieces of text.
#include "SnapshotJson.h"

#include <charconv>
#include <cmath>
#include <nlohmann/json.hpp>
#include <utility>

namespace pl {

namespace {

using Json = nlohmann::json;

constexpr std::size_t kPieceBytes = std::size_t{1} << 20;

class PieceBuffer {
public:
    explicit PieceBuffer(const PieceSink& write) : write_(write) { text_.reserve(kPieceBytes + 64); }
    void add(std::string_view text) {
        text_ += text;
        if (text_.size() >= kPieceBytes) flush();
    }
    // JSON has no NaN (an empty sample window, an absent species): null, read back as NaN. The shortest
    // text that reads back as v; ".0" marks a whole number as a double, as nlohmann prints one, so that
    // -0 stays -0.0 and every reader takes it for a float.
    void number(double v) {
        if (!std::isfinite(v)) return add("null");
        char digits[32];
        const auto end = std::to_chars(digits, digits + sizeof digits, v).ptr;
        const std::string_view text(digits, static_cast<std::size_t>(end - digits));
        add(text);
        if (text.find_first_of(".e") == std::string_view::npos) add(".0");
    }
    void key(const std::string& name) {
        add(Json(name).dump()); // escaped as JSON
        add(":");
    }
    void flush() {
        if (!text_.empty()) write_(text_);
        text_.clear();
    }

private:
    const PieceSink& write_;
    std::string text_;
};

} // namespace

void writeSnapshotJson(const Snapshot& snapshot, const std::vector<ParamSpec>& specs,
                       const PieceSink& write) {
    PieceBuffer out(write);
    out.add("{");
    out.key("preset");
    out.add(Json::parse(serializePreset(snapshot.preset, specs)).dump()); // its keys sorted, as before
    out.add(",");
    out.key("snapshot_schema");
    out.add(std::to_string(Snapshot::kSchema));
    out.add(",");
    out.key("state");
    out.add("{");
    out.key("arrays");
    out.add("{");
    bool first = true;
    for (const auto& [key, values] : snapshot.state.arrays) {
        if (!std::exchange(first, false)) out.add(",");
        out.key(key);
        out.add("[");
        for (std::size_t i = 0; i < values.size(); ++i) {
            if (i > 0) out.add(",");
            out.number(values[i]);
        }
        out.add("]");
    }
    out.add("},");
    out.key("scalars");
    out.add("{");
    first = true;
    for (const auto& [key, value] : snapshot.state.scalars) {
        if (!std::exchange(first, false)) out.add(",");
        out.key(key);
        out.number(value);
    }
    out.add("}}}\n");
    out.flush();
}

} // namespace pl
