// Preset schemas 1 → 2 → 3: every schema-1 and schema-2 file (the built-ins and saved user presets of
// their day, under tests/data/schema1 and schema2) loads to exactly the parameters, seed and obstacles of
// its schema-3 twin; old snapshots load; what is written is schema 3; bad old entries are named as the
// file spells them; a newer name in an older file, and an older name in a schema-3 file, are refused.
#include "catalog/ModelCatalog.h"
#include "common/AtomicFile.h"
#include "common/PresetMigration.h"
#include "common/Snapshot.h"

#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>

using namespace pl;

namespace {

const std::filesystem::path kData = PARTICLELAB_TEST_DATA;
const std::filesystem::path kSchema1 = kData / "schema1";

// The folder of the files of one schema: tests/data/schema1, schema2, schema3.
std::filesystem::path folderOf(int schema) {
    return kData / ("schema" + std::to_string(schema));
}

int schemaOf(const std::string& text) {
    return nlohmann::json::parse(text).at("schema").get<int>();
}

// The twin of an older file: the built-in of that name, or of the name it has now (resources/presets),
// else the file of that name in the newest schema's folder.
Preset twinOf(const std::string& stem) {
    const RenamedPreset* renamed = renamedPreset(stem);
    const std::string name = renamed ? renamed->now : stem;
    for (const auto& b : builtinPresets())
        if (b.name == name) return b.preset;
    const std::string path = (folderOf(Preset::kSchema) / (stem + ".json")).string();
    if (schemaOf(readWholeFile(path)) != Preset::kSchema)
        throw std::runtime_error(path + " is not the newest schema");
    return readPresetFile(path, specsForModel);
}

bool sameObstacles(const std::vector<Obstacle>& a, const std::vector<Obstacle>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].shape != b[i].shape || a[i].x != b[i].x || a[i].y != b[i].y || a[i].radius != b[i].radius ||
            a[i].halfWidth != b[i].halfWidth || a[i].halfHeight != b[i].halfHeight)
            return false;
    return true;
}

// The first parameter whose values differ, or "" when the two maps are identical.
std::string firstDifference(const ParamValues& a, const ParamValues& b) {
    for (const auto& [key, value] : a)
        if (!b.count(key) || b.at(key) != value) return key;
    for (const auto& [key, value] : b)
        if (!a.count(key)) return key;
    return {};
}

QString errorOf(const std::string& text, std::string* key = nullptr) {
    try {
        instantiate(parsePreset(text, specsForModel, "old.json"));
    } catch (const PresetError& e) {
        if (key) *key = e.key();
        return QString::fromStdString(e.what());
    }
    return {};
}

std::string fluidSchema1(const std::string& params) {
    return R"({"schema": 1, "model": "fluid", "params": {)" + params + "}}";
}

} // namespace

