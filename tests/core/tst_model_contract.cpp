// The model contract, checked for every registered kind on every backend it has (a row per kind and
// backend, built from the catalog: a new kind is covered without editing this file), and for the test
// tree's own ballistic kind (contract/BallisticKind.h), built by docs/architecture.md's checklist. The base
// owns the step and the clock; a snapshot continues bit for bit on the CPU reference; a refused preset leaves
// the model as it was; the direction of time is refused where the dynamics cannot reverse and undoes the run
// where they can; a non-finite number in a snapshot and an obstacle outside the scene are refused; and a kind
// with mouse tools keeps the SceneTools rules: centres and drag targets clamped into the box, indices
// checked, a placed body at rest, the piston's tools refused without a piston, heat / cool refusing a factor
// that is not positive.
#include "BackendRows.h"
#include "catalog/ModelCatalog.h"
#include "common/Snapshot.h"
#include "common/StopRequest.h"
#include "contract/BallisticKind.h"
#include "gl/GpuModels.h"

#include <QtTest>
#include <cmath>
#include <limits>
#include <sstream>

using namespace pl;

namespace {

// The preset every check starts from: the one the kind's registration names (its teaching scene), or its
// defaults.
Preset contractPreset(const std::string& kind) {
    const ModelDescriptor& descriptor = *findModel(kind);
    return descriptor.contractPreset.empty() ? defaultPreset(descriptor)
                                             : loadPreset(descriptor.contractPreset);
}

std::string particles(const Model& model) {
    std::ostringstream out;
    model.writeParticles(out);
    return out.str();
}

double dtOf(const Model& model) {
    return std::get<double>(model.params().at("dt"));
}

struct Box {
    double left, bottom, right, top;
    double centreX() const { return 0.5 * (left + right); }
    double centreY() const { return 0.5 * (bottom + top); }
    double width() const { return right - left; }
};

Box boxOf(const Model& model) {
    const SceneView view = model.sceneView();
    return {view.left, view.bottom, view.right, view.top};
}

Obstacle discAt(double x, double y, double radius) {
    Obstacle disc;
    disc.x = x;
    disc.y = y;
    disc.radius = radius;
    return disc;
}

// A copy of preset with its first bounded number one step past the spec's maximum: refused on reset.
std::optional<Preset> refusedVariant(const Preset& preset, const std::vector<ParamSpec>& specs) {
    for (const ParamSpec& spec : specs) {
        if (spec.kind != ParamKind::Real || !std::isfinite(spec.max) || spec.max <= 0) continue;
        Preset bad = preset;
        bad.params[spec.key] = 2.0 * spec.max;
        return bad;
    }
    return std::nullopt;
}

// Two series rows of the same kind agree bit for bit (NaN with NaN); a difference names its column.
void sameRow(const Model& model, const std::vector<double>& a, const std::vector<double>& b) {
    QCOMPARE(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k)
        QVERIFY2(a[k] == b[k] || (std::isnan(a[k]) && std::isnan(b[k])),
                 qPrintable(QString("%1: %2 vs %3")
                                .arg(QString::fromStdString(model.seriesColumns()[k]))
                                .arg(a[k], 0, 'g', 17)
                                .arg(b[k], 0, 'g', 17)));
}

} // namespace

class TestModelContract : public QObject {
    Q_OBJECT

    // One row per registered kind and backend: "gas/cpu", "gas/gl", "dsmc/cpu", …
    static void kindsAndBackends() {
        QTest::addColumn<QString>("kind");
        QTest::addColumn<QString>("backend");
        for (const ModelDescriptor& d : modelCatalog()) {
            const QString kind = QString::fromStdString(d.kind);
            QTest::newRow(qPrintable(kind + "/cpu")) << kind << QStringLiteral("cpu");
            if (gl::findGpuModel(d.kind))
                QTest::newRow(qPrintable(kind + "/gl")) << kind << QStringLiteral("gl");
        }
    }

