// The model registry: every registration agrees with the model it creates (series columns, particle
// count, parameters), declares its units, its plots name columns it has, and every built-in preset belongs
// to a registered kind.
#include "catalog/ModelCatalog.h"
#include "gl/GpuModels.h"
#include "gl/MachineBenchmark.h"

#include <QtTest>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

using namespace pl;

namespace {

std::vector<std::string> namesOf(const std::vector<SeriesColumn>& columns) {
    std::vector<std::string> names;
    for (const SeriesColumn& c : columns) names.push_back(c.name);
    return names;
}

bool contains(const std::vector<std::string>& list, const std::string& name) {
    return std::find(list.begin(), list.end(), name) != list.end();
}

} // namespace

class TestRegistry : public QObject {
    Q_OBJECT
private slots:
    void kindsAreUniqueAndFound() {
        std::set<std::string> kinds;
        for (const ModelDescriptor& d : modelCatalog()) {
            QVERIFY2(kinds.insert(d.kind).second, d.kind.c_str());
            QCOMPARE(findModel(d.kind), &d);
            QVERIFY(!d.title.empty());
            QCOMPARE(specsForModel(d.kind), d.specs);
            const auto model = createModel(d.kind);
            QVERIFY(model);
            QCOMPARE(model->kind(), d.kind);
            QCOMPARE(&model->paramSpecs(), d.specs);
        }
        QVERIFY(!findModel("no-such-kind"));
        QVERIFY(!createModel("no-such-kind"));
        Preset unknown;
        unknown.model = "no-such-kind";
        QVERIFY_THROWS_EXCEPTION(PresetError, particleCount(unknown));
    }

    // One unit system per kind, declared once: the parameter panel, `particlelab-cli list` and the help of
    // run and columns print it from the registration.
    void everyKindDeclaresItsUnits() {
        for (const ModelDescriptor& d : modelCatalog()) {
            QVERIFY2(!d.units.name.empty(), d.kind.c_str());
            QVERIFY2(!d.units.summary.empty(), d.kind.c_str());
            QVERIFY2(d.units.summary != d.units.name, d.kind.c_str()); // the summary spells the units out
        }
    }

    // The descriptor's column list is what the model samples: same names, same order, same count.
    void seriesListMatchesSampleSeries() {
        for (const BuiltinPreset& builtin : builtinPresets()) {
            const ModelDescriptor* d = findModel(builtin.preset.model);
            QVERIFY2(d, builtin.name.c_str());
            const auto model = instantiate(builtin.preset);
            QCOMPARE(namesOf(d->series), model->seriesColumns());
            QCOMPARE(model->sampleSeries().size(), d->series.size());
            model->step();
            QCOMPARE(model->sampleSeries().size(), d->series.size());
            std::set<std::string> unique;
            for (const SeriesColumn& c : d->series) {
                QVERIFY2(!c.name.empty() && !c.label.empty(), builtin.name.c_str());
                QVERIFY2(unique.insert(c.name).second, c.name.c_str());
            }
        }
    }

    void particleCountFromParamsMatchesReset() {
        for (const BuiltinPreset& builtin : builtinPresets()) {
            const auto model = instantiate(builtin.preset);
            QCOMPARE(particleCount(builtin.preset), model->particleCount());
        }
    }

    // Changed counts, caps and obstacles are counted like reset() makes them.
    void particleCountFollowsTheParameters() {
        Preset gas = loadPreset("gas-mixture");
        gas.params["count_a"] = 37.0;
        Preset fluid = loadPreset("fluid-obstacle");
        fluid.obstacles.push_back({});
        fluid.obstacles.back().x = 60;
        fluid.obstacles.back().y = 6;
        fluid.obstacles.back().radius = 5;
        Preset spaced = loadPreset("fluid-dam-break");
        spaced.params["spawn_spacing"] = 0.7;
        Preset dsmc = loadPreset("dsmc-write-up");
        dsmc.params["count_a"] = 500.0;
        for (const Preset* preset : {&gas, &fluid, &spaced, &dsmc}) {
            const auto model = instantiate(*preset);
            QCOMPARE(particleCount(*preset), model->particleCount());
        }
        QVERIFY(particleCount(spaced) < particleCount(loadPreset("fluid-dam-break")));
        QCOMPARE(particleCount(gas), std::size_t(37) + particleCount(loadPreset("gas-mixture")) -
                                         static_cast<std::size_t>(std::get<double>(
                                             loadPreset("gas-mixture").params.at("count_a"))));
        QVERIFY(particleCount(fluid) < particleCount(loadPreset("fluid-obstacle")));
        Preset bad = loadPreset("gas-write-up");
        bad.params["count_a"] = -1.0;
        QVERIFY_THROWS_EXCEPTION(PresetError, particleCount(bad));
    }

