// Snapshots beyond the contract every kind keeps (tst_model_contract): the gas continues bit for bit
// across its spatial sorts and neighbour-list rebuilds, and with thermal walls drawing random numbers;
// snapshots written before the state tables (tests/data/snapshots, one per kind) load and continue
// exactly as the build that wrote them continued; broken snapshots are refused naming the entry; a
// snapshot larger than the old fixed bound reads back, and one beyond the machine's memory is refused.
#include "catalog/ModelCatalog.h"
#include "common/AtomicFile.h"
#include "common/MemoryBudget.h"
#include "common/Snapshot.h"
#include "common/SnapshotJson.h"

#include <QtTest>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <random>
#include <set>
#include <sstream>
#include <unistd.h>

using namespace pl;

namespace {

std::string particles(const Model& model) {
    std::ostringstream out;
    model.writeParticles(out);
    return out.str();
}

// Runs `before` steps, snapshots through text, runs `after` more on the restored copy and on an
// untouched model that never stopped, and compares particles and observables exactly.
void checkContinuation(Preset preset, int before, int after) {
    auto uninterrupted = instantiate(preset);
    for (int s = 0; s < before; ++s) uninterrupted->step();
    const std::string text = serializeSnapshot(takeSnapshot(*uninterrupted), uninterrupted->paramSpecs());
    auto restored = instantiate(parseSnapshot(text, specsForModel, "test"));
    QCOMPARE(restored->stepCount(), uninterrupted->stepCount());
    QCOMPARE(particles(*restored), particles(*uninterrupted));
    for (int s = 0; s < after; ++s) {
        uninterrupted->step();
        restored->step();
    }
    QVERIFY(!uninterrupted->failure());
    QCOMPARE(restored->time(), uninterrupted->time());
    QVERIFY2(particles(*restored) == particles(*uninterrupted), "the trajectories parted");
    const std::vector<double> a = uninterrupted->sampleSeries(), b = restored->sampleSeries();
    QCOMPARE(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k)
        QVERIFY2(a[k] == b[k] || (std::isnan(a[k]) && std::isnan(b[k])),
                 qPrintable(QString("%1: %2 vs %3")
                                .arg(QString::fromStdString(uninterrupted->seriesColumns()[k]))
                                .arg(a[k], 0, 'g', 17)
                                .arg(b[k], 0, 'g', 17)));
}

} // namespace

class TestSnapshot : public QObject {
    Q_OBJECT
private slots:
    void gasContinuesBitForBit() {
        // 250 + 250 steps: across two spatial sorts and many neighbour-list rebuilds.
        checkContinuation(loadPreset("gas-classroom"), 250, 250);
    }

    void gasWithThermalWallsAndObstaclesContinues() {
        Preset p = loadPreset("gas-mixture");
        p.params["wall_mode"] = std::string("thermal");
        p.params["wall_kT"] = 1.0;
        p.obstacles.push_back({Obstacle::Shape::Disc, 0.3, 0.2, 0.1});
        checkContinuation(p, 120, 150);
    }

