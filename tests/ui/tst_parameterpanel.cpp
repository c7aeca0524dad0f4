// The units line says the kind's unit system; and one way to reject a value: a rejected field keeps what was
// typed, turns red and says under it, in the labels' words with unit and allowed range, what is wrong; no
// dialog opens and the model is untouched. A valid value clears the mark. Values are typed with QTest into
// the panel's real editors. Numbers are read in the UI's language, letters are refused in place, a typed
// number keeps its form, the wheel scrolls the panel rather than a field not clicked into, and the line
// about changes waiting for Reset moves no field.
#include "ExperimentDocument.h"
#include "MainWindow.h"
#include "SimulationController.h"
#include "UiTestSupport.h"
#include "panels/ParameterPanel.h"

#include <QAbstractSpinBox>
#include <QLabel>
#include <QLineEdit>
#include <QRegularExpression>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStandardPaths>
#include <QWheelEvent>
#include <QtTest>

using namespace pl;

namespace {

// Replaces a field's text as a user does: click into it, select all, type, Enter.
QString allowedFor(const Model* model, const std::string& key) {
    return QString::fromStdString(describeAllowed(*findSpec(model->paramSpecs(), key)));
}

// The default locale (the UI's language) for one test, put back when it ends.
class LocaleForTest {
public:
    explicit LocaleForTest(const QLocale& locale) { QLocale::setDefault(locale); }
    ~LocaleForTest() { QLocale::setDefault(previous_); }

private:
    QLocale previous_;
};

bool looksRed(QWidget* field) {
    const QColor base = field->palette().color(QPalette::Base);
    return base.red() > base.green() + 20;
}

} // namespace

