// The integrator table against measurement: for every entry the order of convergence on the harmonic
// pair, the force evaluations the model makes per step, and the stability limit, from the stage list's
// amplification matrix on x'' = −ω²x and from the same matrix measured on the model's caged disk.
#include "gas/GasModel.h"
#include "gas/MethodSweep.h"
#include "gas/StabilityMap.h"

#include <QtTest>
#include <algorithm>
#include <array>
#include <set>

using namespace pl;

namespace {

void addRowPerEntry() {
    QTest::addColumn<int>("index");
    for (std::size_t k = 0; k < gasIntegrators().size(); ++k)
        QTest::newRow(gasIntegrators()[k].name.c_str()) << int(k);
}

const GasIntegratorInfo& entryOfRow() {
    QFETCH(int, index);
    return gasIntegrators()[std::size_t(index)];
}

// Largest eigenvalue modulus of a 2×2 matrix {m00, m01, m10, m11}: above 1, the scheme grows.
double spectralRadius(const std::array<double, 4>& m) {
    const double trace = m[0] + m[3], det = m[0] * m[3] - m[1] * m[2];
    const double disc = trace * trace - 4.0 * det;
    return disc >= 0 ? 0.5 * (std::abs(trace) + std::sqrt(disc)) : std::sqrt(det);
}

// One step of the stage list on x'' = −x at step wdt, applied to (x, v) = (1, 0) and (0, 1): the
// columns of its amplification matrix. Kicks use the acceleration of the last force stage, as the
// models' passes do.
std::array<double, 4> stageListAmplification(const GasIntegratorInfo& scheme, double wdt) {
    std::array<double, 4> m{};
    for (int column = 0; column < 2; ++column) {
        double x = column == 0 ? 1.0 : 0.0, v = column == 1 ? 1.0 : 0.0, a = -x;
        for (const GasStage& s : scheme.stages) {
            if (s.kind == GasStageKind::Kick) v += s.fraction * wdt * a;
            if (s.kind == GasStageKind::Drift) x += s.fraction * wdt * v;
            if (s.kind == GasStageKind::Forces) a = -x;
        }
        m[column] = x, m[2 + column] = v;
    }
    return m;
}

// The same matrix measured on the model: one GasModel step of the caged disk of gas/StabilityMap (a light
// disk held by two heavy ones that overlap it by 0.2 d each, so both contacts stay linear springs),
// from a displacement and from a velocity, in units of the displacement and of ω times it.
std::array<double, 4> modelAmplification(const std::string& integrator, double wdt) {
    constexpr double kDiameter = 0.1, kLight = 1e-6, kHeavy = 1e6, kStiffness = 1000.0;
    constexpr double kPreload = 0.2 * kDiameter, kShift = 0.1 * kPreload;
    const double omega = gas::cagedOmega(kStiffness);
    GasModel model;
    model.setParams({{"count_a", 1.0},
                     {"count_b", 2.0},
                     {"integrator", integrator},
                     {"dt", wdt / omega},
                     {"stiffness", kStiffness * kLight},
                     {"diameter_a", kDiameter},
                     {"diameter_b", kDiameter},
                     {"mass_a", kLight},
                     {"mass_b", kHeavy},
                     {"box_width", 10.0 * kDiameter},
                     {"box_height", 2.0 * kDiameter}});
    const double heavyX = kDiameter - kPreload;
    std::array<double, 4> m{};
    for (int column = 0; column < 2; ++column) {
        const double x0 = column == 0 ? kShift : 0.0, v0 = column == 1 ? omega * kShift : 0.0;
        model.placeParticles(
            {{x0, 0.0, v0, 0.0, 0}, {-heavyX, 0.0, 0.0, 0.0, 1}, {heavyX, 0.0, 0.0, 0.0, 1}});
        model.step();
        const GasState& s = model.state();
        const auto light = std::find(s.species.begin(), s.species.end(), 0) - s.species.begin();
        m[column] = s.x[light] / kShift, m[2 + column] = s.vx[light] / (omega * kShift);
    }
    return m;
}

// Rounding in positions of order 0.1 against displacements of 0.002 leaves about 1e-13 in the matrix.
constexpr double kUnitCircle = 1.0 + 1e-9;

} // namespace