    void plotSpecsNameExistingColumns() {
        std::set<std::string> plotNames;
        for (const ModelDescriptor& d : modelCatalog()) {
            const std::vector<std::string> columns = namesOf(d.series);
            const BuiltinPreset* first = builtinPresetsOf(d.kind).front();
            const auto model = instantiate(first->preset);
            model->step();
            std::vector<std::string> profiles;
            for (const NamedProfile& p : model->profiles()) profiles.push_back(p.name);
            for (const PlotSpec& plot : d.plots) {
                QVERIFY2(plotNames.insert(plot.name).second, plot.name.c_str());
                QVERIFY2(!plot.upper.curves.empty(), plot.name.c_str());
                for (const PlotPanel* panel : {&plot.upper, &plot.lower}) {
                    QVERIFY2(contains(columns, panel->xColumn), plot.name.c_str());
                    for (const PlotCurve& curve : panel->curves)
                        QVERIFY2(contains(panel->profile ? profiles : columns, curve.column),
                                 (plot.name + ": " + curve.column).c_str());
                }
            }
        }
    }

    void everyBuiltinPresetsModelIsRegistered() {
        for (const BuiltinPreset& builtin : builtinPresets()) {
            QVERIFY2(findModel(builtin.preset.model), builtin.name.c_str());
            QCOMPARE(builtin.folder, builtin.preset.model); // resources/presets/<kind>/
        }
        std::size_t listed = 0;
        for (const ModelDescriptor& d : modelCatalog()) {
            QVERIFY2(!builtinPresetsOf(d.kind).empty(), d.kind.c_str());
            listed += builtinPresetsOf(d.kind).size();
        }
        QCOMPARE(listed, builtinPresets().size());
    }

    // The report's theory rows are computed in core by the kind, with the verdict as data for a lesson's
    // check: the dam break's front stays below Ritter's bound.
    void theoryRowsCarryTheirVerdicts() {
        const ModelDescriptor& fluid = *findModel("fluid");
        QVERIFY(fluid.theoryRows);
        auto model = instantiate(loadPreset("fluid-dam-break"));
        TimeSeries series(model->seriesColumns());
        series.append(model->sampleSeries());
        for (int s = 1; s <= 100; ++s) {
            model->step();
            if (s % 10 == 0) series.append(model->sampleSeries());
        }
        const std::vector<TheoryRow> rows = fluid.theoryRows(*model, series);
        const auto front = std::find_if(rows.begin(), rows.end(), [](const TheoryRow& row) {
            return row.name.rfind("Surge front", 0) == 0;
        });
        QVERIFY(front != rows.end());
        QVERIFY(front->agrees.has_value() && *front->agrees);
        QVERIFY2(front->note.find("Ritter's shallow-water bound") != std::string::npos, front->note.c_str());
        for (const ModelDescriptor& d : modelCatalog()) QVERIFY2(d.theoryRows, d.kind.c_str());
    }

    // Present mode's numbers: plain digits up to a million (the ballistic board read "2E+03" particles
    // and an energy of "1.03E+03 M·L²/T²"), an exponent beyond, a fixed format as declared.
    void readoutsWritePlainNumbersUpToAMillion() {
        const auto written = [](double value, char format = 'g', int precision = 3) {
            PresentReadout readout;
            readout.format = format;
            readout.precision = precision;
            const NumberFormat f = readoutFormat(readout, value);
            char text[64];
            if (f.format == 'f')
                std::snprintf(text, sizeof text, "%.*f", f.precision, value);
            else
                std::snprintf(text, sizeof text, "%.*g", f.precision, value);
            return std::string(text);
        };
        QCOMPARE(written(2000), std::string("2000"));
        QCOMPARE(written(1031.7), std::string("1032"));
        QCOMPARE(written(999999), std::string("999999"));
        QCOMPARE(written(0.474), std::string("0.474"));
        QCOMPARE(written(12.345), std::string("12.3"));
        QCOMPARE(written(0.000123), std::string("0.000123"));
        QCOMPARE(written(2.5e7), std::string("2.5e+07"));
        QCOMPARE(written(3e-7), std::string("3e-07"));
        QCOMPARE(written(-4500), std::string("-4500"));
        QCOMPARE(written(3.14159, 'f', 2), std::string("3.14"));
    }

