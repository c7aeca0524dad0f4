// The methods lab dock: both experiments run in a worker thread, plot as they go, and cancel cleanly.
#include "SimulationController.h"
#include "catalog/ModelCatalog.h"
#include "fluid/FluidModel.h"
#include "gas/GasModel.h"
#include "methods/DsmcPage.h"
#include "methods/FluidPage.h"
#include "methods/GasSweepPage.h"
#include "methods/LabBatch.h"
#include "methods/LabRunner.h"
#include "methods/MethodsLab.h"
#include "methods/RecommendBar.h"
#include "methods/RelaxPage.h"
#include "methods/StabilityPage.h"

#include <QLabel>
#include <QTabWidget>
#include <QtTest>
#include <qcustomplot.h>

using namespace pl::ui;

class TestMethodsLab : public QObject {
    Q_OBJECT

    static void save(MethodsLab& lab, const QString& name, int tab = -1) {
        if (tab >= 0) lab.tabs()->setCurrentIndex(tab);
        lab.resize(900, 640);
        QDir().mkpath(PARTICLELAB_SCREENSHOT_DIR);
        QVERIFY(lab.grab().save(QString(PARTICLELAB_SCREENSHOT_DIR) + "/" + name));
    }

private slots:
    void echoPlotsDoubleAndFloat() {
        MethodsLab lab;
        lab.setEchoSteps({100, 300, 1000});
        QSignalSpy done(&lab, &MethodsLab::finished);
        lab.runEcho();
        QVERIFY(lab.isRunning());
        QVERIFY(done.wait(60000));
        QVERIFY(!lab.isRunning());
        QCOMPARE(lab.echoPlot()->graphCount(), 2);
        for (int g = 0; g < 2; ++g) QCOMPARE(lab.echoPlot()->graph(g)->dataCount(), 3);
        // float returns worse than double at n = 1000
        QVERIFY(lab.echoPlot()->graph(1)->data()->at(2)->value >
                lab.echoPlot()->graph(0)->data()->at(2)->value);
        save(lab, "methods-lab-echo.png");
    }

    void sweepShowsMeasuredOrders() {
        MethodsLab lab;
        lab.setSweepSteps({16, 32, 64});
        QSignalSpy done(&lab, &MethodsLab::finished);
        lab.runSweep();
        QVERIFY(done.wait(60000));
        QCOMPARE(lab.sweepPlot()->graphCount(), 5);
        for (int g = 0; g < 5; ++g) {
            QCOMPARE(lab.sweepPlot()->graph(g)->dataCount(), 3);
            QVERIFY2(lab.sweepPlot()->graph(g)->name().contains("order"),
                     qPrintable(lab.sweepPlot()->graph(g)->name()));
        }
        QVERIFY(lab.sweepPlot()->graph(2)->name().contains("velocity-verlet (order 2.00, theory 2)"));
        lab.findChild<QTabWidget*>()->setCurrentIndex(1);
        save(lab, "methods-lab-sweep.png");
    }

    void cancelStopsBetweenPoints() {
        MethodsLab lab;
        lab.setSweepSteps({16, 32, 64, 128, 256});
        QSignalSpy done(&lab, &MethodsLab::finished);
        lab.runSweep();
        lab.cancel();
        QVERIFY(done.wait(60000));
        int points = 0;
        for (int g = 0; g < lab.sweepPlot()->graphCount(); ++g)
            points += lab.sweepPlot()->graph(g)->dataCount();
        QVERIFY(points < 25);
        QVERIFY(!lab.isRunning());
    }

