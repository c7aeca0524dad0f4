// Installs ParticleLab's and Qt's translators: the one place that knows where catalogues live
// (qt_add_translations embeds ours under :/i18n; Qt's come from its installation).
#include "Translations.h"

#include "CoreSentences.h"
#include "CoreStrings.h"
#include "common/ParamSpec.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QLocale>
#include <QSettings>
#include <QStringList>
#include <QTranslator>
#include <functional>
#include <memory>

namespace pl::ui {

namespace {

constexpr auto kSettingsKey = "ui/language";
constexpr auto kCatalogueDir = ":/i18n";
constexpr auto kCatalogueName = "particlelab";

struct Installed {
    std::unique_ptr<QTranslator> own, qt;
    QString code = QStringLiteral("en");
};

Installed& installed() {
    static Installed state;
    return state;
}

// Loads catalogue "<name>_<lang>.qm" from dir for the first language of locale that has one.
std::unique_ptr<QTranslator> load(const QLocale& locale, const QString& name, const QString& dir) {
    auto translator = std::make_unique<QTranslator>();
    if (!translator->load(locale, name, QStringLiteral("_"), dir)) return nullptr;
    return translator;
}

} // namespace

QList<Language> availableLanguages() {
    // English is the source language and always there; the others are the embedded catalogues.
    return {{QString(), QCoreApplication::translate("pl::ui::Language", "System default")},
            {QStringLiteral("en"), QStringLiteral("English")},
            {QStringLiteral("de"), QStringLiteral("Deutsch")}};
}

bool installLanguage(const QString& code) {
    Installed& state = installed();
    for (auto* translator : {&state.own, &state.qt}) {
        if (*translator) QCoreApplication::removeTranslator(translator->get());
        translator->reset();
    }
    const QLocale locale = code.isEmpty() ? QLocale::system() : QLocale(code);
    // English texts are the sources, but the English catalogue still carries the plural forms (%n), so
    // it stands in for a language without a catalogue.
    state.own = load(locale, kCatalogueName, kCatalogueDir);
    const bool found = state.own != nullptr;
    if (!found) state.own = load(QLocale(QLocale::English), kCatalogueName, kCatalogueDir);
    if (state.own && state.own->language() != QStringLiteral("en"))
        state.qt = load(locale, QStringLiteral("qtbase"), QLibraryInfo::path(QLibraryInfo::TranslationsPath));
    for (auto* translator : {&state.own, &state.qt})
        if (*translator) QCoreApplication::installTranslator(translator->get());
    state.code = state.own ? QLocale(state.own->language()).name().section('_', 0, 0) : QStringLiteral("en");
    // Numbers are read and written in the language of the texts around them (German 2,5; English 2.5),
    // not in a system setting the user does not see: the catalogue's language, also where the system's
    // locale is another (LANGUAGE=de under LANG=C picks the German texts).
    QLocale::setDefault(found ? QLocale(state.own->language())
                              : QLocale(QLocale::English, QLocale::UnitedStates));
    return found;
}

QString installedLanguage() {
    return installed().code;
}

QString savedLanguage() {
    return QSettings().value(kSettingsKey).toString();
}

void saveLanguage(const QString& code) {
    QSettings().setValue(kSettingsKey, code);
}

QString coreText(const std::string& text) {
    return QCoreApplication::translate(kCoreContext, text.c_str());
}

namespace {

// The template's translation with its numbers in the language's decimal mark and each key as nameOf
// writes it.
QString filledTemplate(const SentenceTemplate& pattern,
                       const std::function<QString(const std::string&)>& nameOf) {
    QString text = coreText(pattern.text);
    const QLocale locale;
    for (const std::string& number : pattern.numbers)
        text = text.arg(QString::fromStdString(number).replace(QLatin1Char('.'), locale.decimalPoint()));
    for (std::size_t k = 0; k < pattern.keys.size(); ++k)
        text.replace(QStringLiteral("{%1}").arg(k + 1), nameOf(pattern.keys[k]));
    return text;
}

} // namespace

QString coreSentence(const std::string& sentence) {
    const SentenceTemplate pattern = sentenceTemplate(sentence);
    if (pattern.numbers.empty() && pattern.keys.empty()) return coreText(sentence);
    return filledTemplate(pattern, [](const std::string& key) { return QString::fromStdString(key); });
}

QString coreRefusal(const std::string& message, const std::vector<ParamSpec>& specs) {
    return filledTemplate(sentenceTemplate(message), [&specs](const std::string& key) {
        const ParamSpec* spec = findSpec(specs, key);
        return spec ? translatedLabel(*spec) : QString::fromStdString(key);
    });
}

QString translatedAllowed(const ParamSpec& spec) {
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator); // bounds as typed: "100000"
    switch (spec.kind) {
    case ParamKind::Real:
    case ParamKind::Integer: {
        // A language that writes a decimal comma separates the bounds with a semicolon.
        const QString separator =
            locale.decimalPoint() == QStringLiteral(",") ? QStringLiteral("; ") : QStringLiteral(", ");
        const auto bound = [&locale](double v) { return locale.toString(v, 'g', 12); };
        QString range = QStringLiteral("[%1%2%3]").arg(bound(spec.min), separator, bound(spec.max));
        if (spec.nonZero) range = QCoreApplication::translate("pl::ui::Allowed", "%1 except 0").arg(range);
        if (!spec.unit.empty()) range += QStringLiteral(" ") + translatedUnit(spec);
        return range;
    }
    case ParamKind::Boolean:
        return QCoreApplication::translate("pl::ui::Allowed", "true or false");
    case ParamKind::Color:
        return QStringLiteral("\"#rrggbb\"");
    case ParamKind::Choice: {
        QStringList choices;
        for (const std::string& choice : spec.choices) choices << coreText(choice);
        return QCoreApplication::translate("pl::ui::Allowed", "one of: %1")
            .arg(choices.join(QStringLiteral(", ")));
    }
    }
    return {};
}

QString translatedLabel(const ParamSpec& spec) {
    return coreText(spec.label);
}
QString translatedUnit(const ParamSpec& spec) {
    return coreText(spec.unit);
}
QString translatedGroup(const ParamSpec& spec) {
    return coreText(spec.group);
}
QString translatedTooltip(const ParamSpec& spec) {
    return coreText(spec.tooltip);
}

} // namespace pl::ui
