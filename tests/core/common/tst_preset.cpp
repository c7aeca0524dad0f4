// Presets: every built-in loads and round-trips; each kind of bad input is refused with its own message
// and nothing is half-applied.
#include "catalog/ModelCatalog.h"
#include "common/AtomicFile.h"
#include "common/InputLimits.h"
#include "common/MemoryBudget.h"
#include "gas/GasModel.h"

#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>
#include <sys/stat.h>
#include <unistd.h>

using namespace pl;

namespace {

std::string gasPreset(const std::string& params, const std::string& extra = "") {
    return R"({"schema": 1, "model": "gas", "name": "t", "seed": 3, "params": {)" + params + "}" + extra +
           "}";
}

// The PresetError message of parsing and instantiating text; empty when it was accepted.
QString errorOf(const std::string& text, std::string* key = nullptr) {
    try {
        instantiate(parsePreset(text, specsForModel, "test.json"));
    } catch (const PresetError& e) {
        if (key) *key = e.key();
        return QString::fromStdString(e.what());
    }
    return {};
}

} // namespace

class TestPreset : public QObject {
    Q_OBJECT
private slots:
    void builtinsExistAndInstantiate() {
        QStringList names;
        for (const auto& p : builtinPresets()) {
            names << QString::fromStdString(p.name);
            QVERIFY2(!p.preset.description.empty(), p.name.c_str());
            auto model = instantiate(p.preset);
            // Every preset starts with particles but the fluid write-up's tank, which waits to be poured.
            QVERIFY2(model->particleCount() > 0 || p.name == "fluid-write-up", p.name.c_str());
        }
        for (const char* required : {"gas-write-up", "gas-classroom", "gas-mixture"})
            QVERIFY(names.contains(required));
    }

    void writeUpPresetIsTheWriteUp() {
        const Preset p = loadPreset("gas-write-up");
        auto model = instantiate(p);
        const auto& md = static_cast<const GasModel&>(*model).parameters();
        QCOMPARE(md.totalCount(), 4096LL);
        QCOMPARE(md.a.diameter, 0.01);
        QCOMPARE(md.stiffness, 1000.0);
        QCOMPARE(md.dt, 1e-4);
        QCOMPARE(md.left(), -1.0);
        QCOMPARE(md.right(), 1.0);
        QVERIFY(md.integrator == GasIntegrator::VelocityVerlet);
        const auto& s = static_cast<const GasModel&>(*model).state();
        for (std::size_t i = 0; i < s.size(); ++i)
            QVERIFY(std::abs(std::hypot(s.vx[i], s.vy[i]) - 1.0) < 1e-12);
    }

