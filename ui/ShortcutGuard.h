// Keeps a window's shortcuts working whatever widget has focus, except in a text field being edited;
// Enter or Escape there finishes the edit and hands the keyboard back to the viewport.
#pragma once

#include <QObject>
#include <QPointer>

class QKeyEvent;
class QWidget;

namespace pl::ui {

// A text field that refused what was typed (marked red, its reason beside it) carries this property as
// true: Enter leaves it the keyboard, so Escape (or a correction) reaches it, not the viewport.
inline constexpr char kRefusedFieldProperty[] = "pl_refused";

// Installed on the application (it must see ShortcutOverride before any widget does). A text field — a
// line edit, a spin box or an editable combo box — is being edited from the moment the user clicks into
// its text or types a key that changes it (a character no shortcut uses, Backspace, Delete, Paste),
// until Enter, Escape or focus leaves it. While it is, it keeps the keys a line edit takes (characters,
// Backspace, the arrows); shortcuts with Ctrl still act. Any other widget, and a text field that merely
// has focus (at start-up, after Tab or a click on its arrows), lets every shortcut of the window act.
class ShortcutGuard : public QObject {
    Q_OBJECT
public:
    // home takes the keyboard after Enter or Escape in a text field of window.
    ShortcutGuard(QWidget* window, QWidget* home);

    // The text field being edited, or nullptr.
    QWidget* editing() const { return editing_; }

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    bool inWindow(const QWidget* widget) const;
    bool matchesShortcut(const QKeyEvent* key) const;
    bool finishEdit(QWidget* field, QKeyEvent* key);

    QPointer<QWidget> window_;
    QPointer<QWidget> home_;
    QPointer<QWidget> editing_;
    bool forwarding_ = false; // while finishEdit hands Enter / Escape to the field itself
};

// The text field that owns widget's text (a spin box for its line edit), or nullptr for other widgets.
QWidget* textFieldOf(QWidget* widget);

} // namespace pl::ui
