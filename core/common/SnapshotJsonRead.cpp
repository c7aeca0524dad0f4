// The snapshot reader without a tree: a SAX pass (nlohmann::json::sax_parse) that puts each number of
// the state where it belongs as it is read, from a text in memory or from a file a buffer at a time.
#include "SnapshotJson.h"

#include "InputLimits.h"
#include "MemoryBudget.h"

#include <algorithm>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>

namespace pl {

namespace {

using Json = nlohmann::json;

constexpr std::size_t kReadBytes = std::size_t{1} << 20;

// The characters the parser reads, from a text or a file a buffer at a time; counts lines for the
// depth refusal. A read error ends the input and is kept for the caller (the parser takes no exception).
class ByteSource {
public:
    explicit ByteSource(std::string_view text)
        : begin_(text.data()), pos_(text.data()), end_(text.data() + text.size()) {}
    explicit ByteSource(FileReader& file) : file_(&file), buffer_(kReadBytes) {}
    bool atEnd() { return pos_ == end_ && !refill(); }
    char peek() const { return *pos_; }
    void advance() { ++pos_; }
    long long line() const { return lines_ + std::count(begin_, pos_, '\n') + 1; }
    const std::string& error() const { return error_; }

private:
    bool refill() {
        if (file_ == nullptr || !error_.empty()) return false;
        lines_ += std::count(begin_, end_, '\n');
        std::size_t n = 0;
        try {
            n = file_->read(buffer_.data(), buffer_.size());
        } catch (const FileError& e) {
            error_ = e.what();
        }
        begin_ = pos_ = buffer_.data();
        end_ = begin_ + n;
        return n > 0;
    }
    FileReader* file_ = nullptr;
    std::vector<char> buffer_;
    const char* begin_ = nullptr;
    const char* pos_ = nullptr;
    const char* end_ = nullptr;
    long long lines_ = 0; // in the buffers before this one
    std::string error_;
};

// An input iterator over a ByteSource, as nlohmann's iterator input adapter takes one; the default one
// is the end.
struct ByteIterator {
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = char;
    ByteSource* source = nullptr;
    char operator*() const { return source->peek(); }
    ByteIterator& operator++() {
        source->advance();
        return *this;
    }
    ByteIterator operator++(int) {
        ByteIterator before = *this;
        source->advance();
        return before;
    }
    bool operator==(const ByteIterator& other) const { return ended() == other.ended(); }
    bool ended() const { return source == nullptr || source->atEnd(); }
};

template <class Handler> bool saxParse(ByteSource& input, Handler& handler) {
    return Json::sax_parse(ByteIterator{&input}, ByteIterator{}, &handler);
}

// Whether the JSON's top-level object names "snapshot_schema": stops at that key, so a snapshot is told
// from its first line or so; nesting deeper than kMaxJsonDepth before it makes it no snapshot.
class SchemaFinder : public nlohmann::json_sax<Json> {
public:
    bool found = false;
    bool null() override { return true; }
    bool boolean(bool) override { return true; }
    bool number_integer(number_integer_t) override { return true; }
    bool number_unsigned(number_unsigned_t) override { return true; }
    bool number_float(number_float_t, const string_t&) override { return true; }
    bool string(string_t&) override { return true; }
    bool binary(binary_t&) override { return true; }
    bool start_object(std::size_t) override { return enter(true); }
    bool key(string_t& key) override {
        found = depth_ == 1 && rootIsObject_ && key == "snapshot_schema";
        return !found;
    }
    bool end_object() override { return --depth_, true; }
    bool start_array(std::size_t) override { return enter(false); }
    bool end_array() override { return --depth_, true; }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
        return false;
    }

private:
    bool enter(bool object) {
        if (depth_ == 0) rootIsObject_ = object;
        return ++depth_ <= kMaxJsonDepth;
    }
    int depth_ = 0;
    bool rootIsObject_ = false;
};

// The snapshot's events, put where they belong as they come: the schema and the preset (small) into
// JSON values, the state's scalars and arrays into a StateRecord. The first problem of each kind is
// kept and reported by finish() in the order parseSnapshot always checked them; nesting beyond
// kMaxJsonDepth and a state beyond the memory this machine can give stop the pass at once.
class SnapshotSax : public nlohmann::json_sax<Json> {
public:
    SnapshotSax(const ByteSource& input, std::string source)
        : input_(input), source_(std::move(source)),
          usableBytes_(kUsableMemoryShare * availableMemoryBytes()) {}

