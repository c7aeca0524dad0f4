// particlelab-cli report: the PDF's text (pdftotext) holds the experiment's parameters, what was run and
// the readouts with their theory; page 1 renders (pdftoppm, kept for a look); the HTML page is
// well-formed XML with its pictures inline; a wrong suffix is refused before anything runs.
#include "CliRunner.h"

#include <QDir>
#include <QFile>
#include <QImage>
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
              "Readouts at the end", "KS distance to Maxwell", "1 % critical value", "Energy"})
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
