// particlelab-cli report: the PDF's text (pdftotext) holds the experiment's parameters, what was run and
// the readouts with their theory (every kind's); page 1 renders (pdftoppm, kept for a look); the HTML page
// is well-formed XML with its pictures inline; --data writes the plots' CSV files; a wrong suffix or a
// data folder that is a file is refused before anything runs.
#include "CliRunner.h"

#include "catalog/ModelCatalog.h"
#include "common/Preset.h"
#include "common/TimeSeries.h"
#include "report/ReportTheory.h"

#include <QDir>
#include <QFile>
#include <QImage>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

using pl::test::runCli;
using pl::test::runProgram;

namespace {
const QStringList kReport{"report", "gas-classroom", "--steps", "300", "--backend", "cpu"};
}

class TestReport : public QObject {
    Q_OBJECT
private slots:
    void pdfHoldsParametersRunAndReadouts() {
        if (QStandardPaths::findExecutable("pdftotext").isEmpty())
            QFAIL("pdftotext is missing: .ci/install-deps.sh installs it (poppler-utils) to read the report "
                  "back");
        QTemporaryDir dir;
        const QString pdf = dir.filePath("r.pdf");
        const auto r = runCli(kReport + QStringList{"--out", pdf});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const auto text = runProgram("pdftotext", {"-layout", pdf, "-"});
        QCOMPARE(text.exitCode, 0);
        for (const char* expected :
             {"Lab report: gas-classroom", "What was run", "Seed", "Steps", "300", "Simulated time",
              "Integrator", "Backend", "CPU (OpenMP)", "Machine", "Parameters", "count_a", "2500",
              "Readouts against theory", "Readouts at the end", "KS distance to Maxwell",
              "1 % critical value", "Energy"})
            QVERIFY2(text.out.contains(QString::fromUtf8(expected)), expected);
        // Page 1 as an image, kept beside the other screenshots for a look.
        if (QStandardPaths::findExecutable("pdftoppm").isEmpty()) return;
        const QString stem = dir.filePath("page");
        QCOMPARE(runProgram("pdftoppm", {"-png", "-r", "60", "-f", "1", "-l", "1", pdf, stem}).exitCode, 0);
        const QStringList pages = QDir(dir.path()).entryList({"page*.png"});
        QCOMPARE(pages.size(), 1);
        const QImage page(dir.filePath(pages.front()));
        QVERIFY(page.width() > 400 && page.height() > 600);
        QDir().mkpath(PARTICLELAB_SCREENSHOT_DIR);
        QFile::remove(PARTICLELAB_SCREENSHOT_DIR "/report-page1.png");
        QVERIFY(QFile::copy(dir.filePath(pages.front()), PARTICLELAB_SCREENSHOT_DIR "/report-page1.png"));
    }

    void htmlIsOnePageThatNeedsNothingBesideIt() {
        QTemporaryDir dir;
        const QString html = dir.filePath("r.html");
        const auto r = runCli(kReport + QStringList{"--out", html});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile file(html);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray bytes = file.readAll();
        QXmlStreamReader xml(bytes);
        int images = 0, svgs = 0;
        while (!xml.atEnd()) {
            xml.readNext();
            if (xml.isStartElement() && xml.name() == QLatin1String("img")) {
                const QString src = xml.attributes().value("src").toString();
                QVERIFY2(src.startsWith("data:"), "a picture outside the page");
                ++images;
                if (src.startsWith("data:image/svg+xml;base64,")) ++svgs;
            }
        }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QVERIFY(svgs >= 1);     // every plot of the gas, as vector graphics
        QVERIFY(images > svgs); // and the scene
        QVERIFY(bytes.contains("count_a") && bytes.contains("1 % critical value"));
    }