    // Each file was written by `particlelab-cli run PRESET --steps N --snapshot KIND….snapshot.json` of
    // the build before the state tables, and its continuation by `particlelab-cli run
    // KIND….snapshot.json --steps 30 --dump-final KIND….after30.csv` of the same build
    // (tests/data/snapshots/README.md). Every kind has one.
    void earlierSnapshotsContinueAsTheyDid() {
        const std::filesystem::path folder = std::filesystem::path(PARTICLELAB_TEST_DATA) / "snapshots";
        std::set<std::string> kinds;
        for (const auto& entry : std::filesystem::directory_iterator(folder)) {
            const std::string file = entry.path().filename().string();
            const std::string suffix = ".snapshot.json";
            if (file.size() <= suffix.size() ||
                file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0)
                continue;
            const std::string stem = file.substr(0, file.size() - suffix.size());
            const Snapshot snapshot = readSnapshotFile(entry.path().string(), specsForModel);
            kinds.insert(snapshot.preset.model);
            auto model = instantiate(snapshot);
            for (int s = 0; s < 30; ++s) model->step();
            QVERIFY2(!model->failure(), stem.c_str());
            std::ifstream expected(folder / (stem + ".after30.csv"));
            QVERIFY2(expected, stem.c_str());
            std::stringstream text;
            text << expected.rdbuf();
            QVERIFY2(particles(*model) == text.str(), (stem + ": the continuation differs").c_str());
        }
        for (const ModelDescriptor& d : modelCatalog())
            QVERIFY2(kinds.count(d.kind) == 1, ("no earlier snapshot of kind " + d.kind).c_str());
        // Each pair has its recipe, from which tests/data/record.sh writes a new kind's pair.
        std::ifstream recipes(folder / "recipes.txt");
        QVERIFY(recipes);
        std::set<std::string> recipeStems;
        for (std::string line; std::getline(recipes, line);)
            if (!line.empty() && line[0] != '#') recipeStems.insert(line.substr(0, line.find(' ')));
        for (const auto& entry : std::filesystem::directory_iterator(folder)) {
            const std::string file = entry.path().filename().string();
            const std::string::size_type at = file.find(".snapshot.json");
            if (at != std::string::npos)
                QVERIFY2(recipeStems.count(file.substr(0, at)), ("no recipe for " + file).c_str());
        }
    }

    void brokenSnapshotsAreRefusedNamingTheEntry() {
        auto model = instantiate(loadPreset("gas-classroom"));
        const Snapshot good = takeSnapshot(*model);
        const auto refusal = [&](Snapshot s) -> std::string {
            const std::string text = serializeSnapshot(s, model->paramSpecs());
            try {
                instantiate(parseSnapshot(text, specsForModel, "broken"));
            } catch (const PresetError& e) {
                return e.key();
            }
            return "accepted";
        };
        Snapshot shorter = good;
        shorter.state.arrays["vx"].pop_back();
        QCOMPARE(refusal(shorter), std::string("state.vx"));
        Snapshot missing = good;
        missing.state.scalars.erase("time");
        QCOMPARE(refusal(missing), std::string("state.time"));
        Snapshot badSpecies = good;
        badSpecies.state.arrays["species"][0] = 0.5;
        QCOMPARE(refusal(badSpecies), std::string("state.species"));
        for (double notACount : {-1.0, 0.5, 1e300}) { // next_id is a 32-bit count
            Snapshot badCounter = good;
            badCounter.state.scalars["next_id"] = notACount;
            QCOMPARE(refusal(badCounter), std::string("state.next_id"));
        }
        QVERIFY_THROWS_EXCEPTION(PresetError, parseSnapshot("{\"snapshot_schema\": 7}", specsForModel, "x"));
        QVERIFY_THROWS_EXCEPTION(PresetError, parseSnapshot("{\"schema\": 1}", specsForModel, "x"));
        QVERIFY(isSnapshotJson(serializeSnapshot(good, model->paramSpecs())));
        QVERIFY(!isSnapshotJson(serializePreset(good.preset, model->paramSpecs())));
    }