    // The row's model, reset to the kind's contract preset; skips a GL row without a GL 4.3 context.
#define PL_CONTRACT_MODEL(made)                                                                              \
    QFETCH(QString, kind);                                                                                   \
    const Preset preset = contractPreset(kind.toStdString());                                                \
    PL_MODEL_ON_ROW_BACKEND(made, preset);                                                                   \
    Model& model = *made.model

private slots:
    // The test tree's own kind joins the catalog first, so every check below runs on it too.
    void initTestCase() {
        registerModel(test::ballisticRegistration());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, registerModel(test::ballisticRegistration()));
        ModelDescriptor incomplete; // no specs, creator or particle count
        incomplete.kind = "incomplete";
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, registerModel(incomplete));
    }

    void everyKindHasARow() {
        QVERIFY(modelCatalog().size() >= 5);
        QVERIFY(findModel("ballistic") != nullptr);
        for (const ModelDescriptor& d : modelCatalog())
            QVERIFY2(d.create && d.specs && d.particleCount && !d.units.name.empty(), d.kind.c_str());
    }

    // ModelBase::step(): one count and one signed dt per step, whatever the model.
    void theBaseOwnsTheClock_data() {
        kindsAndBackends();
    }
    void theBaseOwnsTheClock() {
        PL_CONTRACT_MODEL(made);
        QCOMPARE(model.stepCount(), std::int64_t(0));
        QCOMPARE(model.time(), 0.0);
        const double dt = dtOf(model);
        for (int s = 1; s <= 5; ++s) {
            model.step();
            QCOMPARE(model.stepCount(), std::int64_t(s));
            QCOMPARE(model.time(), s * dt); // derived from the count, not summed
        }
        QVERIFY(!model.failure());
    }

    // The test kind has what a real kind has, from its registration alone: a distribution for the speed
    // dock and theory rows for the report and a lesson's check (its energy against its start).
    void theTestKindHasWhatARealKindHas() {
        const ModelDescriptor& kind = *findModel("ballistic");
        auto model = instantiate(defaultPreset(kind));
        TimeSeries series(model->seriesColumns());
        series.append(model->sampleSeries());
        for (int s = 0; s < 200; ++s) model->step();
        series.append(model->sampleSeries());
        const std::vector<NamedHistogram> histograms = model->histograms();
        QCOMPARE(histograms.size(), std::size_t(1));
        QCOMPARE(histograms[0].counts.total(), double(model->particleCount()));
        QCOMPARE(kind.distributions, std::vector<std::string>{"speedHistogram"});
        QVERIFY(kind.theoryRows);
        const std::vector<TheoryRow> rows = kind.theoryRows(*model, series);
        QCOMPARE(rows.size(), std::size_t(1));
        QVERIFY2(rows[0].agrees.value_or(false), rows[0].note.c_str());
    }

    // The clock counts steps and derives the time within a segment of constant dt and direction (issue 42):
    // a running sum read t = 4.9999999999999902 at step 100 and 200.00000000001123 at step 4000 at
    // dt = 0.05. A snapshot keeps the segment, so a continued run reads the times of one never stopped; a
    // snapshot without it (older builds) starts a segment at its time.
    void theClockDerivesTimeFromTheStepCount() {
        Preset preset = defaultPreset(*findModel("ballistic"));
        preset.params["dt"] = 0.05;
        preset.params["count"] = 4.0;
        auto model = instantiate(preset);
        std::unique_ptr<Model> continued, older;
        for (int s = 1; s <= 4000; ++s) {
            model->step();
            if (s == 100) QCOMPARE(model->time(), 5.0);
            if (s == 2500) {
                const Snapshot snapshot = takeSnapshot(*model);
                continued = instantiate(preset);
                continued->restoreState(snapshot.state);
                StateRecord withoutSegment = snapshot.state;
                for (const char* key : {"segment_step", "segment_time", "segment_step_size"})
                    QVERIFY(withoutSegment.scalars.erase(key) == 1);
                older = instantiate(preset);
                older->restoreState(withoutSegment);
            }
            if (s > 2500) {
                continued->step();
                older->step();
                QCOMPARE(continued->time(), model->time());
                QCOMPARE(older->stepCount(), model->stepCount());
                QCOMPARE(older->time(), 125.0 + (s - 2500) * 0.05);
            }
        }
        QCOMPARE(model->time(), 200.0);
        // A new dt starts a segment at the time reached; so does the direction of time.
        model->setParams({{"dt", 0.1}});
        for (int s = 0; s < 3; ++s) model->step();
        QCOMPARE(model->time(), 200.0 + 3 * 0.1);
        model->setTimeDirection(-1);
        for (int s = 0; s < 3; ++s) model->step();
        QCOMPARE(model->time(), (200.0 + 3 * 0.1) + 3 * -0.1);
        QCOMPARE(model->stepCount(), std::int64_t(4006));
        // A segment that starts after the snapshot's step is refused by its name.
        StateRecord bad = takeSnapshot(*model).state;
        bad.scalars["segment_step"] = 5000;
        try {
            model->restoreState(bad);
            QFAIL("a segment after the snapshot's step was accepted");
        } catch (const PresetError& e) {
            QCOMPARE(e.key(), std::string("state.segment_step"));
        }
    }

    // What a viewport draws: one position, radius and colour value per particle, and particles in view.
    void sceneViewDescribesEveryParticle_data() {
        kindsAndBackends();
    }
    void sceneViewDescribesEveryParticle() {
        PL_CONTRACT_MODEL(made);
        for (int s = 0; s < 3; ++s) model.step();
        const SceneView view = model.sceneView();
        if (view.gpu) return; // the device's buffers, drawn without a copy
        QCOMPARE(view.x.size(), model.particleCount());
        QCOMPARE(view.y.size(), view.x.size());
        QCOMPARE(view.radius.size(), view.x.size());
        QCOMPARE(view.value.size(), view.x.size());
        QVERIFY(view.left < view.right && view.bottom < view.top);
    }

    // Saved as text, read back and continued: on the CPU reference the trajectories agree bit for bit
    // with the run that never stopped. A GPU model restores the clock and the particles (its float
    // buffers and atomics make no promise of bit identity between two GPU runs).
    void snapshotContinuesWhereItWasTaken_data() {
        kindsAndBackends();
    }
    void snapshotContinuesWhereItWasTaken() {
        PL_CONTRACT_MODEL(made);
        constexpr int kBefore = 15, kAfter = 15;
        for (int s = 0; s < kBefore; ++s) model.step();
        const std::vector<double> rowAtSave = model.sampleSeries(); // a row was written, then the snapshot
        const std::string text = serializeSnapshot(takeSnapshot(model), model.paramSpecs());
        const Snapshot snapshot = parseSnapshot(text, specsForModel, "contract");
        const test::BackendModel restoredMade = test::modelOnBackend(backend, snapshot.preset);
        QVERIFY2(restoredMade.model, restoredMade.failure.c_str());
        Model& restored = *restoredMade.model;
        restored.restoreState(snapshot.state);
        QCOMPARE(restored.stepCount(), model.stepCount());
        QCOMPARE(restored.time(), model.time());
        QCOMPARE(restored.particleCount(), model.particleCount());
        if (backend != QLatin1String("cpu")) return;
        QCOMPARE(particles(restored), particles(model));
        // The resumed run's first row shows the state it was saved in, as the row written before it
        // did: interval quantities (collision rates, forces) included.
        sameRow(model, rowAtSave, restored.sampleSeries());
        for (int s = 0; s < kAfter; ++s) {
            model.step();
            restored.step();
        }
        QVERIFY(!model.failure());
        QCOMPARE(restored.time(), model.time());
        QVERIFY2(particles(restored) == particles(model), "the trajectories parted");
        sameRow(model, model.sampleSeries(), restored.sampleSeries());
    }

    // A stop request during a step that may be undone (InterruptibleStepper after a long set-up) ends
    // it half way: every built-in CPU kind polls for it, and the model is back at the step's start, so the
    // run continues bit for bit as the one that was never interrupted. A kind that does not poll
    // finishes the step. GPU rows keep the clock consistent either way.
    void aStopRequestUndoesTheStepItInterrupts_data() {
        kindsAndBackends();
    }
    void aStopRequestUndoesTheStepItInterrupts() {
        PL_CONTRACT_MODEL(made);
        const test::BackendModel twinMade = test::modelOnBackend(backend, preset);
        QVERIFY2(twinMade.model, twinMade.failure.c_str());
        Model& twin = *twinMade.model;
        constexpr int kBefore = 5, kAfter = 10;
        for (int s = 0; s < kBefore; ++s) {
            model.step();
            twin.step();
        }
        InterruptibleStepper stepper(model, InterruptibleStepper::kKeepAfterSeconds);
        requestStop();
        const bool finished = stepper.step();
        withdrawStopRequest();
        if (backend == QLatin1String("cpu")) QVERIFY2(!finished, "the step never looked at the stop request");
        QCOMPARE(stepper.abandoned(), finished ? 0 : 1);
        QCOMPARE(model.stepCount(), std::int64_t(finished ? kBefore + 1 : kBefore));
        QVERIFY(!model.failure());
        if (finished) twin.step();
        for (int s = 0; s < kAfter; ++s) {
            QVERIFY(stepper.step());
            twin.step();
        }
        QCOMPARE(model.stepCount(), twin.stepCount());
        QCOMPARE(model.time(), twin.time());
        if (backend != QLatin1String("cpu")) return;
        QVERIFY2(particles(model) == particles(twin), "the interrupted run parted from the straight one");
        sameRow(model, model.sampleSeries(), twin.sampleSeries());
    }

    // A snapshot whose state holds a non-finite number (a null in the file), or one so large that its
    // square overflows, is refused naming the field, and the model stays as it was: no kind runs on from
    // a NaN or an infinite energy.
    void nonFiniteStateIsRefused_data() {
        kindsAndBackends();
    }
    void nonFiniteStateIsRefused() {
        PL_CONTRACT_MODEL(made);
        for (int s = 0; s < 3; ++s) model.step();
        const Snapshot good = takeSnapshot(model);
        const std::string before = particles(model);
        const auto refusedKey = [&](const StateRecord& state) -> std::string {
            try {
                model.restoreState(state);
            } catch (const PresetError& e) {
                return e.key();
            }
            return "accepted";
        };
        int corrupted = 0;
        for (const auto& [key, values] : good.state.arrays) {
            if (values.size() != model.particleCount() || values.empty()) continue;
            // NaN, and a finite number whose square overflows (a kinetic energy of inf ran on with exit 0).
            for (const double value : {std::numeric_limits<double>::quiet_NaN(), -1e300}) {
                StateRecord bad = good.state;
                bad.arrays[key][0] = value;
                QCOMPARE(refusedKey(bad), "state." + key);
                QCOMPARE(particles(model), before);
            }
            ++corrupted;
        }
        QVERIFY2(corrupted > 0, "the state has no per-particle array");
        StateRecord badTime = good.state;
        badTime.scalars["time"] = std::numeric_limits<double>::infinity();
        QCOMPARE(refusedKey(badTime), std::string("state.time"));
        QCOMPARE(particles(model), before);
    }

    // A preset refused by reset(preset) leaves the parameters, the seed and the particles as they were.
    void refusedPresetLeavesTheModelAsItWas_data() {
        kindsAndBackends();
    }
    void refusedPresetLeavesTheModelAsItWas() {
        PL_CONTRACT_MODEL(made);
        const std::optional<Preset> bad = refusedVariant(preset, model.paramSpecs());
        QVERIFY2(bad, "the kind has no bounded real parameter to refuse");
        const ParamValues before = model.params();
        const std::string particlesBefore = particles(model);
        QVERIFY_THROWS_EXCEPTION(PresetError, model.reset(*bad));
        QVERIFY(model.params() == before);
        QCOMPARE(model.toPreset().seed, preset.seed);
        QCOMPARE(particles(model), particlesBefore);
        Preset other = preset;
        other.model = "no-such-kind";
        QVERIFY_THROWS_EXCEPTION(PresetError, model.reset(other));
        QVERIFY(model.params() == before);
    }

    // A preset whose obstacle lies far outside the scene is refused naming the entry (a kind without
    // obstacles refuses any), and the model stays as it was.
    void obstacleOutsideIsRefused_data() {
        kindsAndBackends();
    }
    void obstacleOutsideIsRefused() {
        PL_CONTRACT_MODEL(made);
        const Box box = boxOf(model);
        Preset outside = preset;
        outside.obstacles.push_back(discAt(box.right + 10 * box.width(), box.centreY(), 0.01 * box.width()));
        const ParamValues before = model.params();
        const std::string particlesBefore = particles(model);
        try {
            model.reset(outside);
            QFAIL("a preset with an obstacle outside the scene was accepted");
        } catch (const PresetError& e) {
            QVERIFY2(e.key().rfind("obstacles", 0) == 0, e.key().c_str());
        }
        QVERIFY(model.params() == before);
        QCOMPARE(particles(model), particlesBefore);
        QCOMPARE(model.toPreset().obstacles.size(), preset.obstacles.size());
    }

    // Only reversible dynamics accept −1; there, as many steps back return to the start (time exactly,
    // the particles to round-off). Turning time round changes no parameter.
    void directionOfTimeIsTheModels_data() {
        kindsAndBackends();
    }
    void directionOfTimeIsTheModels() {
        PL_CONTRACT_MODEL(made);
        QCOMPARE(model.timeDirection(), 1);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, model.setTimeDirection(0));
        if (!model.reversible()) {
            QVERIFY_THROWS_EXCEPTION(std::logic_error, model.setTimeDirection(-1));
            QCOMPARE(model.timeDirection(), 1);
            return;
        }
        const ParamValues params = model.params();
        const SceneView start = model.sceneView();
        std::ostringstream startText;
        model.writeParticles(startText);
        constexpr int kSteps = 10;
        for (int s = 0; s < kSteps; ++s) model.step();
        model.setTimeDirection(-1);
        QVERIFY(model.params() == params);
        for (int s = 0; s < kSteps; ++s) model.step();
        QCOMPARE(model.stepCount(), std::int64_t(2 * kSteps));
        QVERIFY2(std::abs(model.time()) <= 1e-12 * kSteps * dtOf(model),
                 qPrintable(QString::number(model.time())));
        // The positions come back to a small fraction of the box (round-off grows with the steps).
        const SceneView end = model.sceneView();
        QCOMPARE(end.left, start.left);
        QCOMPARE(end.right, start.right);
        const Snapshot back = takeSnapshot(model);
        auto fresh = instantiate(preset);
        const Snapshot begin = takeSnapshot(*fresh);
        // The arrays the registration names; particles are matched by their identity where the kind keeps
        // one (a spatial sort reorders the arrays).
        const StateArrayNames& names = findModel(kind.toStdString())->stateArrays;
        QVERIFY2(!names.x.empty() && !names.y.empty(), "a reversible kind names its position arrays");
        const auto indexById = [&](const Snapshot& snapshot, std::size_t count) {
            std::vector<std::size_t> index(count);
            for (std::size_t i = 0; i < count; ++i)
                index[i] =
                    names.id.empty() ? i : static_cast<std::size_t>(snapshot.state.arrays.at(names.id)[i]);
            return index;
        };
        const std::size_t count = begin.state.arrays.at(names.x).size();
        QCOMPARE(back.state.arrays.at(names.x).size(), count);
        const std::vector<std::size_t> idBack = indexById(back, count), idBegin = indexById(begin, count);
        const double tolerance = 1e-6 * (start.right - start.left);
        for (const std::string& key : {names.x, names.y}) {
            std::vector<double> a(count), b(count);
            for (std::size_t i = 0; i < count; ++i) {
                QVERIFY(idBack[i] < count && idBegin[i] < count);
                a[idBack[i]] = back.state.arrays.at(key)[i];
                b[idBegin[i]] = begin.state.arrays.at(key)[i];
            }
            double worst = 0.0;
            for (std::size_t i = 0; i < count; ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
            QVERIFY2(worst <= tolerance,
                     qPrintable(QString("%1 off by %2").arg(QString::fromStdString(key)).arg(worst)));
        }
    }

    // SceneTools, one rule for every kind that has tools.
    void toolsClampIndexAndRest_data() {
        kindsAndBackends();
    }
    void toolsClampIndexAndRest() {
        PL_CONTRACT_MODEL(made);
        SceneTools* tools = model.tools();
        if (!tools) { // a kind without tools (the DSMC cell) offers none and takes no obstacles in a preset
            Preset withObstacle = preset;
            withObstacle.obstacles.push_back(discAt(0.0, 0.0, 1.0));
            QVERIFY_THROWS_EXCEPTION(PresetError, model.reset(withObstacle));
            QVERIFY(model.tools() == nullptr);
            return;
        }
        while (!tools->obstacles().empty()) tools->removeObstacle(0);
        const Box box = boxOf(model);
        const double radius = 0.01 * box.width();
        // Added: clamped into the box.
        tools->addObstacle(discAt(box.right + 1e6, box.bottom - 1e6, radius));
        QCOMPARE(tools->obstacles().size(), std::size_t(1));
        QCOMPARE(tools->obstacles()[0].x, box.right);
        QCOMPARE(tools->obstacles()[0].y, box.bottom);
        // Placed: clamped, and at rest at once.
        tools->placeObstacle(0, box.left - 1e6, box.top + 1e6);
        QCOMPARE(tools->obstacles()[0].x, box.left);
        QCOMPARE(tools->obstacles()[0].y, box.top);
        QCOMPARE(tools->obstacles()[0].vx, 0.0);
        QCOMPARE(tools->obstacles()[0].vy, 0.0);
        QVERIFY(!tools->bodiesMoving());
        // Indices that name no obstacle: refused, nothing changed.
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, tools->removeObstacle(1));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, tools->dragObstacle(1, box.left, box.bottom));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, tools->releaseObstacle(1));
        QVERIFY_THROWS_EXCEPTION(std::out_of_range, tools->placeObstacle(1, box.left, box.bottom));
        QCOMPARE(tools->obstacles().size(), std::size_t(1));
        // Dragged far outside: the body heads for the clamped corner at no more than the tool speed.
        const double x0 = box.centreX(), y0 = box.centreY();
        tools->placeObstacle(0, x0, y0);
        tools->dragObstacle(0, box.right + 1e6, box.top + 2e6); // raw direction: slope ≈ 2
        QVERIFY(tools->bodiesMoving());
        model.step();
        const Obstacle& o = tools->obstacles()[0];
        const double dx = o.x - x0, dy = o.y - y0;
        QVERIFY2(dx > 0 && dy > 0, qPrintable(QString("moved by (%1, %2)").arg(dx).arg(dy)));
        const double cross = dx * (box.top - y0) - dy * (box.right - x0);
        QVERIFY2(std::abs(cross) <= 1e-9 * std::hypot(dx, dy) * std::hypot(box.right - x0, box.top - y0),
                 qPrintable(QString::number(cross)));
        QVERIFY(std::hypot(dx, dy) <= tools->toolSpeed() * std::abs(dtOf(model)) * (1 + 1e-12));
        tools->releaseObstacle(0);
        tools->removeObstacle(0);
        QVERIFY(tools->obstacles().empty());
        // Heat / cool: only a positive, finite factor.
        for (double factor :
             {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
            QVERIFY_THROWS_EXCEPTION(std::invalid_argument, tools->scaleKineticEnergy(factor));
        // Without a piston, its tools are refused alike.
        if (!tools->hasPiston()) {
            QVERIFY_THROWS_EXCEPTION(std::logic_error, tools->dragPiston(0.0));
            QVERIFY_THROWS_EXCEPTION(std::logic_error, tools->drivePiston(-1));
            QVERIFY_THROWS_EXCEPTION(std::logic_error, tools->placePiston(0.0));
        }
    }
};

QTEST_APPLESS_MAIN(TestModelContract)
#include "tst_model_contract.moc"
