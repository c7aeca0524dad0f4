// The window's keys act whatever widget has focus, except in a text field being typed into; Enter and
// Escape there hand the keyboard back to the viewport, which has it at start and takes it on a click; a
// field that refused its value on Enter keeps it until Escape clears the mark.
// Every key goes through QTest to the widget that has focus, as the X server would deliver it.
#include "ExperimentDocument.h"
#include "MainWindow.h"
#include "SimulationController.h"
#include "UiTestSupport.h"
#include "panels/ParameterPanel.h"
#include "viewport/ViewportCore.h"

#include <QAbstractSpinBox>
#include <QComboBox>
#include <QLineEdit>
#include <QSettings>
#include <QSpinBox>
#include <QStandardPaths>
#include <QStyleOptionSpinBox>
#include <QtTest>

using namespace pl;

namespace {

QWidget* focused() {
    return QApplication::focusWidget();
}

void press(int key, Qt::KeyboardModifiers modifiers = {}) {
    QTest::keyClick(focused(), Qt::Key(key), modifiers);
}

void type(const QString& text) {
    QTest::keyClicks(focused(), text);
}

// Clicks into the text of a spin box, as a user who means to type there does.
void clickIntoText(QAbstractSpinBox* box) {
    QLineEdit* edit = box->findChild<QLineEdit*>();
    QTest::mouseClick(edit, Qt::LeftButton, {}, edit->rect().center());
    QCOMPARE(focused(), box);
}

double paramOf(ui::MainWindow& window, const std::string& key) {
    return std::get<double>(window.controller()->model()->params().at(key));
}

} // namespace

