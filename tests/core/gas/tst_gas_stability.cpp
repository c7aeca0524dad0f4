// Blow-up detection: an unstable time step or a broken state stops the model with what failed, when,
// and a hint that names the stability limit (docs/gas.md#integrators-on-the-harmonic-oscillator: ω dt ≤ 2 for
// Verlet, none for explicit Euler).
#include "GasTestScenes.h"
#include "catalog/ModelCatalog.h"

#include <QtTest>
#include <limits>

using namespace pl;

namespace {

GasModel classroomWith(const ParamValues& values) {
    Preset p = loadPreset("gas-classroom");
    for (const auto& [k, v] : values) p.params[k] = v;
    GasModel model;
    model.reset(p);
    return model;
}

long long runUntilFailure(GasModel& model, long long maxSteps) {
    for (long long s = 0; s < maxSteps && !model.failure(); ++s) model.step();
    return model.stepCount();
}

} // namespace

class TestGasStability : public QObject {
    Q_OBJECT
private slots:
    void stableStepDoesNotFail() {
        GasModel model = classroomWith({});
        runUntilFailure(model, 2000);
        QVERIFY(!model.failure());
    }

    void verletBeyondItsLimitIsCaughtWithHint() {
        // ω = √(2k/m) = 447 for the classroom disks; dt = 5.6e-3 gives ω dt = 2.5 > 2.
        GasModel model = classroomWith({{"dt", 5.6e-3}});
        const long long stopped = runUntilFailure(model, 5000);
        QVERIFY(model.failure());
        const std::string message = model.failure()->message();
        QVERIFY2(message.find("dt·ω = 2.50 > 2.00") != std::string::npos, message.c_str());
        QVERIFY(message.find("velocity-verlet is unstable") != std::string::npos);
        QVERIFY(message.find("at step " + std::to_string(model.failure()->step)) != std::string::npos);
        // A failed model stays where it stopped, with finite numbers for the screen.
        model.step();
        QCOMPARE(model.stepCount(), stopped);
    }

    void hintKeepsSmallNumbersReadable() {
        // ω dt = 447 · 0.5 = 224: π / (ω dt) = 0.014 steps per contact, which one decimal printed as 0.0.
        GasModel model = classroomWith({{"dt", 0.5}});
        runUntilFailure(model, 50);
        QVERIFY(model.failure());
        const std::string hint = model.failure()->hint;
        const auto about = hint.find("(about ");
        const auto below = hint.find("|dt| < ");
        QVERIFY2(about != std::string::npos && below != std::string::npos, hint.c_str());
        const double perContact = std::stod(hint.substr(about + 7));
        QVERIFY2(perContact > 0.013 && perContact < 0.015, hint.c_str());
        QVERIFY2(std::stod(hint.substr(below + 7)) > 0.0, hint.c_str()); // 2 / ω = 0.0045
    }

    void explicitEulerIsExplained() {
        GasModel model = classroomWith({{"integrator", std::string("explicit-euler")}});
        runUntilFailure(model, 20000);
        QVERIFY(model.failure());
        QVERIFY(model.failure()->hint.find("explicit Euler gains energy every step") != std::string::npos);
    }

    void nonFiniteStateIsCaught() {
        GasModel model = classroomWith({});
        model.placeParticles(
            {{0.0, 0.0, std::numeric_limits<double>::quiet_NaN(), 0.0, 0}, {0.5, 0.5, 0.0, 0.0, 0}});
        model.step();
        QVERIFY(model.failure());
        QVERIFY(model.failure()->what.find("NaN") != std::string::npos);
        QCOMPARE(model.failure()->step, 1LL);
    }

    void resetClearsTheFailure() {
        GasModel model = classroomWith({{"dt", 5.6e-3}});
        runUntilFailure(model, 5000);
        QVERIFY(model.failure());
        model.setParams({{"dt", 3.5e-4}});
        model.reset();
        QVERIFY(!model.failure());
        QCOMPARE(model.stepCount(), 0LL);
    }
};

QTEST_APPLESS_MAIN(TestGasStability)
#include "tst_gas_stability.moc"
