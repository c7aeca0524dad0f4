// Accepted collisions per step at equilibrium match N ν Δt / 2
// (docs/dsmc.md#cross-sections-and-collision-frequency) for every cross-section model, including the
// write-up's; the Maxwell-molecule anisotropy decays at ν/2; the BKW moments follow the exact curves.
#include "dsmc/DsmcModel.h"
#include "dsmc/DsmcTheory.h"

#include <QtTest>

using namespace pl;

namespace {

Preset equilibriumCell(const std::string& crossSection, long long particles) {
    Preset p;
    p.model = "dsmc";
    p.seed = 11;
    p.params = {{"initial", std::string("maxwellian")},
                {"count_a", double(particles)},
                {"temperature", 300.0},
                {"cross_section", crossSection},
                {"fn", 1e8},
                {"cell_volume", 1e-8},
                {"dt", 1e-5}};
    return p;
}

// Counts the builds of the state a preset costs.
class CountingResets : public DsmcModel {
public:
    int resets = 0;
    using DsmcModel::reset;
    void reset() override {
        ++resets;
        DsmcModel::reset();
    }
};

// ν Δt of the model as its accuracy warning states it ("ν Δt is up to X collisions …").
double stated(const DsmcModel& model) {
    const std::string warning = model.accuracyWarning();
    const std::string lead = "ν Δt is up to ";
    const auto at = warning.find(lead);
    return at == std::string::npos ? 0.0 : std::stod(warning.substr(at + lead.size()));
}

} // namespace

class TestDsmcRates : public QObject {
    Q_OBJECT
private slots:
    // A collision rate beyond what a step can do is refused from the parameters, before the particles
    // are built (3e7 of them took 5.8 s and 740 MB), and a preset just inside the bound is not refused by
    // that prediction: the exact bound on the built state decides it, for each initial state.
    void aCollisionRateRefusalBuildsNothing_data() {
        QTest::addColumn<QString>("initial");
        QTest::newRow("maxwellian") << "maxwellian";
        QTest::newRow("two-beams") << "two-beams";
        QTest::newRow("bkw") << "bkw";
    }
    void aCollisionRateRefusalBuildsNothing() {
        QFETCH(QString, initial);
        Preset preset = equilibriumCell("hard-sphere", 100000);
        preset.params["initial"] = initial.toStdString();
        preset.params["count_b"] = 50000.0;
        preset.params["dt"] = 1e-2;
        CountingResets model;
        model.resets = 0;
        try {
            model.reset(preset);
            QFAIL("the preset was accepted");
        } catch (const PresetError& e) {
            QCOMPARE(e.key(), std::string("params.dt"));
        }
        QCOMPARE(model.resets, 0);
        // The built state's ν Δt scales with dt: measured at a dt between the guideline (where the warning
        // starts stating it) and the bound, 0.99 of the bound is then accepted.
        double measuredDt = 1e-5;
        for (;; measuredDt /= 2) {
            preset.params["dt"] = measuredDt;
            try {
                model.reset(preset);
                break;
            } catch (const PresetError&) {
            }
        }
        const double perDt = stated(model) / measuredDt;
        QVERIFY(perDt > 0);
        preset.params["dt"] = 0.99 * 10.0 / perDt;
        model.reset(preset);
        QVERIFY2(std::abs(stated(model) - 9.9) < 0.02, model.accuracyWarning().c_str());
    }
    void acceptedCollisionsMatchTheEquilibriumRate_data() {
        QTest::addColumn<QString>("crossSection");
        QTest::newRow("inverse-root") << "inverse-root";
        QTest::newRow("hard-sphere") << "hard-sphere";
        QTest::newRow("vhs") << "vhs";
        QTest::newRow("maxwell") << "maxwell";
    }
    void acceptedCollisionsMatchTheEquilibriumRate() {
        QFETCH(QString, crossSection);
        DsmcModel model;
        model.reset(equilibriumCell(crossSection.toStdString(), 20000));
        const auto& p = model.parameters();
        const double n = static_cast<double>(model.particleCount());
        // ½ N (N − 1) F_N ⟨σ c_r⟩ Δt / V: N ν Δt / 2 with the pair count N(N − 1) the NTC method uses.
        const double expected = 0.5 * n * (n - 1) * p.fn *
                                model.collisionModel().meanSigmaCr(300.0, p.mass()) * p.dt / p.cellVolume;
        const int steps = 300;
        double total = 0;
        for (int s = 0; s < steps; ++s) {
            model.step();
            total += static_cast<double>(model.lastCollisions());
        }
        const double measured = total / steps;
        // Accepted collisions are close to Poisson: the mean of 300 steps has a standard error √(μ/300).
        const double tolerance = 4 * std::sqrt(expected / steps);
        QVERIFY2(std::abs(measured - expected) < tolerance,
                 qPrintable(QString("measured %1 per step, expected %2 ± %3")
                                .arg(measured)
                                .arg(expected)
                                .arg(tolerance)));
        QVERIFY(std::abs(model.observe().t - 300.0) < 1e-9 * 300.0); // still the same equilibrium
    }

