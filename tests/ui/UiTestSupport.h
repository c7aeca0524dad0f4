// Helpers for widget tests: clean settings, an active window of the usual size, and modal message boxes
// answered automatically and counted.
#pragma once

#include <QAbstractSpinBox>
#include <QApplication>
#include <QLineEdit>
#include <QMessageBox>
#include <QScrollArea>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>
#include <QTimer>

namespace pl::test {

// Settings in the test-mode locations, emptied: a test never reads or writes the user's (initTestCase).
inline void useCleanTestSettings() {
    QStandardPaths::setTestModeEnabled(true);
    QSettings().clear();
}

// Shows the window at 1280 × 800 and makes it the active one (the window's shortcuts act only there);
// false when it never becomes active.
inline bool showActive(QWidget& window) {
    window.resize(1280, 800);
    window.show();
    window.activateWindow();
    return QTest::qWaitForWindowActive(&window);
}

// Types text into a number field as a user does: scrolled into view, clicked into, all selected, the
// keys, Return.
inline void typeInto(QWidget* field, const QString& text) {
    auto* box = qobject_cast<QAbstractSpinBox*>(field);
    QVERIFY(box);
    for (QWidget* w = box; w; w = w->parentWidget())
        if (auto* scroll = qobject_cast<QScrollArea*>(w)) scroll->ensureWidgetVisible(box);
    QLineEdit* edit = box->findChild<QLineEdit*>();
    QTest::mouseClick(edit, Qt::LeftButton, {}, edit->rect().center());
    QCOMPARE(QApplication::focusWidget(), box);
    QTest::keyClick(box, Qt::Key_A, Qt::ControlModifier);
    QTest::keyClicks(box, text);
    QTest::keyClick(box, Qt::Key_Return);
}

// While alive, accepts every QMessageBox that opens and remembers its text.
class MessageBoxAnswerer : public QObject {
public:
    explicit MessageBoxAnswerer(QMessageBox::StandardButton answer = QMessageBox::Ok) : answer_(answer) {
        timer_.setInterval(20);
        connect(&timer_, &QTimer::timeout, this, [this] {
            for (QWidget* w : QApplication::topLevelWidgets()) {
                auto* box = qobject_cast<QMessageBox*>(w);
                if (!box || !box->isVisible()) continue;
                texts.append(box->text());
                QAbstractButton* button = box->button(answer_);
                if (button)
                    button->click();
                else
                    box->accept();
            }
        });
        timer_.start();
    }
    QStringList texts;

private:
    QMessageBox::StandardButton answer_;
    QTimer timer_;
};

} // namespace pl::test