    void runnerSurvivesAThrowingJob() {
        LabRunner runner;
        int shown = 0;
        std::vector<LabRunner::Job> jobs;
        jobs.push_back([&]() -> LabRunner::Show { return [&] { ++shown; }; });
        jobs.push_back([]() -> LabRunner::Show { throw std::runtime_error("reference run failed"); });
        jobs.push_back([]() -> LabRunner::Show { throw 7; });
        jobs.push_back([&]() -> LabRunner::Show { return [&] { ++shown; }; });
        QSignalSpy done(&runner, &LabRunner::finished);
        QVERIFY(runner.start(std::move(jobs), "test"));
        QVERIFY(!runner.start({}, "second")); // one run at a time
        QVERIFY(done.wait(10000));
        QCOMPARE(shown, 2);
        QCOMPARE(runner.failedJobs(), 2);
        QVERIFY(runner.findChild<QLabel*>("labStatus")->text().contains("2 of 4 points failed"));
    }

    void gasSweepFromTheCurrentGasMarksAndApplies() {
        SimulationController controller;
        QVERIFY(controller.load(pl::loadPreset("gas-classroom")).isEmpty());
        for (int s = 0; s < 100; ++s) controller.model()->step();
        MethodsLab lab(nullptr, &controller);
        GasSweepPage* page = lab.gasSweepPage();
        page->setSource(GasSweepPage::Source::CurrentGas);
        QSignalSpy done(&lab, &MethodsLab::finished);
        page->run();
        QVERIFY(done.wait(120000));
        QCOMPARE(page->points().size(), std::size_t(25));
        QCustomPlot* plot = page->plot();
        QCOMPARE(plot->graphCount(), 6); // five schemes and the current setting
        QCOMPARE(plot->graph(5)->name(), QString("current setting"));
        QCOMPARE(plot->graph(5)->dataCount(), 1);
        page->recommendBar()->setTarget(1e-5);
        page->recommendBar()->recommend();
        const auto choice = page->recommendBar()->recommendation();
        QVERIFY(choice.has_value());
        QVERIFY(choice->error <= 1e-5);
        page->recommendBar()->apply();
        const auto* gas = dynamic_cast<const pl::GasModel*>(controller.model());
        QCOMPARE(nameOf(gas->parameters().integrator),
                 std::get<std::string>(choice->setting.at("integrator")));
        QCOMPARE(gas->parameters().dt, std::get<double>(choice->setting.at("dt")));
        save(lab, "methods-lab-sweep-gas.png", 1);
    }

    void stabilityMapShowsTheVerletLimit() {
        MethodsLab lab;
        StabilityPage* page = lab.stabilityPage();
        // ω dt from 1 to 3 along each row of k = 100 and 1e4.
        std::vector<double> dts;
        for (double w = 1.0; w <= 3.01; w += 0.25) dts.push_back(w / std::sqrt(2.0 * 100));
        page->setGrid({100.0}, dts);
        page->setIntegrator("velocity-verlet");
        QSignalSpy done(&lab, &MethodsLab::finished);
        page->run();
        QVERIFY(done.wait(60000));
        QCOMPARE(page->cells().size(), dts.size());
        for (const auto& c : page->cells())
            QCOMPARE(c.status.outcome == pl::methods::CellOutcome::Unstable, c.omegaDt > 2.01);
        QCOMPARE(page->plot()->graph(4)->name(), QString("linear limit ω dt = 2"));
    }

    void stabilityMapDefaultGrid() {
        SimulationController controller;
        QVERIFY(controller.load(pl::loadPreset("gas-classroom")).isEmpty());
        MethodsLab lab(nullptr, &controller);
        StabilityPage* page = lab.stabilityPage();
        page->setIntegrator("rk4");
        QSignalSpy done(&lab, &MethodsLab::finished);
        page->run();
        QVERIFY(done.wait(120000));
        QCOMPARE(page->cells().size(), std::size_t(9 * 26));
        for (const auto& c : page->cells()) {
            if (c.omegaDt < 2.6) QVERIFY(c.status.outcome != pl::methods::CellOutcome::Unstable);
            if (c.omegaDt > 3.1) QCOMPARE(c.status.outcome, pl::methods::CellOutcome::Unstable);
        }
        QCOMPARE(page->plot()->graph(5)->name(), QString("current gas"));
        save(lab, "methods-lab-stability.png", 2);
    }

