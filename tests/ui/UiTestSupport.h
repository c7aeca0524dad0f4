// Helpers for widget tests: clean settings, an active window of the usual size, modal message boxes
// answered automatically and counted, and what of a panel its window shows (present mode's board).
#pragma once

#include <QAbstractButton>
#include <QAbstractSlider>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QLineEdit>
#include <QMessageBox>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QStandardPaths>
#include <QTest>
#include <QTimer>
#include <qcustomplot.h>

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

// The part of widget that its window shows: its rectangle clipped by every parent up to the window
// (a scroll area's viewport, the dock, the window), in the widget's own coordinates.
inline QRect shownPart(const QWidget* widget, const QWidget* window) {
    QRect clip = widget->rect();
    QPoint offset(0, 0); // widget → current ancestor
    for (const QWidget* w = widget; w && w != window; w = w->parentWidget()) {
        offset += w->pos();
        const QWidget* parent = w->parentWidget();
        if (!parent) break;
        clip &= parent->rect().translated(-offset);
    }
    return clip;
}

// Every shown widget of panel that is cut off (partly hidden by a parent's edge, a scroll area's
// included, or a button or chooser too narrow for its text), as "objectName (class) W×H".
inline QStringList cutOffWidgets(QWidget* panel, QWidget* window) {
    QStringList cut;
    for (QWidget* w : panel->findChildren<QWidget*>()) {
        if (!w->isVisibleTo(window) || w->rect().isEmpty() || qobject_cast<QScrollBar*>(w)) continue;
        const bool narrow = (qobject_cast<QAbstractButton*>(w) || qobject_cast<QComboBox*>(w)) &&
                            w->width() < w->minimumSizeHint().width();
        if (shownPart(w, window) != w->rect() || narrow)
            cut << QString("%1 (%2) %3x%4")
                       .arg(w->objectName(), w->metaObject()->className())
                       .arg(w->width())
                       .arg(w->height());
    }
    return cut;
}

// The least data area (inside the axes) a board's plot keeps at 1024 × 700, in either mode: room for three
// labelled value ticks that do not overprint and a value label not cut to its first letter (before:
// 40–60 px in projector mode).
inline constexpr int kReadableDataHeight = 90;

// What a teacher can use of a board without scrolling: its controls (buttons, sliders, choosers, number
// fields) that the window shows whole, of all it has, and the heights in pixels of its drawings' data
// areas (inside the axes: what is left for the curves after titles, legends, ticks and labels).
struct BoardReach {
    int controls = 0, inReach = 0;
    QList<int> plotHeights; // per axis rect of every plot, the part of it the window shows
    QStringList outOfReach;
};
inline BoardReach boardReach(QWidget* panel, QWidget* window) {
    BoardReach reach;
    for (QWidget* w : panel->findChildren<QWidget*>()) {
        if (!w->isVisibleTo(window) || qobject_cast<QScrollBar*>(w)) continue;
        if (auto* canvas = qobject_cast<QCustomPlot*>(w)) {
            const QRect shown = shownPart(canvas, window);
            for (QCPAxisRect* rect : canvas->axisRects())
                reach.plotHeights << rect->rect().intersected(shown).height();
            continue;
        }
        if (!qobject_cast<QAbstractButton*>(w) && !qobject_cast<QAbstractSlider*>(w) &&
            !qobject_cast<QComboBox*>(w) && !qobject_cast<QAbstractSpinBox*>(w))
            continue;
        ++reach.controls;
        if (!w->rect().isEmpty() && shownPart(w, window) == w->rect())
            ++reach.inReach;
        else
            reach.outOfReach << w->objectName();
    }
    return reach;
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
