// Snapshots beyond the contract every kind keeps (tst_model_contract): the gas continues bit for bit
// across its spatial sorts and neighbour-list rebuilds, and with thermal walls drawing random numbers;
// snapshots written before the state tables (tests/data/snapshots, one per kind) load and continue
// exactly as the build that wrote them continued; broken snapshots are refused naming the entry.
#include "catalog/ModelCatalog.h"
#include "common/Snapshot.h"

#include <QtTest>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

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
};

QTEST_APPLESS_MAIN(TestSnapshot)
#include "tst_snapshot.moc"
