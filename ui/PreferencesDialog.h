// Preferences (File → Preferences…): the user's choices that outlive a session, kept in QSettings.
#pragma once

#include <QDialog>

class QComboBox;

namespace pl::ui {

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    explicit PreferencesDialog(QWidget* parent = nullptr);

    // The language code chosen in the dialog ("" for the system's language).
    QString chosenLanguage() const;

    // Saves the choices (called when the dialog is accepted).
    void apply() const;

private:
    QComboBox* language_;
};

} // namespace pl::ui
