// Translations: German menus in a new window, Qt's own buttons in German, Preferences saving the choice,
// a German catalogue with every entry finished (placeholders and accelerators kept, every text the sources
// and the core show included), English plurals, and English again.
#include "ExperimentDocument.h"
#include "MainWindow.h"
#include "PreferencesDialog.h"
#include "SimulationController.h"
#include "UiTestSupport.h"
#include "i18n/CoreSentences.h"
#include "i18n/CoreStrings.h"
#include "i18n/Translations.h"
#include "panels/ParameterPanel.h"

#include <QDialogButtonBox>
#include <QMenuBar>
#include <QProcess>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTranslator>
#include <QXmlStreamReader>
#include <QtTest>

using namespace pl;

namespace {

const QString kCatalogue = QStringLiteral(PARTICLELAB_TRANSLATIONS_DIR "/particlelab_de.ts");

struct CatalogueEntry {
    QString context, source, type; // type: "" (finished), "unfinished", "vanished", "obsolete"
    bool numerus = false;
    QStringList translations; // one per plural form
};

// Every <message> of a Qt Linguist .ts file.
QList<CatalogueEntry> readCatalogue(const QString& path) {
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return {};
    QXmlStreamReader xml(&file);
    QList<CatalogueEntry> entries;
    QString context;
    while (xml.readNext() != QXmlStreamReader::EndDocument && !xml.hasError()) {
        if (!xml.isStartElement()) continue;
        if (xml.name() == u"name") {
            context = xml.readElementText();
        } else if (xml.name() == u"message") {
            CatalogueEntry entry{context, {}, {}, xml.attributes().value("numerus") == u"yes", {}};
            while (xml.readNextStartElement()) {
                if (xml.name() == u"source") {
                    entry.source = xml.readElementText();
                } else if (xml.name() == u"translation") {
                    entry.type = xml.attributes().value("type").toString();
                    if (!entry.numerus) {
                        entry.translations << xml.readElementText();
                    } else {
                        while (xml.readNextStartElement()) entry.translations << xml.readElementText();
                    }
                } else {
                    xml.skipCurrentElement();
                }
            }
            entries << entry;
        }
    }
    return xml.hasError() ? QList<CatalogueEntry>{} : entries;
}

bool shipped(const CatalogueEntry& entry) {
    return entry.type != "vanished" && entry.type != "obsolete";
}

// "%1", "%L2", "%n" in a text, sorted.
QStringList placeholders(const QString& text) {
    QStringList found;
    static const QRegularExpression pattern(QStringLiteral("%L?(\\d+|n)"));
    for (auto match = pattern.globalMatch(text); match.hasNext();) found << match.next().captured();
    found.sort();
    return found;
}

// Accelerator markers: '&' not doubled.
int accelerators(const QString& text) {
    return text.count('&') - 2 * text.count(QStringLiteral("&&"));
}

QChar mnemonic(const QString& text) {
    const int at = text.indexOf(QRegularExpression(QStringLiteral("&[^&]")));
    return at < 0 ? QChar() : text.at(at + 1).toLower();
}

// The first menu entry whose accelerator another entry of the same menu (or the menu bar) already has.
QString acceleratorClash(const ui::MainWindow& window) {
    QSet<QChar> bar;
    for (QAction* top : window.menuBar()->actions()) {
        const QChar key = mnemonic(top->text());
        if (!key.isNull() && bar.contains(key)) return "menu bar: " + top->text();
        bar.insert(key);
        QSet<QChar> inMenu;
        for (QAction* item : top->menu()->actions()) {
            const QChar itemKey = mnemonic(item->text());
            if (itemKey.isNull()) continue;
            if (inMenu.contains(itemKey)) return top->text() + ": " + item->text();
            inMenu.insert(itemKey);
        }
    }
    return {};
}

QStringList menuTitles(const ui::MainWindow& window) {
    QStringList titles;
    for (QAction* action : window.menuBar()->actions()) titles << action->text();
    return titles;
}

} // namespace