    void fluidPageMapsCostsAndRecommends() {
        SimulationController controller;
        QVERIFY(controller.load(pl::loadPreset("fluid-dam-break")).isEmpty());
        MethodsLab lab(nullptr, &controller);
        FluidPage* page = lab.fluidPage();
        page->setGrid({0.01, 0.04, 0.08}, {1, 4, 8}, 0.3);
        QSignalSpy done(&lab, &MethodsLab::finished);
        page->run();
        QVERIFY(done.wait(60000));
        QCOMPARE(page->cells().size(), std::size_t(9));
        QCOMPARE(page->costPlot()->graphCount(), 3);
        QCOMPARE(page->mapPlot()->graph(4)->name(), QString("current fluid"));
        page->recommendBar()->setTarget(0.01);
        page->recommendBar()->recommend();
        const auto choice = page->recommendBar()->recommendation();
        QVERIFY(choice.has_value());
        page->recommendBar()->apply();
        const auto* fluid = dynamic_cast<const pl::FluidModel*>(controller.model());
        QCOMPARE(fluid->parameters().dt, std::get<double>(choice->setting.at("dt")));
        save(lab, "methods-lab-fluid.png", 3);
    }

    void dsmcPageAndRelaxation() {
        MethodsLab lab;
        lab.dsmcPage()->setGrid({1000, 16000}, {0.1, 1.0});
        QSignalSpy done(&lab, &MethodsLab::finished);
        lab.dsmcPage()->run();
        QVERIFY(done.wait(60000));
        QCOMPARE(lab.dsmcPage()->cells().size(), std::size_t(4));
        QCOMPARE(lab.dsmcPage()->plot()->graphCount(), 2);
        lab.dsmcPage()->recommendBar()->setTarget(1.0);
        lab.dsmcPage()->recommendBar()->recommend();
        QVERIFY(lab.dsmcPage()->recommendBar()->recommendation().has_value());
        save(lab, "methods-lab-dsmc.png", 4);
        pl::methods::TwoBeamSetup setup;
        setup.particles = 512;
        setup.collisionsPerParticle = 8;
        lab.relaxPage()->setSetup(setup);
        lab.relaxPage()->run();
        QVERIFY(done.wait(60000));
        QVERIFY2(lab.relaxPage()->verdict().contains("cheaper"), qPrintable(lab.relaxPage()->verdict()));
        QVERIFY(lab.relaxPage()->plot()->graph(0)->dataCount() > 10);
        QVERIFY(lab.relaxPage()->plot()->graph(1)->dataCount() > 10);
        save(lab, "methods-lab-relax.png", 5);
    }

    void batchRunWritesThePlotAndItsData() {
        QTemporaryDir dir;
        const QString png = dir.filePath("dsmc.png"), csv = dir.filePath("dsmc.csv");
        QCOMPARE(runLabPage("dsmc", png, csv), QString());
        QImage image(png);
        QVERIFY(!image.isNull() && image.width() > 400);
        QFile data(csv);
        QVERIFY(data.open(QIODevice::ReadOnly));
        const QStringList lines = QString(data.readAll()).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.front(), QString("series,x,y"));
        QCOMPARE(lines.size(), 1 + 16); // 4 ν dt × 4 particle counts
        QVERIFY(runLabPage("nope", png, csv).startsWith("unknown page"));
        QVERIFY(!runLabPage("echo", dir.filePath("missing/dir/echo.png"), {}).isEmpty());
    }

    void closingWhileRunningWaitsForTheWorker() {
        auto* lab = new MethodsLab;
        lab->setEchoSteps({3000});
        lab->runEcho();
        delete lab; // must not crash or leave the thread running
    }
};

QTEST_MAIN(TestMethodsLab)
#include "tst_methodslab.moc"