class TestPresetMigration : public QObject {
    Q_OBJECT
private slots:
    void olderFileLoadsAsItsTwin_data() {
        QTest::addColumn<int>("schema");
        QTest::addColumn<QString>("stem");
        // The built-ins of each schema (ten in schema 1; fourteen in schema 2, with the wind tunnel's) and
        // a saved preset per model.
        for (const auto& [schema, atLeast] : {std::pair{1, 10}, std::pair{2, 14}}) {
            int builtins = 0, saved = 0;
            for (const auto& entry : std::filesystem::directory_iterator(folderOf(schema))) {
                const std::string stem = entry.path().stem().string();
                QTest::addRow("schema%d/%s", schema, stem.c_str()) << schema << QString::fromStdString(stem);
                (stem.rfind("user-", 0) == 0 ? saved : builtins)++;
            }
            QVERIFY(builtins >= atLeast && saved >= 3);
        }
    }
    void olderFileLoadsAsItsTwin() {
        QFETCH(int, schema);
        QFETCH(QString, stem);
        const std::string path = (folderOf(schema) / (stem.toStdString() + ".json")).string();
        QCOMPARE(schemaOf(readWholeFile(path)), schema);
        const Preset old = readPresetFile(path, specsForModel);
        const Preset twin = twinOf(stem.toStdString());
        QCOMPARE(old.model, twin.model);
        QCOMPARE(old.name, twin.name);
        // A built-in's description is prose that may be reworded since (the write-up's presets were); a
        // saved preset's is the user's and stays.
        if (stem.startsWith("user-")) QCOMPARE(old.description, twin.description);
        QCOMPARE(old.seed, twin.seed);
        // Parameters a built-in gained or changed after the file was written: the old file keeps the
        // value it always had (the shock tube's moving sampling window came after schema 2; the fluid
        // obstacle's pool, which gravity switched off no longer launches, pushes only, with a limited
        // release, no artificial pressure, and cohesion and adhesion holding its surface).
        const std::set<std::pair<std::string, std::string>> gainedSince{
            {"tunnel-shock-tube", "sample_window"}, {"fluid-obstacle", "compression_only"},
            {"fluid-obstacle", "release_limit"},    {"fluid-obstacle", "scorr_k"},
            {"fluid-obstacle", "cohesion"},         {"fluid-obstacle", "adhesion"}};
        Preset loaded = old, current = twin;
        for (const auto& [name, key] : gainedSince)
            if (name == stem.toStdString()) loaded.params.erase(key), current.params.erase(key);
        QVERIFY2(firstDifference(loaded.params, current.params).empty(),
                 firstDifference(loaded.params, current.params).c_str());
        QVERIFY(sameObstacles(old.obstacles, twin.obstacles));
        // The models they make hold the same parameters, defaults included.
        const auto a = instantiate(loaded), b = instantiate(current);
        QVERIFY2(firstDifference(a->params(), b->params()).empty(),
                 firstDifference(a->params(), b->params()).c_str());
    }

    void builtinsAreTheNewestSchema() {
        for (const auto& b : builtinPresets()) {
            const auto path = std::filesystem::path(PARTICLELAB_TEST_DATA) / ".." / ".." / "resources" /
                              "presets" / b.folder / (b.name + ".json");
            QVERIFY2(schemaOf(readWholeFile(path.string())) == Preset::kSchema, b.name.c_str());
        }
    }

    void fluidGravityBecomesTheSharedKeys() {
        const Preset p = readPresetFile((kSchema1 / "user-fluid-tank.json").string(), specsForModel);
        QCOMPARE(std::get<bool>(p.params.at("gravity_on")), false);
        QCOMPARE(std::get<double>(p.params.at("gravity")), 5.5); // was gravity_y = −5.5 (up positive)
        QCOMPARE(std::get<double>(p.params.at("box_width")), 60.0);
        QVERIFY(!p.params.count("gravity_y") && !p.params.count("world_width"));
    }

    void writesTheNewestSchema() {
        QTemporaryDir dir;
        for (int schema : {1, 2})
            for (const char* stem :
                 {"user-fluid-tank", "user-gas-piston", "user-dsmc-beams", "fluid-seed", "dsmc-seed"}) {
                const Preset old = readPresetFile((folderOf(schema) / (std::string(stem) + ".json")).string(),
                                                  specsForModel);
                const std::string path = dir.filePath(stem).toStdString() + ".json";
                writePresetFile(path, old, *specsForModel(old.model)); // what the app's Save does
                const std::string text = readWholeFile(path);
                QCOMPARE(schemaOf(text), Preset::kSchema);
                for (const char* gone :
                     {"\"world_width\"", "\"gravity_y\"", "\"count_1\"", "\"hist_bins\"", "\"tool_speed\"",
                      "\"piston_speed\"", "\"seed-3d\"", "\"cross_section\": \"seed\""})
                    QVERIFY2(text.find(gone) == std::string::npos, gone);
                const Preset back = parsePreset(text, specsForModel);
                const auto a = instantiate(old), b = instantiate(back);
                QVERIFY2(firstDifference(a->params(), b->params()).empty(), stem);
            }
    }

