// The one place that chooses a backend: the CPU reference, or the GPU models of this library.
#pragma once

#include "GlContext.h"
#include "common/Model.h"

#include <memory>
#include <string>
#include <vector>

namespace pl::gl {

enum class Backend { Cpu, Gl, Auto };

Backend backendFromName(const std::string& name); // "cpu", "gl", "auto"; throws std::invalid_argument
std::string backendName(Backend backend);
const std::vector<std::string>& backendNames();

// Kinds that have a GPU model (GpuModels.cpp).
bool hasGpuModel(const std::string& kind);

// Particles from which the GPU model is worth its hand-over costs on this context: a software
// rasteriser shares the CPU's cores and never is; a real GPU wins from a few thousand particles.
std::size_t autoGpuThreshold(const ContextInfo& info);

struct BackendChoice {
    std::unique_ptr<Model> model;
    Backend backend = Backend::Cpu; // what was made
    std::string message;            // why, when it is not what was asked for (empty otherwise)
};

// A model reset to preset on the asked backend: the one factory of the CLI, the UI and the bench. For
// Gl and Auto the shared headless context is used unless context is given; a missing GL 4.3 context gives
// the CPU model and a message, never an exception. Auto picks the GPU when the preset's particle count
// (from its parameters, pl::particleCount) reaches the threshold. Throws PresetError for a bad preset,
// like instantiate().
BackendChoice createModel(const Preset& preset, Backend backend,
                          std::shared_ptr<GlContext> context = nullptr);
// The same for a model of kind, reset to preset when given, else to the kind's defaults. Throws
// PresetError for an unknown kind.
BackendChoice createModel(const std::string& kind, Backend backend, const Preset* preset = nullptr,
                          std::shared_ptr<GlContext> context = nullptr);

} // namespace pl::gl