    // Each kind's key readouts beside their theory, in the PDF's text: the gas's speeds against
    // Maxwell–Boltzmann, the DSMC cell's moments against BKW, the tunnel's drag against the
    // free-molecular value, the fluid's density error against the methods lab's tolerance.
    void readoutsStandBesideTheirTheory_data() {
        QTest::addColumn<QStringList>("run");
        QTest::addColumn<QStringList>("expected");
        QTest::newRow("gas") << QStringList{"gas-classroom", "--steps", "300"}
                             << QStringList{"Readouts against theory",
                                            "KS distance of the speeds",
                                            "1.63/√n",
                                            "n = 2500 disks",
                                            "Maxwell–Boltzmann fit of the speeds",
                                            "maximum-likelihood fit",
                                            "of its area"};
        QTest::newRow("dsmc") << QStringList{"dsmc-bkw", "--steps", "100"}
                              << QStringList{"Moment M4 / M4(eq) against BKW", "exact (BKW)", "Moment M8",
                                             "Kurtosis of v_x", "a Maxwellian's is 3"};
        QTest::newRow("tunnel") << QStringList{"tunnel-free-molecular-cylinder", "--steps", "700"}
                                << QStringList{"Drag of the body, averaged over the fields window",
                                               "free-molecular value for a diffuse half cylinder",
                                               "free-molecular flow, where the drag tends to this value"};
        QTest::newRow("fluid") << QStringList{"fluid-dam-break", "--steps", "150"}
                               << QStringList{"Mean density error", "the methods lab's tolerance 1 %",
                                              "Largest compression", "Surge front",
                                              "Ritter's shallow-water bound"};
    }
    void readoutsStandBesideTheirTheory() {
        QFETCH(QStringList, run);
        QFETCH(QStringList, expected);
        QTemporaryDir dir;
        // The HTML page holds each cell's text whole (the PDF's table wraps and hyphenates it).
        const QString html = dir.filePath("r.html");
        const auto r =
            runCli(QStringList{"report"} + run + QStringList{"--backend", "cpu", "--out", html}, 300000);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile file(html);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString page = QString::fromUtf8(file.readAll());
        QVERIFY(page.contains("<h2>Readouts against theory</h2>"));
        for (const QString& line : expected) QVERIFY2(page.contains(line.toHtmlEscaped()), qPrintable(line));
    }

    // The free-molecular cylinder's measured drag lies near the theory: the ratio the report prints.
    void freeMolecularDragRatioIsNearOne() {
        QTemporaryDir dir;
        const QString html = dir.filePath("r.html");
        const auto r = runCli(
            {"report", "tunnel-free-molecular-cylinder", "--steps", "900", "--backend", "cpu", "--out", html},
            300000);
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile file(html);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString page = QString::fromUtf8(file.readAll());
        const auto match = QRegularExpression("\\(ratio ([0-9.]+)\\)").match(page);
        QVERIFY2(match.hasMatch(), "no drag ratio in the report");
        const double ratio = match.captured(1).toDouble();
        qInfo("drag / free-molecular drag: %.3f", ratio);
        QVERIFY2(ratio > 0.85 && ratio < 1.15, qPrintable(match.captured(1)));
    }

    // --data writes one CSV per plot of the scene beside the report; a file in its place is refused.
    void dataFolderHoldsEveryPlotsCsv() {
        QTemporaryDir dir;
        const QString data = dir.filePath("data/of/run");
        const auto r = runCli(kReport + QStringList{"--out", dir.filePath("r.pdf"), "--data", data});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        const QStringList files = QDir(data).entryList({"*.csv"});
        QVERIFY2(files.contains("energyPlot.csv"), qPrintable(files.join(' ')));
        // The speed distribution was missing from the report and from --data.
        QVERIFY2(files.contains("speedHistogram.csv"), qPrintable(files.join(' ')));
        QVERIFY(files.size() >= 3); // every plot of the gas
        for (const QString& name : files) {
            QFile csv(QDir(data).filePath(name));
            QVERIFY(csv.open(QIODevice::ReadOnly));
            const QList<QByteArray> lines = csv.readAll().split('\n');
            QCOMPARE(lines.front(), QByteArray("series,x,y"));
            QVERIFY2(lines.size() > 30, qPrintable(name)); // the run's samples or bins, not an empty table
            const auto theoryRows = std::count_if(
                lines.begin(), lines.end(), [](const QByteArray& line) { return line.contains("Maxwell"); });
            if (name == "speedHistogram.csv") // the bars and the theory's curve beside them
                QVERIFY2(theoryRows > 10, lines.join('\n').left(400).constData());
        }
    }

