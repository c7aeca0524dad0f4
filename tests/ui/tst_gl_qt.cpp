// The GPU models inside Qt: a Qt OpenGL 4.3 context under X (the in-app path, next to the headless EGL
// one of tests/gl), the controller's backend choice, and the "Benchmark this machine" dialog.
#include "SimulationController.h"
#include "gl/MachineBenchmark.h"
#include "gl/MdModelGL.h"
#include "gl/PbfModelGL.h"
#include "gpu/BenchmarkDialog.h"
#include "gpu/QtGlContext.h"
#include "plots/PlotExport.h"

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
        const Preset preset = gl::scaledGasPreset(2048);
        MdModel cpu;
        cpu.reset(preset);
        gl::MdModelGL gpu(context_);
        gpu.reset(preset);
        cpu.step();
        gpu.step();
        const double kc = cpu.observe().kinetic, kg = gpu.observe().kinetic;
        QVERIFY2(std::abs(kg / kc - 1) < 1e-5, qPrintable(QString("%1 vs %2").arg(kg).arg(kc)));
    }

    void fluidStepsInTheQtContext() {
        const Preset preset = gl::scaledFluidPreset(900);
        gl::PbfModelGL gpu(context_);
        gpu.reset(preset);
        for (int s = 0; s < 20; ++s) gpu.step();
        QCOMPARE(gpu.particleCount(), std::size_t(900));
        QVERIFY(!gpu.failure());
        QVERIFY(gpu.observe().maxSpeed > 0);
    }

    void controllerSwitchesBackends() {
        ui::SimulationController controller;
        controller.setBackend(gl::Backend::Gl);
        QVERIFY(controller.load(gl::scaledGasPreset(1024)).isEmpty());
        QCOMPARE(controller.model()->backend(), std::string("gl"));
        controller.advanceFrame();
        QSignalSpy notices(&controller, &ui::SimulationController::notice);
        controller.setBackend(gl::Backend::Cpu);
        QCOMPARE(controller.model()->backend(), std::string("cpu"));
        QCOMPARE(controller.model()->particleCount(), std::size_t(1024));
        QCOMPARE(notices.count(), 1);
        QVERIFY(notices.front().front().toString().contains("CPU"));
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
