// SceneDescription: the sentences come from what the overlay draws (the colour legend, the bodies, the
// piston, the hint, the failure notice) and from present mode's readouts, each in the UI's language through
// the core's catalogue, so the spoken scene and the drawn one say the same.
#include "SceneDescription.h"

#include "SeriesStore.h"
#include "catalog/ModelCatalog.h"
#include "common/Model.h"
#include "i18n/Translations.h"
#include "present/PresentBoard.h"
#include "present/PresentReadouts.h"

#include <QCoreApplication>
#include <QLocale>
#include <QStringList>
#include <algorithm>
#include <climits>

namespace pl::ui {

namespace {
// "Colour shows speed." or "Colours: species A, species B."
QString colourSentence(const SceneView& scene) {
    if (scene.field && !scene.drawParticles)
        return QCoreApplication::translate("SceneDescription", "Colour shows the sampled field %1.")
            .arg(coreText(scene.field->label));
    if (!scene.categories.empty()) {
        QStringList names;
        for (const std::string& c : scene.categories) names << coreSentence(c);
        return QCoreApplication::translate("SceneDescription", "Colours: %1.")
            .arg(names.join(QStringLiteral(", ")));
    }
    if (!scene.colourLabel.empty())
        return QCoreApplication::translate("SceneDescription", "Colour shows %1.")
            .arg(coreText(scene.colourLabel));
    return {};
}
} // namespace

QString sceneAccessibleName(const Model& model) {
    const ModelDescriptor* descriptor = findModel(model.kind());
    const QString title = descriptor ? coreText(descriptor->title) : QString::fromStdString(model.kind());
    return QCoreApplication::translate("SceneDescription", "Scene: %1").arg(title);
}

QString sceneAccessibleDescription(const Model& model, const SceneView& scene, const SeriesStore& series) {
    QStringList sentences;
    if (model.failure())
        sentences << QCoreApplication::translate("SceneDescription",
                                                 "The simulation stopped: its state is no longer physical.");
    const int particles = static_cast<int>(std::min<std::size_t>(model.particleCount(), INT_MAX));
    sentences << QCoreApplication::translate("SceneDescription", "%n particle(s).", nullptr, particles);
    if (const QString colour = colourSentence(scene); !colour.isEmpty()) sentences << colour;
    const int obstacles = static_cast<int>(scene.obstacles.size());
    if (obstacles > 0)
        sentences << QCoreApplication::translate("SceneDescription", "%n obstacle(s).", nullptr, obstacles);
    if (scene.pistonX)
        sentences << QCoreApplication::translate("SceneDescription", "A piston stands at x = %1.")
                         .arg(QLocale().toString(*scene.pistonX, 'g', 3));
    if (!scene.hint.empty()) sentences << coreText(scene.hint);
    QStringList readouts;
    for (const ReadoutSpec& spec : readoutSpecsFor(model)) {
        const int column = series.column(spec.column);
        if (column < 0 || (spec.needsBodies && scene.obstacles.empty())) continue;
        readouts << QStringLiteral("%1 = %2").arg(spec.name, readoutValueText(spec, series.table(), column));
    }
    if (!readouts.isEmpty()) sentences << readouts.join(QStringLiteral(", ")) + QLatin1Char('.');
    return sentences.join(QLatin1Char(' '));
}

} // namespace pl::ui