class TestShortcuts : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { test::useCleanTestSettings(); }

    void init() {
        window_ = std::make_unique<ui::MainWindow>();
        QVERIFY(window_->openPreset("gas-mixture"));
        QVERIFY(test::showActive(*window_));
        speed_ = window_->findChild<QSpinBox*>("stepsPerFrame");
        QVERIFY(speed_);
    }

    void cleanup() {
        window_->controller()->pause();
        window_->document()->setModified(false); // no "save changes?" question on close
        window_.reset();
    }

    void viewportHasTheKeyboardAtStartAndAfterAClick() {
        QCOMPARE(focused(), window_->viewport());
        press(Qt::Key_Space);
        QVERIFY(window_->controller()->isRunning());
        press(Qt::Key_Space);
        QVERIFY(!window_->controller()->isRunning());

        speed_->setFocus(Qt::TabFocusReason);
        QCOMPARE(focused(), speed_);
        QWidget* view = window_->viewport();
        QTest::mouseClick(view, Qt::LeftButton, {}, view->rect().center());
        QCOMPARE(focused(), view);
    }

    void shortcutsActInTheStepsPerFrameBox() {
        // Focus arrives as it does for a user: a click on the box's up arrow.
        QStyleOptionSpinBox option;
        option.initFrom(speed_);
        option.subControls = QStyle::SC_SpinBoxUp;
        const QRect up =
            speed_->style()->subControlRect(QStyle::CC_SpinBox, &option, QStyle::SC_SpinBoxUp, speed_);
        const int before = speed_->value();
        QTest::mouseClick(speed_, Qt::LeftButton, {}, up.center());
        QCOMPARE(focused(), speed_);
        QCOMPARE(speed_->value(), before + 1);

        press(Qt::Key_Space);
        QVERIFY(window_->controller()->isRunning());
        press(Qt::Key_Space);
        QVERIFY(!window_->controller()->isRunning());
        press(Qt::Key_3);
        QCOMPARE(window_->viewportCore()->tool(), ui::ViewportTool::AddDisc);
        QCOMPARE(speed_->value(), before + 1); // the digit was a tool, not typed
        press(Qt::Key_BracketRight);
        QCOMPARE(speed_->value(), before + 2);
        const long long steps = window_->controller()->model()->stepCount();
        press(Qt::Key_Period);
        QCOMPARE(window_->controller()->model()->stepCount(), steps + 1);
        press(Qt::Key_Backspace); // reverse time, not "delete a character"
        QCOMPARE(speed_->value(), -(before + 2));
    }

    void shortcutsActInParameterFields() {
        QWidget* dt = window_->parameters()->editor("dt");
        dt->setFocus(Qt::TabFocusReason);
        QCOMPARE(focused(), dt);
        const QString text = qobject_cast<QAbstractSpinBox*>(dt)->text();
        press(Qt::Key_Space);
        QVERIFY(window_->controller()->isRunning());
        press(Qt::Key_Space);
        QVERIFY(!window_->controller()->isRunning());
        press(Qt::Key_2);
        QCOMPARE(window_->viewportCore()->tool(), ui::ViewportTool::Spawn);
        QCOMPARE(qobject_cast<QAbstractSpinBox*>(dt)->text(), text);

        auto* integrator = qobject_cast<QComboBox*>(window_->parameters()->editor("integrator"));
        QVERIFY(integrator);
        integrator->setFocus(Qt::TabFocusReason);
        press(Qt::Key_Space); // not "open the list"
        QVERIFY(window_->controller()->isRunning());
        press(Qt::Key_1);
        QCOMPARE(window_->viewportCore()->tool(), ui::ViewportTool::Drag);
    }

    void aFieldBeingTypedIntoKeepsItsKeys() {
        auto* dt = qobject_cast<QAbstractSpinBox*>(window_->parameters()->editor("dt"));
        clickIntoText(dt);
        press(Qt::Key_A, Qt::ControlModifier); // select all, as a user replacing the value does
        const long long steps = window_->controller()->model()->stepCount();
        type("0.0002");       // '.' steps and '2' picks a tool when nobody types
        press(Qt::Key_Space); // typed, as in any text field
        QCOMPARE(dt->text(), QString("0.0002 "));
        QVERIFY(!window_->controller()->isRunning());
        QCOMPARE(window_->controller()->model()->stepCount(), steps);
        QCOMPARE(window_->viewportCore()->tool(), ui::ViewportTool::Drag);
        press(Qt::Key_Backspace); // deletes the space and the last digit; time keeps its direction
        press(Qt::Key_Backspace);
        QCOMPARE(dt->text(), QString("0.000"));
        QVERIFY(speed_->value() > 0);
        type("3");
        press(Qt::Key_Return);
        QCOMPARE(paramOf(*window_, "dt"), 0.0003);
        QCOMPARE(focused(), window_->viewport());
        press(Qt::Key_Space); // the keyboard is the window's again
        QVERIFY(window_->controller()->isRunning());
    }

    void typingAfterTabStartsAnEdit() {
        // Focus from Tab alone is not an edit, but the first character that is no shortcut starts one.
        auto* dt = qobject_cast<QAbstractSpinBox*>(window_->parameters()->editor("dt"));
        dt->setFocus(Qt::TabFocusReason);
        press(Qt::Key_A, Qt::ControlModifier);
        type("0.00025");
        QCOMPARE(dt->text(), QString("0.00025"));
        QCOMPARE(window_->viewportCore()->tool(), ui::ViewportTool::Drag);
        press(Qt::Key_Enter);
        QCOMPARE(paramOf(*window_, "dt"), 0.00025);
        QCOMPARE(focused(), window_->viewport());
    }

    void escapeDropsTheTextAndReturnsTheKeyboard() {
        const double before = paramOf(*window_, "dt");
        auto* dt = qobject_cast<QAbstractSpinBox*>(window_->parameters()->editor("dt"));
        const QString shown = dt->text();
        clickIntoText(dt);
        press(Qt::Key_A, Qt::ControlModifier);
        type("0.0001");
        press(Qt::Key_Escape);
        QCOMPARE(focused(), window_->viewport());
        QCOMPARE(dt->text(), shown);
        QCOMPARE(paramOf(*window_, "dt"), before);

        clickIntoText(speed_);
        press(Qt::Key_A, Qt::ControlModifier);
        type("4");
        press(Qt::Key_Return);
        QCOMPARE(speed_->value(), 4);
        QCOMPARE(window_->controller()->stepsPerFrame(), 4);
        QCOMPARE(focused(), window_->viewport());
    }

    // Issue 45: a value refused on Enter left its field red and the keyboard with the viewport, so Escape
    // never reached the field. The refused field keeps the keyboard; Escape puts back the value in use,
    // clears the mark and then hands the keyboard back.
    void escapeAfterARefusedEnterClearsTheRedMark() {
        const double before = paramOf(*window_, "dt");
        auto* dt = qobject_cast<QAbstractSpinBox*>(window_->parameters()->editor("dt"));
        const QString shown = dt->text();
        clickIntoText(dt);
        press(Qt::Key_A, Qt::ControlModifier);
        type("10"); // beyond the time step's range
        press(Qt::Key_Return);
        QVERIFY(!window_->parameters()->problem("dt").isEmpty());
        QCOMPARE(focused(), dt);
        press(Qt::Key_Escape);
        QVERIFY2(window_->parameters()->problem("dt").isEmpty(),
                 qPrintable(window_->parameters()->problem("dt")));
        QCOMPARE(dt->text(), shown);
        QCOMPARE(paramOf(*window_, "dt"), before);
        QCOMPARE(focused(), window_->viewport());
    }

    void controlShortcutsActWhileTyping() {
        QAction* projector = nullptr;
        for (QAction* action : window_->findChildren<QAction*>())
            if (action->shortcut() == QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_P)) projector = action;
        QVERIFY(projector);
        auto* dt = qobject_cast<QAbstractSpinBox*>(window_->parameters()->editor("dt"));
        clickIntoText(dt);
        type("1");
        press(Qt::Key_P, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(projector->isChecked());
        press(Qt::Key_P, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(!projector->isChecked());
    }

private:
    std::unique_ptr<ui::MainWindow> window_;
    QSpinBox* speed_ = nullptr;
};

QTEST_MAIN(TestShortcuts)
#include "tst_shortcuts.moc"