class TestTranslations : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void aNewWindowShowsGermanMenus() {
        QVERIFY(ui::installLanguage("de"));
        QCOMPARE(ui::installedLanguage(), QStringLiteral("de"));
        ui::MainWindow window;
        const QStringList titles = menuTitles(window);
        QVERIFY2(titles.contains("&Datei"), qPrintable(titles.join(", ")));
        QVERIFY2(titles.contains("&Simulation"), qPrintable(titles.join(", ")));
        QVERIFY2(titles.contains("&Ansicht"), qPrintable(titles.join(", ")));
        QVERIFY(!titles.contains("&File"));
        auto* preferences = window.findChild<QAction*>("preferencesAction");
        QVERIFY(preferences);
        QCOMPARE(preferences->text(), QStringLiteral("&Einstellungen…"));

        // The core's texts reach the panels: a parameter label, the units line and the scene's title.
        QVERIFY(window.document()->open("gas-classroom", true));
        QStringList labels;
        for (const QLabel* label : window.parameters()->findChildren<QLabel*>()) labels << label->text();
        QVERIFY2(labels.contains(QStringLiteral("Behälterbreite [L] ⟲")), qPrintable(labels.join(" | ")));
        QVERIFY2(labels.contains(QStringLiteral("Einheiten: reduziert (L, T, M)")),
                 qPrintable(labels.join(" | ")));
        QStringList scenes;
        for (const QComboBox* box : window.findChildren<QComboBox*>())
            for (int i = 0; i < box->count(); ++i) scenes << box->itemText(i);
        QVERIFY2(scenes.contains(QStringLiteral("Gas (Molekulardynamik)")), qPrintable(scenes.join(" | ")));

        window.resize(1280, 800);
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QDir().mkpath(PARTICLELAB_SCREENSHOT_DIR);
        QVERIFY(window.windowImage().save(PARTICLELAB_SCREENSHOT_DIR "/translations-de.png"));
        ui::PreferencesDialog preferencesDialog(&window);
        QCOMPARE(preferencesDialog.windowTitle(), QStringLiteral("Einstellungen"));
        QVERIFY(preferencesDialog.grab().save(PARTICLELAB_SCREENSHOT_DIR "/translations-preferences-de.png"));