    void theSeedsMeanSigmaCrIsTheDerivedConstant() {
        // docs/dsmc.md#cross-sections-and-collision-frequency: ⟨σ c_r⟩ = 1.03705e-18 (4 kT/m)^(1/4) m³/s for
        // σ = 1e-18 c_r^-1/2.
        DsmcModel model;
        const double m = model.parameters().mass();
        const double value = model.collisionModel().meanSigmaCr(17.83, m);
        const double expected = 1.03705e-18 * std::pow(4 * kBoltzmann * 17.83 / m, 0.25);
        QVERIFY(std::abs(value / expected - 1) < 1e-5);
    }

    void maxwellAnisotropyDecaysAtHalfTheCollisionFrequency() {
        Preset p;
        p.model = "dsmc";
        p.seed = 5;
        p.params = {{"cross_section", std::string("maxwell")},
                    {"count_a", 20000.0},
                    {"count_b", 20000.0},
                    {"fn", 2.5e7},
                    {"dt", 1e-5}};
        DsmcModel model;
        model.reset(p);
        const double nu = model.numberDensity() * model.parameters().maxwellSigmaCr;
        // Least-squares slope of ln(T_x − T_⊥) over 3 e-foldings of the anisotropy.
        double st = 0, sy = 0, stt = 0, sty = 0;
        int count = 0;
        while (nu * model.time() < 6.0) {
            const DsmcObservables o = model.observe();
            const double t = o.time, y = std::log(o.tx - o.tPerp);
            st += t;
            sy += y;
            stt += t * t;
            sty += t * y;
            ++count;
            for (int s = 0; s < 10; ++s) model.step();
        }
        const double slope = (count * sty - st * sy) / (count * stt - st * st);
        QVERIFY2(std::abs(-slope / (nu / 2) - 1) < 0.05,
                 qPrintable(QString("decay rate %1, ν/2 = %2").arg(-slope).arg(nu / 2)));
    }

    void bkwMomentsFollowTheExactSolution() {
        Preset p;
        p.model = "dsmc";
        p.seed = 3;
        const long long particles = 40000;
        p.params = {{"cross_section", std::string("maxwell")},
                    {"initial", std::string("bkw")},
                    {"count_a", double(particles)},
                    {"temperature", 300.0},
                    {"fn", 5e7},
                    {"dt", 1e-5}};
        DsmcModel model;
        model.reset(p);
        // Sampling error of a moment ratio from N particles: √((⟨c^4k⟩/⟨c^2k⟩² − 1)/N) at equilibrium,
        // 945/225 for M4 and 135135/11025 for M6; 4 standard errors, plus 0.5 % for the time step.
        const double n = static_cast<double>(particles);
        const double tol4 = 4 * std::sqrt((945.0 / 225 - 1) / n) + 0.005;
        const double tol6 = 4 * std::sqrt((135135.0 / 11025 - 1) / n) + 0.005;
        int checks = 0;
        for (int block = 0; block <= 12; ++block) {
            const DsmcObservables o = model.observe();
            QVERIFY2(std::abs(o.m4 - o.m4Bkw) < tol4,
                     qPrintable(QString("t = %1: M4 %2, exact %3").arg(o.time).arg(o.m4).arg(o.m4Bkw)));
            QVERIFY2(std::abs(o.m6 - o.m6Bkw) < tol6,
                     qPrintable(QString("t = %1: M6 %2, exact %3").arg(o.time).arg(o.m6).arg(o.m6Bkw)));
            ++checks;
            for (int s = 0; s < 50; ++s) model.step();
        }
        QCOMPARE(checks, 13);
        QVERIFY(model.observe().m4Bkw >
                0.99); // the run reached equilibrium: the check covered the whole curve
    }
};

QTEST_APPLESS_MAIN(TestDsmcRates)
#include "tst_dsmc_rates.moc"
