// The thread governor: its choices on machines made of step times (quiet, shared, a load that comes
// and goes), and that a team changing between steps leaves every kind's results bit for bit the same.
#include "catalog/ModelCatalog.h"
#include "common/Parallel.h"
#include "common/ThreadGovernor.h"

#include <QtTest>
#include <functional>
#include <map>
#include <omp.h>

using namespace pl;

namespace {

// A machine as the governor sees it: the wall time of one step [s] on a team, at a moment [s].
using Machine = std::function<double(int threads, double now, std::uint64_t step)>;

struct RunOutcome {
    double seconds = 0;              // wall time of the whole run
    std::map<int, double> secondsAt; // wall time spent on each team
};

RunOutcome govern(int most, const Machine& machine, std::uint64_t steps) {
    ThreadGovernor governor(most);
    RunOutcome outcome;
    for (std::uint64_t s = 0; s < steps; ++s) {
        const int threads = governor.threadsForNextStep();
        const double took = machine(threads, outcome.seconds, s);
        governor.stepTook(took);
        outcome.seconds += took;
        outcome.secondsAt[threads] += took;
    }
    return outcome;
}

// A repeatable ±3 % wobble, the spread of one team's steps on a quiet machine.
double wobble(std::uint64_t step) {
    return 1.0 + 0.03 * std::sin(static_cast<double>(step) * 2.399963);
}

// Two cores, quiet: two threads take 55 % of one thread's time per step (gas-classroom's ratio).
double quietStep(int threads, std::uint64_t step) {
    return (threads == 2 ? 36e-6 : 65e-6) * wobble(step);
}

// One core held by another program: the second thread is set aside by the scheduler now and then, and
// every step waits for it at the barriers (BENCHMARKS.md: 15× slower on average, in bursts of ms).
double sharedStep(int threads, std::uint64_t step) {
    if (threads == 1) return 65e-6 * wobble(step);
    return step % 8 == 0 ? 7e-3 : 90e-6;
}

// The governed run's speed on two cores as a fraction of always running `best` threads.
double speedAgainstAlways(int best, double (*stepTime)(int, std::uint64_t), std::uint64_t steps,
                          const char* machine) {
    const RunOutcome outcome = govern(
        2, [stepTime](int t, double, std::uint64_t s) { return stepTime(t, s); }, steps);
    double always = 0;
    for (std::uint64_t s = 0; s < steps; ++s) always += stepTime(best, s);
    qInfo("%s: %.4f of the time on %d thread(s), %.4f × the speed of always %d", machine,
          outcome.secondsAt.at(best) / outcome.seconds, best, always / outcome.seconds, best);
    return always / outcome.seconds;
}

// The state of a model as its snapshot writes it: every number of the state, exactly.
std::string stateOf(const Model& model) {
    return serializeSnapshot(takeSnapshot(model), *specsForModel(model.kind()));
}

// The built-in preset of a kind with the most particles: the one whose loops run in parallel.
const BuiltinPreset& largestPresetOf(const std::string& kind) {
    const BuiltinPreset* largest = nullptr;
    for (const BuiltinPreset* p : builtinPresetsOf(kind))
        if (!largest || particleCount(p->preset) > particleCount(largest->preset)) largest = p;
    return *largest;
}

} // namespace

class TestThreadGovernor : public QObject {
    Q_OBJECT
private slots:
    void cleanup() { setThreadPolicy({}); }

    void aQuietMachineKeepsEveryCore() {
        QVERIFY(speedAgainstAlways(2, quietStep, 1'000'000, "quiet") >= 0.97); // 36 s of steps
    }