        // Accelerators stay unique within the menu bar and within each menu, in German too.
        const QString clash = acceleratorClash(window);
        QVERIFY2(clash.isEmpty(), qPrintable(clash));
    }

    // Sentences the core builds with numbers: one template each in the catalogue, the numbers written
    // with the language's decimal mark; choice values are shown translated and kept as keys.
    void sentencesWithNumbersAndChoicesAreGerman() {
        const ui::SentenceTemplate pattern = ui::sentenceTemplate("u_x = -1.138e-14 m/s, 2d, M4: 3 each.");
        QCOMPARE(QString::fromStdString(pattern.text), QStringLiteral("u_x = %1 m/s, 2d, M4: %2 each."));
        QCOMPARE(pattern.numbers, (std::vector<std::string>{"-1.138e-14", "3"}));
        const ui::SentenceTemplate refusal = ui::sentenceTemplate("'{fill_x1}' = 2 exceeds {count_b}");
        QCOMPARE(QString::fromStdString(refusal.text), QStringLiteral("{1} = %1 exceeds {2}"));
        QCOMPARE(refusal.keys, (std::vector<std::string>{"fill_x1", "count_b"}));
        QVERIFY(ui::installLanguage("de"));
        QCOMPARE(ui::coreSentence("kT = 0.52, KS distance 0.0123"),
                 QStringLiteral("kT = 0,52, KS-Abstand 0,0123"));
        QCOMPARE(ui::coreSentence("the whole domain: 32000 molecules"),
                 QStringLiteral("das ganze Gebiet: 32000 Moleküle"));
        QCOMPARE(QLocale().decimalPoint(), QStringLiteral(","));
        ui::MainWindow window;
        QVERIFY(window.document()->open("gas-classroom", true));
        auto* integrator = qobject_cast<QComboBox*>(window.parameters()->editor("integrator"));
        QVERIFY(integrator);
        QCOMPARE(integrator->currentText(), QStringLiteral("Velocity-Verlet"));
        integrator->setCurrentIndex(integrator->findText(QStringLiteral("Runge-Kutta 4")));
        QVERIFY(integrator->currentIndex() >= 0);
        emit integrator->activated(integrator->currentIndex());
        QCOMPARE(std::get<std::string>(window.controller()->parameterValues().at("integrator")),
                 std::string("rk4"));
        window.document()->setModified(false);
        QVERIFY(ui::installLanguage("en"));
    }

    // A value the model refuses is explained in German: the sentence's template translated, each
    // parameter by its German label, numbers with the decimal comma, ranges separated by a semicolon.
    void refusalsInThePanelAreGerman() {
        QVERIFY(ui::installLanguage("de"));
        ui::MainWindow window;
        QVERIFY(window.document()->open("gas-classroom", true));
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        ui::ParameterPanel* panel = window.parameters();
        QVERIFY2(panel->editor("dt")->toolTip().contains("Erlaubt: [-1; 1] außer 0 T"),
                 qPrintable(panel->editor("dt")->toolTip()));
        test::typeInto(panel->editor("dt"), "10,5");
        const QString range = panel->problem("dt");
        QVERIFY2(range.startsWith("Zeitschritt liegt außerhalb des Bereichs: 10,5 (erlaubt: [") &&
                     range.endsWith("(erlaubt: [-1; 1] außer 0 T)"),
                 qPrintable(range));
        // The field's own message writes the allowed values the same way as its tooltip.
        test::typeInto(panel->editor("dt"), "zehn");
        QCOMPARE(panel->problem("dt"),
                 QStringLiteral("Zeitschritt: „zehn“ ist keine Zahl (erlaubt: [-1; 1] außer 0 T)"));
        const double cap = std::get<double>(window.controller()->model()->params().at("max_particles"));
        test::typeInto(panel->editor("count_a"), QString::number(static_cast<qint64>(cap) + 1));
        const QString across = panel->problem("count_a");
        QVERIFY2(across.startsWith("Scheiben (A) + Scheiben (B) = ") && across.contains(" übersteigt ") &&
                     across.contains("Teilchenobergrenze = "),
                 qPrintable(across));
        window.document()->setModified(false);
        QVERIFY(ui::installLanguage("en"));
    }

    void qtsOwnTextsFollow() {
        QVERIFY(ui::installLanguage("de"));
        QDialogButtonBox buttons(QDialogButtonBox::Ok | QDialogButtonBox::Cancel);
        QCOMPARE(buttons.button(QDialogButtonBox::Cancel)->text(), QStringLiteral("Abbrechen"));
    }

    void preferencesSaveTheChosenLanguage() {
        QVERIFY(ui::installLanguage("en"));
        ui::saveLanguage(QString());
        ui::MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        window.findChild<QAction*>("preferencesAction")->trigger();
        ui::PreferencesDialog* dialog = nullptr;
        QTRY_VERIFY((dialog = window.findChild<ui::PreferencesDialog*>()) && dialog->isVisible());
        auto* box = dialog->findChild<QComboBox*>("languageBox");
        QCOMPARE(box->currentData().toString(), QString()); // the system's language until chosen
        box->setFocus();
        while (box->currentData().toString() != "de") {
            const int before = box->currentIndex();
            QTest::keyClick(box, Qt::Key_Down);
            QVERIFY2(box->currentIndex() != before, "Deutsch is not offered");
        }
        auto* ok = dialog->findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
        QTest::mouseClick(ok, Qt::LeftButton);
        QTRY_VERIFY(!dialog->isVisible());
        QCOMPARE(ui::savedLanguage(), QStringLiteral("de"));
        // What main() does on the next start.
        QVERIFY(ui::installLanguage(ui::savedLanguage()));
        ui::MainWindow next;
        QVERIFY(menuTitles(next).contains("&Datei"));
    }

    void everyGermanEntryIsFinished() {
        const QList<CatalogueEntry> entries = readCatalogue(kCatalogue);
        QVERIFY2(entries.size() > 100, qPrintable(kCatalogue));
        for (const CatalogueEntry& entry : entries) {
            if (!shipped(entry)) continue;
            const QString where = entry.context + ": " + entry.source;
            QVERIFY2(entry.type.isEmpty(), qPrintable("unfinished: " + where));
            QVERIFY2(!entry.translations.isEmpty(), qPrintable(where));
            for (const QString& translation : entry.translations) {
                QVERIFY2(!translation.isEmpty(), qPrintable("empty: " + where));
                QVERIFY2(entry.numerus || placeholders(translation) == placeholders(entry.source),
                         qPrintable("placeholders differ: " + where + " → " + translation));
                QVERIFY2(!entry.numerus || placeholders(translation).contains("%n"),
                         qPrintable("no %n: " + where + " → " + translation));
                QVERIFY2(accelerators(translation) == accelerators(entry.source),
                         qPrintable("accelerator: " + where + " → " + translation));
            }
        }
    }

    void theCatalogueHoldsEveryTextOfTheSources() {
        // lupdate over today's sources into a copy: a text added since the last translation appears there
        // as unfinished.
        QTemporaryDir dir;
        const QString copy = dir.filePath("particlelab_de.ts");
        QVERIFY(QFile::copy(kCatalogue, copy));
        QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner);
        QProcess lupdate;
        lupdate.setProcessChannelMode(QProcess::MergedChannels);
        lupdate.start(PARTICLELAB_LUPDATE,
                      {"-locations", "none", "@" PARTICLELAB_TRANSLATED_SOURCES, "-ts", copy});
        QVERIFY(lupdate.waitForFinished(120000));
        QVERIFY2(lupdate.exitCode() == 0, lupdate.readAll().constData());
        QStringList missing;
        for (const CatalogueEntry& entry : readCatalogue(copy))
            if (shipped(entry) && entry.type == "unfinished") missing << entry.context + ": " + entry.source;
        QVERIFY2(missing.isEmpty(), qPrintable("not in the catalogue yet (cmake --build build --target "
                                               "update_translations, then translate):\n" +
                                               missing.join('\n')));
    }

    void everyCoreTextHasAGermanTranslation() {
        QTranslator german;
        QVERIFY(german.load(":/i18n/particlelab_de.qm"));
        const std::vector<std::string> texts = ui::coreDisplayStrings();
        QVERIFY(texts.size() > 50);
        for (const std::string& text : texts)
            QVERIFY2(!german.translate(ui::kCoreContext, text.c_str()).isEmpty(), text.c_str());
    }

    void englishHasItsPluralForms() {
        QTranslator english;
        QVERIFY(english.load(":/i18n/particlelab_en.qm"));
        for (const CatalogueEntry& entry : readCatalogue(kCatalogue)) {
            if (!shipped(entry) || !entry.numerus) continue;
            const QByteArray context = entry.context.toUtf8(), source = entry.source.toUtf8();
            for (const int n : {1, 2}) {
                const QString text = english.translate(context, source, nullptr, n);
                QVERIFY2(!text.isEmpty(), source.constData());
                QVERIFY2(!text.contains("(s)"), qPrintable(text));
            }
        }
    }

    void englishAgain() {
        QVERIFY(ui::installLanguage("en"));
        QCOMPARE(ui::installedLanguage(), QStringLiteral("en"));
        ui::MainWindow window;
        const QStringList titles = menuTitles(window);
        QVERIFY2(titles.contains("&File") && titles.contains("&View"), qPrintable(titles.join(", ")));
        const QString clash = acceleratorClash(window);
        QVERIFY2(clash.isEmpty(), qPrintable(clash));
        QCOMPARE(ui::coreText("Box width"), QStringLiteral("Box width"));
    }
};

QTEST_MAIN(TestTranslations)
#include "tst_translations.moc"