    void roundTripThroughFile() {
        QTemporaryDir dir;
        for (const auto& builtin : builtinPresets()) {
            Preset p = builtin.preset;
            const auto model = instantiate(p);
            const bool hasObstacles = model->tools() != nullptr; // a DSMC cell has none
            if (hasObstacles) {
                // Inside each scene's box: obstacle centres outside it are refused.
                const SceneView view = model->sceneView();
                const double cx = 0.5 * (view.left + view.right), cy = 0.5 * (view.bottom + view.top);
                const double w = view.right - view.left, h = view.top - view.bottom;
                p.obstacles.push_back({Obstacle::Shape::Disc, cx + 0.05 * w, cy - 0.1 * h, 0.075 * w});
                p.obstacles.push_back(
                    {Obstacle::Shape::Box, cx - 0.15 * w, cy + 0.2 * h, 0.05 * w, 0.1 * w, 0.05});
            }
            const auto* specs = specsForModel(p.model);
            const std::string path =
                dir.filePath(QString::fromStdString(builtin.name + ".json")).toStdString();
            writePresetFile(path, p, *specs);
            const Preset back = readPresetFile(path, specsForModel);
            QCOMPARE(back.model, p.model);
            QCOMPARE(back.seed, p.seed);
            QCOMPARE(back.description, p.description);
            QCOMPARE(back.obstacles.size(), p.obstacles.size());
            if (hasObstacles) QCOMPARE(back.obstacles.back().halfHeight, 0.05);
            // Every parameter written, equal to what the model runs with.
            auto a = instantiate(p), b = instantiate(back);
            QVERIFY(a->params() == b->params());
            QCOMPARE(back.params.size(), specs->size());
            // A second serialisation is byte-identical: the format is stable.
            QCOMPARE(serializePreset(back, *specs),
                     serializePreset(readPresetFile(path, specsForModel), *specs));
        }
        // Atomic write leaves no temporary file behind.
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files).size(),
                 static_cast<qsizetype>(builtinPresets().size()));
    }

    void modelToPresetRoundTrip() {
        GasModel model;
        model.reset(loadPreset("gas-mixture"));
        model.setParams({{"gravity", 0.5}});
        const Preset p = model.toPreset();
        GasModel copy;
        copy.reset(parsePreset(serializePreset(p, GasParams::describe()), specsForModel));
        QVERIFY(copy.params() == model.params());
    }

    void invalidJsonNamesLine() {
        const QString m = errorOf("{\"schema\": 1,\n \"model\": }");
        QVERIFY2(m.contains("not valid JSON") && m.contains("line 2"), qPrintable(m));
    }

    void unsupportedSchema() {
        const QString m = errorOf(R"({"schema": 4, "model": "gas"})");
        QVERIFY2(m.contains("schema 4 is not supported"), qPrintable(m));
    }

    void unknownModel() {
        QVERIFY(errorOf(R"({"schema": 1, "model": "plasma"})").contains("unknown scene \"plasma\""));
    }

    void unknownKeys() {
        std::string key;
        QVERIFY(errorOf(gasPreset(R"("stifness": 10)"), &key).contains("unknown parameter"));
        QCOMPARE(key, std::string("params.stifness"));
        QVERIFY(errorOf(gasPreset("", R"(, "colour": 1)"), &key).contains("unknown key 'colour'"));
    }

    void wrongType() {
        std::string key;
        const QString m = errorOf(gasPreset(R"("dt": "fast")"), &key);
        QVERIFY2(m.contains("must be a number") && m.contains("[-1, 1]"), qPrintable(m));
        QCOMPARE(key, std::string("params.dt"));
        QVERIFY(errorOf(gasPreset(R"("piston_enabled": 1)")).contains("true or false"));
        QVERIFY(errorOf(gasPreset(R"("count_a": 10.5)")).contains("integer"));
    }

    void outOfRange() {
        std::string key;
        const QString m = errorOf(gasPreset(R"("stiffness": -5)"), &key);
        QVERIFY2(m.contains("out of range") && m.contains("[1e-06, 1e+12] M/T²"), qPrintable(m));
        QCOMPARE(key, std::string("params.stiffness"));
        QVERIFY(errorOf(gasPreset(R"("dt": 0)")).contains("must not be 0"));
        QVERIFY(errorOf(gasPreset(R"("integrator": "leapfrog")")).contains("velocity-verlet"));
    }

    void nonFiniteNumbers() {
        QVERIFY(errorOf(gasPreset(R"("dt": 1e999)")).contains("number overflow"));
        QVERIFY(errorOf(gasPreset(R"("dt": "NaN")")).contains("must be a number"));
    }

    void tooManyParticles() {
        std::string key;
        QVERIFY(errorOf(gasPreset(R"("count_a": 5000, "max_particles": 4000)"), &key)
                    .contains("exceeds max_particles"));
        QCOMPARE(key, std::string("params.count_a"));
        const QString fit = errorOf(gasPreset(R"("count_a": 40000, "diameter_a": 0.02)"), &key);
        QVERIFY2(fit.contains("% fits"), qPrintable(fit));
        // The memory rule (common/MemoryBudget.h): a need beyond any machine is refused naming its key and
        // the fix, a small one passes. tst_cli_robustness checks every kind under an address-space limit.
        QVERIFY(availableMemoryBytes() > 0);
        const auto lessPlease = [](double) { return std::string("use less"); };
        try {
            requireMemory({1e30, "max_particles", lessPlease});
            QFAIL("a state of 1e30 bytes was accepted");
        } catch (const ParamError& e) {
            QCOMPARE(e.key(), std::string("max_particles"));
            QVERIFY2(std::string(e.what()).find("of memory") != std::string::npos &&
                         std::string(e.what()).find("use less") != std::string::npos,
                     e.what());
        }
        requireMemory({1024.0, "max_particles", lessPlease});
        // An assumed memory answers in place of the machine while it lives (the catalogue of translated
        // refusals is made under one), so the refusal is the same on every machine.
        {
            const AssumedMemory small(1024.0 * 1024);
            QCOMPARE(availableMemoryBytes(), 1024.0 * 1024);
            const QString refused = errorOf(gasPreset(R"("max_particles": 100000)"), &key);
            QVERIFY2(refused.contains("of memory") && refused.contains("max_particles"), qPrintable(refused));
        }
        QVERIFY(availableMemoryBytes() != 1024.0 * 1024);
    }

    void badObstacles() {
        std::string key;
        QVERIFY(errorOf(gasPreset("", R"(, "obstacles": [{"shape": "disc", "x": 0, "y": 0, "radius": -1}])"),
                        &key)
                    .contains("radius"));
        QCOMPARE(key, std::string("obstacles[0].radius"));
        QVERIFY(errorOf(gasPreset("", R"(, "obstacles": [{"shape": "star", "x": 0, "y": 0}])"))
                    .contains("\"star\""));
        QVERIFY(errorOf(gasPreset("", R"(, "obstacles": [{"shape": "disc", "x": 9, "y": 0, "radius": 0.1}])"))
                    .contains("outside the box"));
    }

    void missingFileNamesPath() {
        try {
            loadPreset("/nonexistent/dir/p.json");
            QFAIL("loaded a missing file");
        } catch (const PresetError& e) {
            QVERIFY(std::string(e.what()).find("/nonexistent/dir/p.json") != std::string::npos);
        }
        QVERIFY_THROWS_EXCEPTION(FileError, writeFileAtomically("/nonexistent/dir/p.json", "{}"));
    }

    // Nesting beyond kMaxJsonDepth is refused before any parser, copy or printer recurses into it (a
    // preset 200 000 deep used to overflow the stack in the migration's copy of its params).
    void jsonNestedDeeperThanTheLimitIsRefused() {
        const auto nested = [](int depth) { return std::string(depth, '[') + std::string(depth, ']'); };
        for (const int schema : {1, 2}) {
            const std::string deep = R"({"schema": )" + std::to_string(schema) +
                                     R"(, "model": "gas", "params": {"dt": )" + nested(200000) + "}}";
            const QString m = errorOf(deep);
            QVERIFY2(m.startsWith("test.json: ") && m.contains("more than 64 levels deep (line 1)"),
                     qPrintable(m));
        }
        // At the limit the depth is allowed (and the value refused for what it is); inside strings,
        // brackets are text.
        const QString atLimit = errorOf(gasPreset(R"("dt": )" + nested(kMaxJsonDepth - 2)));
        QVERIFY2(!atLimit.isEmpty() && !atLimit.contains("levels deep"), qPrintable(atLimit));
        QVERIFY(errorOf("{\"schema\": 2, \"model\": \"gas\", \"name\": \"" + std::string(1000, '[') + "\"}")
                    .isEmpty());
        const std::string deepSnapshot =
            R"({"snapshot_schema": 1, "state": {"scalars": {}, "arrays": {}}, "preset": )" + nested(100000) +
            "}";
        QVERIFY(!isSnapshotJson(deepSnapshot));
        try {
            parseSnapshot(deepSnapshot, specsForModel, "deep.json");
            QFAIL("a snapshot nested 100 000 deep was read");
        } catch (const PresetError& e) {
            QVERIFY2(std::string(e.what()).find("more than 64 levels deep") != std::string::npos, e.what());
        }
    }

    // The CLI and the app open files through openExperiment: only regular files, of a bounded size, and
    // at once (a FIFO does not block it).
    void experimentFilesAreRegularAndBounded() {
        QTemporaryDir dir;
        const std::string fifo = dir.filePath("fifo.json").toStdString();
        QVERIFY(::mkfifo(fifo.c_str(), 0644) == 0);
        const auto refusal = [](const std::string& path) -> QString {
            try {
                openExperiment(path);
            } catch (const PresetError& e) {
                return QString::fromStdString(e.what());
            }
            return {};
        };
        QVERIFY2(refusal(fifo).contains("it is a FIFO, and only regular files are read"),
                 qPrintable(refusal(fifo)));
        QVERIFY(!isSnapshotFile(fifo));
        QVERIFY(refusal("/dev/null").contains("it is a character device"));
        QVERIFY(refusal(dir.path().toStdString()).contains("it is a directory"));
        const std::string huge = dir.filePath("huge.json").toStdString();
        {
            std::FILE* f = std::fopen(huge.c_str(), "w");
            QVERIFY(f);
            std::fclose(f);
        }
        // A snapshot may be as large as the memory this machine can give its reader (64 MiB assumed here,
        // so the bound is the same on every machine); beyond that a file is refused from its size. Below
        // it, a file that is no snapshot is a preset, of at most 16 MiB.
        {
            const AssumedMemory memory(double(std::size_t{64} << 20));
            QVERIFY(::truncate(huge.c_str(), off_t{1} << 30) == 0); // sparse
            QVERIFY2(refusal(huge).contains("holds 1 GiB, more than the " +
                                            QString::fromStdString(byteSize(snapshotReadBound())) +
                                            " that this machine can read back as a snapshot now: reading a "
                                            "snapshot holds about"),
                     qPrintable(refusal(huge)));
            QVERIFY_THROWS_EXCEPTION(PresetError, readSnapshotFile(huge, specsForModel));
        }
        QVERIFY(::truncate(huge.c_str(), off_t{20} << 20) == 0);
        QVERIFY2(refusal(huge).contains("holds 20 MiB, more than the 16 MiB that a preset file may hold"),
                 qPrintable(refusal(huge)));
        QVERIFY(QString::fromStdString(byteSize(kMaxPresetFileBytes)) == "16 MiB");
        QVERIFY(QString::fromStdString(byteSize(1536)) == "1.5 KiB");
        // A built-in name and a preset file still open; a snapshot opens with its state.
        QVERIFY(!openExperiment("gas-classroom").isSnapshot);
        GasModel model;
        model.reset(loadPreset("gas-classroom"));
        model.step();
        const std::string snapshot = dir.filePath("s.json").toStdString();
        writeSnapshotFile(snapshot, model);
        const OpenedExperiment opened = openExperiment(snapshot);
        QVERIFY(opened.isSnapshot && !opened.snapshot.state.arrays.empty());
    }

    // Whether two output paths are one file: through links, for files not there yet by folder and name.
    void sameFileSeesThroughLinks() {
        QTemporaryDir dir;
        const auto at = [&](const char* name) { return dir.filePath(name).toStdString(); };
        {
            std::FILE* f = std::fopen(at("a.csv").c_str(), "w");
            QVERIFY(f);
            std::fclose(f);
        }
        QVERIFY(::symlink(at("a.csv").c_str(), at("link.csv").c_str()) == 0);
        QVERIFY(::link(at("a.csv").c_str(), at("hard.csv").c_str()) == 0);
        QVERIFY(::mkdir(at("sub").c_str(), 0755) == 0 && ::symlink("sub", at("sublink").c_str()) == 0);
        QVERIFY(sameFile(at("a.csv"), at("a.csv")));
        QVERIFY(sameFile(at("a.csv"), at("link.csv")));
        QVERIFY(sameFile(at("hard.csv"), at("link.csv")));
        QVERIFY(sameFile(at("new.csv"), dir.path().toStdString() + "/./sub/../new.csv"));
        QVERIFY(sameFile(at("sub/n.csv"), at("sublink/n.csv")));
        QVERIFY(!sameFile(at("a.csv"), at("new.csv")));
        QVERIFY(!sameFile(at("sub/n.csv"), at("n.csv")));
        QVERIFY(sameFile("/nonexistent/x.csv", "/nonexistent/./x.csv"));
    }

    void nothingHalfApplied() {
        GasModel model;
        model.reset(loadPreset("gas-classroom"));
        for (int i = 0; i < 10; ++i) model.step();
        const auto before = model.params();
        const auto x0 = model.state().x;
        // One bad value among good ones: nothing changes.
        QVERIFY_THROWS_EXCEPTION(ParamError, model.setParams({{"dt", 2e-4}, {"stiffness", -5.0}}));
        QVERIFY(model.params() == before);
        // A preset that fails cross-field validation leaves the running experiment alone.
        Preset bad = loadPreset("gas-classroom");
        bad.params["count_a"] = 1e6;
        QVERIFY_THROWS_EXCEPTION(PresetError, model.reset(bad));
        QVERIFY(model.params() == before);
        QCOMPARE(model.stepCount(), 10LL);
        QVERIFY(model.state().x == x0);
    }
};

QTEST_APPLESS_MAIN(TestPreset)
#include "tst_preset.moc"