    void aSharedMachineFallsBackToOneThread() {
        QVERIFY(speedAgainstAlways(1, sharedStep, 300'000, "shared") >= 0.95);
    }

    void aShortRunSettlesWithinMilliseconds() {
        // particlelab-cli bench gas-classroom --steps 1000 on a shared machine: 65 ms on one thread.
        const std::uint64_t steps = 1000;
        const RunOutcome outcome = govern(
            2, [](int t, double, std::uint64_t s) { return sharedStep(t, s); }, steps);
        qInfo("1000 shared steps: %.1f ms (65 ms on one thread)", outcome.seconds * 1e3);
        QVERIFY(outcome.seconds < 1.5 * 1000 * 65e-6);
    }

    void aLoadThatComesAndGoesIsFollowed() {
        // Quiet for 10 s, shared for 10 s, quiet again: each change is answered within two windows.
        const auto phase = [](double now) { return now >= 10.0 && now < 20.0; };
        ThreadGovernor governor(2);
        double now = 0, quietOnOne = 0, sharedOnTwo = 0;
        for (std::uint64_t s = 0; now < 30.0; ++s) {
            const int threads = governor.threadsForNextStep();
            const bool shared = phase(now);
            const double took = shared ? sharedStep(threads, s) : quietStep(threads, s);
            if (shared && threads == 2) sharedOnTwo += took;
            if (!shared && threads == 1 && now > 20.0) quietOnOne += took;
            governor.stepTook(took);
            now += took;
        }
        qInfo("while shared, %.3f s of 10 on 2 threads; quiet again, %.3f s of 10 on 1 thread", sharedOnTwo,
              quietOnOne);
        QVERIFY(sharedOnTwo < 1.0); // noticed within 16 ms, then only probes (3 % of the time)
        QVERIFY(quietOnOne < 2.5);  // at most a longest window late, then only probes
    }

    void oneCoreNeverProbes() {
        ThreadGovernor governor(1);
        for (int s = 0; s < 10000; ++s) {
            QCOMPARE(governor.threadsForNextStep(), 1);
            governor.stepTook(1e-4);
        }
    }

    void aLargeMachineClimbsTheLadder() {
        // Eight cores, one of them busy: seven threads are best, eight wait for the busy core.
        const auto machine = [](int t, double, std::uint64_t s) {
            const double work = 400e-6 / t;
            return (t == 8 ? 20.0 * work : work) * wobble(s);
        };
        const RunOutcome outcome = govern(8, machine, 200'000);
        qInfo("eight cores, one busy: %.3f of the time on 7 threads",
              outcome.secondsAt.at(7) / outcome.seconds);
        QVERIFY(outcome.secondsAt.at(7) / outcome.seconds > 0.85);
    }

    // What the governor relies on: a team that changes from step to step gives the one-thread run's
    // state bit for bit, in every kind (at its largest built-in preset, whose loops run in parallel).
    void everyKindIgnoresTheTeamsSize_data() {
        QTest::addColumn<QString>("kind");
        for (const ModelDescriptor& d : modelCatalog())
            QTest::newRow(d.kind.c_str()) << QString::fromStdString(d.kind);
    }
    void everyKindIgnoresTheTeamsSize() {
        QFETCH(QString, kind);
        const BuiltinPreset& preset = largestPresetOf(kind.toStdString());
        constexpr int kSteps = 40;
        omp_set_num_threads(1);
        const std::unique_ptr<Model> one = instantiate(preset.preset);
        for (int s = 0; s < kSteps; ++s) one->step();
        const std::unique_ptr<Model> changing = instantiate(preset.preset);
        for (int s = 0; s < kSteps; ++s) {
            omp_set_num_threads(1 + s % 2);
            changing->step();
        }
        setThreadPolicy({true, 2});
        const std::unique_ptr<Model> governed = instantiate(preset.preset);
        for (int s = 0; s < kSteps; ++s) governed->step();
        setThreadPolicy({});
        omp_set_num_threads(2);
        qInfo("%s: %zu particles", preset.name.c_str(), one->particleCount());
        QVERIFY(!one->failure());
        QVERIFY(stateOf(*one) == stateOf(*changing));
        QVERIFY(stateOf(*one) == stateOf(*governed));
    }
};

QTEST_APPLESS_MAIN(TestThreadGovernor)
#include "tst_thread_governor.moc"