    bool null() override {
        if (inValues()) return push(std::numeric_limits<double>::quiet_NaN());
        return value(Json(nullptr));
    }
    bool boolean(bool v) override { return value(Json(v)); }
    bool number_integer(number_integer_t v) override {
        return inValues() ? push(static_cast<double>(v)) : value(Json(v));
    }
    bool number_unsigned(number_unsigned_t v) override {
        return inValues() ? push(static_cast<double>(v)) : value(Json(v));
    }
    bool number_float(number_float_t v, const string_t&) override {
        return inValues() ? push(v) : value(Json(v));
    }
    bool string(string_t& v) override { return value(Json(std::move(v))); }
    bool binary(binary_t&) override { return value(Json()); }
    bool start_object(std::size_t) override { return open(true); }
    bool start_array(std::size_t) override { return open(false); }
    bool key(string_t& key) override {
        Frame& frame = frames_.back();
        if (!frame.keys.insert(key).second && duplicate_.empty())
            duplicate_ = pathTo(frames_.size() - 1, key);
        frame.key = key;
        return true;
    }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) override {
        syntaxError_ = e.what(); // also numbers beyond the range of a double ("1e999")
        return false;
    }

    // The snapshot, or nullopt (orNothing) or a refusal when the text is not one; throws PresetError
    // naming the first problem otherwise.
    std::optional<Snapshot> finish(const SpecLookup& specsFor, bool orNothing) {
        const auto fail = [&](const std::string& key, const std::string& message) {
            throw PresetError(key, source_ + ": " + message);
        };
        if (!isSnapshot_) {
            if (orNothing) return std::nullopt;
            if (depthLine_ > 0) throw PresetError("", jsonDepthRefusal(source_, depthLine_));
            if (!syntaxError_.empty()) fail("", "not valid JSON: " + syntaxError_);
            fail("snapshot_schema", "not a snapshot (no snapshot_schema)");
        }
        if (depthLine_ > 0) throw PresetError("", jsonDepthRefusal(source_, depthLine_));
        if (!memoryKey_.empty())
            fail(memoryKey_, "'" + memoryKey_ + "' makes the state hold more than the " +
                                 byteSize(static_cast<std::size_t>(usableBytes_)) +
                                 " of memory this machine can give now");
        if (!syntaxError_.empty()) fail("", "not valid JSON: " + syntaxError_);
        if (!duplicate_.empty())
            fail(duplicate_, "duplicate key '" + duplicate_ + "': each key may be given only once");
        if (schema_ != Snapshot::kSchema)
            fail("snapshot_schema", "snapshot_schema " + schema_.dump() +
                                        " is not supported (this version reads " +
                                        std::to_string(Snapshot::kSchema) + ")");
        if (!preset_.is_object()) fail("preset", "'preset' must be an object");
        Snapshot snapshot;
        snapshot.preset = parsePreset(preset_.dump(), specsFor, source_ + " (preset)");
        if (!stateShaped_ || !scalarsSeen_ || !arraysSeen_)
            fail("state", "'state' must hold the objects 'scalars' and 'arrays'");
        if (!valueKey_.empty()) fail(valueKey_, valueError_);
        snapshot.state = std::move(record_);
        return snapshot;
    }

private:
    enum class Role { Root, Capture, Skip, State, Scalars, Arrays, Values };
    struct Frame {
        Role role;
        bool object;
        std::set<std::string> keys;            // objects: the keys given so far
        std::string key;                       // objects: of the member being read; Values: the array's name
        long long index = -1;                  // arrays: of the element being read
        Json* json = nullptr;                  // Capture: the value being built
        std::vector<double>* values = nullptr; // Values: the array being filled
    };

    bool inValues() const { return !frames_.empty() && frames_.back().role == Role::Values; }

    bool push(double v) {
        Frame& frame = frames_.back();
        std::vector<double>& values = *frame.values;
        if (values.size() == values.capacity()) { // grows by doubling, within the memory there is
            const std::size_t more = std::max<std::size_t>(values.capacity(), 1024);
            heldBytes_ += static_cast<double>(more * sizeof(double));
            if (heldBytes_ > usableBytes_) {
                memoryKey_ = "state." + frame.key;
                return false;
            }
            values.reserve(values.capacity() + more);
        }
        values.push_back(v);
        return true;
    }

    // A number or null where a number belongs, or a note of what it should have been.
    void numberAt(const std::string& name, const Json& v, double* out) {
        if (v.is_number())
            *out = v.get<double>();
        else if (v.is_null())
            *out = std::numeric_limits<double>::quiet_NaN();
        else
            refuseValue("state." + name, "must be a number");
    }
    void refuseValue(const std::string& key, const std::string& what) {
        if (!valueKey_.empty()) return;
        valueKey_ = key;
        valueError_ = "'" + key + "' " + what;
    }

    // A value that is no object or array.
    bool value(Json v) {
        if (frames_.empty()) return true; // a bare value: no snapshot
        Frame& parent = frames_.back();
        ++parent.index;
        switch (parent.role) {
        case Role::Root:
            if (parent.key == "snapshot_schema") {
                isSnapshot_ = true;
                schema_ = std::move(v);
            } else if (parent.key == "preset") {
                preset_ = std::move(v);
            } else if (parent.key == "state") {
                stateShaped_ = false;
            }
            break;
        case Role::State:
            if (parent.key == "scalars" || parent.key == "arrays") stateShaped_ = false;
            break;
        case Role::Scalars:
            numberAt(parent.key, v, &record_.scalars[parent.key]);
            break;
        case Role::Arrays:
            refuseValue("state." + parent.key, "must be a list");
            break;
        case Role::Values:
            refuseValue("state." + parent.key, "must be a number");
            break;
        case Role::Capture:
            add(parent, std::move(v));
            break;
        case Role::Skip:
            break;
        }
        return true;
    }

