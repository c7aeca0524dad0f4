// PreferencesDialog: the language, saved for the next start (menus and docks are built once per window,
// so a new language shows when ParticleLab starts again).
#include "PreferencesDialog.h"

#include "i18n/Translations.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QVBoxLayout>
#include <algorithm>

namespace pl::ui {

PreferencesDialog::PreferencesDialog(QWidget* parent) : QDialog(parent), language_(new QComboBox(this)) {
    setWindowTitle(tr("Preferences"));
    language_->setObjectName("languageBox");
    for (const Language& language : availableLanguages()) language_->addItem(language.name, language.code);
    language_->setCurrentIndex(std::max(0, language_->findData(savedLanguage())));
    language_->setToolTip(tr("The language of menus, panels and messages"));

    auto* form = new QFormLayout;
    form->addRow(tr("&Language:"), language_);
    auto* note = new QLabel(tr("A new language shows the next time ParticleLab starts."), this);
    note->setWordWrap(true);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(this, &QDialog::accepted, this, &PreferencesDialog::apply);

    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(note);
    layout->addStretch();
    layout->addWidget(buttons);
}

QString PreferencesDialog::chosenLanguage() const {
    return language_->currentData().toString();
}

void PreferencesDialog::apply() const {
    saveLanguage(chosenLanguage());
}

} // namespace pl::ui