    // Without --steps a report runs what the preset promises: 1000 steps (0.175 T) of gas-classroom
    // reported "not (yet) Maxwell–Boltzmann" for a preset that promises the curve within seconds.
    void theDefaultRunReachesWhatThePresetPromises() {
        QTemporaryDir dir;
        const QString html = dir.filePath("r.html");
        const auto r = runCli({"report", "gas-classroom", "--backend", "cpu", "--out", html});
        QVERIFY2(r.exitCode == 0, qPrintable(r.err));
        QFile file(html);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(file.readAll());
        QVERIFY2(text.contains("consistent with Maxwell–Boltzmann") && !text.contains("not (yet)"),
                 qPrintable(text.mid(text.indexOf("KS distance"), 600)));
        QVERIFY(text.contains(">57143<")); // 4 s at the watchable 2.5 T/s, dt = 1.75e-4
        QVERIFY(text.contains("Distribution of speed"));
    }

    void aDataFolderThatIsAFileIsRefused() {
        QTemporaryDir dir;
        const QString file = dir.filePath("taken");
        QFile taken(file);
        QVERIFY(taken.open(QIODevice::WriteOnly));
        taken.write("mine");
        taken.close();
        const auto r = runCli(kReport + QStringList{"--out", dir.filePath("r.pdf"), "--data", file});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains("is a file"), qPrintable(r.err));
        QCOMPARE(r.err.count('\n'), 1);
        QVERIFY(!QFileInfo::exists(dir.filePath("r.pdf")));
        QVERIFY(taken.open(QIODevice::ReadOnly));
        QCOMPARE(taken.readAll(), QByteArray("mine"));
    }

    // After the piston moved, kT·A at the end against its start: close to 1 for a piston slower than the
    // disks (the 2D adiabat, γ = 2), and computed from the series the report reads.
    void aCompressionIsSetAgainstTheAdiabat() {
        pl::Preset preset = pl::loadPreset("gas-classroom");
        preset.params["piston_enabled"] = true;
        preset.params["piston_x"] = 1.0; // the right wall
        const auto built = pl::createModel("gas");
        built->reset(preset);
        pl::Model& model = *built;
        pl::TimeSeries series(model.seriesColumns()); // sampled as the app and the CLI sample it
        series.append(model.sampleSeries());
        QCOMPARE(pl::ui::theoryReadouts(model, series).size(), std::size_t(2)); // KS and the fit only
        model.tools()->dragPiston(0.8); // a tenth of the area, at the tool speed (0.3 × the rms speed)
        for (int s = 1; s <= 6000; ++s) {
            model.step();
            if (s % 200 == 0) series.append(model.sampleSeries());
        }
        QVERIFY(std::abs(model.tools()->pistonX() - 0.8) < 1e-9);
        const auto rows = pl::ui::theoryReadouts(model, series);
        const auto row = std::find_if(rows.begin(), rows.end(),
                                      [](const pl::ui::ReportRow& r) { return r.name.startsWith("kT·A"); });
        QVERIFY(row != rows.end());
        QVERIFY2(row->name.contains("area × 0.9"), qPrintable(row->name));
        const double ratio = row->value.toDouble();
        qInfo("kT·A end / start after compressing to 0.9 of the area: %.4f", ratio);
        QVERIFY2(ratio > 0.97 && ratio < 1.1, qPrintable(row->value));
        QVERIFY2(row->note.contains("γ = 2"), qPrintable(row->note));
    }

    void aWrongSuffixIsRefusedBeforeTheRun() {
        QTemporaryDir dir;
        const auto r = runCli(kReport + QStringList{"--out", dir.filePath("r.docx")});
        QCOMPARE(r.exitCode, 2);
        QVERIFY2(r.err.contains(".pdf or .html"), qPrintable(r.err));
        QCOMPARE(r.err.count('\n'), 1);
    }
};

QTEST_GUILESS_MAIN(TestReport)
#include "tst_report.moc"
