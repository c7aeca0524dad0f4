// The application's language: which translators are installed, the saved choice, and the lookup of the
// core's English texts (parameter labels, scene titles) at the point where the UI shows them.
#pragma once

#include <QList>
#include <QString>
#include <string>
#include <vector>

namespace pl {
struct ParamSpec;
}

namespace pl::ui {

struct Language {
    QString code; // "" for the system's language, else an ISO 639 code: "en", "de"
    QString name; // in its own language, as a menu shows it: "Deutsch"
};

// The languages Preferences offers: the system default first, then every shipped translation.
QList<Language> availableLanguages();

// Replaces the installed translators by those of code ("" follows the system's UI languages, "en" is the
// source language): ParticleLab's own catalogue and Qt's (dialog buttons, file dialogs). Widgets made
// afterwards show the new language. Returns false when no ParticleLab catalogue exists for code (English
// then shows).
bool installLanguage(const QString& code);
// The language code installLanguage() last installed ("en" when English shows).
QString installedLanguage();

// The choice kept in QSettings ("ui/language"); "" (the system's language) when none was made.
QString savedLanguage();
void saveLanguage(const QString& code);

// A core text in the installed language; the text itself when no translation exists.
QString coreText(const std::string& text);
// A core sentence with numbers ("kT = 0.52, KS distance 0.012"): its template (CoreSentences.h) in the
// installed language, the numbers written with the language's decimal mark.
QString coreSentence(const std::string& sentence);
// A model's refusal of parameter values (ParamError::message(), its parameters marked {key}): its
// template in the installed language, each parameter named by its translated label from specs.
QString coreRefusal(const std::string& message, const std::vector<ParamSpec>& specs);
// The values a parameter allows, in the installed language: its bounds with the language's numbers and
// its unit, or its choices.
QString translatedAllowed(const ParamSpec& spec);
QString translatedLabel(const ParamSpec& spec);
QString translatedUnit(const ParamSpec& spec);
QString translatedGroup(const ParamSpec& spec);
QString translatedTooltip(const ParamSpec& spec);

} // namespace pl::ui
