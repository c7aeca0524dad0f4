// Crash insurance through the real application: the window autosaves its experiment with every
// particle while time runs; after `kill -9` of a running particlelab, the next start offers the
// experiment back and continues it from the step it had reached; a clean exit leaves nothing behind.
#include "Autosave.h"
#include "ExperimentDocument.h"
#include "MainWindow.h"
#include "SimulationController.h"
#include "UiTestSupport.h"
#include "catalog/ModelCatalog.h"

#include <QDir>
#include <QElapsedTimer>
#include <QProcess>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace pl;

class TestAutosave : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
        QVERIFY(state_.isValid());
        qputenv("XDG_STATE_HOME", state_.path().toUtf8());
    }

    void savesTheRunningExperimentAndForgetsItOnAcleanExit() {
        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-classroom"));
        for (int f = 0; f < 5; ++f) window.controller()->advanceFrame();
        ui::Autosave* autosave = window.autosave();
        QVERIFY(autosave->path().startsWith(state_.path()));
        QVERIFY(autosave->saveNow().isEmpty());
        const Snapshot saved = readSnapshotFile(autosave->path().toStdString(), specsForModel);
        QCOMPARE(static_cast<std::int64_t>(saved.state.scalar("step")),
                 window.controller()->model()->stepCount());
        QCOMPARE(saved.preset.model, std::string("gas"));
        // A process that still runs (this one) is never offered back.
        QVERIFY(!autosave->offerRestore());
        window.document()->setModified(false);
        QVERIFY(window.close());
        QVERIFY(!QFile::exists(autosave->path()));
    }

    void aKilledAppComesBackOnTheNextStart() {
        QProcess app;
        QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
        env.insert("XDG_STATE_HOME", state_.path());
        env.insert("XDG_CONFIG_HOME", state_.filePath("config"));
        env.insert("XDG_DATA_HOME", state_.filePath("data"));
        env.insert("QT_QPA_PLATFORM", "offscreen");
        app.setProcessEnvironment(env);
        app.start(PARTICLELAB_GUI, {"gas-classroom"});
        QVERIFY(app.waitForStarted());
        const QString file =
            QDir(state_.path()).filePath(QString("ParticleLab/autosave-%1.json").arg(app.processId()));
        QElapsedTimer clock;
        clock.start();
        while (!QFile::exists(file) && clock.elapsed() < 30000) QTest::qWait(100);
        QVERIFY2(QFile::exists(file), "no autosave within 30 s of running");
        QTest::qWait(200); // the rename is atomic: the file is complete once it exists
        app.kill();        // SIGKILL: no chance to clean up
        QVERIFY(app.waitForFinished());
        const std::int64_t savedStep = static_cast<std::int64_t>(
            readSnapshotFile(file.toStdString(), specsForModel).state.scalar("step"));
        QVERIFY(savedStep > 0);

        ui::MainWindow window;
        QVERIFY(window.openPreset("gas-write-up"));
        test::MessageBoxAnswerer answerer(QMessageBox::Yes);
        const bool restored = window.autosave()->offerRestore();
        QVERIFY2(restored, qPrintable(answerer.texts.join(" / ")));
        QCOMPARE(answerer.texts.size(), 1);
        QVERIFY2(answerer.texts.first().contains("did not close normally"),
                 qPrintable(answerer.texts.first()));
        const Model* model = window.controller()->model();
        QCOMPARE(model->kind(), std::string("gas"));
        QCOMPARE(model->stepCount(), savedStep);
        QCOMPARE(model->particleCount(), std::size_t(2500));
        QVERIFY(window.document()->isModified());
        QVERIFY(!QFile::exists(file)); // the orphan is gone: it is offered once
        window.controller()->advanceFrame();
        QVERIFY(!window.controller()->model()->failure());
        window.document()->setModified(false);
    }

private:
    QTemporaryDir state_;
};

QTEST_MAIN(TestAutosave)
#include "tst_autosave.moc"