    // A state of 14 M numbers, a 290 MB file, beyond the 256 MiB that earlier builds read at most: it is
    // written in pieces and read back as it streams in, every number bit for bit (-0, subnormals, the
    // extremes, whole numbers up to 2⁵³; NaN comes back as NaN). A text read back equally and a key
    // given twice is refused by its path.
    void largeSnapshotsReadBackBitForBit() {
        auto model = instantiate(loadPreset("gas-classroom"));
        Snapshot big = takeSnapshot(*model);
        std::mt19937_64 bits(46);
        const double special[] = {-0.0,
                                  0.0,
                                  std::numeric_limits<double>::denorm_min(),
                                  -std::numeric_limits<double>::max(),
                                  std::numeric_limits<double>::min(),
                                  9007199254740992.0,
                                  1e22,
                                  123456789012345678.0,
                                  0.1,
                                  std::numeric_limits<double>::quiet_NaN()};
        for (const char* key : {"big_a", "big_b"}) {
            std::vector<double>& values = big.state.arrays[key];
            values.resize(7'000'000);
            for (double& v : values) {
                const std::uint64_t word = bits();
                std::memcpy(&v, &word, sizeof v);
                if (!std::isfinite(v)) v = std::ldexp(static_cast<double>(word >> 11), -53);
            }
            std::copy(std::begin(special), std::end(special), values.begin());
        }
        QTemporaryDir dir;
        const std::string path = dir.filePath("big.plsnap").toStdString();
        writeSnapshotFile(path, *model); // a small one first: the big one replaces it atomically
        writePiecesAtomically(
            path, [&](const PieceSink& write) { writeSnapshotJson(big, model->paramSpecs(), write); });
        const auto bytes = std::filesystem::file_size(path);
        QVERIFY2(bytes > (std::size_t{256} << 20), qPrintable(QString::number(bytes)));
        const Snapshot back = readSnapshotFile(path, specsForModel);
        const auto same = [](double a, double b) {
            return (std::isnan(a) && std::isnan(b)) || std::memcmp(&a, &b, sizeof a) == 0;
        };
        QCOMPARE(back.state.scalars.size(), big.state.scalars.size());
        for (const auto& [key, value] : big.state.scalars)
            QVERIFY2(same(back.state.scalars.at(key), value), key.c_str());
        QCOMPARE(back.state.arrays.size(), big.state.arrays.size());
        for (const auto& [key, values] : big.state.arrays) {
            const std::vector<double>& read = back.state.arrays.at(key);
            QCOMPARE(read.size(), values.size());
            for (std::size_t i = 0; i < values.size(); ++i)
                if (!same(values[i], read[i]))
                    QFAIL(qPrintable(QString("%1[%2]: %3 read back as %4")
                                         .arg(key.c_str())
                                         .arg(i)
                                         .arg(values[i], 0, 'g', 17)
                                         .arg(read[i], 0, 'g', 17)));
        }
        QCOMPARE(back.preset.params, big.preset.params);
        QVERIFY(openExperiment(path).isSnapshot);
        QVERIFY(isSnapshotFile(path));

        std::string twice = serializeSnapshot(takeSnapshot(*model), model->paramSpecs());
        twice.replace(twice.find("\"arrays\":{"), 10, "\"arrays\":{\"vx\":[1.0],");
        try {
            parseSnapshot(twice, specsForModel, "twice");
            QFAIL("a key given twice was read");
        } catch (const PresetError& e) {
            QCOMPARE(e.key(), std::string("state.arrays.vx"));
        }
    }

    // Larger than this machine's memory can read: refused from its size, naming the file, its size,
    // the bound and the memory (one GiB assumed here, so the answer is the same on every machine).
    void snapshotsBeyondTheMemoryAreRefusedFromTheirSize() {
        QTemporaryDir dir;
        const std::string path = dir.filePath("huge.plsnap").toStdString();
        {
            std::ofstream out(path);
            out << R"({"preset":{},"snapshot_schema":1,)";
        }
        QVERIFY(::truncate(path.c_str(), off_t{4} << 30) == 0); // sparse
        const AssumedMemory oneGiB(double(std::size_t{1} << 30));
        const QString expected = QString::fromStdString(
            "will not read '" + path + "': it holds 4 GiB, more than the " + byteSize(snapshotReadBound()) +
            " that this machine can read back as a snapshot now: reading a snapshot holds about");
        for (const auto& read : std::vector<std::function<void()>>{
                 [&] { readSnapshotFile(path, specsForModel); }, [&] { openExperiment(path); }}) {
            try {
                read();
                QFAIL("a 4 GiB snapshot was read with 1 GiB of memory");
            } catch (const PresetError& e) {
                const QString m = e.what();
                QVERIFY2(m.startsWith(expected) && m.contains("this machine can give 819.2 MiB now"),
                         qPrintable(m));
            }
        }
    }
};

QTEST_APPLESS_MAIN(TestSnapshot)
#include "tst_snapshot.moc"