    void oldSnapshotLoads_data() {
        QTest::addColumn<int>("schema");
        QTest::newRow("schema1") << 1;
        QTest::newRow("schema2") << 2;
    }
    void oldSnapshotLoads() {
        QFETCH(int, schema);
        for (const char* stem : {"user-fluid-tank", "user-gas-piston", "user-dsmc-beams", "dsmc-seed"}) {
            const std::string oldText =
                readWholeFile((folderOf(schema) / (std::string(stem) + ".json")).string());
            auto model = instantiate(twinOf(stem));
            for (int s = 0; s < 3; ++s) model->step();
            const Snapshot now = takeSnapshot(*model);
            // The same snapshot as an older program wrote it: its state, and the preset in its schema.
            nlohmann::json root = nlohmann::json::parse(serializeSnapshot(now, model->paramSpecs()));
            QCOMPARE(root["preset"]["schema"].get<int>(), Preset::kSchema);
            root["preset"] = nlohmann::json::parse(oldText);
            std::unique_ptr<Model> resumed, reference;
            try {
                resumed = instantiate(parseSnapshot(root.dump(), specsForModel, "old-snapshot.json"));
                reference = instantiate(
                    parseSnapshot(serializeSnapshot(now, model->paramSpecs()), specsForModel, "now"));
            } catch (const PresetError& e) {
                QFAIL(qPrintable(QString("%1: %2").arg(stem, e.what())));
            }
            QVERIFY2(firstDifference(resumed->params(), reference->params()).empty(), stem);
            QVERIFY2(resumed->saveState().arrays == reference->saveState().arrays, stem);
            resumed->step();
            reference->step();
            QVERIFY2(resumed->saveState().arrays == reference->saveState().arrays, stem);
        }
    }

    void schema2KeyInASchema1FileIsNamed() {
        std::string key;
        const QString m = errorOf(fluidSchema1(R"("box_width": 50)"), &key);
        QCOMPARE(key, std::string("params.box_width"));
        QVERIFY2(m.contains("schema-2 key"), qPrintable(m));
        QCOMPARE(errorOf(R"({"schema": 1, "model": "gas", "params": {"gravity_on": false}})", &key).isEmpty(),
                 false);
        QCOMPARE(key, std::string("params.gravity_on"));
    }

    void badSchema1ValuesAreNamedAsWritten() {
        std::string key;
        QVERIFY(errorOf(fluidSchema1(R"("gravity_y": "down")"), &key).contains("must be a number"));
        QCOMPARE(key, std::string("params.gravity_y"));
        const QString range = errorOf(fluidSchema1(R"("gravity_y": -2e4)"), &key);
        QCOMPARE(key, std::string("params.gravity_y"));
        QVERIFY2(range.contains("now 'gravity'"), qPrintable(range));
        QVERIFY(!errorOf(fluidSchema1(R"("gravity": 9.8)"), &key).isEmpty()); // schema 1: a switch
        QCOMPARE(key, std::string("params.gravity"));
        QVERIFY(!errorOf(R"({"schema": 1, "model": "dsmc", "params": {"count_1": -5}})", &key).isEmpty());
        QCOMPARE(key, std::string("params.count_1"));
        QVERIFY(errorOf(fluidSchema1(R"("gravity_y": 0)")).isEmpty());
    }

