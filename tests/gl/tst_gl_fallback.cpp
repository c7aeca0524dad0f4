// Without a usable GL 4.3 context the factory falls back to the CPU with one clear message.
#include "gas/GasModel.h"
#include "gl/Backends.h"

#include <QtTest>

#include <cstdlib>

using namespace pl;
using namespace pl::gl;

class TestGlFallback : public QObject {
    Q_OBJECT

private slots:
    void initTestCase() {
        // Before any context exists in this process: no EGL device has this index.
        qputenv("PARTICLELAB_EGL_DEVICE", "4711");
    }

    void noContextIsAClearError() {
        try {
            (void)createHeadlessContext();
            QFAIL("a context was created on a device that does not exist");
        } catch (const GlUnavailable& e) {
            QVERIFY2(std::string(e.what()).find("PARTICLELAB_EGL_DEVICE=4711") != std::string::npos,
                     e.what());
        }
    }

    void factoryFallsBackToTheCpu() {
        Preset preset;
        preset.model = "gas";
        preset.params = {{"count_a", 100.0}};
        for (Backend b : {Backend::Gl, Backend::Auto}) {
            BackendChoice choice = createModel("gas", b, &preset);
            QCOMPARE(choice.backend, Backend::Cpu);
            QVERIFY(choice.model != nullptr);
            QVERIFY2(choice.message.find("GPU backend unavailable, running on the CPU") == 0,
                     choice.message.c_str());
            QCOMPARE(choice.model->particleCount(), std::size_t(100));
            choice.model->step();
            QCOMPARE(choice.model->stepCount(), std::int64_t(1));
        }
    }
};

QTEST_GUILESS_MAIN(TestGlFallback)
#include "tst_gl_fallback.moc"