class TestParameterPanel : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::useCleanTestSettings(); }

    void init() {
        window_ = std::make_unique<ui::MainWindow>();
        QVERIFY(window_->openPreset("gas-mixture"));
        QVERIFY(test::showActive(*window_));
        panel_ = window_->parameters();
    }

    void cleanup() {
        window_->document()->setModified(false);
        window_.reset();
    }

    // The first line says the kind's unit system, from its registration; the tooltip spells it out.
    void theFirstLineSaysTheKindsUnits() {
        for (const ModelDescriptor& kind : modelCatalog()) {
            QVERIFY(window_->openPreset(QString::fromStdString(builtinPresetsOf(kind.kind).front()->name)));
            const auto* line = window_->parameters()->findChild<QLabel*>("unitsLine");
            QVERIFY(line);
            QVERIFY(line->isVisible());
            QCOMPARE(line->text(), "Units: " + QString::fromStdString(kind.units.name));
            QCOMPARE(line->toolTip(), QString::fromStdString(kind.units.summary));
            window_->document()->setModified(false);
        }
    }

    void aTimeStepOutOfRangeStaysRedAndSaysWhy() {
        test::MessageBoxAnswerer dialogs;
        const Model* model = window_->controller()->model();
        const ParamValues before = model->params();
        QWidget* dt = panel_->editor("dt");
        QVERIFY(!looksRed(dt));
        test::typeInto(dt, "10");
        QTest::qWait(60); // a dialog, were there one, would be seen and answered by now

        QCOMPARE(qobject_cast<QAbstractSpinBox*>(dt)->text(), QString("10")); // not reverted
        QVERIFY(looksRed(dt));
        const QString problem = panel_->problem("dt");
        QVERIFY2(problem.contains("Time step") && problem.contains(allowedFor(model, "dt")),
                 qPrintable(problem));
        QVERIFY2(!problem.contains("'dt'"), qPrintable(problem));
        auto* line = panel_->findChild<QLabel*>("problem-dt");
        QVERIFY(line && line->isVisible() && line->text() == problem);
        QVERIFY(window_->controller()->model()->params() == before);
        QVERIFY2(dialogs.texts.isEmpty(), qPrintable(dialogs.texts.join('\n')));
        QDir().mkpath(PARTICLELAB_SCREENSHOT_DIR); // for a person to look at: the red field and its line
        QVERIFY(window_->windowImage().save(QString(PARTICLELAB_SCREENSHOT_DIR) +
                                            "/parameterpanel-rejected.png"));

        test::typeInto(panel_->editor("dt"), "0.0002");
        QVERIFY(panel_->problem("dt").isEmpty());
        QVERIFY(!line->isVisible());
        QVERIFY(!looksRed(dt));
        QCOMPARE(std::get<double>(window_->controller()->model()->params().at("dt")), 0.0002);
    }

    // Stiffness 1e12 was accepted without a mark and blew the run up at once, whose message then advised
    // "a smaller time step". A change that puts dt·ω beyond the integrator's limit is marked before a step
    // is taken with it, naming the values that fit, and the model keeps what it had.
    void aChangeBeyondTheStabilityLimitIsMarked() {
        const Model* model = window_->controller()->model();
        const ParamValues before = model->params();
        QWidget* stiffness = panel_->editor("stiffness");
        test::typeInto(stiffness, "1e12");
        QVERIFY(looksRed(stiffness));
        const QString problem = panel_->problem("stiffness");
        QVERIFY2(problem.contains("would make every step unstable") && problem.contains("use dt ≤") &&
                     problem.contains("or stiffness ≤"),
                 qPrintable(problem));
        QVERIFY(window_->controller()->model()->params() == before);
        test::typeInto(stiffness, "2e5"); // within the limit: accepted, the mark gone
        QVERIFY2(panel_->problem("stiffness").isEmpty(), qPrintable(panel_->problem("stiffness")));
        QCOMPARE(std::get<double>(window_->controller()->model()->params().at("stiffness")), 2e5);
    }

    // A blow-up's message names the change made last before it (here a time step for explicit Euler,
    // which no limit refuses: it gains energy at every dt), not always the time step.
    void aBlowUpNamesTheLastChange() {
        test::MessageBoxAnswerer dialogs;
        auto* controller = window_->controller();
        QVERIFY(controller->setParameters({{"integrator", std::string("explicit-euler")}}).isEmpty());
        test::typeInto(panel_->editor("dt"), "0.002");
        QVERIFY(panel_->problem("dt").isEmpty());
        controller->play();
        QTRY_VERIFY_WITH_TIMEOUT(!dialogs.texts.isEmpty(), 30000);
        QVERIFY2(dialogs.texts.front().contains("The last change before it: Time step (to 0.002)"),
                 qPrintable(dialogs.texts.front()));
    }

    void aNegativeDiameterIsReportedNotReverted() {
        test::MessageBoxAnswerer dialogs;
        const double before = std::get<double>(window_->controller()->model()->params().at("diameter_a"));
        test::typeInto(panel_->editor("diameter_a"), "-0.1");
        QCOMPARE(qobject_cast<QAbstractSpinBox*>(panel_->editor("diameter_a"))->text(), QString("-0.1"));
        const QString problem = panel_->problem("diameter_a");
        QVERIFY2(problem.contains("Diameter (A)") && problem.contains("-0.1") &&
                     problem.contains(allowedFor(window_->controller()->model(), "diameter_a")),
                 qPrintable(problem));
        QCOMPARE(std::get<double>(window_->controller()->model()->params().at("diameter_a")), before);
        QVERIFY(dialogs.texts.isEmpty());
    }

    void errorsAcrossFieldsNameLabelsNotKeys() {
        // More disks than the particle cap: the message speaks of both fields by their labels.
        const double cap = std::get<double>(window_->controller()->model()->params().at("max_particles"));
        test::typeInto(panel_->editor("count_a"), QString::number(static_cast<qint64>(cap) + 1));
        const QString problem = panel_->problem("count_a");
        QVERIFY2(problem.contains("Disks (A)") && problem.contains("Particle cap"), qPrintable(problem));
        static const QRegularExpression internalKey("\\b[a-z]+_[a-z0-9_]+\\b");
        QVERIFY2(!internalKey.match(problem).hasMatch(), qPrintable(problem));
    }

    void aFractionInAnIntegerFieldStaysAsTyped() {
        test::typeInto(panel_->editor("count_a"), "2.5");
        QCOMPARE(qobject_cast<QAbstractSpinBox*>(panel_->editor("count_a"))->text(), QString("2.5"));
        QVERIFY2(panel_->problem("count_a").contains("integer"), qPrintable(panel_->problem("count_a")));
    }

    void textThatIsNoNumberStaysUntilEscape() {
        auto* dt = qobject_cast<QAbstractSpinBox*>(panel_->editor("dt"));
        const QString shown = dt->text();
        test::typeInto(dt, "1e");
        QCOMPARE(dt->text(), QString("1e"));
        QVERIFY2(panel_->problem("dt").contains("not a number"), qPrintable(panel_->problem("dt")));
        QVERIFY(looksRed(dt));
        // Escape drops what was typed: the field shows the value in use again, and is no longer red.
        QLineEdit* edit = dt->findChild<QLineEdit*>();
        QTest::mouseClick(edit, Qt::LeftButton, {}, edit->rect().center());
        QTest::keyClick(dt, Qt::Key_Escape);
        QCOMPARE(dt->text(), shown);
        QVERIFY(panel_->problem("dt").isEmpty());
        QVERIFY(!looksRed(dt));
    }

    void otherEditsLeaveARejectedFieldAlone() {
        test::typeInto(panel_->editor("dt"), "10");
        QVERIFY(panel_->apply("gravity", 0.5).isEmpty()); // every field is shown again after a change
        QCOMPARE(qobject_cast<QAbstractSpinBox*>(panel_->editor("dt"))->text(), QString("10"));
        QVERIFY(!panel_->problem("dt").isEmpty());
    }

    // Numbers are read in the UI's language: German 2,5 is 2.5.
    void aGermanCommaIsTheDecimalMark() {
        const LocaleForTest german_(QLocale(QLocale::German, QLocale::Germany));
        ui::MainWindow german;
        QVERIFY(german.openPreset("gas-mixture"));
        QVERIFY(test::showActive(german));
        test::typeInto(german.parameters()->editor("mass_a"), "2,5");
        QVERIFY2(german.parameters()->problem("mass_a").isEmpty(),
                 qPrintable(german.parameters()->problem("mass_a")));
        QCOMPARE(std::get<double>(german.controller()->parameterValues().at("mass_a")),
                 2.5); // waits for Reset
        QCOMPARE(qobject_cast<QAbstractSpinBox*>(german.parameters()->editor("mass_a"))->text(),
                 QString("2,5"));
        german.document()->setModified(false);
    }

    // In English 2,5 is no number: refused in place with the reason, never read as 25.
    void anEnglishCommaIsRefusedInPlace() {
        const LocaleForTest english_(QLocale(QLocale::English, QLocale::UnitedStates));
        ui::MainWindow english;
        QVERIFY(english.openPreset("gas-mixture"));
        QVERIFY(test::showActive(english));
        const double before = std::get<double>(english.controller()->model()->params().at("mass_a"));
        QWidget* mass = english.parameters()->editor("mass_a");
        test::typeInto(mass, "2,5");
        QCOMPARE(qobject_cast<QAbstractSpinBox*>(mass)->text(), QString("2,5"));
        QVERIFY(looksRed(mass));
        const QString problem = english.parameters()->problem("mass_a");
        QVERIFY2(problem.contains("not a number") && problem.contains("“.”"), qPrintable(problem));
        QCOMPARE(std::get<double>(english.controller()->model()->params().at("mass_a")), before);
        english.document()->setModified(false);
    }

    void lettersTurnTheFieldRed() {
        const double before = std::get<double>(window_->controller()->model()->params().at("gravity"));
        QWidget* gravity = panel_->editor("gravity");
        test::typeInto(gravity, "abc");
        QCOMPARE(qobject_cast<QAbstractSpinBox*>(gravity)->text(), QString("abc")); // not swallowed
        QVERIFY(looksRed(gravity));
        QVERIFY2(panel_->problem("gravity").contains("not a number"), qPrintable(panel_->problem("gravity")));
        QCOMPARE(std::get<double>(window_->controller()->model()->params().at("gravity")), before);
    }

    void aTypedNumberKeepsItsForm() {
        test::typeInto(panel_->editor("count_a"), "1e3");
        QVERIFY2(panel_->problem("count_a").isEmpty(), qPrintable(panel_->problem("count_a")));
        QCOMPARE(std::get<double>(window_->controller()->parameterValues().at("count_a")), 1000.0);
        QCOMPARE(qobject_cast<QAbstractSpinBox*>(panel_->editor("count_a"))->text(), QString("1e3"));
        // Other edits show every field again: this one keeps what was typed.
        QVERIFY(panel_->apply("gravity", 0.5).isEmpty());
        QCOMPARE(qobject_cast<QAbstractSpinBox*>(panel_->editor("count_a"))->text(), QString("1e3"));
    }

    // The wheel over a field that was not clicked into scrolls the panel and changes no value.
    void theWheelScrollsThePanelNotAField() {
        window_->resize(1024, 700);
        QTest::qWait(50);
        auto* scroll = panel_->findChild<QScrollArea*>();
        QVERIFY(scroll);
        QVERIFY2(scroll->verticalScrollBar()->maximum() > 0, "the panel scrolls at 1024 × 700");
        window_->viewport()->setFocus();
        const ParamValues before = window_->controller()->model()->params();
        for (const std::string key : {"diameter_a", "integrator"}) {
            QWidget* field = panel_->editor(key);
            QVERIFY(field);
            scroll->ensureWidgetVisible(field);
            QScrollBar* bar = scroll->verticalScrollBar();
            const int position = bar->value();
            const int delta = position == bar->maximum() ? 120 : -120; // up at the end, else down
            const QPoint at = field->rect().center();
            QWheelEvent wheel(at, field->mapToGlobal(at), {}, QPoint(0, delta), Qt::NoButton, {},
                              Qt::NoScrollPhase, false);
            QApplication::sendEvent(field, &wheel);
            QVERIFY2(!wheel.isAccepted(), key.c_str()); // passed on, as Qt passes a real wheel to the parents
            QVERIFY2(window_->controller()->model()->params() == before, key.c_str());
            QApplication::sendEvent(scroll->viewport(), &wheel);
            QVERIFY2(bar->value() != position, key.c_str());
            QVERIFY(!field->hasFocus());
        }
        // Clicked into, the wheel turns the field.
        auto* diameter = qobject_cast<QAbstractSpinBox*>(panel_->editor("diameter_a"));
        scroll->ensureWidgetVisible(diameter);
        diameter->setFocus(Qt::MouseFocusReason);
        const QPoint at = diameter->rect().center();
        QWheelEvent wheel(at, diameter->mapToGlobal(at), {}, QPoint(0, 120), Qt::NoButton, {},
                          Qt::NoScrollPhase, false);
        QApplication::sendEvent(diameter, &wheel);
        QVERIFY(std::get<double>(window_->controller()->parameterValues().at("diameter_a")) !=
                std::get<double>(before.at("diameter_a")));
    }

    // The line that says changes wait for Reset takes no room of its own: the fields stay where they are.
    void theFieldsStayPutWhenAChangeWaitsForReset() {
        QWidget* dt = panel_->editor("dt");
        const QPoint before = dt->mapTo(panel_, QPoint(0, 0));
        QVERIFY(panel_->apply("count_a", 900.0).isEmpty());
        QCOMPARE(window_->controller()->pendingUntilReset().size(), std::size_t(1));
        QTest::qWait(20);
        QCOMPARE(dt->mapTo(panel_, QPoint(0, 0)), before);
        auto* waiting = panel_->findChild<QLabel*>("pendingLine");
        QVERIFY(waiting && waiting->isVisible());
        QVERIFY(panel_->apply("count_a", 800.0).isEmpty());
        QTest::qWait(20);
        QCOMPARE(dt->mapTo(panel_, QPoint(0, 0)), before);
    }

private:
    std::unique_ptr<ui::MainWindow> window_;
    ui::ParameterPanel* panel_ = nullptr;
};

QTEST_MAIN(TestParameterPanel)
#include "tst_parameterpanel.moc"
