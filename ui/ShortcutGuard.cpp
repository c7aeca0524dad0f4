// ShortcutGuard: Qt asks the focus widget first (ShortcutOverride) whether it wants a key a shortcut
// uses; a spin box or a line edit says yes to every character, so Space and the digits never reached
// the window's actions. The guard answers for those widgets unless the user is typing into them.
#include "ShortcutGuard.h"

#include <QAbstractSpinBox>
#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QKeyEvent>
#include <QLineEdit>
#include <QShortcut>

namespace pl::ui {

namespace {

bool isFinishKey(const QKeyEvent* key) {
    return key->key() == Qt::Key_Return || key->key() == Qt::Key_Enter || key->key() == Qt::Key_Escape;
}

// Keys after which a line edit's text is no longer what the program put there.
bool changesText(const QKeyEvent* key) {
    if (key->key() == Qt::Key_Backspace || key->key() == Qt::Key_Delete) return true;
    if (key->matches(QKeySequence::Paste) || key->matches(QKeySequence::Cut) ||
        key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo))
        return true;
    const bool command = key->modifiers() & (Qt::ControlModifier | Qt::AltModifier | Qt::MetaModifier);
    return !command && !key->text().isEmpty() && key->text().front().isPrint();
}

} // namespace

QWidget* textFieldOf(QWidget* widget) {
    if (!widget) return nullptr;
    if (auto* spin = qobject_cast<QAbstractSpinBox*>(widget)) return spin->isReadOnly() ? nullptr : spin;
    if (auto* combo = qobject_cast<QComboBox*>(widget)) return combo->isEditable() ? combo : nullptr;
    if (auto* edit = qobject_cast<QLineEdit*>(widget)) {
        if (edit->isReadOnly()) return nullptr;
        QWidget* owner = edit->parentWidget();
        if (qobject_cast<QAbstractSpinBox*>(owner) || qobject_cast<QComboBox*>(owner)) return owner;
        return edit;
    }
    return nullptr;
}

ShortcutGuard::ShortcutGuard(QWidget* window, QWidget* home) : QObject(window), window_(window), home_(home) {
    qApp->installEventFilter(this);
}

bool ShortcutGuard::inWindow(const QWidget* widget) const {
    return widget && window_ && widget->window() == window_;
}

bool ShortcutGuard::matchesShortcut(const QKeyEvent* key) const {
    // A keypad digit is the digit: Qt's shortcut map reads it so too.
    const QKeySequence pressed(QKeyCombination(key->modifiers() & ~Qt::KeypadModifier, Qt::Key(key->key())));
    for (const QAction* action : window_->findChildren<QAction*>())
        if (action->isEnabled() && action->shortcuts().contains(pressed)) return true;
    for (const QShortcut* shortcut : window_->findChildren<QShortcut*>())
        if (shortcut->isEnabled() && shortcut->keys().contains(pressed)) return true;
    return false;
}

bool ShortcutGuard::finishEdit(QWidget* field, QKeyEvent* key) {
    // The field acts on the key first (a spin box applies its text on Enter), then the viewport takes
    // the keyboard; Escape puts back the value the field holds, dropping what was typed.
    if (key->key() == Qt::Key_Escape)
        if (auto* spin = qobject_cast<QAbstractSpinBox*>(field); spin && spin->property("value").isValid())
            spin->setProperty("value", spin->property("value"));
    forwarding_ = true;
    QCoreApplication::sendEvent(field, key);
    forwarding_ = false;
    key->accept(); // handled here: not passed on to the field's parents
    if (key->key() != Qt::Key_Escape && field->property(kRefusedFieldProperty).toBool()) {
        editing_ = field; // still being edited: Escape here drops the text and its red mark
        return true;
    }
    editing_ = nullptr;
    if (home_) home_->setFocus(Qt::OtherFocusReason);
    return true;
}

bool ShortcutGuard::eventFilter(QObject* watched, QEvent* event) {
    if (forwarding_ || !window_) return false;
    switch (event->type()) {
    case QEvent::ShortcutOverride: {
        auto* key = static_cast<QKeyEvent*>(event);
        QWidget* focus = QApplication::focusWidget();
        if (!inWindow(focus) || focus == home_) return false;
        QWidget* field = textFieldOf(focus);
        if (field && field == editing_) {
            if (!isFinishKey(key)) return false; // the field keeps the keys a line edit takes
            key->accept();                       // Enter and Escape end the edit, whatever they are bound to
            return true;
        }
        if (!matchesShortcut(key)) return false;
        key->ignore(); // no widget overrides it: the window's shortcut acts
        return true;
    }
    case QEvent::KeyPress: {
        auto* key = static_cast<QKeyEvent*>(event);
        QWidget* focus = QApplication::focusWidget();
        if (watched != focus || !inWindow(focus)) return false; // once per key, at its first receiver
        QWidget* field = textFieldOf(focus);
        if (!field) return false;
        if (isFinishKey(key)) return finishEdit(field, key);
        if (changesText(key)) editing_ = field;
        return false;
    }
    case QEvent::MouseButtonPress: {
        // A click into the text (not on a spin box's arrows, which are the spin box itself) starts an edit.
        auto* edit = qobject_cast<QLineEdit*>(watched);
        if (edit && inWindow(edit)) editing_ = textFieldOf(edit);
        return false;
    }
    case QEvent::FocusOut: {
        // A context menu or another window taking the keyboard for a while does not end the edit.
        const auto reason = static_cast<QFocusEvent*>(event)->reason();
        if (reason == Qt::PopupFocusReason || reason == Qt::ActiveWindowFocusReason) return false;
        auto* widget = qobject_cast<QWidget*>(watched);
        if (widget && widget == editing_) editing_ = nullptr;
        return false;
    }
    default:
        return false;
    }
}

} // namespace pl::ui