class TestGasIntegratorTable : public QObject {
    Q_OBJECT

private slots:
    void everyIntegratorOnceWithItsName() {
        std::set<GasIntegrator> ids;
        std::set<std::string> names;
        for (const auto& info : gasIntegrators()) {
            ids.insert(info.id);
            names.insert(info.name);
            QCOMPARE(integratorFromName(info.name), info.id);
            QCOMPARE(&gasIntegrator(info.id), &info);
            QVERIFY(!info.description.empty() && !info.passes.empty());
        }
        QCOMPARE(ids.size(), gasIntegrators().size());
        QCOMPARE(names.size(), gasIntegrators().size());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, integratorFromName("leapfrog"));
        // The parameter offers exactly the table's names, the default first.
        const auto& specs = GasParams::describe();
        const auto spec =
            std::find_if(specs.begin(), specs.end(), [](auto& s) { return s.key == "integrator"; });
        QVERIFY(spec != specs.end());
        QVERIFY(spec->choices == gasIntegratorNames());
        QCOMPARE(GasParams{}.integrator, gasIntegrators().front().id);
        const auto byOrder = gasIntegratorNamesByOrder();
        QCOMPARE(std::set<std::string>(byOrder.begin(), byOrder.end()), names);
    }

    void measuredOrderIsTheTablesOrder_data() { addRowPerEntry(); }
    void measuredOrderIsTheTablesOrder() {
        const GasIntegratorInfo& scheme = entryOfRow();
        const gas::SweepResult r = gas::sweepHarmonicPair({scheme.name}, {16, 32, 64, 128, 256});
        QCOMPARE(r.orders.size(), std::size_t(1));
        qInfo("%-16s measured order %.3f (table %d)", scheme.name.c_str(), r.orders[0].measured,
              scheme.order);
        QVERIFY(std::abs(r.orders[0].measured - scheme.order) <= 0.2);
    }

    void forceEvaluationsPerStepAreTheTables_data() { addRowPerEntry(); }
    void forceEvaluationsPerStepAreTheTables() {
        const GasIntegratorInfo& scheme = entryOfRow();
        GasModel model;
        model.setParams({{"count_a", 2.0}, {"integrator", scheme.name}, {"dt", 1e-3}, {"diameter_a", 0.1}});
        model.placeParticles({{-0.04, 0.0, 0.0, 0.0, 0}, {0.04, 0.0, 0.0, 0.0, 0}});
        model.step();              // the first step may have to compute the initial forces
        constexpr int kSteps = 20; // fewer than the energy check's interval, which evaluates forces too
        const std::int64_t before = model.forceEvaluations();
        for (int k = 0; k < kSteps; ++k) model.step();
        const double perStep = double(model.forceEvaluations() - before) / kSteps;
        QCOMPARE(perStep, double(scheme.forcesPerStep()));
    }

    void stageListIsStableUpToTheTablesLimit_data() { addRowPerEntry(); }
    void stageListIsStableUpToTheTablesLimit() {
        const GasIntegratorInfo& scheme = entryOfRow();
        if (!scheme.onlyKicksAndDrifts())
            QSKIP("RK4 is one opaque stage; modelIsStableUpToTheTablesLimit covers it");
        const auto radius = [&](double wdt) { return spectralRadius(stageListAmplification(scheme, wdt)); };
        if (scheme.stabilityLimit == 0.0) {
            for (double wdt : {1e-3, 0.1, 1.0}) QVERIFY(radius(wdt) > kUnitCircle);
            return;
        }
        // The limit as the table writes it (Forest–Ruth's 1.5734 to four decimals).
        const double limit = scheme.stabilityLimit;
        for (double wdt = 0.01; wdt < limit - 1e-4; wdt += 0.01) QVERIFY(radius(wdt) <= kUnitCircle);
        QVERIFY(radius(limit - 1e-4) <= kUnitCircle);
        QVERIFY(radius(limit + 1e-4) > kUnitCircle);
    }

    void modelIsStableUpToTheTablesLimit_data() { addRowPerEntry(); }
    void modelIsStableUpToTheTablesLimit() {
        const GasIntegratorInfo& scheme = entryOfRow();
        const auto radius = [&](double wdt) { return spectralRadius(modelAmplification(scheme.name, wdt)); };
        if (scheme.stabilityLimit == 0.0) { // explicit Euler: |λ|² = 1 + (ω dt)² at every step
            for (double wdt : {0.01, 0.1, 1.0}) QCOMPARE(radius(wdt), std::sqrt(1.0 + wdt * wdt));
            return;
        }
        const double limit = scheme.stabilityLimit;
        for (double wdt : {0.1, 0.5, 0.9 * limit, 0.999 * limit})
            QVERIFY2(radius(wdt) <= kUnitCircle, scheme.name.c_str());
        qInfo("%-16s |λ| = %.6f at 1.001 × the table's limit %.4f", scheme.name.c_str(),
              radius(1.001 * limit), limit);
        QVERIFY(radius(1.001 * limit) > kUnitCircle);
    }
};

QTEST_GUILESS_MAIN(TestGasIntegratorTable)
#include "tst_gas_integrator_table.moc"
