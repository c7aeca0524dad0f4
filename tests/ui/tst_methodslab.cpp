// The methods lab dock: both experiments run in a worker thread, plot as they go, and cancel cleanly.
#include "methods/MethodsLab.h"

#include <QTabWidget>
#include <QtTest>
#include <qcustomplot.h>

using namespace pl::ui;

class TestMethodsLab : public QObject {
    Q_OBJECT

    static void save(MethodsLab& lab, const QString& name) {
        lab.resize(720, 560);
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

    void closingWhileRunningWaitsForTheWorker() {
        auto* lab = new MethodsLab;
        lab->setEchoSteps({3000});
        lab->runEcho();
        delete lab; // must not crash or leave the thread running
    }
};

QTEST_MAIN(TestMethodsLab)
#include "tst_methodslab.moc"
