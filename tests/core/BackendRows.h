// Qt Test rows `cpu` and `gl` for the physics tests of a model that has a GL backend (DESIGN.md,
// Tests): one test body runs on the CPU reference and on the OpenGL 4.3 model made by gl::createModel
// on the shared headless context. The gl row skips only where no GL 4.3 context exists.
#pragma once

#include "gl/Backends.h"

#include <QtTest>
#include <memory>
#include <string>

namespace pl::test {

inline void addBackendRows() {
    QTest::addColumn<QString>("backend");
    QTest::newRow("cpu") << QStringLiteral("cpu");
    QTest::newRow("gl") << QStringLiteral("gl");
}

// A model on one backend. skip: why the row cannot run here (no GL 4.3 context); failure: why the model
// could not be made although it should have been (a GL context exists but the GPU model failed).
struct BackendModel {
    std::unique_ptr<Model> model;
    std::string skip, failure;

    template <class ConcreteModel> ConcreteModel& as() const { return dynamic_cast<ConcreteModel&>(*model); }
};

inline BackendModel modelOnBackend(const QString& backend, const Preset& preset) {
    BackendModel made;
    if (backend == QLatin1String("cpu")) {
        made.model = gl::createModel(preset.model, gl::Backend::Cpu, &preset).model;
        return made;
    }
    std::shared_ptr<gl::GlContext> context;
    try {
        context = gl::sharedHeadlessContext();
    } catch (const gl::GlUnavailable& e) {
        made.skip = std::string("no GL 4.3 context: ") + e.what();
        return made;
    }
    gl::BackendChoice choice = gl::createModel(preset.model, gl::Backend::Gl, &preset, context);
    if (choice.backend != gl::Backend::Gl) {
        made.failure = "the GL model was not made: " + choice.message;
        return made;
    }
    made.model = std::move(choice.model);
    return made;
}

} // namespace pl::test

// Declares `made` (a BackendModel) for the row's backend: skips the row without a GL 4.3 context and
// fails it when the model cannot be made.
#define PL_MODEL_ON_ROW_BACKEND(made, preset)                                                                \
    QFETCH(QString, backend);                                                                                \
    const pl::test::BackendModel made = pl::test::modelOnBackend(backend, preset);                           \
    if (!made.skip.empty()) QSKIP(made.skip.c_str());                                                        \
    QVERIFY2(made.model != nullptr, made.failure.c_str())
