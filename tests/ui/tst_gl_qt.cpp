// The GPU models inside Qt: a Qt OpenGL 4.3 context under X (the in-app path, next to the headless EGL
// one of tests/gl), the controller's backend choice, and the "Benchmark this machine" dialog.
#include "BenchmarkDialog.h"
#include "ExperimentDocument.h"
#include "MainWindow.h"
#include "SimulationController.h"
#include "gl/FluidModelGL.h"
#include "gl/GasModelGL.h"
#include "gl/MachineBenchmark.h"
#include "plots/PlotExport.h"
#include "viewport/GLViewport.h"
#include "viewport/QtGlContext.h"

#include <QtTest>
#include <qcustomplot.h>

using namespace pl;

class TestGlQt : public QObject {
    Q_OBJECT
    std::shared_ptr<gl::GlContext> context_;

private slots:
    void initTestCase() {
        QCOMPARE(QGuiApplication::platformName(), QString("xcb"));
        context_ = ui::appComputeContext();
        QVERIFY2(context_, "Qt makes a 4.3 core context under X");
        QVERIFY(context_->info().source.find("Qt xcb") == 0);
    }

    void gasStepsInTheQtContextLikeTheCpu() {
        const Preset preset = gl::scaledPreset("gas", 2048);
        GasModel cpu;
        cpu.reset(preset);
        gl::GasModelGL gpu(context_);
        gpu.reset(preset);
        cpu.step();
        gpu.step();
        const double kc = cpu.observe().kinetic, kg = gpu.observe().kinetic;
        QVERIFY2(std::abs(kg / kc - 1) < 1e-5, qPrintable(QString("%1 vs %2").arg(kg).arg(kc)));
    }

    void fluidStepsInTheQtContext() {
        const Preset preset = gl::scaledPreset("fluid", 900);
        gl::FluidModelGL gpu(context_);
        gpu.reset(preset);
        for (int s = 0; s < 20; ++s) gpu.step();
        QCOMPARE(gpu.particleCount(), std::size_t(900));
        QVERIFY(!gpu.failure());
        QVERIFY(gpu.observe().maxSpeed > 0);
    }

    void controllerSwitchesBackends() {
        ui::SimulationController controller;
        controller.setBackend(gl::Backend::Gl);
        QVERIFY(controller.load(gl::scaledPreset("gas", 1024)).isEmpty());
        QCOMPARE(controller.model()->backend(), std::string("gl"));
        controller.advanceFrame();
        QSignalSpy notices(&controller, &ui::SimulationController::notice);
        controller.setBackend(gl::Backend::Cpu);
        QCOMPARE(controller.model()->backend(), std::string("cpu"));
        QCOMPARE(controller.model()->particleCount(), std::size_t(1024));
        QCOMPARE(notices.count(), 1);
        QVERIFY(notices.front().front().toString().contains("CPU"));
    }

    // With the GPU backend the viewport draws the particles from the model's buffers; the picture is the
    // one the CPU copy gives (the same disks in the same colours; float positions move some by a pixel).
    void viewportDrawsStraightFromTheGpuBuffers() {
        // Lit pixels of the viewport after a few frames; −1 when the window or its viewport is missing.
        auto viewportImage = [](gl::Backend backend, long long* gpuFrames) -> long long {
            ui::MainWindow window;
            window.controller()->setBackend(backend);
            window.document()->open("gas-classroom", true);
            window.resize(1280, 800);
            window.show();
            if (!QTest::qWaitForWindowExposed(&window)) return -1;
            // A fixed pace: the automatic one steps as many as each backend's cost allows, a different state.
            window.controller()->setStepsPerFrame(5);
            for (int f = 0; f < 3; ++f) window.controller()->advanceFrame();
            auto* viewport = window.findChild<ui::GLViewport*>();
            if (!viewport) return -1;
            QTest::qWait(300); // the viewport's window paints the frames it was asked for
            *gpuFrames = viewport->framesFromGpuBuffers();
            QImage image = viewport->grabFramebuffer();
            // Particle pixels: anything brighter than the dark background.
            long long lit = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) lit += qGray(image.pixel(x, y)) > 60 ? 1 : 0;
            return lit;
        };
        long long gpuFrames = 0, cpuFrames = 0;
        const long long litGpu = viewportImage(gl::Backend::Gl, &gpuFrames);
        const long long litCpu = viewportImage(gl::Backend::Cpu, &cpuFrames);
        qInfo("lit pixels: %lld from GPU buffers, %lld from the CPU copy; GPU frames %lld", litGpu, litCpu,
              gpuFrames);
        QVERIFY2(gpuFrames > 0, "the GL viewport drew from the model's buffers");
        QCOMPARE(cpuFrames, 0LL);
        QVERIFY(litGpu > 0 && litCpu > 10000);
        QVERIFY(std::abs(double(litGpu) / double(litCpu) - 1) < 0.05);
    }

    void benchmarkDialogPlotsEveryBackend() {
        ui::BenchmarkDialog dialog;
        dialog.setJobs({{"gas", gl::Backend::Cpu, 512},
                        {"gas", gl::Backend::Gl, 512},
                        {"gas", gl::Backend::Gl, 2048},
                        {"fluid", gl::Backend::Cpu, 400},
                        {"fluid", gl::Backend::Gl, 400}});
        gl::BenchSettings quick;
        quick.repeats = 1;
        quick.targetSeconds = 0.02;
        quick.minSteps = 2;
        quick.warmupSteps = 1;
        dialog.setSettings(quick);
        dialog.show();
        QSignalSpy done(&dialog, &ui::BenchmarkDialog::finished);
        dialog.start();
        QVERIFY(dialog.isRunning());
        QVERIFY(done.wait(60000));
        QCOMPARE(dialog.results().size(), std::size_t(5));
        for (const auto& p : dialog.results()) QVERIFY(p.particleStepsPerSecond > 0);
        QCOMPARE(dialog.plot()->graphCount(), 4); // gas/fluid × CPU/GPU
        const QString dir = PARTICLELAB_SCREENSHOT_DIR;
        QDir().mkpath(dir);
        QVERIFY(dialog.grab().save(dir + "/benchmark-dialog.png"));
        ui::ImageExportOptions options;
        QVERIFY(ui::savePlotImage(dialog.plot(), dir + "/benchmark-plot.svg", options).isEmpty());
    }

    void stoppingTheBenchmarkKeepsWhatWasMeasured() {
        ui::BenchmarkDialog dialog;
        dialog.setJobs({{"gas", gl::Backend::Cpu, 256},
                        {"gas", gl::Backend::Cpu, 512},
                        {"gas", gl::Backend::Cpu, 1024}});
        QSignalSpy done(&dialog, &ui::BenchmarkDialog::finished);
        dialog.start();
        dialog.stop();
        QCOMPARE(done.count(), 1);
        QVERIFY(!dialog.isRunning());
        QVERIFY(dialog.results().size() < 3);
    }
};

int main(int argc, char** argv) {
    QApplication::setAttribute(Qt::AA_ShareOpenGLContexts); // as the application does
    QApplication app(argc, argv);
    TestGlQt test;
    return QTest::qExec(&test, argc, argv);
}
#include "tst_gl_qt.moc"