    // The preset the model contract starts from is one of the kind's own built-in presets, and the arrays
    // the registration names are in its snapshots (docs/architecture.md, "Adding a model kind").
    void contractPresetAndStateArraysAreTheKinds() {
        for (const ModelDescriptor& d : modelCatalog()) {
            QVERIFY2(!d.contractPreset.empty(), d.kind.c_str());
            const auto presets = builtinPresetsOf(d.kind);
            QVERIFY2(std::any_of(presets.begin(), presets.end(),
                                 [&](const BuiltinPreset* p) { return p->name == d.contractPreset; }),
                     (d.kind + ": " + d.contractPreset).c_str());
            const Snapshot snapshot = takeSnapshot(*instantiate(loadPreset(d.contractPreset)));
            for (const std::string& name : {d.stateArrays.x, d.stateArrays.y, d.stateArrays.id})
                if (!name.empty())
                    QVERIFY2(snapshot.state.arrays.count(name), (d.kind + ": " + name).c_str());
        }
    }

    // A new experiment starts from defaultPreset(): the model a plain create() gives.
    void defaultPresetIsTheDefaultModel() {
        for (const ModelDescriptor& d : modelCatalog()) {
            const Preset defaults = defaultPreset(d);
            const Preset made = d.create()->toPreset();
            QCOMPARE(defaults.model, made.model);
            QCOMPARE(defaults.seed, made.seed);
            QCOMPARE(defaults.obstacles.size(), made.obstacles.size());
            QVERIFY2(defaults.params == made.params, d.kind.c_str());
            QCOMPARE(instantiate(defaults)->particleCount(), d.create()->particleCount());
        }
    }

    // The machine benchmark's scale, from each kind's registration: every size the dialog and
    // particlelab-bench time by default is one the kind's model takes, with about that many particles
    // (the fluid's block rounds to whole rows, the tunnel's fill to the free stream's count).
    void benchmarkScalesGiveTheSizesAsked() {
        int scaled = 0;
        for (const ModelDescriptor& d : modelCatalog()) {
            const BenchmarkScale& scale = d.benchmark;
            if (!scale.scaledPreset) continue;
            ++scaled;
            QVERIFY2(scale.largest && scale.largest() > 0 && !scale.limit.empty(), d.kind.c_str());
            QVERIFY2(!scale.benchSizes.empty() && !scale.sizesHelp.empty(), d.kind.c_str());
            QVERIFY2(scale.gpuBytesPerParticleStep > 0 &&
                         (scale.goalBytesPerParticleStep > 0) != (scale.goalParticleStepsPerSecond > 0),
                     d.kind.c_str());
            std::vector<std::size_t> sizes = scale.dialogSizes;
            sizes.insert(sizes.end(), scale.benchSizes.begin(), scale.benchSizes.end());
            for (const std::size_t n : sizes) {
                const std::string where = d.kind + " at " + std::to_string(n);
                QVERIFY2(n <= scale.largest(), where.c_str());
                const Preset preset = scale.scaledPreset(n);
                QCOMPARE(preset.model, d.kind);
                const double made = static_cast<double>(d.particleCount(preset));
                QVERIFY2(std::abs(made / static_cast<double>(n) - 1.0) < 0.1,
                         (where + ": " + std::to_string(made) + " particles").c_str());
            }
            // The smallest size refuses nothing (a model of the kind takes its parameters).
            QVERIFY2((d.create()->setParams(scale.scaledPreset(sizes.front()).params), true), d.kind.c_str());
        }
        QVERIFY(scaled >= 3); // the gas, the fluid and the tunnel
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, gl::scaledPreset("dsmc", 1000));
    }

    // The hand-off to a peer (particlelab-cli export): each named peer takes the kinds that name it.
    void peersAreNamedByTheirKinds() {
        std::set<std::string> peers;
        for (const ModelDescriptor& d : modelCatalog())
            if (!d.peer.empty()) peers.insert(d.peer);
        QVERIFY(peers.count("lammps") && peers.count("sparta"));
        QCOMPARE(findModel("gas")->peer, std::string("lammps"));
    }

    void gpuModelsAreRegisteredKinds() {
        QVERIFY(!gl::gpuModels().empty());
        for (const gl::GpuModel& m : gl::gpuModels()) {
            QVERIFY2(findModel(m.kind), m.kind.c_str());
            QCOMPARE(gl::findGpuModel(m.kind), &m);
        }
        QVERIFY(!gl::findGpuModel("dsmc"));
    }
};

QTEST_APPLESS_MAIN(TestRegistry)
#include "tst_registry.moc"
