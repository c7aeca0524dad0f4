// Two-disk collisions against the analytic harmonic contact (docs/gas.md#harmonic-contact-of-two-disks):
// contact time t_c = π √(μ/k), elastic exit velocities, pass-through above v_n = d ω, momentum conservation.
#include "GasTestScenes.h"

#include <QtTest>
#include <numbers>

using namespace pl;

namespace {

struct CollisionResult {
    double contactTime;
    double v1, v2; // final x velocities
    double speed1, speed2, x1, x2;
    double maxMomentumError;
};

// Disks of masses m1, m2 (diameter d) approach head-on along x with velocities u1, u2.
CollisionResult collide(double m1, double m2, double d, double k, double u1, double u2, double dt,
                        double duration, double impactOffset = 0.0) {
    GasModel model = test::makeGas({{"box_width", 10.0},
                                    {"box_height", 10.0},
                                    {"count_a", 1.0},
                                    {"count_b", 1.0},
                                    {"mass_a", m1},
                                    {"mass_b", m2},
                                    {"diameter_a", d},
                                    {"diameter_b", d},
                                    {"stiffness", k},
                                    {"dt", dt}});
    model.placeParticles({{-1.5 * d, 0.0, u1, 0.0, 0}, {1.5 * d, impactOffset, u2, 0.0, 1}});
    const auto p0 = test::totalMomentum(model);
    double firstContact = -1, lastContact = -1, momentumError = 0;
    const auto steps = static_cast<long long>(std::llround(duration / dt));
    for (long long s = 0; s < steps; ++s) {
        model.step();
        const auto& st = model.state();
        const bool touching = std::hypot(st.x[0] - st.x[1], st.y[0] - st.y[1]) < d;
        if (touching && firstContact < 0) firstContact = model.time();
        if (touching) lastContact = model.time();
        const auto p = test::totalMomentum(model);
        momentumError = std::max(momentumError, std::hypot(p.first - p0.first, p.second - p0.second));
    }
    const auto& st = model.state();
    return {lastContact - firstContact + dt, st.vx[0], st.vx[1], std::hypot(st.vx[0], st.vy[0]),
            std::hypot(st.vx[1], st.vy[1]),  st.x[0],  st.x[1],  momentumError};
}

} // namespace

class TestGasCollision : public QObject {
    Q_OBJECT
private slots:
    void equalMassesExchangeVelocities() {
        const double k = 1000, m = 1, d = 0.05;
        const double tc = std::numbers::pi * std::sqrt(m / (2 * k)); // μ = m/2
        const double dt = tc / 2000;
        const auto r = collide(m, m, d, k, 1.0, -1.0, dt, 0.3);
        // The contact is resolved to one step.
        QVERIFY2(std::abs(r.contactTime - tc) <= 1.5 * dt,
                 qPrintable(QString("%1 vs %2").arg(r.contactTime).arg(tc)));
        QVERIFY(std::abs(r.v1 + 1.0) < 1e-6);
        QVERIFY(std::abs(r.v2 - 1.0) < 1e-6);
    }

    void contactTimeIndependentOfSpeed() {
        const double k = 1000, m = 1, d = 0.05;
        const double tc = std::numbers::pi * std::sqrt(m / (2 * k));
        const double dt = tc / 2000;
        for (double speed : {0.2, 0.5, 1.0}) {
            const auto r = collide(m, m, d, k, speed, -speed, dt, 0.6 / speed);
            QVERIFY(std::abs(r.contactTime - tc) <= 1.5 * dt);
        }
    }

    void unequalMassesFollowElasticFormulas() {
        const double k = 1000, m1 = 1, m2 = 3, d = 0.1, u1 = 1, u2 = -1;
        const double mu = m1 * m2 / (m1 + m2);
        const double tc = std::numbers::pi * std::sqrt(mu / k);
        const double dt = tc / 2000;
        const auto r = collide(m1, m2, d, k, u1, u2, dt, 0.4);
        QVERIFY(std::abs(r.contactTime - tc) <= 1.5 * dt);
        QVERIFY(std::abs(r.v1 - ((m1 - m2) * u1 + 2 * m2 * u2) / (m1 + m2)) < 1e-6); // −2
        QVERIFY(std::abs(r.v2 - ((m2 - m1) * u2 + 2 * m1 * u1) / (m1 + m2)) < 1e-6); // 0
    }

    void fastPairsPassThrough() {
        // v_n = 4 > d ω = 0.05 · √2000 ≈ 2.24: the disks cross each other and keep their speeds. An impact
        // parameter of 0.3 d keeps them off r = 0, where the force direction is undefined.
        const double k = 1000, m = 1, d = 0.05;
        const double dt = std::numbers::pi * std::sqrt(m / (2 * k)) / 2000;
        const auto r = collide(m, m, d, k, 2.0, -2.0, dt, 0.1, 0.3 * d);
        QVERIFY(r.x1 > r.x2);
        QVERIFY(std::abs(r.speed1 - 2.0) < 1e-6);
        QVERIFY(std::abs(r.speed2 - 2.0) < 1e-6);
    }

    void momentumConservedInObliqueCollision() {
        const double k = 1000, m1 = 1, m2 = 2.5, d = 0.1;
        const double dt = 1e-4;
        const auto r = collide(m1, m2, d, k, 1.2, -0.7, dt, 0.3, 0.4 * d);
        QVERIFY2(r.maxMomentumError < 1e-12, qPrintable(QString::number(r.maxMomentumError)));
    }
};

QTEST_APPLESS_MAIN(TestGasCollision)
#include "tst_gas_collision.moc"