    void newerNamesInAnOlderFileAreNamed() {
        std::string key;
        QString m = errorOf(R"({"schema": 2, "model": "gas", "params": {"tool_speed_factor": 0.5}})", &key);
        QCOMPARE(key, std::string("params.tool_speed_factor"));
        QVERIFY2(m.contains("schema-3 key") && m.contains("\"schema\": 3"), qPrintable(m));
        m = errorOf(R"({"schema": 1, "model": "fluid", "params": {"tool_speed_factor": 0.5}})", &key);
        QCOMPARE(key, std::string("params.tool_speed_factor"));
        QVERIFY2(m.contains("schema-3 key") && m.contains("schema-1 file"), qPrintable(m));
        m = errorOf(R"({"schema": 2, "model": "dsmc", "params": {"cross_section": "inverse-root"}})", &key);
        QCOMPARE(key, std::string("params.cross_section"));
        QVERIFY2(m.contains("schema-3 choice"), qPrintable(m));
        QVERIFY(!errorOf(R"({"schema": 1, "model": "fluid", "params": {"kernel": "3d"}})", &key).isEmpty());
        QCOMPARE(key, std::string("params.kernel"));
    }

    // Schema 2 → 3: the relative speeds' keys and the choices named after the write-up, chained after
    // schema 1 → 2, with errors naming the entry as the file spells it.
    void schema3NamesReplaceTheOldOnes() {
        const Preset gas = parsePreset(
            R"({"schema": 2, "model": "gas", "params": {"tool_speed": 0.4, "piston_speed": 0.2}})",
            specsForModel);
        QCOMPARE(std::get<double>(gas.params.at("tool_speed_factor")), 0.4);
        QCOMPARE(std::get<double>(gas.params.at("piston_speed_factor")), 0.2);
        QVERIFY(!gas.params.count("tool_speed") && !gas.params.count("piston_speed"));
        const Preset fluid = parsePreset(
            R"({"schema": 1, "model": "fluid", "params": {"tool_speed": 0.3, "kernel": "seed-3d"}})",
            specsForModel);
        QCOMPARE(std::get<double>(fluid.params.at("tool_speed_factor")), 0.3);
        QCOMPARE(std::get<std::string>(fluid.params.at("kernel")), std::string("3d"));
        for (const char* model : {"dsmc", "tunnel"}) {
            const Preset p = parsePreset(R"({"schema": 2, "model": ")" + std::string(model) +
                                             R"(", "params": {"cross_section": "seed"}})",
                                         specsForModel);
            QCOMPARE(std::get<std::string>(p.params.at("cross_section")), std::string("inverse-root"));
        }
        // The wind tunnel's speeds are in m/s and keep their keys.
        const Preset tunnel = parsePreset(
            R"({"schema": 2, "model": "tunnel", "params": {"tool_speed": 20, "piston_speed": 100}})",
            specsForModel);
        QCOMPARE(std::get<double>(tunnel.params.at("tool_speed")), 20.0);
        QCOMPARE(std::get<double>(tunnel.params.at("piston_speed")), 100.0);
        std::string key;
        const QString range =
            errorOf(R"({"schema": 1, "model": "gas", "params": {"tool_speed": 1e9}})", &key);
        QCOMPARE(key, std::string("params.tool_speed"));
        QVERIFY2(range.contains("now 'tool_speed_factor'"), qPrintable(range));
    }

    void schema3FileNamesTheNewNames() {
        std::string key;
        QString m = errorOf(R"({"schema": 3, "model": "gas", "params": {"tool_speed": 0.5}})", &key);
        QCOMPARE(key, std::string("params.tool_speed"));
        QVERIFY2(m.contains("'tool_speed' is called 'tool_speed_factor' since preset schema 3"),
                 qPrintable(m));
        m = errorOf(R"({"schema": 3, "model": "gas", "params": {"piston_speed": 0.5}})", &key);
        QVERIFY2(m.contains("'piston_speed_factor'"), qPrintable(m));
        m = errorOf(R"({"schema": 3, "model": "fluid", "params": {"world_width": 50}})", &key);
        QVERIFY2(m.contains("'world_width' is called 'box_width' since preset schema 2"), qPrintable(m));
        m = errorOf(R"({"schema": 3, "model": "fluid", "params": {"gravity_y": -9.8}})", &key);
        QVERIFY2(m.contains("'gravity' since preset schema 2, with the sign flipped"), qPrintable(m));
        m = errorOf(R"({"schema": 3, "model": "tunnel", "params": {"cross_section": "seed"}})", &key);
        QCOMPARE(key, std::string("params.cross_section"));
        QVERIFY2(m.contains("\"seed\" is called \"inverse-root\" since preset schema 3"), qPrintable(m));
        m = errorOf(R"({"schema": 3, "model": "fluid", "params": {"kernel": "seed-3d"}})", &key);
        QVERIFY2(m.contains("\"seed-3d\" is called \"3d\""), qPrintable(m));
        m = errorOf(R"({"schema": 3, "model": "gas", "params": {"stifness": 5}})", &key);
        QVERIFY2(!m.contains("is called"), qPrintable(m)); // a misspelling is only unknown
        QVERIFY(renamedKeyNote("tunnel", "tool_speed").empty());
        QVERIFY(renamedValueNote("dsmc", "cross_section", "vhs").empty());
    }

    void schema2FileUsesOnlySchema2Keys() {
        std::string key;
        QVERIFY(
            !errorOf(R"({"schema": 2, "model": "fluid", "params": {"world_width": 50}})", &key).isEmpty());
        QCOMPARE(key, std::string("params.world_width"));
        QVERIFY(!errorOf(R"({"schema": 2, "model": "fluid", "params": {"gravity": true}})", &key).isEmpty());
        QCOMPARE(key, std::string("params.gravity"));
    }

    // The wind tunnel's presets took the kind's name, and the write-up's scenes lost the word "seed": the
    // old names load the same preset, from the command line (with a notice) and from a file or snapshot
    // that names them.
    void renamedPresetsStillLoad() {
        for (const char* old : {"dsmc-cylinder", "dsmc-free-molecular-cylinder", "dsmc-shock-tube",
                                "dsmc-couette", "gas-seed", "dsmc-seed", "fluid-seed"}) {
            const RenamedPreset* renamed = renamedPreset(old);
            QVERIFY2(renamed, old);
            const Preset now = loadPreset(renamed->now);
            const Preset before = loadPreset(old);
            QCOMPARE(before.name, std::string(renamed->now));
            QCOMPARE(before.model, std::string(renamed->kind));
            QCOMPARE(now.model, std::string(renamed->kind));
            QVERIFY(before.params == now.params);
            QVERIFY(!isSnapshotFile(old));
            const std::string notice = presetRenameNotice(old);
            QVERIFY2(notice.find(renamed->now) != std::string::npos, notice.c_str());
            QVERIFY(presetRenameNotice(renamed->now).empty());
        }
        QVERIFY(renamedPreset("dsmc-bkw") == nullptr); // the other presets keep their names
        const Preset file =
            parsePreset(R"({"schema": 2, "model": "tunnel", "name": "dsmc-couette"})", specsForModel, "file");
        QCOMPARE(file.name, std::string("tunnel-couette"));
        const Preset gas =
            parsePreset(R"({"schema": 2, "model": "gas", "name": "dsmc-couette"})", specsForModel, "file");
        QCOMPARE(gas.name, std::string("dsmc-couette")); // a user's own name for another kind stays
        const Preset writeUp =
            parsePreset(R"({"schema": 3, "model": "dsmc", "name": "dsmc-seed"})", specsForModel, "file");
        QCOMPARE(writeUp.name, std::string("dsmc-write-up"));
    }

    void unknownSchemasAreRefused() {
        for (int schema : {0, Preset::kSchema + 1}) {
            const QString m = errorOf(R"({"schema": )" + std::to_string(schema) + R"(, "model": "gas"})");
            QVERIFY2(m.contains("not supported") &&
                         m.contains(QString("schemas 1 to %1").arg(Preset::kSchema)),
                     qPrintable(m));
        }
    }
};

QTEST_APPLESS_MAIN(TestPresetMigration)
#include "tst_preset_migration.moc"