    // A value put into the one being captured; returns where it is.
    Json* add(Frame& parent, Json v) {
        if (parent.object) return &((*parent.json)[parent.key] = std::move(v));
        parent.json->push_back(std::move(v));
        return &parent.json->back();
    }

    bool open(bool object) {
        if (frames_.size() >= static_cast<std::size_t>(kMaxJsonDepth)) {
            depthLine_ = input_.line();
            return false;
        }
        Frame frame{Role::Skip, object, {}, {}, -1, nullptr, nullptr};
        const Json empty = object ? Json::object() : Json::array();
        if (frames_.empty()) {
            if (object) frame.role = Role::Root;
        } else {
            Frame& parent = frames_.back();
            ++parent.index;
            const std::string& key = parent.key;
            switch (parent.role) {
            case Role::Root:
                if (key == "snapshot_schema" || key == "preset") {
                    Json& target = key == "preset" ? preset_ : schema_;
                    isSnapshot_ = isSnapshot_ || key == "snapshot_schema";
                    target = empty;
                    frame.role = Role::Capture;
                    frame.json = &target;
                } else if (key == "state") {
                    frame.role = object ? Role::State : Role::Skip;
                    stateShaped_ = stateShaped_ && object;
                }
                break;
            case Role::State:
                if (key == "scalars" || key == "arrays") {
                    stateShaped_ = stateShaped_ && object;
                    (key == "scalars" ? scalarsSeen_ : arraysSeen_) = object;
                    if (object) frame.role = key == "scalars" ? Role::Scalars : Role::Arrays;
                }
                break;
            case Role::Scalars:
                refuseValue("state." + key, "must be a number");
                break;
            case Role::Arrays:
                if (object) {
                    refuseValue("state." + key, "must be a list");
                } else { // most arrays of a state have one length: the one before tells the next's
                    frame.role = Role::Values;
                    frame.key = key;
                    frame.values = &record_.arrays[key];
                    heldBytes_ -= static_cast<double>(frame.values->capacity() * sizeof(double));
                    *frame.values = {};
                    heldBytes_ += static_cast<double>(lastLength_ * sizeof(double));
                    if (heldBytes_ > usableBytes_) {
                        memoryKey_ = "state." + key;
                        return false;
                    }
                    frame.values->reserve(lastLength_);
                }
                break;
            case Role::Values:
                refuseValue("state." + parent.key, "must be a number");
                break;
            case Role::Capture:
                frame.role = Role::Capture;
                frame.json = add(parent, empty);
                break;
            case Role::Skip:
                break;
            }
        }
        frames_.push_back(std::move(frame));
        return true;
    }

    bool close() {
        if (inValues()) lastLength_ = frames_.back().values->size();
        frames_.pop_back();
        return true;
    }

    // "preset.params.dt", "preset.obstacles[1].x": where key sits under the first `depth` frames.
    std::string pathTo(std::size_t depth, const std::string& key) const {
        std::string path;
        for (std::size_t i = 0; i < depth; ++i)
            path += frames_[i].object ? (path.empty() ? "" : ".") + frames_[i].key
                                      : "[" + std::to_string(frames_[i].index) + "]";
        return path.empty() ? key : path + "." + key;
    }

    const ByteSource& input_;
    std::string source_;
    std::vector<Frame> frames_;
    bool isSnapshot_ = false;
    Json schema_, preset_;
    bool stateShaped_ = true, scalarsSeen_ = false, arraysSeen_ = false;
    StateRecord record_;
    std::size_t lastLength_ = 0;
    double usableBytes_;
    double heldBytes_ = 0.0;
    long long depthLine_ = 0;
    std::string syntaxError_, duplicate_, memoryKey_, valueKey_, valueError_;
};

} // namespace

bool declaresSnapshot(std::string_view text) {
    ByteSource input(text);
    SchemaFinder finder;
    saxParse(input, finder);
    return finder.found;
}

bool declaresSnapshot(FileReader& file) {
    ByteSource input(file);
    SchemaFinder finder;
    saxParse(input, finder);
    return finder.found;
}

std::optional<Snapshot> readSnapshotJson(std::string_view text, const SpecLookup& specsFor,
                                         const std::string& source, bool orNothing) {
    ByteSource input(text);
    SnapshotSax reader(input, source);
    saxParse(input, reader);
    return reader.finish(specsFor, orNothing);
}

std::optional<Snapshot> readSnapshotJson(FileReader& file, const SpecLookup& specsFor, bool orNothing) {
    ByteSource input(file);
    SnapshotSax reader(input, file.path());
    saxParse(input, reader);
    if (!input.error().empty()) throw PresetError("", input.error());
    return reader.finish(specsFor, orNothing);
}

} // namespace pl
